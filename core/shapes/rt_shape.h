/* SPDX-License-Identifier: MIT */
/* rt_shape: ray-shape intersection and surface normals, for every kind
 * through one dispatch (rt_shape.c; each kind's file is listed in
 * rt_kinds.h). Internal to the core. */
#ifndef RT_SHAPE_H
#define RT_SHAPE_H

#include "rt_kinds.h"

/* Ray-object intersection: the nearest t with tmin < t < tmax. Returns 1
 * and sets *t and *part (which face, cap or side; a mesh's triangle) on a
 * hit, else 0. A kind this build removed (RT_NO_SPHERE, ...) never
 * hits. */
int rt_intersect(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                 fx_t *t, uint16_t *part);

/* 1 if ray r surely misses object o: every shape but the quad is first
 * tested against its bounding sphere (bc, br; for a mesh when both are
 * small), so a ray passing it by misses. near: o is small and its bc
 * and br and r's origin are within 2^22 (64 units; rt_dir_grids.near),
 * so fx_cross_beyond may take its narrow form. */
static inline int rt_passes_by(const rt_object *o, const rt_ray *r,
                               int near)
{
    if (o->kind == RT_QUAD || (!near && (!o->small || !r->small)))
        return 0;
    /* The y and x components of oc x d: of the seed's tests, the first
     * rejects most, the two together more than three quarters; the z
     * one costs more than it saves. near implies both small. */
    const int32_t ox = o->bc.x - r->o.x, oy = o->bc.y - r->o.y;
    const int32_t oz = o->bc.z - r->o.z;
    return fx_cross_beyond(oz, r->d.x, ox, r->d.z, o->br, near) ||
           fx_cross_beyond(oy, r->d.z, oz, r->d.y, o->br, near);
}

/* rt_quad_num out of line, for the shadow rays' culling. */
int64_t rt_quad_side(const rt_object *o, fx_vec3 p, int small);

/* Outward unit normal of o on the given part where ray r hits it at t.
 * *p is the hit point o + t d, rounded. With precise set (for a hit that
 * casts reflected or refracted rays, whose directions inherit the
 * normal's error), on a cylinder's side *p becomes the point of the side
 * where the ray meets it, rounded, and the normal is taken there: the
 * rounding of t and of p moves o + t d off the side
 * (rt_upright_normal.c). */
fx_dir3 rt_normal(const rt_object *o, const rt_ray *r, fx_t t, fx_vec3 *p,
                  uint16_t part, int precise);

#endif /* RT_SHAPE_H */
