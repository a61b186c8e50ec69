/* SPDX-License-Identifier: MIT */
/*
 * api.c: the WebAssembly module's exports (api.h). Everything is static
 * but the meshes (heap.h): one scene, and two images (the fixed-point
 * core's and the double reference's) of at most FT_MAX_PIXELS pixels
 * each. A scene error is worded exactly as the command line words it
 * (port/posix/cli_util.c, cli_print_parse_error): "NAME:LINE:COL: error:
 * MESSAGE", then the line, then a caret under the column.
 */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "api.h"
#include "heap.h"
#include "mesh.h"
#include "ref_render.h"
#include "rt_parse.h"
#include "rt_render.h"

/* The page offers sizes up to 1024 x 768. */
#ifndef FT_MAX_PIXELS
#define FT_MAX_PIXELS (1024 * 768)
#endif
#define FT_MAX_WIDTH 1024
/* Scene text the page can hand over, and the message for an error. */
#define FT_TEXT_BYTES (1u << 20)
#define FT_NAME_BYTES 256
#define FT_MSG_BYTES 1024

static char text[FT_TEXT_BYTES];
static char name[FT_NAME_BYTES];
static char msg[FT_MSG_BYTES];
static rt_scene scene;
static int have_scene;
static size_t files_mark; /* the heap's top above the files */
static rt_options opt[2];   /* [0] the core, [1] the reference */
static rt_stats stats[2];
static uint8_t image[2][FT_MAX_PIXELS * 3];
/* The core's row and scratch (rt_buffer_bytes: 3 + 9 + about 25 bytes a
 * pixel of the widest row, with adaptive and draft both on). */
static uint8_t row_buf[FT_MAX_WIDTH * 48];

/* ---- Messages -------------------------------------------------------------- */

/* The message, appended to (FT_MSG_BYTES at most, always terminated). */
static size_t msg_len;

static void put_c(char c)
{
    if (msg_len + 1 < FT_MSG_BYTES)
        msg[msg_len++] = c;
    msg[msg_len] = '\0';
}

static void put_s(const char *str)
{
    while (*str)
        put_c(*str++);
}

