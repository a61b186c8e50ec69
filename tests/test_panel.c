/* SPDX-License-Identifier: MIT */
/*
 * test_panel: the mono and grey panel converter of rt_panel.h. Exact
 * bytes on known inputs for each layout (plain MSB-first rows, SSD1306
 * pages, two grey pixels a byte) and each dither (threshold, the 4x4
 * Bayer matrix and its phase in a window, Floyd-Steinberg worked by
 * hand); ordered grey is rt_grey4() pixel for pixel; flat greys keep
 * their brightness; the buffers are exactly rt_panel_out_bytes() and
 * rt_panel_err_count() long, whatever the height (nothing past them is
 * written); bad set-ups are refused.
 */
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "rt_grey.h"
#include "rt_panel.h"

#define GUARD 16
#define MAXW 256

/* A grey RGB888 row of the lumas v[0..n): grey pixels keep their luma. */
static void grey_row(uint8_t *rgb, const uint8_t *v, unsigned n)
{
    for (unsigned j = 0; j < n; j++)
        rgb[3 * j] = rgb[3 * j + 1] = rgb[3 * j + 2] = v[j];
}

static void flat_row(uint8_t *rgb, uint8_t v, unsigned n)
{
    memset(rgb, v, 3u * n);
}

/* Converts one grey row; returns the bytes ready. */
static size_t convert(rt_panel *p, unsigned y, const uint8_t *v, unsigned n)
{
    uint8_t rgb[3 * MAXW];
    grey_row(rgb, v, n);
    return rt_panel_row(p, y, rgb);
}

static void test_mono(void)
{
    uint8_t out[2], rgb[3 * 8];
    rt_panel p;
    static const uint8_t v[9] = { 0, 127, 128, 255, 200, 10, 130, 255, 255 };
    CHECK_EQ(rt_panel_init(&p, RT_PANEL_MONO, RT_PANEL_THRESHOLD, 0, 9, out,
                           NULL),
             RT_OK);
    CHECK_EQ(convert(&p, 0, v, 9), 2);
    CHECK_EQ(out[0], 0x3B); /* 0 0 1 1 1 0 1 1, MSB first */
    CHECK_EQ(out[1], 0x80); /* the ninth pixel, then unused zero bits */
    CHECK_EQ(rt_panel_flush(&p), 0);

    /* Luma 128 lights the pixels of Bayer values 0..7: half of them. */
    static const uint8_t want[4] = { 0xAA, 0x55, 0xAA, 0x55 };
    CHECK_EQ(rt_panel_init(&p, RT_PANEL_MONO, RT_PANEL_ORDERED, 0, 8, out,
                           NULL),
             RT_OK);
    flat_row(rgb, 128, 8);
    for (unsigned y = 0; y < 8; y++) {
        CHECK_EQ(rt_panel_row(&p, y, rgb), 1);
        CHECK_EQ(out[0], want[y % 4]);
    }
    /* A window from column 1: the matrix follows the frame's columns. */
    CHECK_EQ(rt_panel_init(&p, RT_PANEL_MONO, RT_PANEL_ORDERED, 1, 8, out,
                           NULL),
             RT_OK);
    CHECK_EQ(rt_panel_row(&p, 0, rgb), 1);
    CHECK_EQ(out[0], 0x55);
    /* Black is never lit and white always, at every threshold. */
    flat_row(rgb, 0, 8);
    CHECK_EQ(rt_panel_row(&p, 1, rgb), 1);
    CHECK_EQ(out[0], 0x00);
    flat_row(rgb, 255, 8);
    CHECK_EQ(rt_panel_row(&p, 2, rgb), 1);
    CHECK_EQ(out[0], 0xFF);
}

