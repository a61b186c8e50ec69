/* SPDX-License-Identifier: MIT */
/*
 * rt_draft: draft renders, by adaptive undersampling (rt_options.draft).
 * A coarse lattice, every 2^RT_DRAFT_LEVELS-th pixel of every
 * 2^RT_DRAFT_LEVELS-th row (and the last column and row), is traced; then,
 * level by level at half the spacing, each pixel between lattice pixels
 * is traced only where its neighbours on the coarser level disagree: they
 * hit different objects or texture cells (along the whole path, reflected
 * and refracted rays included), a shadow ray of one is blocked where the
 * other's is not, their colours differ by more than o->draft levels, or
 * an object the row's culling (rt_cull) allows there could lie in front
 * of them and the pixel's centre ray hits it. Elsewhere the pixel is the
 * rounded mean of its neighbours. Two rows per level live in the caller's
 * buffer, so rows stream in order with O(width) memory, and each row
 * depends only on its own y: any banding gives the same bytes. Internal.
 */
#ifndef RT_DRAFT_H
#define RT_DRAFT_H

#include "rt_thin.h"

/* A draft render's state: the rows of each level, and the spans of the
 * row being worked on. */
typedef struct {
    const rt_tracer *tr;
    rt_work *wk;
    const rt_cam_frame *cf; /* the samples of a traced pixel */
    const rt_options *o;
    uint8_t *slot[RT_DRAFT_LEVELS][2];  /* rows of levels 1.. (rt_draft.c) */
    int32_t slot_y[RT_DRAFT_LEVELS][2]; /* the row each holds, -1: none */
    /* The indices of each level's first and last column computed (level
     * 0: the columns themselves); a slot holds those from first on. */
    unsigned first[RT_DRAFT_LEVELS + 1], last[RT_DRAFT_LEVELS + 1];
    int32_t rs_y;                       /* the row rs is set up for */
    rt_aa_spans rs;
    rt_thin thin;
    uint32_t sig; /* the current sample's hits (draft_sign_hit) */
    fx_t sign_w;  /* hits of rays of this weight or less are not signed */
} rt_draft;

/* Bytes of scratch rt_draft_init() takes for any n consecutive columns
 * (n <= width): two rows per level, of the level's columns that the n
 * columns' pixels reach. For n = width, every column of each level. */
size_t rt_draft_slot_bytes(const rt_options *o, unsigned n);

/* Bytes of a row of interpolation flags for n pixels: one bit each. */
size_t rt_draft_flag_bytes(unsigned n);

/* Sets *d up for a draft render of columns c0..c1 (c0 <= c1 < width)
 * with threshold o->draft (> 0), traced pixels taking cf->n x cf->n
 * samples; scratch holds rt_draft_slot_bytes(o, c1 - c0 + 1) bytes and
 * stays the draft's until the render ends. Turns on wk's signing of
 * hits. */
void rt_draft_init(rt_draft *d, const rt_tracer *tr, rt_work *wk,
                   const rt_cam_frame *cf, const rt_options *o, unsigned c0,
                   unsigned c1, uint8_t *scratch);

/* Columns c0..c1 of draft row y into rgb (8-bit RGB, 3 bytes a pixel,
 * column c0 first) and flags (rt_draft_flag_bytes(); bit j % 8 of byte
 * j / 8 set: pixel c0 + j was interpolated). Rows may come in any order;
 * in order is cheapest. */
void rt_draft_row(rt_draft *d, unsigned y, uint8_t *rgb, uint8_t *flags);

/* Bytes of scratch rt_draft_render() needs after the output row, for a
 * window n columns wide. */
size_t rt_draft_bytes(const rt_options *o, unsigned n);

/* Columns x0 <= x < x1 of rows y0 <= y < y1 of a draft render without
 * adaptive anti-aliasing, each row handed to fn; row_buf holds
 * rt_window_bytes(o, x1 - x0). */
rt_status rt_draft_render(const rt_tracer *tr, rt_work *wk,
                          const rt_cam_frame *cf, const rt_options *o,
                          unsigned x0, int y0, unsigned x1, int y1,
                          uint8_t *row_buf, rt_row_fn fn, void *ctx);

#endif /* RT_DRAFT_H */
