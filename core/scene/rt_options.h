/* SPDX-License-Identifier: MIT */
/*
 * rt_options: what a render is asked for (size, samples, depth, pixel
 * format, the faint-ray and draft settings), the counters it returns, and
 * the effects a scene needs against those a build can draw. rt_render.h,
 * the boundary to a platform, takes these; the tracer reads them too.
 */
#ifndef RT_OPTIONS_H
#define RT_OPTIONS_H

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

/* Effects the scene needs at spp samples per pixel, as RT_FEAT_* bits
 * (rt_features.h); spp > 1 adds RT_FEAT_SUPERSAMPLING. */
uint32_t rt_scene_features(const rt_scene *s, uint8_t spp);

/* RT_FEAT_* bits this build can render (all, less the RT_NO_* removals). */
uint32_t rt_build_features(void);

/* Short names of feature bits, for messages: "reflection", "box", ... */
const char *rt_feature_name(uint32_t bit);

#endif /* RT_OPTIONS_H */
