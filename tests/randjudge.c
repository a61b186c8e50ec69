/* SPDX-License-Identifier: MIT */
/*
 * randjudge: the verdict of the randomized differential test
 * (tools/random_test.sh) on one scene.
 *
 *   randjudge CORE.ppm REF.ppm REF3.ppm [NEAR.ppm ...]
 *
 * CORE is the fixed-point render and REF the reference's, W x H; REF3 is
 * the reference at 3W x 3H, whose 3x3 block (3x .. 3x+2, 3y .. 3y+2)
 * samples pixel (x, y) at its centre and a third of a pixel around it;
 * each NEAR is the reference, W x H, with the eye moved by a few ulps.
 *
 * A pixel is a speckle when it is off from REF by more than 64/255 where
 * REF's 3x3 neighbourhood is smooth (no channel spans more than 64 in it:
 * issue 18's definition, `fixtrace compare`'s outliers away from edges),
 * REF3 is smooth within the pixel too (its nine samples of the pixel
 * span at most 64), and no reference sample near it, REF's own, the nine
 * of REF3 or those of NEAR, is within 64/255 of the core's pixel: no ray
 * of the pixel's footprint, and none within the documented tolerance of a
 * few ulps near a silhouette, sees what the core sees. Texture cells and
 * bump lattices of an ulp or two, finer than a pixel, are noise in both
 * renderers (docs/numerics.md) and mostly pass; a wrong shadow, a hole or
 * a wrong cell on a smooth surface does not.
 *
 * Prints "speckles N" and the first few, and exits 1 when N > 0 (2 for
 * unreadable or mismatched images). Host-only test tool.
 */
#include <stdio.h>
#include <stdlib.h>

#include "ppm.h"

#define LEVEL 64
#define MAX_NEAR 8

static const uint8_t *px(const ppm_image *m, int x, int y)
{
    return m->data + 3 * ((size_t)y * (size_t)m->width + (size_t)x);
}

/* Largest channel difference of two pixels. */
static int pdiff(const uint8_t *a, const uint8_t *b)
{
    int e = 0;
    for (int c = 0; c < 3; c++) {
        int d = a[c] > b[c] ? a[c] - b[c] : b[c] - a[c];
        e = d > e ? d : e;
    }
    return e;
}

/* Some channel spans more than LEVEL in the 3x3 block around (x, y). */
static int at_edge(const ppm_image *m, int x, int y)
{
    for (int c = 0; c < 3; c++) {
        int lo = 255, hi = 0;
        for (int yy = y - 1; yy <= y + 1; yy++)
            for (int xx = x - 1; xx <= x + 1; xx++) {
                if (xx < 0 || yy < 0 || xx >= m->width || yy >= m->height)
                    continue;
                int v = px(m, xx, yy)[c];
                lo = v < lo ? v : lo;
                hi = v > hi ? v : hi;
            }
        if (hi - lo > LEVEL)
            return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    ppm_image core, ref, ref3, near[MAX_NEAR];
    char err[256];
    int n_near = argc - 4;
    if (argc < 4 || n_near > MAX_NEAR) {
        fprintf(stderr, "usage: randjudge CORE.ppm REF.ppm REF3.ppm "
                        "[NEAR.ppm ...] (at most %d)\n", MAX_NEAR);
        return 2;
    }
    if (ppm_read(argv[1], &core, err, sizeof err) != 0 ||
        ppm_read(argv[2], &ref, err, sizeof err) != 0 ||
        ppm_read(argv[3], &ref3, err, sizeof err) != 0) {
        fprintf(stderr, "randjudge: %s\n", err);
        return 2;
    }
    const int w = core.width, h = core.height;
    if (ref.width != w || ref.height != h || ref3.width != 3 * w ||
        ref3.height != 3 * h) {
        fprintf(stderr, "randjudge: image sizes do not match\n");
        return 2;
    }
    for (int k = 0; k < n_near; k++) {
        if (ppm_read(argv[4 + k], &near[k], err, sizeof err) != 0) {
            fprintf(stderr, "randjudge: %s\n", err);
            return 2;
        }
        if (near[k].width != w || near[k].height != h) {
            fprintf(stderr, "randjudge: %s is not %dx%d\n", argv[4 + k], w,
                    h);
            return 2;
        }
    }
    long speckles = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const uint8_t *p = px(&core, x, y);
            if (pdiff(p, px(&ref, x, y)) <= LEVEL || at_edge(&ref, x, y) ||
                at_edge(&ref3, 3 * x + 1, 3 * y + 1))
                continue;
            int seen = 0;
            for (int j = 0; j < 3 && !seen; j++)
                for (int i = 0; i < 3 && !seen; i++)
                    seen = pdiff(p, px(&ref3, 3 * x + i, 3 * y + j)) <= LEVEL;
            for (int k = 0; k < n_near && !seen; k++)
                seen = pdiff(p, px(&near[k], x, y)) <= LEVEL;
            if (seen)
                continue;
            if (speckles < 4)
                printf("speckle at (%d, %d): core %d %d %d, reference %d %d "
                       "%d\n", x, y, p[0], p[1], p[2], px(&ref, x, y)[0],
                       px(&ref, x, y)[1], px(&ref, x, y)[2]);
            speckles++;
        }
    printf("speckles %ld\n", speckles);
    ppm_free(&core);
    ppm_free(&ref);
    ppm_free(&ref3);
    for (int k = 0; k < n_near; k++)
        ppm_free(&near[k]);
    return speckles > 0;
}
