/* SPDX-License-Identifier: MIT */
/*
 * Sets of rows (rt_render_row_set): for every scene in scenes/, at an odd
 * size, in five modes (1 and 4 spp, adaptive anti-aliasing, a draft, and
 * dithered RGB565), rows named in any order give exactly the bytes of the
 * same rows of a full render: bottom to top, every third row, and the
 * frame split between two calls, each with its own buffer, in pairs of
 * rows. A row outside the frame or no row source is
 * refused before any row, and a callback's stop ends the call.
 */
#include <stdlib.h>
#include <string.h>

#include "cli_util.h"
#include "harness.h"
#include "mesh_obj.h"
#include "rt_render.h"

#define TW 29
#define TH 19

/* The rows to hand out, in order, and the full render they must match. */
typedef struct {
    const int *order;
    int n, next;
    const uint8_t *full;
    size_t row_bytes;
    int rows, bad;
} row_src;

static int next_row(void *ctx)
{
    row_src *r = ctx;
    return r->next < r->n ? r->order[r->next++] : -1;
}

static int check_row(void *ctx, int y, const uint8_t *row, size_t n)
{
    row_src *r = ctx;
    if (n != r->row_bytes ||
        memcmp(row, r->full + (size_t)y * r->row_bytes, n) != 0)
        r->bad++;
    r->rows++;
    return 0;
}

static int to_image(void *ctx, int y, const uint8_t *row, size_t n)
{
    memcpy((uint8_t *)ctx + (size_t)y * n, row, n);
    return 0;
}

static int stop_now(void *ctx, int y, const uint8_t *row, size_t n)
{
    (void)ctx, (void)y, (void)row, (void)n;
    return 1;
}

/* Renders the rows of `order` with one call and checks each. */
static void check_order(const char *what, const rt_scene *s,
                        const rt_options *o, const uint8_t *full,
                        const int *order, int n)
{
    uint8_t *buf = malloc(rt_buffer_bytes(o));
    row_src r = { order, n, 0, full, rt_row_bytes(o), 0, 0 };
    if (!CHECK(buf != NULL))
        return;
    rt_status st = rt_render_row_set(s, o, next_row, buf, check_row, &r,
                                     NULL);
    if (!CHECK(st == RT_OK && r.rows == n && r.bad == 0))
        printf("    %s: status %d, %d of %d rows, %d differ\n", what,
               (int)st, r.rows, n, r.bad);
    free(buf);
}

/* The frame split between two calls, each with a buffer of its own, in
 * pairs of rows (0, 1, 4, 5, ... and 2, 3, 6, 7, ...), as two cores
 * would share it. */
static void check_two(const char *what, const rt_scene *s,
                      const rt_options *o, const uint8_t *full)
{
    int even[TH], odd[TH], ne = 0, no = 0;
    for (int y = 0; y < TH; y++) {
        if ((y / 2) % 2 == 0)
            even[ne++] = y;
        else
            odd[no++] = y;
    }
    check_order(what, s, o, full, even, ne);
    check_order(what, s, o, full, odd, no);
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
        { "adaptive", 4, 8, 0, RT_RGB888, 0 },
        { "draft", 1, 0, 32, RT_RGB888, 0 },
        { "4spp-565le-dither", 4, 0, 0, RT_RGB565_LE, 1 },
    };
    int reverse[TH], thirds[TH], n3 = 0;
    for (int y = 0; y < TH; y++)
        reverse[y] = TH - 1 - y;
    for (int k = 0; k < 3; k++)
        for (int y = k; y < TH; y += 3)
            thirds[n3++] = y;
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        rt_options o;
        char what[128];
        rt_options_from_scene(&o, s);
        o.width = TW;
        o.height = TH;
        o.spp = modes[m].spp;
        o.adaptive = modes[m].adaptive;
        o.draft = modes[m].draft;
        o.format = modes[m].format;
        o.dither = modes[m].dither;
        uint8_t *buf = malloc(rt_buffer_bytes(&o));
        if (!CHECK(buf != NULL))
            return;
        CHECK_EQ(rt_render_rows(s, &o, 0, TH, buf, to_image, full, NULL),
                 RT_OK);
        free(buf);
        snprintf(what, sizeof what, "%s %s reverse", name, modes[m].name);
        check_order(what, s, &o, full, reverse, TH);
        snprintf(what, sizeof what, "%s %s thirds", name, modes[m].name);
        check_order(what, s, &o, full, thirds, n3);
        snprintf(what, sizeof what, "%s %s two", name, modes[m].name);
        check_two(what, s, &o, full);
    }
}

/* Refusals: a row past the frame and no row source; and a stop from the
 * callback. */
static void check_refusals(const rt_scene *s)
{
    static uint8_t full[TW * TH * 3];
    rt_options o;
    rt_options_from_scene(&o, s);
    o.width = TW;
    o.height = TH;
    uint8_t *buf = malloc(rt_buffer_bytes(&o));
    if (!CHECK(buf != NULL))
        return;
    static const int past[] = { TH };
    row_src r = { past, 1, 0, full, rt_row_bytes(&o), 0, 0 };
    CHECK_EQ(rt_render_row_set(s, &o, next_row, buf, check_row, &r, NULL),
             RT_ERR_ARG);
    CHECK_EQ(r.rows, 0);
    CHECK_EQ(rt_render_row_set(s, &o, NULL, buf, check_row, &r, NULL),
             RT_ERR_ARG);
    static const int two[] = { 3, 4 };
    row_src t = { two, 2, 0, full, rt_row_bytes(&o), 0, 0 };
    CHECK_EQ(rt_render_row_set(s, &o, next_row, buf, stop_now, &t, NULL),
             RT_ERR_ABORTED);
    CHECK_EQ(t.next, 1); /* stopped after the first row */
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
                check_refusals(&scene);
        }
        free(text);
        free(names[i]);
    }
    mesh_obj_free(&meshes);
    return th_summary();
}
