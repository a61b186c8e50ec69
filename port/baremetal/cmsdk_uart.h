/* SPDX-License-Identifier: MIT */
/* cmsdk_uart: the CMSDK APB UART of the MPS2 boards (an385, m0, an505),
 * for OUTPUT=uart: DATA at +0x0, STATE at +0x4 (bit 0: TX full), CTRL at
 * +0x8 (bit 0: TX enable; without it nothing is sent), BAUDDIV at +0x10
 * (clock / baud; QEMU ignores it). */
#ifndef CMSDK_UART_H
#define CMSDK_UART_H

#include <stdint.h>

#define CMSDK_UART_REG(base, off) (*(volatile uint32_t *)((base) + (off)))

static inline void cmsdk_uart_init(uint32_t base, uint32_t bauddiv)
{
    CMSDK_UART_REG(base, 0x10u) = bauddiv;
    CMSDK_UART_REG(base, 0x8u) = 1u;
}

static inline void cmsdk_uart_putc(uint32_t base, uint8_t c)
{
    while (CMSDK_UART_REG(base, 0x4u) & 1u) {
    }
    CMSDK_UART_REG(base, 0x0u) = c;
}

#endif /* CMSDK_UART_H */