static void put_u(unsigned long v)
{
    char d[24];
    int k = 0;
    do {
        d[k++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    while (k)
        put_c(d[--k]);
}

static void put_i(long v)
{
    if (v < 0) {
        put_c('-');
        put_u(0ul - (unsigned long)v);
    } else {
        put_u((unsigned long)v);
    }
}

/* The command line's message for an option out of its range. */
static int range_error(const char *option, long lo, long hi, long got)
{
    put_s("fixtrace: ");
    put_s(option);
    put_s(" must be from ");
    put_i(lo);
    put_s(" to ");
    put_i(hi);
    put_s(" (got ");
    put_i(got);
    put_s(")");
    return RT_ERR_ARG;
}

static void clear_message(void)
{
    msg_len = 0;
    msg[0] = '\0';
}

void wasm_message_parse_error(const char *file, const char *src, size_t len,
                              const rt_parse_error *e)
{
    put_s(file);
    put_c(':');
    put_u(e->line);
    put_c(':');
    put_u(e->col);
    put_s(": error: ");
    put_s(e->msg);
    put_c('\n');
    if (e->line_off > len)
        return;
    size_t n = e->line_len;
    if (n > len - e->line_off)
        n = len - e->line_off;
    if (n > 200)
        n = 200; /* a binary file can have one enormous line */
    put_s("    ");
    for (size_t k = 0; k < n; k++) {
        unsigned char ch = (unsigned char)src[e->line_off + k];
        put_c(ch == '\t' ? ' ' : (ch < 32 || ch > 126 ? '?' : (char)ch));
    }
    put_s("\n    ");
    for (size_t k = 1; k < e->col && k < 200; k++)
        put_c(' ');
    put_s("^\n");
}

/* ---- Exports --------------------------------------------------------------- */

char *ft_text(void) { return text; }
uint32_t ft_text_capacity(void)
{
    return FT_TEXT_BYTES;
}

char *ft_name(void) { return name; }

const char *ft_message(void) { return msg; }

void ft_reset(void)
{
    have_scene = 0;
    wasm_files_clear();
    wasm_heap_release(0);
    files_mark = 0;
}

int ft_file(uint32_t len)
{
    clear_message();
    name[FT_NAME_BYTES - 1] = '\0';
    if (have_scene || len > FT_TEXT_BYTES ||
        wasm_file_add(name, strlen(name), text, len) != 0) {
        put_s("fixtrace: out of memory");
        return RT_ERR_CAPACITY;
    }
    files_mark = wasm_heap_mark();
    return RT_OK;
}

int ft_parse(uint32_t len)
{
    rt_parse_error e;
    rt_status st;
    have_scene = 0;
    clear_message();
    wasm_heap_release(files_mark); /* the last scene's meshes */
    name[FT_NAME_BYTES - 1] = '\0';
    if (len > FT_TEXT_BYTES)
        len = FT_TEXT_BYTES;
    st = rt_parse_with_meshes(text, len, &scene, &e, wasm_mesh_load, name);
    if (st != RT_OK) {
        wasm_message_parse_error(name, text, len, &e);
        return st;
    }
    have_scene = 1;
    return RT_OK;
}

int ft_scene_width(void) { return scene.width; }
int ft_scene_height(void) { return scene.height; }
int ft_scene_spp(void) { return scene.spp; }
int ft_scene_depth(void) { return scene.depth; }

int ft_begin(int which, int width, int height, int spp, int depth,
             int adaptive, int draft)
{
    clear_message();
    if (!have_scene || which < 0 || which > 1)
        return RT_ERR_ARG;
    if (spp != 0 && spp != 1 && spp != 4 && spp != 9 && spp != 16) {
        put_s("fixtrace: -s must be 1, 4, 9 or 16 (got ");
        put_i(spp);
        put_s(")");
        return RT_ERR_ARG;
    }
    if (depth > RT_MAX_DEPTH)
        return range_error("-d", 0, RT_MAX_DEPTH, depth);
    if (adaptive < 0 || adaptive > 255)
        return range_error("--adaptive", 1, 255, adaptive);
    if (draft < 0 || draft > 255)
        return range_error("--draft", 1, 255, draft);
    rt_options *o = &opt[which];
    rt_options_from_scene(o, &scene);
    if (width > 0)
        o->width = (uint16_t)width;
    if (height > 0)
        o->height = (uint16_t)height;
    if (spp > 0)
        o->spp = (uint8_t)spp;
    if (depth >= 0)
        o->depth = (uint8_t)depth;
    if (which == 0) {
        o->adaptive = (uint8_t)adaptive;
        o->draft = (uint8_t)draft;
    }
    if (o->adaptive && o->spp == 1) {
        put_s("fixtrace: --adaptive needs -s 4, 9 or 16");
        return RT_ERR_ARG;
    }
    if ((uint32_t)o->width * o->height > FT_MAX_PIXELS ||
        o->width > FT_MAX_WIDTH || rt_buffer_bytes(o) > sizeof row_buf) {
        put_s("the page renders at most 1024 x 768 pixels");
        return RT_ERR_ARG;
    }
    stats[which] = (rt_stats){0};
    return RT_OK;
}

static int take_row(void *ctx, int y, const uint8_t *row, size_t n)
{
    uint8_t *img = ctx;
    memcpy(img + (size_t)y * n, row, n);
    return 0;
}

int ft_rows(int which, int y0, int y1)
{
    if (!have_scene || which < 0 || which > 1)
        return RT_ERR_ARG;
    if (which == 0)
        return rt_render_rows(&scene, &opt[0], y0, y1, row_buf, take_row,
                              image[0], &stats[0]);
    /* The reference builds its mesh boxes for each call and frees them. */
    const size_t mark = wasm_heap_mark();
    const int st = ref_render_rows(&scene, &opt[1], y0, y1, row_buf,
                                   take_row, image[1], &stats[1]);
    wasm_heap_release(mark);
    return st;
}

uint8_t *ft_image(int which)
{
    return image[which ? 1 : 0];
}
int ft_width(int which) { return opt[which ? 1 : 0].width; }
int ft_height(int which)
{
    return opt[which ? 1 : 0].height;
}

double ft_stat(int which, int k)
{
    const rt_stats *st = &stats[which ? 1 : 0];
    const uint64_t v[7] = {st->primary, st->shadow, st->reflection,
                           st->refraction, st->tests, st->cut,
                           st->interpolated};
    return k >= 0 && k < 7 ? (double)v[k] : -1.0;
}
