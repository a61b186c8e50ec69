/* SPDX-License-Identifier: MIT */
/*
 * rt_ray: a ray, the distances it is tested with, and where a ray leaving
 * a surface starts. Internal to the core.
 */
#ifndef RT_RAY_H
#define RT_RAY_H

#include "rt_scene.h"
#include "fx_dot.h"

/* Smallest hit distance and secondary-ray offset: 1/512 (see
 * docs/render-model.md and docs/numerics.md). */
#define RT_EPS ((fx_t)128)
#define RT_EPS_LOG2 7u /* RT_EPS = 2^RT_EPS_LOG2 */

/* |d.n| below this (2 FX_UBITS fraction bits, fx_d3_dot_raw) counts as
 * parallel: 2^-16. */
#define RT_PAR_DOT ((int64_t)1 << (2 * FX_UBITS - 16))

/* An object index meaning "none" (nothing skipped, no known origin). */
#define RT_NO_OBJECT 0xFFFFu

typedef struct {
    fx_vec3 o;     /* origin */
    fx_dir3 d;     /* unit direction */
    int32_t e;     /* fx_d3_unit_err(d): |d|^2 - 1 in Q32.32 */
    uint8_t small; /* fx_v3_small(o): the 32-bit intersection paths apply */
} rt_ray;

/* Rounding leaves |d| a little off 1, by e = fx_d3_unit_err(d) (far
 * below 2^-28 for 30 fraction bits). The closest approach is
 * (oc.d) / |d|^2, not oc.d: without the factor its error is e |oc|; with
 * t (1 - e) it is e^2 |oc|. The bounding-sphere test applies it. */

/* Sets a ray's origin and unit direction, and the two values its tests
 * derive from them (fx_d3_unit_err, fx_v3_small). */
static inline void rt_ray_set(rt_ray *r, fx_vec3 o, fx_dir3 d)
{
    r->o = o;
    r->d = d;
    r->e = fx_d3_unit_err(d);
    r->small = (uint8_t)fx_v3_small(o);
}

/* How far along the normal a ray leaving object o starts off its surface,
 * 2^k (this k; a power of two, so offsetting needs no product):
 * shading offsets secondary and shadow rays by it, and the direction grids
 * (rt_dirgrid.c) widen their cones by it, so the two must agree.
 * Cylinders and cones are solved in a frame whose unit is 2^frame_shift
 * ulps (rt_upright), so a ray's root on its own surface is off by about
 * that much over the cosine of its angle to the surface. Starting it 4
 * frame units off the surface (never less than RT_EPS) keeps that root
 * behind it at any angle: no acne on large open shapes' inner walls. At
 * most 2^17. */
static inline unsigned rt_origin_log2(const rt_object *o)
{
    if ((o->kind == RT_CYLINDER || o->kind == RT_CONE) &&
        o->u.upright.frame_shift > 4)
        return (unsigned)o->u.upright.frame_shift + 2u;
    return RT_EPS_LOG2;
}

/* The offset itself, 2^rt_origin_log2(o) (7 to 17). */
static inline fx_t rt_origin_offset(const rt_object *o)
{
    return (fx_t)1 << rt_origin_log2(o);
}

/* One component of a + s c for s = +-2^k (sign neg), k <= 17, and a unit
 * component c, rounded as fx_madd_u: s c 2^-FX_UBITS + 1/2 rounded down
 * is (+-c + 2^(U-1-k)) >> (U - k) exactly (U = FX_UBITS), or +-c 2^(k-U)
 * for k >= U: a shift instead of a 64-bit product. */
static inline fx_t rt_madd_pow2(fx_t a, int32_t c, unsigned k, int neg)
{
    const int32_t v = neg ? -c : c; /* exact: |c| <= 2^FX_UBITS */
    if (FX_UBITS <= 17 && k >= FX_UBITS) /* k <= 17 */
        return fx_add(a, v * ((int32_t)1 << (k - FX_UBITS)));
    return fx_add(a, (v + ((int32_t)1 << (FX_UBITS - 1 - k))) >>
                         (FX_UBITS - k));
}

/* fx_v3_madd_d(a, d, neg ? -2^k : 2^k), by rt_madd_pow2. */
static inline fx_vec3 rt_v3_madd_pow2(fx_vec3 a, fx_dir3 d, unsigned k,
                                      int neg)
{
    return fx_v3(rt_madd_pow2(a.x, d.x, k, neg),
                 rt_madd_pow2(a.y, d.y, k, neg),
                 rt_madd_pow2(a.z, d.z, k, neg));
}

#endif /* RT_RAY_H */
