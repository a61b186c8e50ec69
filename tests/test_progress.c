/* SPDX-License-Identifier: MIT */
/*
 * test_progress: the time left shown by the progress bar (progress.c), on
 * a simulated render whose top quarter is cheap sky and whose rest costs
 * ten times as much a row, with 20 % noise on each row's time. With the
 * rows' weights known (as the probe measures them), the estimate after
 * the first tenth of the rows never climbs more than 5 % of the whole
 * render's time above the lowest it has shown, and from a fifth on is
 * within 10 % of the render's time of the truth; with every row weighing the same (the old estimate,
 * elapsed x rows left / rows done), it climbs, which is what this fixes.
 * The probe itself runs on a real scene and gives every row a weight.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "progress.h"
#include "rt_parse.h"

enum { ROWS = 480, EVERY = 8 };

static uint64_t rng = 0x853C49E6748FEA9BULL;

/* Runs the simulated render; returns how far the estimate climbed above
 * the lowest it had shown, after 10 % of the rows, as a fraction of the
 * total time, and sets *worst_err to its largest error after 20 %, as a
 * fraction of the total time too. */
static double simulate(const double *weights, const double *cost,
                       double *worst_err)
{
    progress_eta e;
    double total = 0, t = 0, low = -1, rise = 0;
    for (int y = 0; y < ROWS; y++)
        total += cost[y];
    CHECK_EQ(progress_eta_init_weights(&e, ROWS, weights), 0);
    *worst_err = 0;
    for (int y = 0; y < ROWS; y++) {
        t += cost[y];
        progress_eta_row(&e, y);
        if (y % EVERY != EVERY - 1)
            continue;
        double left = progress_eta_left(&e, t);
        if (y >= ROWS / 10) {
            if (low >= 0 && left - low > rise * total)
                rise = (left - low) / total;
            low = low < 0 || left < low ? left : low;
        }
        if (y >= ROWS / 5) {
            double err = fabs(left - (total - t)) / total;
            *worst_err = err > *worst_err ? err : *worst_err;
        }
    }
    CHECK(fabs(e.done - e.total) < 1e-9 * e.total);
    progress_eta_free(&e);
    return rise;
}

static void test_simulated(void)
{
    static double weight[ROWS], cost[ROWS];
    for (int y = 0; y < ROWS; y++) {
        weight[y] = y < ROWS / 4 ? 1.0 : 10.0;
        double noise = 0.8 + 0.4 * (double)(th_rnd64(&rng) % 1000) / 1000.0;
        cost[y] = 0.001 * weight[y] * noise;
    }
    double err;
    double rise = simulate(weight, cost, &err);
    if (!CHECK(rise <= 0.05))
        printf("    the estimate rose by %.1f %% of the render\n", 100 * rise);
    if (!CHECK(err <= 0.10))
        printf("    the estimate was off by %.0f %% of the render\n",
               100 * err);
    /* Equal weights: the estimate climbs through the costly rows. */
    rise = simulate(NULL, cost, &err);
    if (!CHECK(rise > 0.2))
        printf("    equal weights: rose by only %.1f %%\n", 100 * rise);
}

static void test_probe(void)
{
    static const char text[] =
        "image 64 48\ncamera eye 0 1 -5 look 0 0 0\nlight 5 5 -5\n"
        "material m color 1 1 1 reflect 0.5\n"
        "sphere center 0 0 0 radius 1 material m\n"
        "quad corner -5 -1 -5 edge1 0 0 10 edge2 10 0 0 material m\n";
    static rt_scene scene;
    rt_parse_error pe;
    rt_options opt;
    progress_eta e;
    CHECK_EQ(rt_parse(text, sizeof text - 1, &scene, &pe), RT_OK);
    rt_options_from_scene(&opt, &scene);
    CHECK_EQ(progress_eta_init(&e, &scene, &opt, rt_render_rows), 0);
    CHECK(e.rows == 48 && e.total > 0);
    for (int y = 0; y < 48; y++) {
        CHECK(!e.weight || e.weight[y] > 0);
        progress_eta_row(&e, y);
    }
    CHECK(progress_eta_left(&e, 1.0) < 1e-9);
    progress_eta_free(&e);
    /* No renderer: equal weights. */
    CHECK_EQ(progress_eta_init(&e, &scene, &opt, NULL), 0);
    CHECK(e.weight == NULL && e.total == 48);
    CHECK(progress_eta_left(&e, 1.0) == 0); /* nothing done yet */
    progress_eta_free(&e);
}

int main(void)
{
    test_simulated();
    test_probe();
    return th_summary();
}
