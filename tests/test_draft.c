/* SPDX-License-Identifier: MIT */
/*
 * Draft renders (rt_options.draft):
 * - every scene in scenes/: bands of 7 rows and of 1 row give the bytes of
 *   one band, alone and with adaptive anti-aliasing or 4 spp; every pixel
 *   that was traced is the full render's pixel (at least as many pixels
 *   match as --stats counts traced); some are interpolated; RGB565 rows
 *   are the RGB888 rows' top bits;
 * - thin features: poles and bars one pixel wide and small far spheres,
 *   in front of a floor and in front of the sky, show in a draft as in
 *   the full render (within 8 levels, the interpolation's rounding and
 *   shading), at any threshold.
 */
#include <stdlib.h>
#include <string.h>

#include "cli_util.h"
#include "harness.h"
#include "mesh_obj.h"
#include "rt_parse.h"
#include "rt_render.h"

#define TW 64
#define TH 48
#define MAXW 128
#define MAXH 96

/* Renders o into img in bands of `band` rows; adds to *st. */
static rt_status render(const rt_scene *s, const rt_options *o, uint8_t *img,
                        int band, rt_stats *st)
{
    static uint8_t buf[MAXW * 64];
    th_sink k = { img, rt_row_bytes(o) };
    rt_status rc = RT_OK;
    if (!CHECK(rt_buffer_bytes(o) <= sizeof buf))
        return RT_ERR_ARG;
    for (int y = 0; y < o->height && rc == RT_OK; y += band) {
        int y1 = y + band > o->height ? o->height : y + band;
        rc = rt_render_rows(s, o, y, y1, buf, th_to_image, &k, st);
    }
    return rc;
}

static int parse(const char *text, rt_scene *s)
{
    rt_parse_error pe;
    rt_status st = rt_parse(text, strlen(text), s, &pe);
    if (!CHECK(st == RT_OK))
        printf("    line %u col %u: %s\n", (unsigned)pe.line,
               (unsigned)pe.col, pe.msg);
    return st == RT_OK;
}

/* Same bytes in every banding; traced pixels are the full render's. */
static void check_scene(const char *name, const rt_scene *s)
{
    static uint8_t full[TW * TH * 3], a[TW * TH * 3], b[TW * TH * 3];
    static uint8_t c565[TW * TH * 2];
    rt_options o;
    rt_stats st;
    rt_options_from_scene(&o, s);
    o.width = TW;
    o.height = TH;
    CHECK_EQ(render(s, &o, full, TH, NULL), RT_OK);
    o.draft = 64;
    memset(&st, 0, sizeof st);
    CHECK_EQ(render(s, &o, a, TH, &st), RT_OK);
    CHECK_EQ(render(s, &o, b, 7, NULL), RT_OK);
    CHECK(memcmp(a, b, sizeof a) == 0);
    CHECK_EQ(render(s, &o, b, 1, NULL), RT_OK);
    CHECK(memcmp(a, b, sizeof a) == 0);
    long same = 0;
    for (int p = 0; p < TW * TH; p++)
        same += memcmp(a + 3 * p, full + 3 * p, 3) == 0;
    if (!CHECK(same >= TW * TH - (long)st.interpolated))
        printf("    %s: %ld pixels as in the full render, %ld traced\n",
               name, same, TW * TH - (long)st.interpolated);
    if (!CHECK(st.interpolated > 0 && st.interpolated < TW * TH))
        printf("    %s: %llu interpolated\n", name,
               (unsigned long long)st.interpolated);
    o.format = RT_RGB565_LE;
    CHECK_EQ(render(s, &o, c565, TH, NULL), RT_OK);
    int ok565 = 1;
    for (int p = 0; p < TW * TH; p++) {
        unsigned v = (unsigned)c565[2 * p + 1] << 8 | c565[2 * p];
        ok565 &= v == ((unsigned)(a[3 * p] >> 3) << 11 |
                       (unsigned)(a[3 * p + 1] >> 2) << 5 |
                       (unsigned)(a[3 * p + 2] >> 3));
    }
    CHECK(ok565);
    o.format = RT_RGB888;
    /* With adaptive anti-aliasing, and with a 2 x 2 grid. */
    o.spp = 4;
    o.adaptive = 8;
    CHECK_EQ(render(s, &o, a, TH, NULL), RT_OK);
    CHECK_EQ(render(s, &o, b, 5, NULL), RT_OK);
    CHECK(memcmp(a, b, sizeof a) == 0);
    o.adaptive = 0;
    CHECK_EQ(render(s, &o, a, TH, NULL), RT_OK);
    CHECK_EQ(render(s, &o, b, 3, NULL), RT_OK);
    CHECK(memcmp(a, b, sizeof a) == 0);
}

/* Thin features: the scene with them (thin) and without (plain). The
 * light is at the eye, so that no shadow of theirs shows: only the
 * objects themselves tell the two apart. */
