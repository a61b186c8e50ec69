/* SPDX-License-Identifier: MIT */
/* rt_shape: ray-shape intersection and surface normals. Internal. */
#ifndef RT_SHAPE_H
#define RT_SHAPE_H

#include "rt_ray.h"

/* Ray-object intersection: the nearest t with tmin < t < tmax. Returns 1
 * and sets *t and *part (which face, cap or side; a mesh's triangle) on a
 * hit, else 0. A kind
 * this build removed (RT_NO_SPHERE, ...) never hits. */
int rt_intersect(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                 fx_t *t, uint16_t *part);

/* Outward unit normal of o on the given part where ray r hits it at t.
 * *p is the hit point o + t d, rounded. With precise set (for a hit that
 * casts reflected or refracted rays, whose directions inherit the
 * normal's error), on a cylinder's side *p becomes the point of the side
 * where the ray meets it, rounded, and the normal is taken there: the
 * rounding of t and of p moves o + t d off the side (rt_normal.c). */
fx_dir3 rt_normal(const rt_object *o, const rt_ray *r, fx_t t, fx_vec3 *p,
                  uint16_t part, int precise);

/* Where ray r meets the side of cylinder or cone o near its side root t,
 * from Newton steps at the unrounded o + t d (as rt_normal's for a
 * reflective side): 1 with *t30, the distance with 30 fraction bits; 0
 * where the steps decline (a ray within rounding of tangent). */
int rt_side_root(const rt_object *o, const rt_ray *r, fx_t t, int64_t *t30);

#endif /* RT_SHAPE_H */
