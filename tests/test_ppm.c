/* SPDX-License-Identifier: MIT */
/*
 * Tests of the host's PPM reader and writer (port/posix/ppm.c): headers,
 * comments, maxvals and truncated or malformed files.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "harness.h"
#include "ppm.h"

static char tmpdir[] = "/tmp/fixtrace-ppm-XXXXXX";

/* Paths of the test's files in tmpdir, filled in by main(). */
static char p_rt[64], p_missing[64];

static int parse_str(const char *text, ppm_image *img, char *err)
{
    return ppm_parse((const uint8_t *)text, strlen(text), img, err, 160);
}

static void test_ppm(void)
{
    ppm_image a, b;
    char err[160];
    FILE *f;
    char hdr[32];
    int i;
    CHECK_EQ(ppm_alloc(&a, 3, 2), 0);
    for (i = 0; i < 18; i++)
        a.data[i] = (uint8_t)(i * 14 + 1);
    CHECK_EQ(ppm_save(p_rt, &a, err, sizeof err), 0);
    CHECK_EQ(ppm_read(p_rt, &b, err, sizeof err), 0);
    CHECK(b.width == 3 && b.height == 2 && b.data &&
          memcmp(a.data, b.data, 18) == 0);
    ppm_free(&b);
    ppm_free(&a);
    CHECK(a.data == NULL);
    f = tmpfile();
    CHECK(f != NULL);
    if (f) {
        CHECK_EQ(ppm_write_header(f, 3, 2), 0);
        rewind(f);
        memset(hdr, 0, sizeof hdr);
        CHECK_EQ(fread(hdr, 1, sizeof hdr - 1, f), 11);
        CHECK(strcmp(hdr, "P6\n3 2\n255\n") == 0);
        fclose(f);
    }
    /* Comments and odd whitespace are fine. */
    CHECK_EQ(parse_str("P6\n# made by hand\n2\t1 # w h\n255\rABCDEF", &a,
                       err), 0);
    CHECK(a.width == 2 && a.height == 1 && a.data && a.data[5] == 'F');
    ppm_free(&a);
    CHECK_EQ(parse_str("P6 1 1 255 xyz+trailing", &a, err), 0);
    ppm_free(&a);
    /* Refusals, each with its reason. */
    CHECK_EQ(parse_str("P3 1 1 255 0 0 0", &a, err), -1);
    CHECK(strstr(err, "P6") != NULL);
    CHECK_EQ(parse_str("P6 1 1 65535 xxxxxx", &a, err), -1);
    CHECK(strstr(err, "maxval") != NULL);
    CHECK_EQ(parse_str("P6 2 1 255 abcde", &a, err), -1);
    CHECK(strstr(err, "truncated") != NULL);
    CHECK(a.data == NULL && a.width == 0);
    CHECK_EQ(parse_str("P6 0 1 255 ", &a, err), -1);
    CHECK_EQ(parse_str("P6 2x1 255 abcdef", &a, err), -1);
    CHECK_EQ(parse_str("P6 2 ", &a, err), -1);
    CHECK(strstr(err, "height") != NULL);
    CHECK_EQ(parse_str("P6 -2 1 255 abcdef", &a, err), -1);
    CHECK_EQ(parse_str("P6 99999999999 1 255 ", &a, err), -1);
    CHECK_EQ(parse_str("P6 1 1 255", &a, err), -1);
    CHECK_EQ(parse_str("", &a, err), -1);
    CHECK_EQ(ppm_read(p_missing, &a, err, sizeof err), -1);
    CHECK(strstr(err, "missing.ppm") != NULL);
}

/* A w x h image of one grey level. */
int main(void)
{
    if (mkdtemp(tmpdir)) {
        snprintf(p_rt, sizeof p_rt, "%s/rt.ppm", tmpdir);
        snprintf(p_missing, sizeof p_missing, "%s/missing.ppm", tmpdir);
        test_ppm();
        unlink(p_rt);
        rmdir(tmpdir);
    } else {
        CHECK(!"mkdtemp failed");
    }
    return th_summary();
}
