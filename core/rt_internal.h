/*
 * Declarations shared by the core's own files; not part of the public API.
 */
#ifndef RT_INTERNAL_H
#define RT_INTERNAL_H

#include "rt_scene.h"
#include "rt_render.h"

/* Smallest hit distance and secondary-ray offset: 1/512 (see
 * docs/render-model.md and docs/numerics.md). */
#define RT_EPS ((fx_t)128)

/* |d.n| below this (Q32.32) counts as parallel: 2^-16. */
#define RT_PAR_Q32 ((int64_t)1 << 16)

typedef struct {
    fx_vec3 o;     /* origin */
    fx_vec3 d;     /* unit direction */
    int32_t e;     /* rt_unit_err(d): |d|^2 - 1 in Q32.32 */
    uint8_t small; /* rt_small3(o): the 32-bit intersection paths apply */
} rt_ray;

/* |d|^2 - 1 of a unit direction, in Q32.32 (rounding leaves |d| a little
 * off 1; the bounding-sphere test corrects for it). Each component is
 * within an ulp, so |e| is far below 2^18. The closest approach is
 * (oc.d) / |d|^2, not oc.d: without the factor its error is e |oc| (half a
 * unit for a sphere 30000 units away); with t (1 - e) it is e^2 |oc|. */
static inline int32_t rt_unit_err(fx_vec3 d)
{
    return (int32_t)((int64_t)d.x * d.x + (int64_t)d.y * d.y +
                     (int64_t)d.z * d.z - ((int64_t)1 << 32));
}

/* 1 if every component of v is below 2^29 (8192 units) in magnitude:
 * differences of two such points fit 32 bits. */
static inline int rt_small3(fx_vec3 v)
{
    const uint32_t lim = (uint32_t)1 << 30;
    return (uint32_t)v.x + (lim >> 1) < lim &&
           (uint32_t)v.y + (lim >> 1) < lim && (uint32_t)v.z + (lim >> 1) < lim;
}

/* floor(n / d) for d > 0 and n < d * 2^32 (the quotient fits 32 bits). */
uint32_t rt_udiv64_32(uint64_t n, uint32_t d);

/* Ray-object intersection: the nearest t with tmin < t < tmax. Returns 1
 * and sets *t and *part (which face, cap or side) on a hit, else 0. */
int rt_intersect(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                 fx_t *t, uint8_t *part);

/* Outward unit normal of o at surface point p on the given part. */
fx_vec3 rt_normal(const rt_object *o, fx_vec3 p, uint8_t part);

/* Which of material m's colours its texture shows on object o at point p:
 * 0 for m->color (and for no texture), 1 for m->color2. */
unsigned rt_texel(const rt_material *m, const rt_object *o, fx_vec3 p);

/* Bump-perturbed unit normal (m->bump != 0). */
fx_vec3 rt_bump(const rt_material *m, const rt_object *o, fx_vec3 p,
                fx_vec3 n);

/* Unit vector along a x b, from the exact 64-bit cross product, so tiny
 * vectors do not round to zero. The zero vector if a and b are parallel. */
fx_vec3 rt_cross_unit(fx_vec3 a, fx_vec3 b);

/* tan(deg / 2) for 0 < deg < 180, relative error about 2^-28 before the
 * final rounding to Q16.16; saturates. */
fx_t rt_tan_half_deg(fx_t deg);

#endif /* RT_INTERNAL_H */
