/* SPDX-License-Identifier: MIT */
/*
 * board_microbit.c: QEMU microbit (nRF51822, Cortex-M0, 16 KB RAM).
 *
 * Output: semihosting (out_semihost.c), which QEMU supports on the M0 as
 * on any M-profile core, or the UART (out_uart.c).
 *
 * Counter: TIMER0 as a 32-bit timer at 16 MHz. Under -icount shift=7 one
 * instruction is 128 ns = 2.048 ticks, so instructions = ticks * 125 / 256,
 * rounded; a difference of two readings is off by less than one tick, 0.49
 * instructions, so the rounded count is exact. TIMER0 wraps after 268 s of
 * virtual time (2.1 G instructions), so TIMER1 runs beside it at 1 MHz
 * (prescaler 4) and supplies the upper bits. Read TIMER0 only at the ends
 * of a measurement: QEMU keeps its 62.5 ns tick to whole nanoseconds, and
 * each read can leave it up to 0.5 ns fast.
 */
#include "port.h"

#define REG(addr) (*(volatile uint32_t *)(addr))
#define TIMER0 0x40008000u
#define TIMER1 0x40009000u
#define TASKS_START 0x000u
#define TASKS_CAPTURE0 0x040u
#define MODE 0x504u
#define BITMODE 0x508u
#define PRESCALER 0x510u
#define CC0 0x540u

static void timer_start(uint32_t base, uint32_t prescaler)
{
    REG(base + MODE) = 0;    /* timer, not counter */
    REG(base + BITMODE) = 3; /* 32 bits */
    REG(base + PRESCALER) = prescaler;
    REG(base + TASKS_START) = 1;
}

static uint32_t timer_read(uint32_t base)
{
    REG(base + TASKS_CAPTURE0) = 1;
    return REG(base + CC0);
}


/* The nRF51 UART (OUTPUT=uart): enable, start the transmitter, then for
 * each byte clear TXDRDY, write TXD and wait for TXDRDY. Pins and baud
 * rate are QEMU's don't-cares; on a micro:bit the USB serial line is
 * PSELTXD = 24 at BAUDRATE 0x01D7E000 (115200). */
#define UART 0x40002000u
#define UART_STARTTX 0x008u
#define UART_TXDRDY 0x11Cu
#define UART_ENABLE 0x500u
#define UART_PSELTXD 0x50Cu
#define UART_TXD 0x51Cu
#define UART_BAUDRATE 0x524u

void port_uart_init(void)
{
    REG(UART + UART_PSELTXD) = 24u;
    REG(UART + UART_BAUDRATE) = 0x01D7E000u;
    REG(UART + UART_ENABLE) = 4u;
    REG(UART + UART_STARTTX) = 1u;
}

void port_uart_putc(uint8_t c)
{
    REG(UART + UART_TXDRDY) = 0;
    REG(UART + UART_TXD) = c;
    while (REG(UART + UART_TXDRDY) == 0) {
    }
}

void port_init(void)
{
    port_output_init();
    timer_start(TIMER1, 4); /* 16 MHz / 2^4 = 1 MHz */
    timer_start(TIMER0, 0); /* 16 MHz */
}

uint64_t port_cycles(void)
{
    /* The two timers started a few instructions apart, so TIMER0 is
     * within a few dozen ticks of 16 * TIMER1: take the value congruent
     * to TIMER0 modulo 2^32 that is nearest to that estimate. */
    uint64_t est = (uint64_t)timer_read(TIMER1) * 16u;
    uint32_t fine = timer_read(TIMER0);
    return est + (uint64_t)(int64_t)(int32_t)(fine - (uint32_t)est);
}

uint64_t port_cycles_to_insns(uint64_t cycles)
{
    return (cycles * 125 + 128) / 256;
}
