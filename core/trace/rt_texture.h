/* SPDX-License-Identifier: MIT */
/* rt_texture: solid textures and bump maps. Internal. */
#ifndef RT_TEXTURE_H
#define RT_TEXTURE_H

#include "rt_scene.h"

/* Which of material m's colours its texture shows on object o at point p:
 * 0 for m->color (and for no texture), 1 for m->color2. */
unsigned rt_texel(const rt_material *m, const rt_object *o, fx_vec3 p);

/* Bump-perturbed unit normal (m->bump != 0). */
fx_dir3 rt_bump(const rt_material *m, const rt_object *o, fx_vec3 p,
                fx_dir3 n);

#endif /* RT_TEXTURE_H */
