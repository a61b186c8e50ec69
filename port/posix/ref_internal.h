/* SPDX-License-Identifier: MIT */
/*
 * ref_internal: what the reference renderer's files share and nobody else
 * needs: the double vector helpers, the Q16.16 to double conversions and
 * the shape check the scene loader uses. Include it only from
 * port/posix/ref_*.c; the public API is ref_render.h.
 *
 * The helpers are static inline so each file gets its own copy; they are
 * plain IEEE double operations, so which file computes them does not
 * change a single bit of the result.
 */
#ifndef REF_INTERNAL_H
#define REF_INTERNAL_H

#include <math.h>
#include "ref_render.h"

typedef ref_vec3 vec;

static inline vec v3(double x, double y, double z)
{
    vec v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}
static inline vec add(vec a, vec b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec sub(vec a, vec b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec scale(vec a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec mul(vec a, vec b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline vec madd(vec a, vec b, double s) { return add(a, scale(b, s)); }
static inline double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline double len(vec a) { return sqrt(dot(a, a)); }
static inline vec cross(vec a, vec b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
              a.x * b.y - a.y * b.x);
}
static inline vec norm(vec a)
{
    double l = len(a);
    return l > 0 ? scale(a, 1.0 / l) : a;
}
static inline double comp(vec a, int axis)
{
    return axis == 0 ? a.x : (axis == 1 ? a.y : a.z);
}
/* The unit vector along axis 0, 1 or 2, times s. */
static inline vec axis_vec(int axis, double s)
{
    return v3(axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0);
}

/* Q16.16 to double: value / 65536, as ref_render.h describes. */
static inline double fxd(fx_t v) { return (double)v / 65536.0; }
static inline vec fxv(fx_vec3 v) { return v3(fxd(v.x), fxd(v.y), fxd(v.z)); }
static inline vec fxc(rt_rgb c) { return v3(fxd(c.r), fxd(c.g), fxd(c.b)); }

/* Returns 1 if the shape has a size (a positive radius, a non-degenerate
 * quad, a box with max > min on every axis, a positive radius and height),
 * else 0. The renderer refuses a scene with a shape that fails
 * (RT_ERR_DEGENERATE) rather than divide by its zero size. */
int ref_shape_ok(const ref_shape *sh);

#endif /* REF_INTERNAL_H */
