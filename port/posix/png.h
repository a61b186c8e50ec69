/* SPDX-License-Identifier: MIT */
/* png: a small PNG encoder (RGB, 8 bits, a filter chosen per row, our own
 * deflate) and decoder (8-bit RGB or grey, any filters, not interlaced),
 * so the host tool writes and reads pictures browsers show without any
 * external package. */
#ifndef PNG_H
#define PNG_H

#include <stdint.h>
#include <stdio.h>

#include "ppm.h"

/* Writes w x h RGB888 pixels as a PNG to f. Returns 0, or -1 on a write
 * error. */
int png_write(FILE *f, const uint8_t *rgb, int w, int h);

/* Decodes a PNG held in memory: 8-bit RGB or grey, not interlaced, any
 * filters and any deflate blocks, every CRC and the Adler-32 checked.
 * Returns 0 with *img filled (the caller frees it), or -1 with a reason in
 * err[0..errlen) and *img zeroed. */
int png_decode(const uint8_t *buf, size_t len, ppm_image *img, char *err,
               size_t errlen);

/* CRC-32 (ISO 3309, as PNG uses) of n bytes, continuing from crc (start
 * with 0). */
uint32_t png_crc32(uint32_t crc, const uint8_t *p, size_t n);


#endif /* PNG_H */
