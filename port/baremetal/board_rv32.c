/* SPDX-License-Identifier: MIT */
/*
 * board_rv32.c: QEMU riscv32 virt (rv32imac, machine mode).
 *
 * Output: RISC-V semihosting (out_semihost.c; QEMU needs
 * -semihosting-config enable=on,target=native), or the 16550 UART
 * (out_uart.c).
 *
 * Counter: minstret, the retired-instruction counter, read as 64 bits.
 * Under -icount shift=0 QEMU makes it the exact guest instruction count,
 * so no conversion is needed.
 */
#include "port.h"

extern uint32_t _sstack[];


/* The virt machine's 16550 UART (OUTPUT=uart): THR at +0, LSR at +5
 * (bit 5: THR empty). QEMU needs no set-up; a real 16550 wants its
 * divisor latch and line control set here. */
#define UART_THR (*(volatile uint8_t *)0x10000000u)
#define UART_LSR (*(volatile const uint8_t *)0x10000005u)

void port_uart_init(void)
{
}

void port_uart_putc(uint8_t c)
{
    while ((UART_LSR & 0x20u) == 0) {
    }
    UART_THR = c;
}

void port_init(void)
{
    port_output_init();
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
