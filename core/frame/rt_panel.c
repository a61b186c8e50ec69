/* SPDX-License-Identifier: MIT */
/*
 * rt_panel: RGB888 rows to mono and 16-grey panel bytes (rt_panel.h).
 */
#include "rt_panel.h"
#include "rt_grey.h"

/* The 4x4 Bayer matrix, 0..15: each value once in every aligned tile. */
static const uint8_t panel_bayer4[4][4] = {
    { 0, 8, 2, 10 }, { 12, 4, 14, 6 }, { 3, 11, 1, 9 }, { 15, 7, 13, 5 }
};

size_t rt_panel_out_bytes(unsigned format, unsigned width)
{
    switch (format) {
    case RT_PANEL_MONO:
        return ((size_t)width + 7u) / 8u;
    case RT_PANEL_MONO_PAGE:
        return width;
    case RT_PANEL_GREY4:
        return ((size_t)width + 1u) / 2u;
    default:
        return 0;
    }
}

size_t rt_panel_err_count(unsigned dither, unsigned width)
{
    return dither == RT_PANEL_DIFFUSION ? (size_t)width + 2u : 0;
}

rt_status rt_panel_init(rt_panel *p, unsigned format, unsigned dither,
                        unsigned x0, unsigned width, uint8_t *out,
                        int16_t *err)
{
    if (!p || format >= RT_PANEL_FORMATS || dither >= RT_PANEL_DITHERS ||
        width < 1 || width > UINT16_MAX || x0 > UINT16_MAX || !out ||
        (dither == RT_PANEL_DIFFUSION && !err))
        return RT_ERR_ARG;
    p->format = (uint8_t)format;
    p->dither = (uint8_t)dither;
    p->x0 = (uint16_t)x0;
    p->width = (uint16_t)width;
    p->pending = 0;
    p->page = 0;
    p->out = out;
    p->err = err;
    for (size_t i = 0; i < rt_panel_err_count(dither, width); i++)
        err[i] = 0;
    return RT_OK;
}

/* a / 16 rounded to nearest, halves away from zero: the same for either
 * sign, without shifting a negative number. */
static int div16(int a)
{
    return a >= 0 ? (a + 8) / 16 : -((-a + 8) / 16);
}

/* The output value of luma v (0..255) at frame column x of row y: 0 or 1
 * (mono), 0..15 (grey). Error diffusion quantises as THRESHOLD. */
static unsigned quantise(const rt_panel *p, unsigned v, unsigned x,
                         unsigned y)
{
    const int grey = p->format == RT_PANEL_GREY4;
    if (p->dither == RT_PANEL_ORDERED) {
        const unsigned b = panel_bayer4[y & 3u][x & 3u];
        if (grey) /* rt_grey4's mapping, from the luma */
            return (v + (((2u * b + 1u) * 17u) >> 5)) / 17u;
        return v >= ((2u * b + 1u) * 255u + 16u) / 32u;
    }
    return grey ? (v * 15u + 127u) / 255u : v >= 128u;
}

/* Stores value q (0/1 or 0..15) of the row's pixel j. */
static void put(rt_panel *p, unsigned j, unsigned y, unsigned q)
{
    uint8_t *o = p->out;
    switch (p->format) {
    case RT_PANEL_MONO:
        o[j / 8] = (uint8_t)(o[j / 8] | q << (7u - j % 8u));
        break;
    case RT_PANEL_MONO_PAGE:
        o[j] = (uint8_t)(o[j] | q << (y % 8u));
        break;
    default: /* GREY4 */
        o[j / 2] = (uint8_t)(o[j / 2] | q << (j % 2u ? 0 : 4));
        break;
    }
}

size_t rt_panel_row(rt_panel *p, unsigned y, const uint8_t *rgb)
{
    const unsigned w = p->width;
    const int page = p->format == RT_PANEL_MONO_PAGE;
    /* A fresh row, or a fresh page: start from zero bits. */
    if (!page || !p->pending || y / 8u != p->page)
        for (size_t i = 0; i < rt_panel_out_bytes(p->format, w); i++)
            p->out[i] = 0;
    p->page = (uint16_t)(y / 8u);
    /* Error diffusion: err[j + 1] holds pixel j's error from the row
     * above, times 16; it is replaced by the next row's once pixel j + 1
     * has given its share (the three below-shares wait in nb[]). */
    int16_t *e = p->err;
    int right = 0, nb[3] = { 0, 0, 0 }; /* errors times 16 */
    const unsigned top = p->format == RT_PANEL_GREY4 ? 15u : 1u;
    for (unsigned j = 0; j < w; j++) {
        unsigned v = rt_grey_luma(rgb + 3u * j), q;
        if (p->dither == RT_PANEL_DIFFUSION) {
            int t = (int)v + div16(e[j + 1] + right);
            t = t < 0 ? 0 : (t > 255 ? 255 : t);
            q = quantise(p, (unsigned)t, 0, 0);
            const int err = t - (int)(q * 255u / top);
            right = 7 * err;
            nb[0] += 3 * err; /* pixel j - 1 below: now complete */
            nb[1] += 5 * err;
            nb[2] = err;
            e[j] = (int16_t)nb[0]; /* at most 9 * 255 */
            nb[0] = nb[1];
            nb[1] = nb[2];
        } else {
            q = quantise(p, v, p->x0 + j, y);
        }
        put(p, j, y, q);
    }
    if (p->dither == RT_PANEL_DIFFUSION)
        e[w] = (int16_t)nb[0];
    if (!page)
        return rt_panel_out_bytes(p->format, w);
    p->pending = y % 8u != 7u;
    return p->pending ? 0 : w;
}

size_t rt_panel_flush(rt_panel *p)
{
    const size_t n = p->pending ? p->width : 0;
    p->pending = 0;
    return n;
}
