/* SPDX-License-Identifier: MIT */
/*
 * board_lm3s6965.c: the Stellaris LM3S6965 EVB (QEMU lm3s6965evb), a
 * Cortex-M3 with 256 KB of flash, 64 KB of RAM and a 128x64 OLED with 16
 * grey levels (oled_ssd0323.c).
 *
 * Output: semihosting (out_semihost.c) for the image and the figures, as on
 * every board, and each row on the panel: port_display_row() maps it to
 * grey levels with the library's panel converter (core/frame/rt_panel.h,
 * RT_PANEL_GREY4 with the ordered dither, as the host's tools/grey4.c) and
 * sends it as it comes, two pixels a byte; there is no frame buffer, only
 * one panel row of 64 bytes on the stack.
 * When the run is done the firmware says so and keeps the picture up:
 * tools/qemu_screen.py then takes the monitor's screendump and quits QEMU.
 *
 * Counter: SysTick on the processor clock, set to 50 MHz as on the real
 * board (the PLL's 200 MHz / 4; QEMU derives the clock period from RCC's
 * SYSDIV field alone, 5 ns * (SYSDIV + 1) = 20 ns). Under -icount shift=7
 * an instruction is 128 ns = 6.4 ticks, so instructions = ticks * 5 / 32,
 * rounded: a difference of two readings is off by less than one tick,
 * 0.16 instructions, and the rounded count is exact. This machine has no
 * readable free-running timer (QEMU's GPTM model cannot read its count),
 * and SysTick is 24 bits, wrapping every 2^24 ticks (2.6 M instructions):
 * its interrupt counts the wraps. Its handler is five instructions (32
 * ticks), which port_cycles() takes out again, so the count is of the
 * program alone. tests/suite_firmware.sh checks it with a loop of known
 * length that spans wraps.
 */
#include "port.h"
#include "mpu_guard.h"
#include "oled_ssd0323.h"
#include "rt_panel.h"

#define REG(addr) (*(volatile uint32_t *)(addr))

/* System control: the clock. */
#define SYSCTL_RIS REG(0x400FE050u)
#define SYSCTL_RCC REG(0x400FE060u)
#define RCC_MOSCDIS (1u << 0)
#define RCC_OSCSRC_MASK (3u << 4)
#define RCC_XTAL_MASK (0xFu << 6)
#define RCC_XTAL_8MHZ (0xEu << 6) /* the EVB's crystal */
#define RCC_BYPASS (1u << 11)
#define RCC_PWRDN (1u << 13)
#define RCC_USESYSDIV (1u << 22)
#define RCC_SYSDIV_MASK (0xFu << 23)
#define RCC_SYSDIV_4 (3u << 23) /* 200 MHz / 4 = 50 MHz */
#define RIS_PLLLRIS (1u << 6)

/* SysTick. */
#define SYST_CSR REG(0xE000E010u)
#define SYST_RVR REG(0xE000E014u)
#define SYST_CVR REG(0xE000E018u)
#define SYST_RELOAD 0xFFFFFFu
#define SYST_PERIOD (SYST_RELOAD + 1u)
#define SYST_HANDLER_TICKS 32u /* 5 instructions * 6.4 ticks */


/* SysTick wraps since port_init(), counted by systick_handler. */
volatile uint32_t systick_wraps __attribute__((used));

void systick_handler(void);

/* Exactly five instructions, so that port_cycles() can take them out. It
 * replaces the weak default of startup_cortexm.c's vector table. */
__attribute__((naked)) void systick_handler(void)
{
    __asm__ volatile(".syntax unified\n\t"
                     "ldr r0, =systick_wraps\n\t"
                     "ldr r1, [r0]\n\t"
                     "adds r1, r1, #1\n\t"
                     "str r1, [r0]\n\t"
                     "bx lr\n\t"
                     ".ltorg");
}

/* 50 MHz from the PLL, in the order the data sheet gives: bypass the PLL,
 * power it up on the 8 MHz crystal, set the divider, wait for the lock,
 * then use it. */
static void clock_50mhz(void)
{
    uint32_t rcc = SYSCTL_RCC;
    rcc = (rcc | RCC_BYPASS) & ~RCC_USESYSDIV;
    SYSCTL_RCC = rcc;
    rcc &= ~(RCC_MOSCDIS | RCC_OSCSRC_MASK | RCC_XTAL_MASK | RCC_PWRDN);
    rcc |= RCC_XTAL_8MHZ;
    SYSCTL_RCC = rcc;
    rcc = (rcc & ~RCC_SYSDIV_MASK) | RCC_SYSDIV_4 | RCC_USESYSDIV;
    SYSCTL_RCC = rcc;
    for (uint32_t n = 0; n < 100000u && !(SYSCTL_RIS & RIS_PLLLRIS); n++)
        ;
    SYSCTL_RCC = rcc & ~RCC_BYPASS;
}

void port_init(void)
{
    port_output_init();
    mpu_guard_stack();

    clock_50mhz();
    SYST_RVR = SYST_RELOAD;
    SYST_CVR = 0;
    SYST_CSR = 7u; /* processor clock, interrupt, enable */

    oled_init();
}

uint64_t port_cycles(void)
{
    uint32_t wraps, now;
    do { /* a wrap between the two reads: read both again */
        wraps = systick_wraps;
        now = SYST_CVR;
    } while (wraps != systick_wraps);
    return (uint64_t)wraps * (SYST_PERIOD - SYST_HANDLER_TICKS) +
           (SYST_RELOAD - now);
}

uint64_t port_cycles_to_insns(uint64_t cycles)
{
    return (cycles * 5 + 16) / 32;
}

void port_display_row(int y, const uint8_t *rgb, unsigned width)
{
    unsigned w = width < OLED_WIDTH ? width : OLED_WIDTH;
    unsigned nbytes = (w + 1) / 2;
    uint8_t line[OLED_WIDTH / 2];
    rt_panel panel; /* the ordered dither keeps nothing between rows */

    if (y == 0)
        oled_window(0, nbytes - 1, 0, OLED_HEIGHT - 1);
    if (y < 0 || (unsigned)y >= OLED_HEIGHT ||
        rt_panel_init(&panel, RT_PANEL_GREY4, RT_PANEL_ORDERED, 0, w, line,
                      0) != RT_OK)
        return;
    oled_data(line, (unsigned)rt_panel_row(&panel, (unsigned)y, rgb));
}

void port_display_done(void)
{
    SYST_CSR = 0; /* nothing left to count; let the core sleep */
    port_log("display_done\n");
    for (;;)
        __asm__ volatile("wfi");
}
