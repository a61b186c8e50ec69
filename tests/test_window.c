/* SPDX-License-Identifier: MIT */
/*
 * Windows of the frame (rt_render_window): for every scene in scenes/, at
 * an odd size, in seven modes (1, 4 and 9 spp, adaptive anti-aliasing,
 * drafts, both together, dithered RGB565 in either byte order), windows
 * of every kind (the whole frame, single pixels at the corners and
 * inside, one-column and one-row strips along each edge, rectangles
 * touching each edge, and seeded random ones) give exactly the bytes of
 * the same pixels of a full render. The buffer is rt_window_bytes() and
 * nothing past it is written; rows come in order with the window's byte
 * count; its size does not grow with the frame's width; bad windows are
 * refused.
 */
#include <stdlib.h>
#include <string.h>

#include "cli_util.h"
#include "harness.h"
#include "mesh_obj.h"
#include "rt_render.h"

#define TW 53
#define TH 37
#define GUARD 64

/* The rows of a window, checked against a full render as they come. */
typedef struct {
    const uint8_t *full; /* the full render, TW pixels a row */
    size_t bpp;
    int x0, x1, next_y, bad_rows, bad_bytes;
} window_sink;

static int check_row(void *ctx, int y, const uint8_t *row, size_t n)
{
    window_sink *k = ctx;
    const size_t want = (size_t)(k->x1 - k->x0) * k->bpp;
    if (y != k->next_y || n != want)
        k->bad_rows++;
    else if (memcmp(row, k->full + ((size_t)y * TW + (size_t)k->x0) * k->bpp,
                    n) != 0)
        k->bad_bytes++;
    k->next_y = y + 1;
    return 0;
}

static int stop_now(void *ctx, int y, const uint8_t *row, size_t n)
{
    (void)ctx;
    (void)y;
    (void)row;
    (void)n;
    return 1;
}

/* Renders window (x0, y0)-(x1, y1) into a buffer of exactly
 * rt_window_bytes() and a guard, and compares it with full. */
static void check_window(const char *name, const char *mode,
                         const rt_scene *s, const rt_options *o,
                         const uint8_t *full, int x0, int y0, int x1, int y1)
{
    const size_t nb = rt_window_bytes(o, (unsigned)(x1 - x0));
    uint8_t *buf = malloc(nb + GUARD);
    if (!CHECK(buf != NULL))
        return;
    memset(buf + nb, 0xA5, GUARD);
    window_sink k = { full, o->format == RT_RGB888 ? 3u : 2u, x0, x1, y0,
                      0, 0 };
    rt_status st = rt_render_window(s, o, x0, y0, x1, y1, buf, check_row, &k,
                                    NULL);
    int guard_ok = 1;
    for (size_t i = 0; i < GUARD; i++)
        guard_ok &= buf[nb + i] == 0xA5;
    if (!CHECK(st == RT_OK && k.bad_rows == 0 && k.bad_bytes == 0 &&
               k.next_y == y1 && guard_ok))
        printf("    %s %s window %d,%d-%d,%d: status %d, %d rows out of "
               "order, %d differ, guard %s\n",
               name, mode, x0, y0, x1, y1, (int)st, k.bad_rows, k.bad_bytes,
               guard_ok ? "kept" : "overwritten");
    free(buf);
}

