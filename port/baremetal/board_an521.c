/* SPDX-License-Identifier: MIT */
/*
 * board_an521.c: QEMU mps2-an521, two Cortex-M33 in an SSE-200 subsystem,
 * both running Secure. The board-level devices are the an505's: output
 * through semihosting or UART0 at its Secure alias, and the FPGAIO
 * counters (board_an505.c says how their ticks become instructions; on
 * this board the virtual clock advances with the instructions of both
 * cores, so the count port_cycles() gives is their sum).
 *
 * The second core: at reset the SSE-200 holds core 1 (bit 1 of CPUWAIT in
 * the system control registers is set). port_core1_start() writes the
 * address of core 1's own vector table to INITSVTOR1, the Secure vector
 * table core 1 reads at its reset, then clears the CPUWAIT bit, which
 * resets and releases the core. Core 1 takes its stack pointer and entry
 * from that table: its stack is [_sstack1, _estack1) of the linker script
 * (linker/an521.ld), and its entry sets MSPLIM to the bottom of it and
 * runs port_core1_main().
 */
#include "port.h"
#include "cmsdk_uart.h"

#define FPGAIO_CLK100HZ (*(volatile const uint32_t *)0x50302014u)
#define FPGAIO_COUNTER (*(volatile const uint32_t *)0x50302018u)
#define TICKS_PER_CLK100 200000u

/* SSE-200 system control registers, Secure, at 0x50021000. */
#define SYSCTL_INITSVTOR1 (*(volatile uint32_t *)0x50021114u)
#define SYSCTL_CPUWAIT (*(volatile uint32_t *)0x50021118u)
#define CPUWAIT_CORE1 (1u << 1)

extern uint32_t _sstack1[], _estack1[];
void fault_hard(void);
void fault_mem(void);
void fault_bus(void);
void fault_usage(void);
void fault_secure(void);
void fault_other(void);
static void core1_reset(void) __attribute__((noreturn));

typedef void (*vector_fn)(void);

/* Core 1's vector table. VTOR ignores the low 7 bits of the address, so
 * the table is aligned to 128 bytes. The fault entries are core 0's
 * (startup_cortexm.c): a fault on either core ends the run with its
 * code. */
__attribute__((aligned(128))) static const vector_fn core1_vectors[16] = {
    (vector_fn)(uintptr_t)_estack1, /* initial stack pointer */
    core1_reset,
    fault_other, /* NMI */
    fault_hard,
    fault_mem,
    fault_bus,
    fault_usage,
    fault_secure,
    0, 0, 0,
    fault_other, /* SVCall */
    fault_other, /* DebugMonitor */
    0,
    fault_other, /* PendSV */
    fault_other  /* SysTick */
};

static void core1_reset(void)
{
    __asm__ volatile("msr msplim, %0" : : "r"(_sstack1));
    port_core1_main();
    for (;;)
        __asm__ volatile("wfe");
}

void port_core1_start(void)
{
    SYSCTL_INITSVTOR1 = (uint32_t)(uintptr_t)core1_vectors;
    __asm__ volatile("dsb" ::: "memory");
    SYSCTL_CPUWAIT &= ~CPUWAIT_CORE1;
}

/* UART0 for OUTPUT=uart (cmsdk_uart.h), 115200 baud at 20 MHz. */
void port_uart_init(void)
{
    cmsdk_uart_init(0x50200000u, 174u);
}

void port_uart_putc(uint8_t c)
{
    cmsdk_uart_putc(0x50200000u, c);
}

/* Core 0's SysTick, counting the processor clock (20 MHz), with no
 * interrupt. */
#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
/* 25,600 ticks: 10,000 instructions of virtual time at -icount shift=7. */
#define TURN_TICKS 25600u

/* QEMU runs the two cores in turns on one host thread (-icount rules out
 * running them at once), and a core keeps its turn until the next timer
 * of the virtual clock falls due, which with no timer running is
 * billions of instructions. A running SysTick falls due every TURN_TICKS,
 * so the cores take turns of a few thousand instructions each, as two
 * cores side by side would share the time; a core that waits for the
 * other spends its turn polling, so its count includes the wait. On a
 * real SSE-200 the counter is just a counter: nothing takes an
 * interrupt. */
void port_init(void)
{
    SYST_RVR = TURN_TICKS - 1u;
    SYST_CVR = 0;
    SYST_CSR = 5u; /* enable, processor clock, no interrupt */
    port_output_init();
}

uint64_t port_cycles(void)
{
    uint64_t est = (uint64_t)FPGAIO_CLK100HZ * TICKS_PER_CLK100;
    uint32_t fine = FPGAIO_COUNTER;
    return est + (uint32_t)(fine - (uint32_t)est);
}

uint64_t port_cycles_to_insns(uint64_t cycles)
{
    return (cycles * 25 + 32) / 64;
}
