/* SPDX-License-Identifier: MIT */
/*
 * rt_pixel: the output formats (RGB888, RGB565 in either byte order) and
 * the 4x4 ordered dither RGB565 rows may get. Static inline: it runs once
 * per pixel. Internal.
 */
#ifndef RT_PIXEL_H
#define RT_PIXEL_H

#include "rt_render.h"

/* Bytes of n output pixels: n * 3 (RGB888) or n * 2 (RGB565). */
static inline size_t rt_pixel_bytes(const rt_options *o, unsigned n)
{
    return (size_t)n * (o->format == RT_RGB888 ? 3u : 2u);
}

/* Bytes of one output row: width * 3 (RGB888) or width * 2 (RGB565). */
static inline size_t rt_pixel_row_bytes(const rt_options *o)
{
    return rt_pixel_bytes(o, o->width);
}

/* Adds an ordered-dither threshold below one output step (8 for 5 bits,
 * 4 for 6 bits), so rounding down to 5/6 bits averages out. */
static inline unsigned rt_dither(unsigned v, unsigned step, unsigned t)
{
    v += (t * step) / 16;
    return v > 255 ? 255 : v;
}

/* Stores pixel x of row y (8-bit RGB) into row, whose first pixel is
 * column x0 (x >= x0), in o->format; dithered when o->dither is set and
 * the format is RGB565. The dither follows the frame's columns, so a
 * window of the frame gets the bytes of a full render. */
static inline void rt_put_pixel(uint8_t *row, const rt_options *o,
                                unsigned x0, unsigned x, unsigned y,
                                const uint8_t rgb8[3])
{
    static const uint8_t bayer4[4][4] = {
        { 0, 8, 2, 10 }, { 12, 4, 14, 6 }, { 3, 11, 1, 9 }, { 15, 7, 13, 5 }
    };
    const unsigned i = x - x0;
    if (o->format == RT_RGB888) {
        row[3 * i] = rgb8[0];
        row[3 * i + 1] = rgb8[1];
        row[3 * i + 2] = rgb8[2];
        return;
    }
    unsigned r = rgb8[0], g = rgb8[1], b = rgb8[2];
    if (o->dither) {
        unsigned t = bayer4[y & 3][x & 3];
        r = rt_dither(r, 8, t);
        g = rt_dither(g, 4, t);
        b = rt_dither(b, 8, t);
    }
    unsigned v = ((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3);
    uint8_t lo = (uint8_t)(v & 0xFF), hi = (uint8_t)(v >> 8);
    row[2 * i] = o->format == RT_RGB565_LE ? lo : hi;
    row[2 * i + 1] = o->format == RT_RGB565_LE ? hi : lo;
}

#endif /* RT_PIXEL_H */