#define THIN_HEAD                                                             \
    "image 96 72 spp 1 depth 2\n"                                             \
    "camera eye 0 2 -10 look 0 2 0 up 0 1 0 fov 50\n"                         \
    "background 0.1 0.1 0.25\n"                                               \
    "light 0 2 -10\n"                                                         \
    "material white color 0.95 0.95 0.95\n"                                   \
    "material red color 0.9 0.1 0.1\n"                                        \
    "material floor color 0.4 0.45 0.4 checker 0.3 0.3 0.3 3\n"               \
    "quad corner -30 0 -5 edge1 0 0 60 edge2 60 0 0 material floor\n"
static const char thin_extra[] =
    /* 72 pixels span 9.3 units at 10 units away: 0.13 unit a pixel. Poles
     * about one pixel wide and bars about one pixel high, against the
     * floor and against the sky, and far spheres of about one pixel. */
    "box min -2.06 0 -0.06 max -1.94 5 0.06 material white\n"
    "cylinder base 1.3 0 0 radius 0.07 height 4.5 material white\n"
    "box min -4 1.1 -0.06 max 4 1.22 0.06 material red\n"
    "box min -3 3.9 -0.06 max 3 4.02 0.06 material white\n"
    "sphere center 2.6 4.2 40 radius 0.35 material red\n"
    "sphere center -3.4 0.3 30 radius 0.3 material white\n";

/* 1 if a channel of a and b differs by more than tol. */
static int far_apart(const uint8_t *a, const uint8_t *b, int tol)
{
    for (int k = 0; k < 3; k++)
        if (a[k] - b[k] > tol || b[k] - a[k] > tol)
            return 1;
    return 0;
}

static void check_thin(void)
{
    static rt_scene thin, plain;
    static char text[2048];
    static uint8_t full[MAXW * MAXH * 3], base[MAXW * MAXH * 3];
    static uint8_t dr[MAXW * MAXH * 3];
    static const uint8_t thresholds[] = { 8, 64, 255 };
    snprintf(text, sizeof text, "%s%s", THIN_HEAD, thin_extra);
    if (!parse(text, &thin) || !parse(THIN_HEAD, &plain))
        return;
    rt_options o;
    rt_options_from_scene(&o, &thin);
    CHECK_EQ(render(&thin, &o, full, o.height, NULL), RT_OK);
    CHECK_EQ(render(&plain, &o, base, o.height, NULL), RT_OK);
    const int n = o.width * o.height;
    int shown = 0;
    for (int p = 0; p < n; p++)
        shown += memcmp(full + 3 * p, base + 3 * p, 3) != 0;
    if (!CHECK(shown >= 150 && shown <= 600)) /* about one pixel wide */
        printf("    %d pixels show the thin objects\n", shown);
    for (unsigned t = 0; t < sizeof thresholds; t++) {
        rt_stats st;
        memset(&st, 0, sizeof st);
        o.draft = thresholds[t];
        CHECK_EQ(render(&thin, &o, dr, o.height, &st), RT_OK);
        int lost = 0;
        for (int p = 0; p < n; p++)
            lost += memcmp(full + 3 * p, base + 3 * p, 3) != 0 &&
                    far_apart(dr + 3 * p, full + 3 * p, 8);
        if (!CHECK(lost == 0))
            printf("    draft %u: %d of the %d thin pixels are more than 8 "
                   "levels off the full render\n", thresholds[t], lost,
                   shown);
        /* It is still a draft: much of the floor is interpolated. */
        if (!CHECK(st.interpolated * 4 > (uint64_t)n))
            printf("    draft %u: %llu of %d interpolated\n", thresholds[t],
                   (unsigned long long)st.interpolated, n);
    }
}

int main(void)
{
    static rt_scene scene;
    char *names[256];
    static mesh_obj_ctx meshes;
    char err[256];
    int count = th_scene_names(names, 256);
    CHECK(count >= 2);
    for (int i = 0; i < count; i++) {
        char path[512];
        size_t len;
        snprintf(path, sizeof path, "scenes/%s", names[i]);
        char *text = cli_read_file(path, &len, err, sizeof err);
        rt_parse_error pe;
        /* A scene's meshes are kept until the next scene's. */
        mesh_obj_free(&meshes);
        mesh_obj_init(&meshes, path, stdout, 1);
        if (CHECK(text != NULL) &&
            CHECK(mesh_obj_parse_scene(text, len, path, &scene, &pe,
                                       &meshes) == RT_OK))
            check_scene(names[i], &scene);
        free(text);
        free(names[i]);
    }
    check_thin();

    /* Without draft the buffer is as before; a draft needs more. */
    rt_options o;
    rt_options_from_scene(&o, &scene);
    o.width = 100;
    size_t plain = rt_buffer_bytes(&o);
    CHECK_EQ(plain, rt_row_bytes(&o));
    o.draft = 1;
    CHECK(rt_buffer_bytes(&o) > plain);
    mesh_obj_free(&meshes);
    return th_summary();
}
