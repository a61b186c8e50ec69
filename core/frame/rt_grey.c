/* SPDX-License-Identifier: MIT */
/*
 * rt_grey: the grey mapping of 4-bit displays (rt_grey.h).
 */
#include "rt_grey.h"

/* The 4x4 Bayer matrix, 0..15: each value once in every aligned tile. */
static const uint8_t grey_bayer4[4][4] = {
    { 0, 8, 2, 10 }, { 12, 4, 14, 6 }, { 3, 11, 1, 9 }, { 15, 7, 13, 5 }
};

/* One output level spans this many 8-bit levels (255 = 15 * 17). */
#define GREY_STEP 17u

uint8_t rt_grey_luma(const uint8_t rgb[3])
{
    unsigned y = 77u * rgb[0] + 150u * rgb[1] + 29u * rgb[2] + 128u;
    return (uint8_t)(y >> 8); /* at most (255 * 256 + 128) >> 8 = 255 */
}

uint8_t rt_grey4(const uint8_t rgb[3], unsigned x, unsigned y)
{
    /* The threshold is the centre of the Bayer value's 1/16 of a step:
     * (2 t + 1) * 17 / 32, 0..16. */
    unsigned t = grey_bayer4[y & 3u][x & 3u];
    unsigned thr = ((2u * t + 1u) * GREY_STEP) >> 5;
    return (uint8_t)((rt_grey_luma(rgb) + thr) / GREY_STEP); /* <= 271/17 */
}

void rt_grey4_row(const uint8_t *rgb, unsigned width, unsigned y,
                  uint8_t *out)
{
    for (unsigned x = 0; x < width; x++)
        out[x] = rt_grey4(rgb + 3u * x, x, y);
}
