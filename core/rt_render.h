/* SPDX-License-Identifier: MIT */
/*
 * rt_render: the core's one boundary to a platform. The caller owns the
 * scene, a row buffer of rt_row_bytes() bytes and a callback; the renderer
 * fills one scanline at a time and hands it over. There is no frame buffer.
 */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include <stddef.h>
#include "rt_scene.h"

/* Pixel layout of the rows handed to the callback. */
typedef enum {
    RT_RGB888 = 0,  /* 3 bytes per pixel: R, G, B */
    RT_RGB565_LE,   /* 2 bytes per pixel, little-endian 5:6:5 */
    RT_RGB565_BE    /* 2 bytes per pixel, big-endian (byte-swapped) 5:6:5 */
} rt_format;

typedef struct {
    uint16_t width, height; /* 1..RT_MAX_WIDTH, 1..RT_MAX_HEIGHT */
    uint8_t spp;            /* 1, 4, 9 or 16 (n*n grid) */
    uint8_t depth;          /* recursion depth, 0..RT_MAX_DEPTH */
    uint8_t format;         /* rt_format */
    uint8_t dither;         /* RGB565 only: 1 = ordered 4x4 dither */
    uint8_t adaptive;       /* 0: every pixel gets spp samples. 1..255:
                               adaptive anti-aliasing, only pixels whose
                               3x3 neighbourhood of centre samples differs
                               by more than this many 8-bit levels get the
                               spp grid; the rest keep their centre sample */
    uint8_t trace_all;      /* 0: skip reflected and refracted rays too
                               faint to move a pixel by half an 8-bit
                               level divided by spp, all of them together
                               (see docs/render-model.md). 1: trace every
                               ray to `depth` */
    uint8_t draft;          /* 0: every pixel is traced. 1..255: a draft
                               render (adaptive undersampling, rt_draft.h):
                               a coarse lattice of pixels is traced, and a
                               pixel between only where its neighbours
                               hit other objects or texture cells, differ
                               in shadow or by more than this many 8-bit
                               levels, or may hide a thin object; the rest
                               is their mean (docs/effects.md) */
} rt_options;

/* Ray and test counters. The renderer adds to them and never resets them,
 * so a caller can sum several calls; zero them before the first. */
typedef struct {
    uint64_t primary;    /* camera rays */
    uint64_t shadow;     /* shadow rays */
    uint64_t reflection; /* reflection rays, including total internal */
    uint64_t refraction; /* transmitted rays */
    uint64_t tests;      /* ray-object intersection tests */
    uint64_t cut;        /* reflected and refracted rays left untraced as
                            too faint (rt_options.trace_all) */
    uint64_t interpolated; /* pixels whose colour is the mean of traced
                              neighbours, without a ray of their own
                              (rt_options.draft); the rest were traced */
} rt_stats;

/* Receives finished row y. `row` holds rt_row_bytes() bytes and belongs to
 * the caller that passed it to rt_render_rows(); it is valid only until the
 * callback returns. Return 0 to go on, non-zero to stop the render. */
typedef int (*rt_row_fn)(void *ctx, int y, const uint8_t *row, size_t nbytes);

/* Fills *o from the scene's defaults (size, spp, depth), RGB888. */
void rt_options_from_scene(rt_options *o, const rt_scene *s);

/* Bytes in one row handed to the callback (width * 3 or width * 2). */
size_t rt_row_bytes(const rt_options *o);

/* Bytes the caller's row buffer must hold: rt_row_bytes(), plus 9 * width
 * of scratch when adaptive anti-aliasing is on, plus about 25 * width for
 * a draft render (its lattice rows). */
size_t rt_buffer_bytes(const rt_options *o);

/* Renders rows y0 <= y < y1 (top row is 0) into row_buf (rt_buffer_bytes()
 * bytes), calling fn after each. Rows are independent: any split into
 * bands gives the same bytes.
 * stats may be NULL. Returns RT_OK, RT_ERR_ARG for bad options or rows, or
 * for a scene outside the parser's ranges (colours in [0, 1], light and
 * ambient colours in [0, 16], coefficients in [0, 1], reflect +
 * transparency <= 1, shininess 1..1024, valid indices),
 * RT_ERR_UNSUPPORTED when the scene needs an effect this build removed, or
 * RT_ERR_ABORTED when fn returned non-zero. */
rt_status rt_render_rows(const rt_scene *s, const rt_options *o, int y0,
                         int y1, uint8_t *row_buf, rt_row_fn fn, void *ctx,
                         rt_stats *stats);

/* Effects the scene needs at spp samples per pixel, as RT_FEAT_* bits
 * (rt_features.h); spp > 1 adds RT_FEAT_SUPERSAMPLING. */
uint32_t rt_scene_features(const rt_scene *s, uint8_t spp);

/* RT_FEAT_* bits this build can render (all, less the RT_NO_* removals). */
uint32_t rt_build_features(void);

/* Short names of feature bits, for messages: "reflection", "box", ... */
const char *rt_feature_name(uint32_t bit);

#endif /* RT_RENDER_H */
