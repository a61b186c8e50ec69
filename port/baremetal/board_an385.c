/* SPDX-License-Identifier: MIT */
/*
 * board_an385.c: QEMU mps2-an385 (Cortex-M3), also used by the m0 build
 * (Cortex-M0 code on the same machine).
 *
 * Output: semihosting (out_semihost.c), or UART0 (out_uart.c).
 *
 * Counter: the FPGAIO COUNTER, a 32-bit up-counter at 25 MHz of virtual
 * time since reset. Under -icount shift=7
 * one instruction is 128 ns = 3.2 ticks, so instructions = ticks * 5 / 16,
 * rounded: a difference of two readings is off by less than one tick, 0.31
 * instructions, so the rounded count is exact.
 *
 * COUNTER wraps after 172 s of virtual time (1.3 G instructions), less
 * than a large render on the M0. The FPGAIO 100 Hz counter, which also
 * counts from reset, supplies the upper bits: 100 Hz * 250000 = 25 MHz.
 * QEMU computes both from the virtual clock without rounding drift, so
 * reading them does not disturb them.
 */
#include "port.h"

#define FPGAIO_CLK100HZ (*(volatile const uint32_t *)0x40028014u)
#define FPGAIO_COUNTER (*(volatile const uint32_t *)0x40028018u)
#define TICKS_PER_CLK100 250000u

/* MPU registers. The machine's core is an M3 even for the m0 build, whose
 * M0 instruction set reaches them with plain stores. */
#define MPU_CTRL (*(volatile uint32_t *)0xE000ED94u)
#define MPU_RNR (*(volatile uint32_t *)0xE000ED98u)
#define MPU_RBAR (*(volatile uint32_t *)0xE000ED9Cu)
#define MPU_RASR (*(volatile uint32_t *)0xE000EDA0u)

extern uint32_t _sstack[];


/* CMSDK APB UART0 (OUTPUT=uart): DATA, STATE (bit 0: TX full), CTRL
 * (bit 0: TX enable; without it nothing is sent). QEMU ignores the baud
 * divider; on the FPGA board, BAUDDIV = clock / baud. */
#define UART_BASE 0x40004000u
#define UART_DATA (*(volatile uint32_t *)(UART_BASE + 0x0u))
#define UART_STATE (*(volatile const uint32_t *)(UART_BASE + 0x4u))
#define UART_CTRL (*(volatile uint32_t *)(UART_BASE + 0x8u))
#define UART_BAUDDIV (*(volatile uint32_t *)(UART_BASE + 0x10u))

void port_uart_init(void)
{
    UART_BAUDDIV = 217u; /* 25 MHz / 115200 */
    UART_CTRL = 1u;
}

void port_uart_putc(uint8_t c)
{
    while (UART_STATE & 1u) {
    }
    UART_DATA = c;
}

void port_init(void)
{
    port_output_init();
    /* Memory below RAM reads as zero and ignores writes on this machine,
     * so an overflowing stack would go unnoticed: make the lowest 32 bytes
     * of the stack a no-access MPU region (it faults, exit 101). The
     * linker script aligns the stack to 32 bytes. */
    MPU_RNR = 0;
    MPU_RBAR = (uint32_t)(uintptr_t)_sstack;
    MPU_RASR = (1u << 28) | (4u << 1) | 1u; /* XN, no access, 32 B, on */
    MPU_CTRL = 5u; /* enable, default map for everything else */
    __asm__ volatile("dsb\n\tisb" : : : "memory");
}

uint64_t port_cycles(void)
{
    /* Slow counter first: the fast one is then at least its estimate, and
     * less than one 100 Hz period (250000 ticks) beyond it. */
    uint64_t est = (uint64_t)FPGAIO_CLK100HZ * TICKS_PER_CLK100;
    uint32_t fine = FPGAIO_COUNTER;
    return est + (uint32_t)(fine - (uint32_t)est);
}

uint64_t port_cycles_to_insns(uint64_t cycles)
{
    return (cycles * 5 + 8) / 16;
}
