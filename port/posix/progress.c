/* SPDX-License-Identifier: MIT */
/* progress: the time left in a render (progress.h). */
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "progress.h"

/* How far each new estimate moves the one shown (0..1). */
#define SMOOTHING 0.25

int progress_eta_init_weights(progress_eta *e, int rows, const double *w)
{
    memset(e, 0, sizeof *e);
    e->rows = rows;
    e->total = rows;
    if (!w)
        return 0;
    e->weight = malloc(sizeof *e->weight * (size_t)rows);
    if (!e->weight)
        return -1;
    e->total = 0;
    for (int y = 0; y < rows; y++) {
        e->weight[y] = w[y];
        e->total += w[y];
    }
    return 0;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The probe's row callback: each row's time since the one before. */
typedef struct {
    double *cost, last;
    int rows;
} probe_ctx;

static int time_row(void *ctx, int y, const uint8_t *row, size_t n)
{
    probe_ctx *p = ctx;
    double t = now();
    (void)row;
    (void)n;
    if (y >= 0 && y < p->rows)
        p->cost[y] = t - p->last;
    p->last = t;
    return 0;
}

int progress_eta_init(progress_eta *e, const rt_scene *s,
                      const rt_options *opt, progress_render_fn render)
{
    int h = opt->height;
    if (!render)
        return progress_eta_init_weights(e, h, NULL);
    rt_options p = *opt;
    p.width = (uint16_t)(opt->width / PROGRESS_PROBE ? opt->width /
                         PROGRESS_PROBE : 1);
    p.height = (uint16_t)(h / PROGRESS_PROBE ? h / PROGRESS_PROBE : 1);
    p.spp = 1;
    p.adaptive = 0;
    double *probe = calloc(p.height, sizeof *probe);
    double *w = malloc(sizeof *w * (size_t)h);
    uint8_t *buf = malloc(rt_buffer_bytes(&p));
    double sum = 0;
    int rc = 0;
    if (probe && w && buf) {
        /* One call, timed row by row: per-call set-up stays out of the
         * rows' costs, except the first row's, which takes the second's. */
        probe_ctx pc = {probe, now(), p.height};
        if (render(s, &p, 0, p.height, buf, time_row, &pc, NULL) == RT_OK) {
            if (p.height > 1)
                probe[0] = probe[1];
            for (int y = 0; y < p.height; y++)
                sum += probe[y];
        }
    }
    if (sum > 0 && probe && w) {
        /* Each row takes its probe row's time, plus a tenth of the mean
         * so that no row weighs nothing (a probe row can be too quick for
         * the clock). */
        double floor_w = 0.1 * sum / p.height;
        for (int y = 0; y < h; y++)
            w[y] = probe[(long)y * p.height / h] + floor_w;
        rc = progress_eta_init_weights(e, h, w);
    } else {
        rc = progress_eta_init_weights(e, h, NULL);
    }
    free(probe);
    free(w);
    free(buf);
    return rc;
}

void progress_eta_row(progress_eta *e, int y)
{
    if (y >= 0 && y < e->rows)
        e->done += e->weight ? e->weight[y] : 1.0;
}

double progress_eta_left(progress_eta *e, double elapsed)
{
    if (e->done <= 0)
        return 0;
    double left = e->total - e->done;
    double est = elapsed * (left > 0 ? left : 0) / e->done;
    if (!e->have_shown) {
        e->shown = est;
        e->have_shown = 1;
    } else {
        e->shown += SMOOTHING * (est - e->shown);
    }
    return e->shown;
}

void progress_eta_free(progress_eta *e)
{
    free(e->weight);
    e->weight = NULL;
}
