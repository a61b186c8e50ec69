/* SPDX-License-Identifier: MIT */
/*
 * rt_kinds: what each kind of shape provides to the one dispatch
 * (rt_shape.c, behind rt_shape.h). A shape is one file: rt_sphere.c,
 * rt_quad.c, rt_box.c, rt_upright.c (cylinders and cones, with their
 * precise normals in rt_upright_normal.c) and rt_mesh*.c. Adding a kind
 * means a new file with these four functions, their prototypes here and
 * one case in each switch of rt_shape.c. Internal to core/shapes.
 *
 *   prepare  derives the kind's constants and its bounding sphere (bc, br)
 *            from the fields the scene sets; RT_OK or RT_ERR_DEGENERATE
 *   hit      the nearest t with tmin < t < tmax (rt_intersect's contract)
 *   normal   the outward unit normal at a hit (rt_normal's contract)
 *
 * Row culling and the direction grids need only the bounding sphere, the
 * kind and, for a quad, its plane (n, dist): fields prepare sets.
 */
#ifndef RT_KINDS_H
#define RT_KINDS_H

#include "rt_shape.h"

/* Raw ulps added to bounding-sphere radii, which must never cull a ray
 * that meets the shape. */
#define RT_BOUND_MARGIN 8

rt_status rt_sphere_prepare(rt_object *o);
int rt_sphere_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                  fx_t *t, uint16_t *part);
fx_dir3 rt_sphere_normal(const rt_object *o, fx_vec3 p);

rt_status rt_quad_prepare(rt_object *o);
int rt_quad_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                fx_t *t, uint16_t *part);

rt_status rt_box_prepare(rt_object *o);
int rt_box_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
               fx_t *t, uint16_t *part);
fx_dir3 rt_box_normal(const rt_object *o, fx_vec3 p, unsigned part);

/* Cylinders (RT_CYLINDER) and cones (RT_CONE). */
rt_status rt_upright_prepare(rt_object *o);
int rt_upright_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                   fx_t *t, uint16_t *part);
fx_dir3 rt_upright_normal(const rt_object *o, const rt_ray *r, fx_t t,
                          fx_vec3 *p, unsigned part, int precise);

/* A mesh's bounding sphere, then its hierarchy (rt_mesh_hit). */
int rt_mesh_hit_bounded(const rt_object *o, const rt_ray *r, fx_t tmin,
                        fx_t tmax, fx_t *t, uint16_t *part);

/* Distance along the unit component d (d != 0) from coordinate o to the
 * plane at coordinate p, (p - o) / d rounded to nearest: a flat quad's
 * distance, so that box faces and caps lying in such a quad's plane tie
 * with it exactly. 2^32 or more (beyond any tmax) comes back as INT64_MAX
 * or -INT64_MAX. */
int64_t rt_plane_t(int64_t p, fx_t o, int32_t d);

#endif /* RT_KINDS_H */
