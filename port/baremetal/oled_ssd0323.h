/* SPDX-License-Identifier: MIT */
/*
 * oled_ssd0323.h: the SSD0323 OLED controller of the LM3S6965 EVB (128x64
 * pixels, 16 grey levels, two pixels per byte) on SSI0, with its
 * data/command line on a GPIO. board_lm3s6965.c turns rows into bytes;
 * this driver only moves them. A panel of another kind replaces this file
 * and its three functions (docs/porting.md).
 */
#ifndef OLED_SSD0323_H
#define OLED_SSD0323_H

#include <stdint.h>

/* The panel: 128 columns of pixels (64 of bytes) by 64 rows. */
#define OLED_WIDTH 128u
#define OLED_HEIGHT 64u

/* Turns on the clocks, pins and SSI0, sends the controller's set-up and
 * clears the whole display memory to black. */
void oled_init(void);

/* Sets the window that oled_data() fills, row by row: byte columns c0..c1
 * (0..63, two pixels each) of rows r0..r1 (0..63). */
void oled_window(unsigned c0, unsigned c1, unsigned r0, unsigned r1);

/* Sends n bytes of pixel data into the window (high nibble: the left
 * pixel). Returns when the last one is on the bus. */
void oled_data(const uint8_t *bytes, unsigned n);

#endif /* OLED_SSD0323_H */
