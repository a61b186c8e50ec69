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

#define FPGAIO_CLK100HZ (*(volatile const uint32_t *)0x50302014u)
#define FPGAIO_COUNTER (*(volatile const uint32_t *)0x50302018u)
#define TICKS_PER_CLK100 200000u


/* CMSDK APB UART0 (OUTPUT=uart): DATA, STATE (bit 0: TX full), CTRL
 * (bit 0: TX enable; without it nothing is sent). QEMU ignores the baud
 * divider; on the FPGA board, BAUDDIV = clock / baud. */
#define UART_BASE 0x50200000u
#define UART_DATA (*(volatile uint32_t *)(UART_BASE + 0x0u))
#define UART_STATE (*(volatile const uint32_t *)(UART_BASE + 0x4u))
#define UART_CTRL (*(volatile uint32_t *)(UART_BASE + 0x8u))
#define UART_BAUDDIV (*(volatile uint32_t *)(UART_BASE + 0x10u))

void port_uart_init(void)
{
    UART_BAUDDIV = 174u; /* 20 MHz / 115200 */
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
