/* SPDX-License-Identifier: MIT */
/*
 * board_template.c: the starting point for a new board (docs/porting.md).
 *
 * Copy it to board_<name>.c, change the "#if 0" below to "#if 1" and fill
 * in every place marked FILL IN. With linker/template.ld copied to
 * linker/<name>.ld and a fragment mk/boards/<name>.mk, that is the whole
 * port: the startup code (startup_cortexm.c or startup_rv32.c), the output
 * channels (out_semihost.c over semihost.c, or out_uart.c over the UART
 * below), the stack painting (common.c)
 * and the firmware itself (main.c) are shared by every board.
 *
 * A board provides five functions (port.h): port_init(), port_cycles(),
 * port_cycles_to_insns(), port_uart_init() and port_uart_putc(). The values filled in below are those of
 * QEMU's mps2-an385 as an example; look up yours in the board's manual,
 * or in QEMU's source for a QEMU machine (hw/arm/, hw/timer/).
 */

/* Set this to "#if 1" to enable the content. */
#if 0

/*********************
 *      INCLUDES
 *********************/
#include "port.h"

/*********************
 *      DEFINES
 *********************/

/* FILL IN: a free-running up-counter that ticks at a fixed rate of the
 * (virtual) clock from reset. QEMU's -icount mode makes virtual time
 * advance by exactly 2^shift ns per instruction, so such a counter counts
 * instructions. mps2-an385: the FPGAIO COUNTER, 32 bits at 25 MHz. */
#define BOARD_FAST_COUNTER (*(volatile const uint32_t *)0x40028018u)

/* FILL IN: a second, slower counter from reset that supplies the upper
 * bits, so that port_cycles() does not wrap when the fast one does (after
 * 2^32 ticks: 172 s of virtual time at 25 MHz). BOARD_SLOW_TICKS is how
 * many fast ticks one slow tick lasts. mps2-an385: the FPGAIO 100 Hz
 * counter, 25 MHz / 100 Hz = 250000. Set BOARD_SLOW_TICKS to 0 if there
 * is none: runs longer than one wrap then report a wrong count. */
#define BOARD_SLOW_COUNTER (*(volatile const uint32_t *)0x40028014u)
#define BOARD_SLOW_TICKS 250000u

/* FILL IN: instructions per fast tick as a fraction NUM / DEN, for the
 * -icount shift given to the board in mk/boards/<name>.mk (FW_ICOUNT). At
 * shift 7 an instruction takes 128 ns; a 25 MHz counter ticks every 40 ns,
 * so one tick is 40 / 128 = 5 / 16 instruction. With shift 0 and a
 * counter of instructions (RISC-V minstret): 1 / 1. */
#define BOARD_INSNS_NUM 5u
#define BOARD_INSNS_DEN 16u

/* FILL IN: 1 to make the lowest 32 bytes of the stack a no-access region
 * of the ARMv7-M MPU (Cortex-M3, M4, M7), so that an overflow faults at
 * once instead of writing below RAM; tests/suite_firmware.sh overflows the
 * stack on purpose and wants a fault exit. 0 for a part without that MPU:
 * then guard the stack another way (MSPLIM on ARMv8-M, board_an505.c; a
 * PMP region on RISC-V, board_rv32.c). The linker script aligns the stack
 * to 32 bytes. */
#if defined(__arm__)
#define BOARD_MPU_GUARD 1
#else
#define BOARD_MPU_GUARD 0 /* RISC-V: a PMP region instead (board_rv32.c) */
#endif

#if BOARD_MPU_GUARD
#define MPU_CTRL (*(volatile uint32_t *)0xE000ED94u)
#define MPU_RNR (*(volatile uint32_t *)0xE000ED98u)
#define MPU_RBAR (*(volatile uint32_t *)0xE000ED9Cu)
#define MPU_RASR (*(volatile uint32_t *)0xE000EDA0u)
extern uint32_t _sstack[];
#endif

/* FILL IN: the UART that OUTPUT=uart sends the image and text on
 * (out_uart.c frames the image). mps2-an385: CMSDK UART0, DATA at +0,
 * STATE at +4 (bit 0: TX full), CTRL at +8 (bit 0: TX enable), BAUDDIV at
 * +0x10 (clock / baud). */
#define BOARD_UART_BASE 0x40004000u
#define BOARD_UART_DATA (*(volatile uint32_t *)(BOARD_UART_BASE + 0x0u))
#define BOARD_UART_STATE (*(volatile const uint32_t *)(BOARD_UART_BASE + 0x4u))
#define BOARD_UART_CTRL (*(volatile uint32_t *)(BOARD_UART_BASE + 0x8u))
#define BOARD_UART_BAUDDIV (*(volatile uint32_t *)(BOARD_UART_BASE + 0x10u))

/**********************
 *   GLOBAL FUNCTIONS
 **********************/

/* FILL IN: set up the UART for sending: clock, pins, baud rate, enable. */
void port_uart_init(void)
{
    BOARD_UART_BAUDDIV = 217u; /* 25 MHz / 115200 */
    BOARD_UART_CTRL = 1u;      /* TX enable */
}

/* FILL IN: send one byte, waiting while the transmitter is full. */
void port_uart_putc(uint8_t c)
{
    while (BOARD_UART_STATE & 1u) {
    }
    BOARD_UART_DATA = c;
}

/* Called first thing in main(), after the startup code has copied .data,
 * zeroed .bss and painted the stack. */
void port_init(void)
{
    /* The image and the figures leave through semihosting
     * (out_semihost.c) or the UART below (out_uart.c, OUTPUT=uart): this
     * opens the channels. */
    port_output_init();

    /* FILL IN: anything the board needs before the render: clocks, a
     * watchdog to feed or disable, the counters above if they need
     * starting (the nRF51's TIMER0 does: board_microbit.c). A Cortex-M4F
     * or M33 built for the hard-float ABI must enable the FPU here (CPACR
     * at 0xE000ED88, bits 20-23) before any floating-point instruction;
     * the core itself never uses one. */

#if BOARD_MPU_GUARD
    MPU_RNR = 0;
    MPU_RBAR = (uint32_t)(uintptr_t)_sstack;
    MPU_RASR = (1u << 28) | (4u << 1) | 1u; /* XN, no access, 32 B, on */
    MPU_CTRL = 5u; /* enable, default map for everything else */
    __asm__ volatile("dsb\n\tisb" : : : "memory");
#endif
}

/* The cycle counter as 64 bits that do not wrap within a run. */
uint64_t port_cycles(void)
{
#if BOARD_SLOW_TICKS > 0
    /* Slow counter first: the fast one is then at least its estimate and
     * less than one slow tick beyond it, so the low 32 bits of the fast
     * counter correct the estimate exactly. */
    uint64_t est = (uint64_t)BOARD_SLOW_COUNTER * BOARD_SLOW_TICKS;
    uint32_t fine = BOARD_FAST_COUNTER;
    return est + (uint32_t)(fine - (uint32_t)est);
#else
    return BOARD_FAST_COUNTER;
#endif
}

/* Converts a difference of two port_cycles() values to instructions,
 * rounded to nearest. */
uint64_t port_cycles_to_insns(uint64_t cycles)
{
    return (cycles * BOARD_INSNS_NUM + BOARD_INSNS_DEN / 2) /
           BOARD_INSNS_DEN;
}

#else
/* An empty translation unit is not valid C. */
typedef int board_template_is_disabled;
#endif
