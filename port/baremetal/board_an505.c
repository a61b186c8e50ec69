/* SPDX-License-Identifier: MIT */
/*
 * board_an505.c: QEMU mps2-an505 (Cortex-M33, running Secure).
 *
 * Output: semihosting (out_semihost.c), or UART0 at its Secure alias
 * (out_uart.c). The core is built for the soft-float
 * ABI, so no FP instruction runs and the FPU stays disabled.
 *
 * Counter: the FPGAIO COUNTER at its Secure alias, a 32-bit up-counter at
 * 20 MHz of virtual time since reset. Under -icount shift=7 one
 * instruction is 128 ns = 2.56 ticks, so instructions = ticks * 25 / 64,
 * rounded; a difference of two readings is off by less than one tick,
 * 0.39 instructions, so the rounded count is exact. The FPGAIO 100 Hz
 * counter supplies the upper bits (100 Hz * 200000 = 20 MHz), as on the
 * an385.
 */
#include "port.h"
#include "cmsdk_uart.h"

#define FPGAIO_CLK100HZ (*(volatile const uint32_t *)0x50302014u)
#define FPGAIO_COUNTER (*(volatile const uint32_t *)0x50302018u)
#define TICKS_PER_CLK100 200000u


/* UART0 for OUTPUT=uart (cmsdk_uart.h), 115200 baud at 20 MHz. */
void port_uart_init(void)
{
    cmsdk_uart_init(0x50200000u, 174u);
}

void port_uart_putc(uint8_t c)
{
    cmsdk_uart_putc(0x50200000u, c);
}

void port_init(void)
{
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
