/* SPDX-License-Identifier: MIT */
/*
 * libFuzzer harness for the scene parser and, through it, the renderers.
 *
 * Every input goes to rt_parse() and rt_parse_fx(). The parser's promises
 * are checked on the way: the error position lies inside the input and the
 * message is terminated; a scene it accepts stays inside its capacities and
 * only names materials it has. Each accepted scene is then rendered at a
 * tiny size by the core (rt_render_rows; a row alone and a window of it,
 * rt_render_window, must give the same bytes) and by the double reference
 * (ref_render_rows), so both are fuzzed on whatever the parser lets
 * through. The render size, samples and depth are cut down until one input
 * costs a bounded number of ray-object tests, so a run stays fast under
 * ASan. A broken promise calls abort(), which libFuzzer reports as a crash
 * with the input saved.
 *
 * Build and run: make fuzz (mk/fuzz.mk). Repeat inputs:
 * build/fuzz/fuzz_scene FILE... (FUZZ_SCENE_VERBOSE=1 shows each parse).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rt_parse.h"
#include "rt_render.h"
#include "ref_render.h"

/* Upper bound on the ray-object tests one render may cost (estimated). */
#define FUZZ_TEST_BUDGET 60000u

/* The largest image the harness renders. */
#define FUZZ_W 6
#define FUZZ_H 4

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static rt_scene scene;

/* FUZZ_SCENE_VERBOSE set: say what the parser made of each input. */
static int verbose = -1;

/* Stops with a message naming the broken promise. */
static void require(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_scene: broken promise: %s\n", what);
        abort();
    }
}

/* The parser's error report describes a place inside the input. */
static void check_error(const rt_parse_error *e, size_t size, rt_status st)
{
    require(st == RT_ERR_PARSE || st == RT_ERR_CAPACITY ||
                st == RT_ERR_DEGENERATE || st == RT_ERR_UNSUPPORTED,
            "rt_parse returns OK, PARSE, CAPACITY, DEGENERATE or "
            "UNSUPPORTED (a mesh)");
    require(memchr(e->msg, '\0', sizeof e->msg) != NULL,
            "error message is NUL-terminated");
    require(e->msg[0] != '\0', "error message is not empty");
    require(e->line >= 1 && e->col >= 1, "error line and col are 1-based");
    require(e->line_off <= size && e->line_len <= size - e->line_off,
            "error line lies inside the input");
    require(e->col - 1u <= e->line_len, "error column lies on its line");
    require(e->tok_len <= e->line_len - (e->col - 1u),
            "error token lies on its line");
    for (const char *m = e->msg; *m; m++)
        require(*m >= 0x20 && *m < 0x7f, "error message is plain ASCII");
}

/* An accepted scene stays inside its capacities and documented ranges. */
static void check_scene(const rt_scene *s)
{
    require(s->n_objects <= RT_MAX_OBJECTS, "n_objects <= RT_MAX_OBJECTS");
    require(s->n_lights <= RT_MAX_LIGHTS, "n_lights <= RT_MAX_LIGHTS");
    require(s->n_materials <= RT_MAX_MATERIALS,
            "n_materials <= RT_MAX_MATERIALS");
    require(s->width >= 1 && s->width <= RT_MAX_WIDTH && s->height >= 1 &&
                s->height <= RT_MAX_HEIGHT,
            "image size in range");
    require(s->depth <= RT_MAX_DEPTH, "depth <= RT_MAX_DEPTH");
    require(s->spp == 1 || s->spp == 4 || s->spp == 9 || s->spp == 16,
            "spp is a square");
    require(s->cam.fov > 0 && s->cam.fov < FX_INT(180), "fov in (0, 180)");
    for (unsigned i = 0; i < s->n_objects; i++) {
        require(s->obj[i].kind < RT_KIND_COUNT, "object kind valid");
        require(s->obj[i].material < s->n_materials,
                "object material defined");
    }
    for (unsigned i = 0; i < s->n_materials; i++) {
        const rt_material *m = &s->mat[i];
        require(m->shininess >= 1 && m->shininess <= 1024,
                "shininess in 1..1024");
        require(m->reflect >= 0 && m->transparency >= 0 &&
                    (int64_t)m->reflect + m->transparency <= FX_ONE,
                "reflect + transparency in [0, 1]");
        require(m->texture <= RT_TEX_CHECKER3D && m->axis <= 2,
                "texture kind and axis valid");
    }
}

typedef struct {
    int height;
    size_t nbytes;
    int rows;
    uint8_t last[FUZZ_W * 3]; /* the bottom row, as first rendered */
    size_t win_off, win_bytes; /* a window's part of it */
} row_sink;

static int take_row(void *ctx, int y, const uint8_t *row, size_t nbytes)
{
    row_sink *k = ctx;
    require(y >= 0 && y < k->height, "callback row in range");
    require(nbytes == k->nbytes, "callback gets rt_row_bytes()");
    if (y == k->height - 1)
        memcpy(k->last, row, nbytes);
    k->rows++;
    return 0;
}

/* A window of the bottom row: the same bytes as that part of it. */
static int compare_window(void *ctx, int y, const uint8_t *row,
                          size_t nbytes)
{
    const row_sink *k = ctx;
    require(y == k->height - 1 && nbytes == k->win_bytes,
            "a window's row is its width");
    require(memcmp(k->last + k->win_off, row, nbytes) == 0,
            "a window equals the same pixels of the full frame");
    return 0;
}

static int compare_row(void *ctx, int y, const uint8_t *row, size_t nbytes)
{
    const row_sink *k = ctx;
    require(y == k->height - 1 && nbytes == k->nbytes, "band is one row");
    require(memcmp(k->last, row, nbytes) == 0,
            "a row rendered alone equals the same row in the full frame");
    return 0;
}

