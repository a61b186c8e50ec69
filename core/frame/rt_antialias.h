/* SPDX-License-Identifier: MIT */
/*
 * rt_antialias: the samples of each pixel of a row: the n x n grid
 * (rt_options.spp = n * n), and adaptive anti-aliasing, which gives the
 * grid only to pixels whose neighbourhood differs. Internal.
 */
#ifndef RT_ANTIALIAS_H
#define RT_ANTIALIAS_H

#include "rt_render.h"
#include "rt_trace.h"

/* One pixel row's camera rays: what they may hit (rt_cull), and where. */
typedef struct {
    rt_row_spans hit;
    int32_t lo, hi; /* columns outside [lo, hi] can hit nothing */
    rt_cam_ray base[RT_MAX_SPP_SIDE]; /* w + sy up for each sample row */
} rt_aa_spans;

/* Sets *rs up for pixel row y at cf->n x cf->n samples: the row's spans
 * (rt_cull_row, or every object without RT_CULL), their column range and
 * the sample rows' bases. */
void rt_aa_row_setup(rt_aa_spans *rs, const rt_tracer *tr,
                     const rt_cam_frame *cf, const rt_options *o, unsigned y);

/* Fills columns x0 <= x < x1 of row y into row (x1 - x0 pixels, column
 * x0 first) in o->format, each pixel the mean of its cf->n x cf->n
 * samples. */
void rt_aa_row(const rt_tracer *tr, rt_work *wk, const rt_cam_frame *cf,
               const rt_options *o, unsigned y, unsigned x0, unsigned x1,
               uint8_t *row);

/* Columns x0 <= x < x1 of rows y0 <= y < y1 with adaptive anti-aliasing
 * (o->adaptive > 0, cfn->n > 1), each row handed to fn; row_buf holds
 * rt_window_bytes(o, x1 - x0). With o->draft > 0 the centre samples come
 * from a draft render. */
rt_status rt_aa_adaptive(const rt_tracer *tr, rt_work *wk,
                         const rt_cam_frame *cfn, const rt_options *o,
                         unsigned x0, int y0, unsigned x1, int y1,
                         uint8_t *row_buf, rt_row_fn fn, void *ctx);

#endif /* RT_ANTIALIAS_H */
