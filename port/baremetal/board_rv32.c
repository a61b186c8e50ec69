/*
 * board_rv32.c: QEMU riscv32 virt (rv32imac, machine mode).
 *
 * Output: RISC-V semihosting (semihost.c); QEMU needs
 * -semihosting-config enable=on,target=native.
 *
 * Counter: minstret, the retired-instruction counter, read as 64 bits.
 * Under -icount shift=0 QEMU makes it the exact guest instruction count,
 * so no conversion is needed.
 */
#include "port.h"

extern uint32_t _sstack[];

void port_init(void)
{
    port_semihost_init();
    /* The stack grows down towards .rodata and .text, all plain RAM: make
     * its lowest 32 bytes a locked, no-access PMP region, so an overflow
     * traps (exit 106) instead of overwriting code. Locked entries bind
     * machine mode too. NAPOT encoding: base / 4 | (size / 8 - 1). */
    uint32_t addr = ((uint32_t)(uintptr_t)_sstack >> 2) | 3u;
    __asm__ volatile("csrw pmpaddr0, %0" : : "r"(addr));
    __asm__ volatile("csrw pmpcfg0, %0" : : "r"(0x98u)); /* L, NAPOT */
}

static uint32_t minstret(void)
{
    uint32_t v;
    __asm__ volatile("csrr %0, minstret" : "=r"(v));
    return v;
}

static uint32_t minstreth(void)
{
    uint32_t v;
    __asm__ volatile("csrr %0, minstreth" : "=r"(v));
    return v;
}

uint64_t port_cycles(void)
{
    uint32_t hi, lo;
    do { /* read again if the low half carried between the reads */
        hi = minstreth();
        lo = minstret();
    } while (minstreth() != hi);
    return (uint64_t)hi << 32 | lo;
}

uint64_t port_cycles_to_insns(uint64_t cycles)
{
    return cycles;
}
