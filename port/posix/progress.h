/* SPDX-License-Identifier: MIT */
/* progress: the time left in a render, for the progress bar. Rows differ
 * in cost (sky is cheap, glass is not), so the rows done so far say
 * little about the rest by their number alone. A quick probe renders the
 * scene at 1/PROGRESS_PROBE of the width and height, 1 spp, and times
 * each of its rows: that is the weight of the rows it stands for. The time left is then the elapsed time scaled by the weight
 * left over the weight done, and smoothed, so it falls steadily instead
 * of climbing whenever the render reaches the costly rows. */
#ifndef PROGRESS_H
#define PROGRESS_H

#include "rt_render.h"

/* The probe's scale-down in each direction. */
#define PROGRESS_PROBE 8

/* The renderer the probe calls: rt_render_rows() or ref_render_rows(). */
typedef rt_status (*progress_render_fn)(const rt_scene *, const rt_options *,
                                        int, int, uint8_t *, rt_row_fn,
                                        void *, rt_stats *);

typedef struct {
    int rows;
    double *weight;    /* per row; NULL: every row the same */
    double total, done; /* weights: all rows, rows finished */
    double shown;      /* the smoothed estimate last returned, seconds */
    int have_shown;
} progress_eta;

/* Sets up for a render of opt->height rows. With render non-NULL, runs the
 * probe (about 1/64 of the pixels at 1 spp); if it fails or finds no work,
 * or with render NULL, every row weighs the same. Returns 0, or -1 when
 * memory runs out. */
int progress_eta_init(progress_eta *e, const rt_scene *s,
                      const rt_options *opt, progress_render_fn render);

/* Sets up with given row weights (w[0..rows), copied; NULL: equal). For
 * tests. Returns 0, or -1 when memory runs out. */
int progress_eta_init_weights(progress_eta *e, int rows, const double *w);

/* Row y is finished. */
void progress_eta_row(progress_eta *e, int y);

/* Seconds left after `elapsed` seconds, smoothed over the calls; 0 before
 * any row is done. */
double progress_eta_left(progress_eta *e, double elapsed);

/* Releases the weights. */
void progress_eta_free(progress_eta *e);

#endif /* PROGRESS_H */
