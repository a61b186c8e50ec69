/* SPDX-License-Identifier: MIT */
/*
 * rt_panel: RGB888 rows (as rt_render hands them over) to the bytes of
 * monochrome and 16-grey panels: SSD1306/SH1106-class OLEDs, e-paper,
 * SSD0323/SSD1322 grey OLEDs. Rows go in one at a time, in order; the
 * converter keeps no frame, only what the chosen mode needs:
 *
 *   mode                     output bytes            error buffer
 *   RT_PANEL_MONO            (width + 7) / 8 a row   diffusion: width + 2
 *   RT_PANEL_MONO_PAGE       width a page of 8 rows  int16 (2 width + 4
 *   RT_PANEL_GREY4           (width + 1) / 2 a row   bytes); else none
 *
 * so O(width) memory in every mode. Each pixel is first its luma, 0..255
 * (rt_grey.h: BT.601 weights, white 255). A set bit lights a pixel (the
 * SSD1306's sense: bright is 1; PBM's black is 1, so a PBM writer inverts
 * it); a grey level is 0 (black) to 15 (white).
 *
 * Dithering:
 * - RT_PANEL_THRESHOLD: none. Mono: lit when the luma is 128 or more;
 *   grey: the nearest level, (luma * 15 + 127) / 255.
 * - RT_PANEL_ORDERED: a 4x4 Bayer matrix indexed by the frame's column
 *   and row, so tiles and windows of a frame dither as the whole frame.
 *   Mono: lit when the luma reaches the threshold (2 b + 1) * 255 / 32
 *   (8..247) of the pixel's Bayer value b; grey: rt_grey4() (the mapping
 *   of the LM3S6965 board's OLED).
 * - RT_PANEL_DIFFUSION: Floyd-Steinberg, left to right on every row; each
 *   pixel's quantisation error (in 8-bit levels, from its luma plus the
 *   errors it received, clamped to 0..255) goes 7/16 right, 3/16 down
 *   left, 5/16 down and 1/16 down right, rounded to nearest. Only the
 *   next row's errors are kept. Errors cross rows, so the rows must come
 *   in order, one after another, and a window dithers as a picture of its
 *   own, not as that part of a full frame's dither.
 *
 * Freestanding and integer-only like the rest of the core.
 */
#ifndef RT_PANEL_H
#define RT_PANEL_H

#include <stddef.h>
#include <stdint.h>
#include "rt_scene.h"

/* Output layouts. */
typedef enum {
    /* 1 bit a pixel, a row at a time: (width + 7) / 8 bytes, the first
     * pixel in the top bit (MSB-first), unused low bits of the last byte
     * 0. E-paper and memory-in-pixel displays, PBM. */
    RT_PANEL_MONO = 0,
    /* 1 bit a pixel in SSD1306 page order: a page is 8 rows, frame rows
     * 8 p .. 8 p + 7; its width bytes are the columns, bit k of a byte
     * the page's row k (bit 0 at the top). A page is handed over when
     * its row 7 has come, or by rt_panel_flush() at the end; rows of a
     * page that never came are 0, and a row of another page starts that
     * page afresh. SSD1306, SH1106 and the like, in horizontal or page
     * addressing. */
    RT_PANEL_MONO_PAGE,
    /* 4 bits a pixel, two a byte: (width + 1) / 2 bytes a row, the first
     * of each pair in the high nibble, a missing last one 0. SSD0323,
     * SSD1322, SSD1327. */
    RT_PANEL_GREY4,
    RT_PANEL_FORMATS
} rt_panel_format;

/* Dithering. */
typedef enum {
    RT_PANEL_THRESHOLD = 0, /* none: the nearest value */
    RT_PANEL_ORDERED,       /* 4x4 Bayer matrix */
    RT_PANEL_DIFFUSION,     /* Floyd-Steinberg error diffusion */
    RT_PANEL_DITHERS
} rt_panel_dither;

/* A converter's state; set up by rt_panel_init(), the buffers the
 * caller's. */
typedef struct {
    uint8_t format, dither; /* rt_panel_format, rt_panel_dither */
    uint16_t x0;            /* the frame column of a row's first pixel */
    uint16_t width;         /* pixels a row */
    uint8_t pending;        /* MONO_PAGE: out holds part of a page, */
    uint16_t page;          /* this one (frame rows 8 page ..) */
    uint8_t *out;           /* rt_panel_out_bytes() */
    int16_t *err;           /* DIFFUSION: rt_panel_err_count() */
} rt_panel;

/* Bytes of the output buffer for rows width pixels wide: a row (MONO,
 * GREY4) or a page (MONO_PAGE); 0 for an unknown format. */
size_t rt_panel_out_bytes(unsigned format, unsigned width);

/* int16_t elements of the error buffer: width + 2 with error diffusion,
 * else 0 (err may then be NULL). */
size_t rt_panel_err_count(unsigned dither, unsigned width);

/* Sets *p up to convert rows of width pixels (1..65535) whose first pixel
 * is frame column x0 (the ordered dither's phase; 0 for whole rows), into
 * out (rt_panel_out_bytes()), with err (rt_panel_err_count() elements)
 * for error diffusion. Returns RT_OK, or RT_ERR_ARG for an unknown format
 * or dither, a width of 0 or above 65535, x0 above 65535 or a missing
 * buffer. */
rt_status rt_panel_init(rt_panel *p, unsigned format, unsigned dither,
                        unsigned x0, unsigned width, uint8_t *out,
                        int16_t *err);

/* Converts frame row y, width RGB888 pixels at rgb. Returns how many
 * bytes of p->out are ready to send: the row (MONO, GREY4), or with
 * MONO_PAGE the page when y is its last row (y % 8 == 7), else 0. The
 * bytes stay valid until the next call. */
size_t rt_panel_row(rt_panel *p, unsigned y, const uint8_t *rgb);

/* After the last row: the bytes of p->out still to send, a MONO_PAGE
 * page whose last row never came (the image's height not a multiple of
 * 8), else 0. */
size_t rt_panel_flush(rt_panel *p);

#endif /* RT_PANEL_H */
