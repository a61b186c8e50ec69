/* SPDX-License-Identifier: MIT */
/*
 * port.h: the services the bare-metal firmware needs from a board. Each
 * function here must be defined for each board (in board_<name>.c, or in
 * the shared out_semihost.c or out_uart.c for the output channels). Each
 * board is declared in its own mk/boards/<name>.mk, which names its files,
 * CPU flags, linker script and QEMU machine. A new board means one board
 * file, one linker script and one mk/boards/<name>.mk (docs/porting.md).
 */
#ifndef PORT_H
#define PORT_H

#include <stddef.h>
#include <stdint.h>

/* Exit codes of the firmware (QEMU passes them through as its own status).
 * 0 is success; anything else names what went wrong. */
enum {
    PORT_EXIT_OK = 0,
    PORT_EXIT_PARSE = 2,     /* rt_parse() rejected the embedded scene */
    PORT_EXIT_OPTIONS = 3,   /* size or spp outside this build's limits */
    PORT_EXIT_RENDER = 4,    /* rt_render_rows() returned an error */
    PORT_EXIT_STACK = 5,     /* the stack came within 64 bytes of its end */
    PORT_EXIT_CORE1 = 6,     /* the second core gave no sign of life */
    PORT_EXIT_HARDFAULT = 101, /* HardFault (every fault on Cortex-M0) */
    PORT_EXIT_MEMFAULT = 102,  /* MemManage */
    PORT_EXIT_BUSFAULT = 103,  /* BusFault */
    PORT_EXIT_USAGEFAULT = 104, /* UsageFault */
    PORT_EXIT_SECUREFAULT = 105, /* SecureFault (ARMv8-M) */
    PORT_EXIT_TRAP = 106       /* NMI, a stray interrupt or a RISC-V trap */
};

/* Sets up the output channels and starts the cycle counter. Called first
 * thing in main(), after the startup code has set up .data and .bss. */
void port_init(void);

/* ---- Output channels: out_semihost.c (OUTPUT=semihost, the default) or
 * out_uart.c (OUTPUT=uart); mk/firmware.mk links one. ------------------ */

/* Opens the image and text channels. Boards call it from port_init(). */
void port_output_init(void);

/* Starts an image of w x h pixels whose rows, `payload` bytes in all, in
 * rt_format `format`, follow through port_write(): a PPM header over
 * semihosting, the frame header over the UART (out_uart.c). */
void port_image_begin(unsigned w, unsigned h, unsigned format,
                      uint32_t payload);

/* Ends the image begun by port_image_begin(): nothing over semihosting,
 * the frame's CRC-32 over the UART. */
void port_image_end(void);

/* Sends n bytes of image data; binary-clean, nothing else goes to this
 * channel. Blocks until the bytes are handed on; the buffer is the
 * caller's again on return. */
void port_write(const void *buf, size_t n);

/* Sends NUL-terminated text for people (figures, errors) on a channel
 * separate from the image. */
void port_log(const char *s);

/* Stops the program with the given exit status. Never returns. */
void port_exit(int code) __attribute__((noreturn));

/* The board's free-running cycle counter as a 64-bit count that does not
 * wrap within a run. Boards whose fast counter is 32 bits pair it with a
 * slow one to get the upper bits, so no periodic calls are needed. */
uint64_t port_cycles(void);

/* Converts a difference of two port_cycles() values to retired guest
 * instructions. Exact under QEMU's -icount settings that `make qemu` uses
 * for this board (see port/baremetal/README.md). */
uint64_t port_cycles_to_insns(uint64_t cycles);

/* ---- A display (boards built with -DFW_DISPLAY=1 only) ----------------- */

/* 1 on a board with a panel (FW_CAPS in mk/boards/<board>.mk): main.c then
 * also shows every row there, and the board defines the two functions
 * below (board_lm3s6965.c). */
#ifndef FW_DISPLAY
#define FW_DISPLAY 0
#endif

/* Shows RGB888 row y (width pixels) on the panel, as the row callback
 * gets it; the row is the caller's again on return. Rows come in order
 * from y = 0; what does not fit the panel is left out. */
void port_display_row(int y, const uint8_t *rgb, unsigned width);

/* Called after a successful run, once the figures are logged: says so on
 * the text channel and keeps the picture up until the host has taken it
 * (the board may never return). */
void port_display_done(void);

/* ---- A second core (boards built with -DFW_CORES=2 only) -------------- */

/* 2 on a board with two cores (FW_CAPS in mk/boards/<board>.mk): main.c
 * then renders with both (dual.c), and the board defines
 * port_core1_start(). */
#ifndef FW_CORES
#define FW_CORES 1
#endif

/* Releases the second core, which then runs port_core1_main() on its own
 * stack, [_sstack1, _estack1) of the board's linker script, with the
 * stack limit set where the core has one. Returns at once: the caller
 * (dual.c) waits for the core's first sign of life, for a bounded number
 * of polls. If port_core1_main() returns, the core stays parked. */
void port_core1_start(void);

/* What the second core runs (dual.c). */
void port_core1_main(void);

/* The board's UART, for OUTPUT=uart (out_uart.c): port_uart_init() sets
 * it up for sending (port_output_init() calls it), port_uart_putc() sends
 * one byte, waiting while the transmitter is full. Every board file
 * defines them; --gc-sections drops them from a semihosting build. */
void port_uart_init(void);
void port_uart_putc(uint8_t c);

/* ---- Helpers shared by the boards and the firmware --------------------- */

/* The semihosting traps (semihost.c): open the host's stdout and stderr;
 * write n bytes to stdout (to_stderr 0) or stderr (1); exit with a status
 * QEMU passes on. */
void port_semihost_init(void);
void port_semihost_write(int to_stderr, const void *buf, size_t n);
void port_semihost_exit(int code) __attribute__((noreturn));

/* Logs v in decimal on the text channel (common.c). */
void port_log_u64(uint64_t v);

/* Logs one figure as a line "name value\n" on the text channel (common.c). */
void port_log_value(const char *name, uint64_t v);

/* Writes a binary PPM header "P6\n<w> <h>\n255\n", as the host writes
 * it, through port_write (common.c; out_semihost.c's port_image_begin). */
void port_write_ppm_header(unsigned w, unsigned h);

/* Fills the unused stack below the current stack pointer with a pattern
 * (common.c). The startup code calls it before main(). */
void port_stack_paint(void);

/* Bytes of stack ever used since port_stack_paint(): the distance from the
 * top of the stack to the lowest word that no longer holds the pattern. */
size_t port_stack_used(void);

/* Bytes reserved for the stack by the linker script. */
size_t port_stack_size(void);

#endif /* PORT_H */
