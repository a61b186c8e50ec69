/* SPDX-License-Identifier: MIT */
/*
 * Tests of the image comparison (port/posix/compare.c): PSNR, pixel
 * counts over thresholds, the heat map and `fixtrace compare` itself.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "harness.h"
#include "compare.h"
#include "ppm.h"

/* |a - b| <= tol for doubles; prints both on failure. */
#define CHECK_DBL(a, b, tol)                                                  \
    do {                                                                      \
        double td_a_ = (a), td_b_ = (b);                                      \
        if (!th_check(fabs(td_a_ - td_b_) <= (tol), __FILE__, __LINE__,       \
                      #a " ~ " #b))                                           \
            printf("    got %.17g, want %.17g\n", td_a_, td_b_);             \
    } while (0)

static char tmpdir[] = "/tmp/fixtrace-compare-XXXXXX";

/* Paths of the test's files in tmpdir, filled in by main(). */
static char p_missing[64], p_a[64], p_b[64], p_c[64], p_d[64];

static void flat(ppm_image *img, int w, int h, uint8_t v)
{
    ppm_alloc(img, w, h);
    memset(img->data, v, (size_t)w * h * 3);
}

static void test_compare(void)
{
    ppm_image a, b, c, heat;
    compare_result r;
    uint8_t px[3];
    char err[160];
    char *argv[8];
    flat(&a, 10, 10, 100);
    flat(&b, 10, 10, 100);
    CHECK_EQ(compare_images(&a, &b, &r), 0);
    CHECK(isinf(r.psnr) && r.psnr > 0);
    CHECK(r.max_err == 0 && r.mae == 0 && r.bad == 0 && r.outliers == 0);
    /* One channel off by 30: MSE = 900 / 300 = 3. */
    b.data[3 * 55] = 130;
    CHECK_EQ(compare_images(&a, &b, &r), 0);
    CHECK_DBL(r.psnr, 10 * log10(65025.0 / 3), 1e-9);
    CHECK_EQ(r.max_err, 30);
    CHECK_DBL(r.mae, 0.1, 1e-12);
    CHECK_EQ(r.bad, 1);
    CHECK_DBL(r.bad_pct, 1.0, 1e-12);
    CHECK_EQ(r.outliers, 0);
    /* An outlier of A (the render) on flat ground of B (the reference):
     * a speckle, although it makes A's own neighbourhood an edge. */
    b.data[3 * 55] = 100;
    a.data[3 * 55 + 2] = 200;
    CHECK_EQ(compare_images(&a, &b, &r), 0);
    CHECK(r.outliers == 1 && r.interior_outliers == 1 && r.max_err == 100);
    /* A bright neighbour in B: an edge of the reference, no speckle; A
     * misses it too, so that is a second outlier. */
    memset(b.data + 3 * 56, 250, 3);
    CHECK_EQ(compare_images(&a, &b, &r), 0);
    CHECK(r.outliers == 2 && r.interior_outliers == 0);
    memset(b.data + 3 * 56, 100, 3);
    a.data[3 * 55 + 2] = 100;
    b.data[3 * 55] = 130; /* back to one channel off by 30 */
    flat(&c, 10, 9, 100);
    CHECK_EQ(compare_images(&a, &c, &r), -1);
    /* Heat colours. */
    compare_heat(0, px);
    CHECK(px[0] == 0 && px[1] == 0 && px[2] == 0);
    compare_heat(3, px);
    CHECK(px[0] == 0 && px[1] == 0 && px[2] == 255);
    compare_heat(15, px);
    CHECK(px[0] == 0 && px[1] == 255 && px[2] == 0);
    compare_heat(63, px);
    CHECK(px[0] == 255 && px[1] == 255 && px[2] == 0);
    compare_heat(255, px);
    CHECK(px[0] == 255 && px[1] == 0 && px[2] == 0);
    compare_heat(1, px);
    CHECK(px[0] == 0 && px[1] == 0 && px[2] == 128);
    /* The command. */
    b.data[3 * 55 + 2] = 100;
    ppm_save(p_a, &a, err, sizeof err);
    ppm_save(p_b, &b, err, sizeof err);
    ppm_save(p_c, &c, err, sizeof err);
    argv[0] = "compare";
    argv[1] = p_a;
    argv[2] = p_b;
    argv[3] = "--diff";
    argv[4] = p_d;
    argv[5] = "--min-psnr";
    argv[6] = "43";
    CHECK_EQ(compare_main(7, argv), 0);
    CHECK_EQ(ppm_read(p_d, &heat, err, sizeof err), 0);
    compare_heat(30, px);
    CHECK(heat.data && memcmp(heat.data + 3 * 55, px, 3) == 0 &&
          heat.data[0] == 0);
    ppm_free(&heat);
    argv[6] = "44";
    CHECK_EQ(compare_main(7, argv), 1);
    argv[3] = "--max-bad";
    argv[4] = "0.5";
    CHECK_EQ(compare_main(5, argv), 1);
    argv[4] = "1";
    CHECK_EQ(compare_main(5, argv), 0);
    argv[4] = "lots";
    CHECK_EQ(compare_main(5, argv), 2);
    CHECK_EQ(compare_main(2, argv), 2);
    argv[3] = "--bogus";
    CHECK_EQ(compare_main(4, argv), 2);
    argv[2] = p_c;
    CHECK_EQ(compare_main(3, argv), 2);
    argv[2] = p_missing;
    CHECK_EQ(compare_main(3, argv), 2);
    ppm_free(&a);
    ppm_free(&b);
    ppm_free(&c);
}

int main(void)
{
    char *const files[] = {p_a, p_b, p_c, p_d};
    size_t i;
    if (mkdtemp(tmpdir)) {
        snprintf(p_missing, sizeof p_missing, "%s/missing.ppm", tmpdir);
        snprintf(p_a, sizeof p_a, "%s/a.ppm", tmpdir);
        snprintf(p_b, sizeof p_b, "%s/b.ppm", tmpdir);
        snprintf(p_c, sizeof p_c, "%s/c.ppm", tmpdir);
        snprintf(p_d, sizeof p_d, "%s/d.ppm", tmpdir);
        test_compare();
        for (i = 0; i < sizeof files / sizeof files[0]; i++)
            unlink(files[i]);
        rmdir(tmpdir);
    } else {
        CHECK(!"mkdtemp failed");
    }
    return th_summary();
}
