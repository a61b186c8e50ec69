/* SPDX-License-Identifier: MIT */
/* rt_scene: scene defaults and the per-material constants the tracer
 * uses (each shape's are its own file's, core/shapes/rt_kinds.h). */
#include "rt_libc.h"
#include "rt_scene.h"

/* rt_object is 128 bytes on every target (its union's size_ member): a
 * power of two, so indexing rt_scene.obj is a shift. */
typedef char rt_object_size_check[sizeof(rt_object) == 128 ? 1 : -1];

void rt_scene_init(rt_scene *s)
{
    memset(s, 0, sizeof *s);
    s->cam.eye = fx_v3(0, 0, FX_INT(-10));
    s->cam.look = fx_v3(0, 0, 0);
    s->cam.up = fx_v3(0, FX_ONE, 0);
    s->cam.fov = FX_INT(60);
    s->ambient.r = s->ambient.g = s->ambient.b = FX_ONE;
    s->width = 320;
    s->height = 240;
    s->spp = 1;
    s->depth = RT_MAX_DEPTH;
    s->shadows = 1;
}

void rt_material_defaults(rt_material *m)
{
    memset(m, 0, sizeof *m);
    m->ambient = (fx_t)6554;  /* 0.1 */
    m->diffuse = (fx_t)58982; /* 0.9 */
    m->specular = FX_HALF;
    m->shininess = 10;
    m->ior = FX_ONE;
}

rt_status rt_material_prepare(rt_material *m)
{
    if (m->transparency > 0) {
        if (m->ior <= 0)
            return RT_ERR_ARG;
        m->ior_inv = fx_recip(m->ior);
    }
    if (m->texture != RT_TEX_NONE) {
        if (m->tex_scale <= 0)
            return RT_ERR_ARG;
        m->tex_rcp = fx_floor_rcp(m->tex_scale);
    }
    if (m->bump != 0) {
        if (m->bump_scale <= 0)
            return RT_ERR_ARG;
        m->bump_rcp = fx_floor_rcp(m->bump_scale);
    }
    return RT_OK;
}
