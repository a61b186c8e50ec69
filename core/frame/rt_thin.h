/* SPDX-License-Identifier: MIT */
/*
 * rt_thin: what a draft render (rt_draft.h) needs to keep thin objects
 * and small far ones that fall between its lattice pixels: which objects
 * could be seen between neighbours that agree, in front of them. All the
 * shapes are convex, so rays between rays that hit one object hit it
 * too, no farther than the farthest of those hits; only an object between
 * the eye and those hits can hide there. One whose bounding sphere lies
 * farther away cannot, nor a quad whose plane all of them lie in front
 * of; for the rest, the pixel's centre ray is tested against the object
 * alone. Internal.
 */
#ifndef RT_THIN_H
#define RT_THIN_H

#include "rt_antialias.h"

/* Quads whose planes a draft render tracks (more are always tested). */
#define RT_THIN_QUADS 16

/* Per-render tables. */
typedef struct {
    /* Per object: no camera ray meets its bounding sphere nearer than
     * near (0 when unknown); quads: its bit in the front bits
     * (RT_THIN_QUADS for none). */
    fx_t near[RT_MAX_OBJECTS];
    uint8_t quad_bit[RT_MAX_OBJECTS];
    uint16_t quad_obj[RT_THIN_QUADS];
    fx_t quad_d0[RT_THIN_QUADS]; /* n . (eye - a): the eye's side */
    unsigned n_quads;
} rt_thin;

/* The camera ray at screen offset k along the sample row of base. */
static inline void rt_thin_ray(const rt_scene *s, const rt_cam_frame *cf,
                               const rt_cam_ray *base, int32_t k, rt_ray *r)
{
    rt_ray_set(r, s->cam.eye, rt_cam_dir(cf, base, rt_cam_soff(cf, k)));
}

/* Sets up *t for scene s. */
void rt_thin_init(rt_thin *t, const rt_scene *s);

/* Drops from rs (pixel row y, set up by rt_aa_row_setup with cf) the
 * quads no ray of the row can hit: its corners lie on one side of each
 * sample row's plane. Tracing gives the same colours without them; they
 * would only cost tests and, here, rays. */
void rt_thin_row(rt_aa_spans *rs, const rt_scene *s, const rt_cam_frame *cf,
                 unsigned height, unsigned y);

/* The front bits of camera ray r with its nearest hit at t (FX_MAX: a
 * miss): bit q set if the ray does not reach tracked quad q's plane
 * before t. */
uint16_t rt_thin_front(const rt_thin *t, const rt_scene *s, const rt_ray *r,
                       fx_t tmax);

/* 1 if the centre ray of pixel x (of the row of rs; made into *r once,
 * *have_ray then 1) hits object i nearer than tmax, or with more samples
 * than one per pixel, always. */
int rt_thin_hit(const rt_thin *t, const rt_tracer *tr, rt_work *wk,
                const rt_cam_frame *cf, const rt_aa_spans *rs, unsigned width,
                unsigned x, unsigned i, fx_t tmax, rt_ray *r, int *have_ray);

/* 1 if at column x of the row of rs an object other than obj may be seen
 * in front of neighbours that hit obj at most tmax away, all in front of
 * the quads of the bits front (rt_thin_hit decides). Inline: it runs for
 * most pixels of a draft. */
static inline int rt_thin_may_hide(const rt_thin *t, const rt_tracer *tr,
                                   rt_work *wk, const rt_cam_frame *cf,
                                   const rt_aa_spans *rs, unsigned width,
                                   unsigned x, unsigned obj, fx_t tmax,
                                   unsigned front, rt_ray *r, int *have_ray)
{
    for (unsigned k = 0; k < rs->hit.count; k++) {
        const rt_span *sp = &rs->hit.span[k];
        const unsigned i = sp->obj, q = t->quad_bit[i];
        if (x < (unsigned)sp->x0 || x > (unsigned)sp->x1 || i == obj)
            continue;
        if (q < RT_THIN_QUADS ? ((front >> q) & 1u) : t->near[i] > tmax)
            continue; /* it cannot be in front */
        if (rt_thin_hit(t, tr, wk, cf, rs, width, x, i, tmax, r, have_ray))
            return 1;
    }
    return 0;
}

#endif /* RT_THIN_H */