static void check_scene(const char *name, const rt_scene *s)
{
    static uint8_t full[TW * TH * 3];
    static const struct {
        const char *name;
        uint8_t spp, adaptive, draft, format, dither;
    } modes[] = {
        { "1spp", 1, 0, 0, RT_RGB888, 0 },
        { "4spp", 4, 0, 0, RT_RGB888, 0 },
        { "9spp-565be-dither", 9, 0, 0, RT_RGB565_BE, 1 },
        { "adaptive", 4, 8, 0, RT_RGB888, 0 },
        { "draft", 1, 0, 32, RT_RGB888, 0 },
        { "adaptive-draft", 4, 8, 32, RT_RGB888, 0 },
        { "draft-565le-dither", 1, 0, 16, RT_RGB565_LE, 1 },
    };
    /* x0, y0, x1, y1; negative numbers count from the far edge. */
    static const int wins[][4] = {
        { 0, 0, TW, TH },        { 0, 0, 1, 1 },
        { TW - 1, TH - 1, TW, TH }, { TW - 1, 0, TW, 1 },
        { 0, TH - 1, 1, TH },    { 26, 18, 27, 19 },
        { 0, 0, 1, TH },         { TW - 1, 0, TW, TH },
        { 0, 0, TW, 1 },         { 0, TH - 1, TW, TH },
        { 0, 5, 7, 20 },         { TW - 7, TH - 9, TW, TH },
        { 3, 0, 12, 5 },         { 17, 9, 36, 28 },
        { 1, 1, TW - 1, TH - 1 }, { 5, 2, 6, TH },
    };
    uint64_t seed = 0x9E3779B97F4A7C15ull;
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        rt_options o;
        rt_options_from_scene(&o, s);
        o.width = TW;
        o.height = TH;
        o.spp = modes[m].spp;
        o.adaptive = modes[m].adaptive;
        o.draft = modes[m].draft;
        o.format = modes[m].format;
        o.dither = modes[m].dither;
        uint8_t *buf = malloc(rt_buffer_bytes(&o));
        th_sink sink = { full, rt_row_bytes(&o) };
        CHECK(buf != NULL);
        CHECK_EQ(rt_render_rows(s, &o, 0, TH, buf, th_to_image, &sink, NULL),
                 RT_OK);
        free(buf);
        for (size_t w = 0; w < sizeof wins / sizeof wins[0]; w++)
            check_window(name, modes[m].name, s, &o, full, wins[w][0],
                         wins[w][1], wins[w][2], wins[w][3]);
        for (int r = 0; r < 4; r++) {
            int x0 = (int)(th_rnd64(&seed) % TW);
            int y0 = (int)(th_rnd64(&seed) % TH);
            int x1 = x0 + 1 + (int)(th_rnd64(&seed) % (uint64_t)(TW - x0));
            int y1 = y0 + 1 + (int)(th_rnd64(&seed) % (uint64_t)(TH - y0));
            check_window(name, modes[m].name, s, &o, full, x0, y0, x1, y1);
        }
    }
}

/* The buffer of a window depends on its width, not the frame's; for the
 * whole width it is rt_buffer_bytes(); bad windows are refused. */
static void check_sizes(const rt_scene *s)
{
    static const uint8_t modes[][3] = {
        /* spp, adaptive, draft */
        { 1, 0, 0 }, { 4, 8, 0 }, { 1, 0, 16 }, { 4, 8, 16 }
    };
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        rt_options o;
        rt_options_from_scene(&o, s);
        o.spp = modes[m][0];
        o.adaptive = modes[m][1];
        o.draft = modes[m][2];
        o.width = 320;
        const size_t narrow = rt_window_bytes(&o, 16);
        CHECK_EQ(rt_window_bytes(&o, o.width), rt_buffer_bytes(&o));
        CHECK(narrow < rt_buffer_bytes(&o) / 10);
        o.width = 1024;
        CHECK_EQ(rt_window_bytes(&o, 16), narrow);
        /* Under 40 bytes a column and 400 bytes, however wide the frame. */
        CHECK(narrow <= 16 * 40 + 400);
    }
    rt_options o;
    rt_options_from_scene(&o, s);
    o.width = TW;
    o.height = TH;
    uint8_t *buf = malloc(rt_buffer_bytes(&o));
    window_sink k = { 0, 3, 0, 0, 0, 0, 0 };
    CHECK_EQ(rt_render_window(s, &o, 4, 0, 4, 1, buf, check_row, &k, NULL),
             RT_ERR_ARG);
    CHECK_EQ(rt_render_window(s, &o, 5, 0, 4, 1, buf, check_row, &k, NULL),
             RT_ERR_ARG);
    CHECK_EQ(rt_render_window(s, &o, -1, 0, 4, 1, buf, check_row, &k, NULL),
             RT_ERR_ARG);
    CHECK_EQ(rt_render_window(s, &o, 0, 0, TW + 1, 1, buf, check_row, &k,
                              NULL),
             RT_ERR_ARG);
    CHECK_EQ(rt_render_window(s, &o, 0, 2, 4, 1, buf, check_row, &k, NULL),
             RT_ERR_ARG);
    CHECK_EQ(rt_render_window(s, &o, 0, 0, 4, TH + 1, buf, check_row, &k,
                              NULL),
             RT_ERR_ARG);
    CHECK_EQ(k.next_y, 0); /* refused before any row */
    CHECK_EQ(rt_render_window(s, &o, 3, 2, 9, 5, buf, stop_now, 0, NULL),
             RT_ERR_ABORTED);
    free(buf);
}

int main(void)
{
    static rt_scene scene;
    static mesh_obj_ctx meshes;
    char *names[256];
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
                                       &meshes) == RT_OK)) {
            check_scene(names[i], &scene);
            if (i == 0)
                check_sizes(&scene);
        }
        free(text);
        free(names[i]);
    }
    mesh_obj_free(&meshes);
    return th_summary();
}
