/* SPDX-License-Identifier: MIT */
/*
 * rt_grey: RGB888 pixels to 16 grey levels, for 4-bit displays such as the
 * SSD0323 OLED of the LM3S6965 board (port/baremetal/oled_ssd0323.c). The
 * firmware and the host's conversion (tools/grey4.c) both call these
 * functions, so a panel and the host's picture of it agree to the pixel.
 *
 * Freestanding and integer-only like the rest of the core; the renderer
 * itself does not use it.
 */
#ifndef RT_GREY_H
#define RT_GREY_H

#include <stdint.h>

/* Luma of an RGB888 pixel, 0..255: (77 R + 150 G + 29 B + 128) / 256, the
 * BT.601 weights in eighths of a percent. They sum to 256, so white stays
 * 255 and black 0; rounds to nearest. */
uint8_t rt_grey_luma(const uint8_t rgb[3]);

/* Grey level 0..15 of the RGB888 pixel at column x of row y: its luma plus
 * a 4x4 ordered-dither threshold (0..16, below one step of 17), divided by
 * 17 (255 / 15) and rounded down. Black gives 0 and white 15; over any
 * aligned 4x4 tile a flat luma v averages v * 15 / 255 within 1/16 of a
 * level, so gradients keep their mean brightness. */
uint8_t rt_grey4(const uint8_t rgb[3], unsigned x, unsigned y);

/* rt_grey4() for the `width` pixels of RGB888 row y at rgb: one level
 * (0..15) per byte in out[0..width). */
void rt_grey4_row(const uint8_t *rgb, unsigned width, unsigned y,
                  uint8_t *out);

#endif /* RT_GREY_H */
