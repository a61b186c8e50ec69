/*
 * board_an385.c: QEMU mps2-an385 (Cortex-M3), also used by the m0 build
 * (Cortex-M0 code on the same machine).
 *
 * Output: semihosting (semihost.c). Counter: the FPGAIO COUNTER, a 32-bit
 * up-counter at 25 MHz of virtual time since reset. Under -icount shift=7
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

void port_init(void)
{
    port_semihost_init();
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
