/* SPDX-License-Identifier: MIT */
/* rt_texture: solid textures and bump maps. Internal. */
#ifndef RT_TEXTURE_H
#define RT_TEXTURE_H

#include "rt_ray.h"

/* Which of material m's colours its texture shows at the hit of ray r at
 * t on object o (outward unit normal n_out), read at p, the hit point
 * moved 2^-RT_EPS_LOG2 inside: 0 for m->color (and for no texture), 1
 * for m->color2. Where p lies within a few ulps of a cell's edge, the
 * side of the edge is the exact hit's (of the rounded ray, and for a face
 * in an axis plane of the exact t), not the rounded point's; a point on
 * the edge is in the cell above it. */
unsigned rt_texel(const rt_material *m, const rt_object *o, const rt_ray *r,
                  fx_t t, fx_dir3 n_out, fx_vec3 p);

/* Bump-perturbed unit normal (m->bump != 0). */
fx_dir3 rt_bump(const rt_material *m, const rt_object *o, fx_vec3 p,
                fx_dir3 n);

#endif /* RT_TEXTURE_H */