static void test_pages(void)
{
    enum { W = 10, H = 10 };
    uint8_t out[W], v[W];
    rt_panel p;
    CHECK_EQ(rt_panel_init(&p, RT_PANEL_MONO_PAGE, RT_PANEL_THRESHOLD, 0, W,
                           out, NULL),
             RT_OK);
    /* The diagonal x == y. */
    for (unsigned y = 0; y < H; y++) {
        for (unsigned x = 0; x < W; x++)
            v[x] = x == y ? 255 : 0;
        size_t n = convert(&p, y, v, W);
        CHECK_EQ(n, y == 7 ? W : 0);
        if (y == 7)
            for (unsigned x = 0; x < W; x++)
                CHECK_EQ(out[x], x < 8 ? 1u << x : 0); /* bit k: row k */
    }
    CHECK_EQ(rt_panel_flush(&p), W); /* rows 8 and 9: half a page */
    for (unsigned x = 0; x < W; x++)
        CHECK_EQ(out[x], x == 8 ? 0x01 : (x == 9 ? 0x02 : 0));
    CHECK_EQ(rt_panel_flush(&p), 0);

    /* A window from row 5: its first page holds rows 5..7 only. */
    CHECK_EQ(rt_panel_init(&p, RT_PANEL_MONO_PAGE, RT_PANEL_THRESHOLD, 0, 2,
                           out, NULL),
             RT_OK);
    memset(v, 255, sizeof v);
    CHECK_EQ(convert(&p, 5, v, 2), 0);
    CHECK_EQ(convert(&p, 6, v, 2), 0);
    CHECK_EQ(convert(&p, 7, v, 2), 2);
    CHECK_EQ(out[0], 0xE0);
    CHECK_EQ(out[1], 0xE0);
    /* A row of another page before this one ended starts that page. */
    CHECK_EQ(convert(&p, 11, v, 2), 0);
    CHECK_EQ(convert(&p, 25, v, 2), 0);
    CHECK_EQ(rt_panel_flush(&p), 2);
    CHECK_EQ(out[0], 0x02); /* row 25 alone: bit 1 of page 3 */
}

static void test_grey(void)
{
    uint8_t out[3], rgb[3 * MAXW];
    rt_panel p;
    static const uint8_t v[5] = { 0, 17, 8, 9, 255 };
    CHECK_EQ(rt_panel_init(&p, RT_PANEL_GREY4, RT_PANEL_THRESHOLD, 0, 5, out,
                           NULL),
             RT_OK);
    CHECK_EQ(convert(&p, 0, v, 5), 3);
    CHECK_EQ(out[0], 0x01); /* levels 0 and 1, the first in the high nibble */
    CHECK_EQ(out[1], 0x01); /* 8 rounds down to 0, 9 up to 1 */
    CHECK_EQ(out[2], 0xF0); /* 15, and no sixth pixel */

    /* Ordered: rt_grey4() of each pixel at its frame column, on colours. */
    uint64_t seed = 12345;
    uint8_t grey[MAXW / 2];
    const unsigned w = 37, x0 = 3;
    int same = 1;
    CHECK_EQ(rt_panel_init(&p, RT_PANEL_GREY4, RT_PANEL_ORDERED, x0, w, grey,
                           NULL),
             RT_OK);
    for (unsigned y = 0; y < 8; y++) {
        for (unsigned i = 0; i < 3 * w; i++)
            rgb[i] = (uint8_t)th_rnd64(&seed);
        CHECK_EQ(rt_panel_row(&p, y, rgb), (w + 1) / 2);
        for (unsigned j = 0; j < w; j++) {
            unsigned got = j % 2 ? grey[j / 2] & 15u : grey[j / 2] >> 4;
            same &= got == rt_grey4(rgb + 3 * j, x0 + j, y);
        }
    }
    CHECK(same);
}

/* Floyd-Steinberg on a 3x2 mid-grey, worked by hand (errors times 16):
 * row 0: 128 -> 1 (error -127); 128 - 889/16 = 72 -> 0; 128 + 504/16 =
 * 160 -> 1. Row 1: 128 - 419/16 = 102 -> 0; 128 + 662/16 = 169 -> 1;
 * 128 - 1005/16 = 65 -> 0. */
static void test_diffusion(void)
{
    uint8_t out[1], rgb[3 * 3];
    int16_t err[5];
    rt_panel p;
    CHECK_EQ(rt_panel_err_count(RT_PANEL_DIFFUSION, 3), 5);
    CHECK_EQ(rt_panel_init(&p, RT_PANEL_MONO, RT_PANEL_DIFFUSION, 0, 3, out,
                           err),
             RT_OK);
    flat_row(rgb, 128, 3);
    CHECK_EQ(rt_panel_row(&p, 0, rgb), 1);
    CHECK_EQ(out[0], 0xA0);
    CHECK_EQ(err[1], -419); /* the next row's errors, times 16 */
    CHECK_EQ(err[2], -52);
    CHECK_EQ(err[3], -403);
    CHECK_EQ(rt_panel_row(&p, 1, rgb), 1);
    CHECK_EQ(out[0], 0x40);
}

/* Flat greys keep their mean brightness under every dither: over 64x64
 * pixels, within 1/32 of the full scale (2 levels of 64 for grey). */
