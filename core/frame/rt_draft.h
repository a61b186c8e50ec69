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
    int32_t rs_y;                       /* the row rs is set up for */
    rt_aa_spans rs;
    rt_thin thin;
    uint32_t sig; /* the current sample's hits (draft_sign_hit) */
    fx_t sign_w;  /* hits of rays of this weight or less are not signed */
} rt_draft;

/* Bytes of scratch rt_draft_init() takes: two rows per level. */
size_t rt_draft_slot_bytes(const rt_options *o);

/* Bytes of a row of interpolation flags: one bit per pixel. */
size_t rt_draft_flag_bytes(const rt_options *o);

/* Sets *d up for a draft render with threshold o->draft (> 0), traced
 * pixels taking cf->n x cf->n samples; scratch holds
 * rt_draft_slot_bytes(o) bytes and stays the draft's until the render
 * ends. Turns on wk's signing of hits. */
void rt_draft_init(rt_draft *d, const rt_tracer *tr, rt_work *wk,
                   const rt_cam_frame *cf, const rt_options *o,
                   uint8_t *scratch);

/* Draft row y into rgb (8-bit RGB, 3 * width bytes) and flags
 * (rt_draft_flag_bytes(); bit x % 8 of byte x / 8 set: pixel x was
 * interpolated). Rows may come in any order; in order is cheapest. */
void rt_draft_row(rt_draft *d, unsigned y, uint8_t *rgb, uint8_t *flags);

/* Bytes of scratch rt_draft_render() needs after the output row. */
size_t rt_draft_bytes(const rt_options *o);

/* Rows y0 <= y < y1 of a draft render without adaptive anti-aliasing,
 * each handed to fn; row_buf holds rt_row_bytes(o) + rt_draft_bytes(o). */
rt_status rt_draft_render(const rt_tracer *tr, rt_work *wk,
                          const rt_cam_frame *cf, const rt_options *o, int y0,
                          int y1, uint8_t *row_buf, rt_row_fn fn, void *ctx);

#endif /* RT_DRAFT_H */
