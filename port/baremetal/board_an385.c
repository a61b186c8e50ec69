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
#include "cmsdk_uart.h"
#include "mpu_guard.h"

#define FPGAIO_CLK100HZ (*(volatile const uint32_t *)0x40028014u)
#define FPGAIO_COUNTER (*(volatile const uint32_t *)0x40028018u)
#define TICKS_PER_CLK100 250000u



/* UART0 for OUTPUT=uart (cmsdk_uart.h), 115200 baud at 25 MHz. */
void port_uart_init(void)
{
    cmsdk_uart_init(0x40004000u, 217u);
}

void port_uart_putc(uint8_t c)
{
    cmsdk_uart_putc(0x40004000u, c);
}

void port_init(void)
{
    port_output_init();
    mpu_guard_stack();
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