static void test_flat(void)
{
    enum { W = 64, H = 64 };
    static const uint8_t lumas[] = { 0, 30, 77, 128, 200, 255 };
    for (unsigned f = 0; f < 2; f++) {
        const unsigned fmt = f ? RT_PANEL_GREY4 : RT_PANEL_MONO;
        const unsigned top = f ? 15u : 1u;
        for (unsigned d = 0; d < RT_PANEL_DITHERS; d++) {
            if (d == RT_PANEL_THRESHOLD)
                continue; /* it keeps no mean */
            for (size_t k = 0; k < sizeof lumas; k++) {
                uint8_t out[W], rgb[3 * W];
                int16_t err[W + 2];
                rt_panel p;
                long sum = 0;
                CHECK_EQ(rt_panel_init(&p, fmt, d, 0, W, out, err), RT_OK);
                flat_row(rgb, lumas[k], W);
                for (unsigned y = 0; y < H; y++) {
                    rt_panel_row(&p, y, rgb);
                    for (unsigned j = 0; j < W; j++)
                        sum += f ? (j % 2 ? out[j / 2] & 15 : out[j / 2] >> 4)
                                 : (out[j / 8] >> (7 - j % 8)) & 1;
                }
                /* sum / (W H top) against luma / 255, in 1/32 steps */
                long want = (long)lumas[k] * W * H * (long)top / 255;
                long tol = (long)W * H * (long)top / 32;
                if (!CHECK(labs(sum - want) <= tol))
                    printf("    format %u dither %u luma %u: %ld, want %ld\n",
                           fmt, d, lumas[k], sum, want);
            }
        }
    }
}

/* Each buffer is exactly as long as its function says, for any height:
 * guards after them stay untouched over 100 rows of random colours. */
static void test_memory(void)
{
    uint64_t seed = 99;
    CHECK_EQ(rt_panel_out_bytes(RT_PANEL_MONO, 128), 16);
    CHECK_EQ(rt_panel_out_bytes(RT_PANEL_MONO_PAGE, 128), 128);
    CHECK_EQ(rt_panel_out_bytes(RT_PANEL_GREY4, 128), 64);
    CHECK_EQ(rt_panel_err_count(RT_PANEL_ORDERED, 128), 0);
    CHECK_EQ(rt_panel_err_count(RT_PANEL_DIFFUSION, 128), 130);
    for (unsigned fmt = 0; fmt < RT_PANEL_FORMATS; fmt++) {
        for (unsigned d = 0; d < RT_PANEL_DITHERS; d++) {
            const unsigned w = 45;
            const size_t no = rt_panel_out_bytes(fmt, w);
            const size_t ne = rt_panel_err_count(d, w);
            uint8_t out[MAXW + GUARD], rgb[3 * w];
            int16_t err[MAXW + GUARD];
            rt_panel p;
            memset(out, 0x5A, sizeof out);
            for (size_t i = 0; i < sizeof err / sizeof err[0]; i++)
                err[i] = 0x5A5A;
            CHECK_EQ(rt_panel_init(&p, fmt, d, 7, w, out, err), RT_OK);
            for (unsigned y = 0; y < 100; y++) {
                for (unsigned i = 0; i < 3 * w; i++)
                    rgb[i] = (uint8_t)th_rnd64(&seed);
                rt_panel_row(&p, y, rgb);
            }
            rt_panel_flush(&p);
            int kept = 1;
            for (size_t i = no; i < no + GUARD; i++)
                kept &= out[i] == 0x5A;
            for (size_t i = ne; i < ne + GUARD; i++)
                kept &= err[i] == 0x5A5A;
            if (!CHECK(kept))
                printf("    format %u dither %u wrote past its buffers\n",
                       fmt, d);
        }
    }
}

static void test_refused(void)
{
    uint8_t out[4];
    int16_t err[8];
    rt_panel p;
    CHECK_EQ(rt_panel_init(&p, RT_PANEL_FORMATS, 0, 0, 4, out, err),
             RT_ERR_ARG);
    CHECK_EQ(rt_panel_init(&p, 0, RT_PANEL_DITHERS, 0, 4, out, err),
             RT_ERR_ARG);
    CHECK_EQ(rt_panel_init(&p, 0, 0, 0, 0, out, err), RT_ERR_ARG);
    CHECK_EQ(rt_panel_init(&p, 0, 0, 0, 70000, out, err), RT_ERR_ARG);
    CHECK_EQ(rt_panel_init(&p, 0, 0, 70000, 4, out, err), RT_ERR_ARG);
    CHECK_EQ(rt_panel_init(&p, 0, 0, 0, 4, NULL, err), RT_ERR_ARG);
    CHECK_EQ(rt_panel_init(&p, 0, RT_PANEL_DIFFUSION, 0, 4, out, NULL),
             RT_ERR_ARG);
    CHECK_EQ(rt_panel_out_bytes(RT_PANEL_FORMATS, 4), 0);
}

int main(void)
{
    test_mono();
    test_pages();
    test_grey();
    test_diffusion();
    test_flat();
    test_memory();
    test_refused();
    return th_summary();
}