/* Estimated ray-object tests: each traced ray tests every object, and each
 * hit sends one shadow ray per light; every level of recursion may trace a
 * reflected and a transmitted ray. Adaptive sampling adds a centre sample
 * to the grid. */
static uint64_t cost(const rt_options *o, const rt_scene *s)
{
    uint64_t samples = o->spp + (o->adaptive && o->spp > 1 ? 1u : 0u);
    uint64_t rays = (uint64_t)o->width * o->height * samples *
                    ((2u << o->depth) - 1u);
    return rays * ((uint64_t)s->n_objects + 1u) * (s->n_lights + 1u);
}

/* Options from the scene's own, cut down to the harness's budget. The
 * format, dither and adaptive threshold come from the input's length, so
 * every layout and both sampling modes are exercised and a saved input
 * repeats exactly. */
static void pick_options(rt_options *o, const rt_scene *s, size_t size)
{
    rt_options_from_scene(o, s);
    o->width = o->width < FUZZ_W ? o->width : FUZZ_W;
    o->height = o->height < FUZZ_H ? o->height : FUZZ_H;
    o->depth = o->depth < 3 ? o->depth : 3;
    o->spp = o->spp < 4 ? o->spp : 4;
    o->format = (uint8_t)(size % 3u);
    o->dither = (uint8_t)((size / 3u) & 1u);
    o->adaptive = (size / 6u) & 1u ? (uint8_t)(1u + (size / 12u) % 64u) : 0;
    while (cost(o, s) > FUZZ_TEST_BUDGET) {
        if (o->spp > 1)
            o->spp = 1;
        else if (o->depth > 0)
            o->depth--;
        else if (o->width > 1)
            o->width = (uint16_t)(o->width / 2u);
        else if (o->height > 1)
            o->height = (uint16_t)(o->height / 2u);
        else
            break; /* 1x1, depth 0: bounded by the capacities */
    }
}

static void render(const rt_scene *s, size_t size)
{
    rt_options o;
    rt_stats st;
    row_sink k;
    pick_options(&o, s, size);
    memset(&k, 0, sizeof k);
    k.height = o.height;
    k.nbytes = rt_row_bytes(&o);
    require(k.nbytes <= sizeof k.last, "row fits the harness's copy");
    require(rt_buffer_bytes(&o) >= k.nbytes, "buffer holds a row");
    /* Exactly rt_buffer_bytes(): ASan sees any access past it. */
    uint8_t *row = malloc(rt_buffer_bytes(&o));
    require(row != NULL, "malloc");
    memset(&st, 0, sizeof st);

    rt_status rs = rt_render_rows(s, &o, 0, o.height, row, take_row, &k, &st);
    require(rs == RT_OK, "rt_render_rows renders an accepted scene");
    require(k.rows == o.height, "one callback per row");
    require(o.adaptive ? st.primary >= (uint64_t)o.width * o.height
                       : st.primary == (uint64_t)o.width * o.height * o.spp,
            "one primary ray per sample");

    /* Rows are independent: the bottom row alone gives the same bytes. */
    rs = rt_render_rows(s, &o, o.height - 1, o.height, row, compare_row, &k,
                        NULL);
    require(rs == RT_OK, "rt_render_rows renders one band");

    /* So do the same pixels of a window, in a buffer of exactly
     * rt_window_bytes(). */
    const int x0 = (int)(size % o.width);
    const int x1 = x0 + 1 + (int)((size / 7u) % (o.width - (unsigned)x0));
    const size_t bpp = k.nbytes / o.width;
    uint8_t *win = malloc(rt_window_bytes(&o, (unsigned)(x1 - x0)));
    require(win != NULL, "malloc");
    k.win_off = (size_t)x0 * bpp;
    k.win_bytes = (size_t)(x1 - x0) * bpp;
    rs = rt_render_window(s, &o, x0, o.height - 1, x1, o.height, win,
                          compare_window, &k, NULL);
    require(rs == RT_OK, "rt_render_window renders a window");
    free(win);

    k.rows = 0;
    rs = ref_render_rows(s, &o, 0, o.height, row, take_row, &k, NULL);
    require(rs == RT_OK, "ref_render_rows renders an accepted scene");
    require(k.rows == o.height, "reference: one callback per row");
    free(row);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* A copy of exactly the input's length: ASan sees any overread. */
    char *text = malloc(size ? size : 1);
    rt_parse_error e;
    fx_t v;
    size_t used = 12345;

    require(text != NULL, "malloc");
    if (size)
        memcpy(text, data, size);

    rt_status ns = rt_parse_fx(text, size, &v, &used);
    require(used <= size, "rt_parse_fx uses at most the input");
    require(ns == RT_OK || ns == RT_ERR_PARSE, "rt_parse_fx status");
    require(ns != RT_OK || used > 0, "a number uses at least one byte");

    rt_status st = rt_parse(text, size, &scene, &e);
    if (verbose < 0)
        verbose = getenv("FUZZ_SCENE_VERBOSE") != NULL;
    if (verbose && st == RT_OK)
        fprintf(stderr, "fuzz_scene: parsed: %u objects, %u lights\n",
                (unsigned)scene.n_objects, (unsigned)scene.n_lights);
    else if (verbose)
        fprintf(stderr, "fuzz_scene: status %d at %u:%u: %s\n", (int)st,
                (unsigned)e.line, (unsigned)e.col, e.msg);
    if (st == RT_OK) {
        check_scene(&scene);
        render(&scene, size);
    } else {
        check_error(&e, size, st);
    }
    free(text);
    return 0;
}
