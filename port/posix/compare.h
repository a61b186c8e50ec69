/* SPDX-License-Identifier: MIT */
/*
 * compare: how far one RGB888 image is from another (the fixed-point render
 * from the reference, say), as numbers and as a heat-map image; and the
 * `fixtrace compare` command built on them.
 */
#ifndef COMPARE_H
#define COMPARE_H

#include "ppm.h"

/* A pixel is "bad" when a channel is off by more than this (of 255). */
#define COMPARE_BAD_LEVEL 2

/* A pixel is an outlier when a channel is off by more than this. */
#define COMPARE_OUTLIER_LEVEL 64

/* A pixel is at an edge of image B (the reference, by convention) when,
 * in the 3x3 neighbourhood around it (clipped at the border), some channel
 * spans more than this. An outlier away from B's edges is a speckle: no
 * silhouette or texture edge of the ideal image explains it. (Judged on A,
 * a lone wrong pixel would make its own neighbourhood an edge.) */
#define COMPARE_EDGE_RANGE 64

typedef struct {
    int width, height;
    double psnr;            /* dB, over all channels; HUGE_VAL if equal */
    int max_err;            /* largest channel difference, 0..255 */
    double mae;             /* mean absolute channel difference (of 255) */
    long bad;               /* pixels off by more than COMPARE_BAD_LEVEL */
    double bad_pct;         /* the same as a percentage of all pixels */
    long outliers;          /* pixels off by more than COMPARE_OUTLIER_LEVEL */
    long interior_outliers; /* speckles: outliers not at an edge of B */
} compare_result;

/* Compares a with b. Returns 0 with *r filled, or -1 when their sizes
 * differ (then *r is zeroed). */
int compare_images(const ppm_image *a, const ppm_image *b, compare_result *r);

/* The heat-map colour for a channel error e (0..255): black for 0, then a
 * ramp on log2(1 + e) through blue (e = 3), green (15), yellow (63, about
 * the outlier level) to red (255). */
void compare_heat(int e, uint8_t rgb[3]);

/* Fills *out (allocated here; ppm_free() it) with the heat map of the
 * largest channel error at each pixel. Returns 0, or -1 when the sizes
 * differ or memory runs out. */
int compare_heatmap(const ppm_image *a, const ppm_image *b, ppm_image *out);

/* `fixtrace compare A.ppm B.ppm [--diff DIFF.ppm] [--min-psnr DB]
 * [--max-bad PERCENT] [--max-interior-outliers N]`; argv[0] is "compare".
 * Prints the metrics to stdout. Returns the exit status: 0 when every
 * threshold given is met, 1 when one is missed (each is named on stderr),
 * 2 for bad usage, unreadable or invalid images, sizes that differ, or a
 * diff image that cannot be written. */
int compare_main(int argc, char **argv);

#endif /* COMPARE_H */
