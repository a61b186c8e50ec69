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

/* Outward unit normal of o at surface point p on the given part. */
fx_dir3 rt_normal(const rt_object *o, fx_vec3 p, uint16_t part);

#endif /* RT_SHAPE_H */
