/* SPDX-License-Identifier: MIT */
/*
 * test_grey: the 4-bit grey mapping of rt_grey.h. The ends map to 0 and
 * 15, levels never decrease with luma, every luma keeps its mean over a
 * 4x4 tile (within 1/16 of a level), the luma weights are BT.601's in
 * 1/256, and the row function equals the pixel function.
 */
#include "harness.h"
#include "rt_grey.h"

static uint8_t grey_of(unsigned v, unsigned x, unsigned y)
{
    const uint8_t p[3] = { (uint8_t)v, (uint8_t)v, (uint8_t)v };
    return rt_grey4(p, x, y);
}

int main(void)
{
    static const uint8_t black[3] = { 0, 0, 0 }, white[3] = { 255, 255, 255 };
    static const uint8_t red[3] = { 255, 0, 0 }, green[3] = { 0, 255, 0 };
    static const uint8_t blue[3] = { 0, 0, 255 };

    CHECK_EQ(rt_grey_luma(black), 0);
    CHECK_EQ(rt_grey_luma(white), 255);
    CHECK_EQ(rt_grey_luma(red), 77);   /* (77 * 255 + 128) >> 8 = 77 */
    CHECK_EQ(rt_grey_luma(green), 149); /* (150 * 255 + 128) >> 8 */
    CHECK_EQ(rt_grey_luma(blue), 29);

    /* Black and white are flat: no dither threshold moves them. */
    int ends = 1;
    for (unsigned y = 0; y < 4; y++)
        for (unsigned x = 0; x < 4; x++)
            ends &= rt_grey4(black, x, y) == 0 && rt_grey4(white, x, y) == 15;
    CHECK(ends);

    /* Monotonic in luma at every position, never above 15, and a tile's
     * mean is v * 15 / 255 within 1/16 level: the sum of the 16 levels is
     * within 1 of 16 * v / 17. */
    int mono = 1, range = 1, mean = 1;
    for (unsigned v = 0; v < 256; v++) {
        unsigned sum = 0;
        for (unsigned y = 0; y < 4; y++) {
            for (unsigned x = 0; x < 4; x++) {
                unsigned g = grey_of(v, x, y);
                sum += g;
                range &= g <= 15;
                if (v > 0)
                    mono &= g >= grey_of(v - 1, x, y);
            }
        }
        long d = (long)(17 * sum) - (long)(16 * v);
        if (d < -17 || d > 17) {
            mean = 0;
            printf("    luma %u: tile sum %u, want %.2f\n", v, sum,
                   16.0 * v / 17.0);
        }
    }
    CHECK(mono);
    CHECK(range);
    CHECK(mean);

    /* The row function is the pixel function, position by position. */
    uint8_t row[3 * 37], out[37];
    uint64_t st = 12345;
    for (unsigned i = 0; i < sizeof row; i++)
        row[i] = (uint8_t)(th_rnd64(&st) >> 56);
    int same = 1;
    for (unsigned y = 0; y < 5; y++) {
        rt_grey4_row(row, 37, y, out);
        for (unsigned x = 0; x < 37; x++)
            same &= out[x] == rt_grey4(row + 3 * x, x, y);
    }
    CHECK(same);
    return th_summary();
}
