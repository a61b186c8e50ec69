/* SPDX-License-Identifier: MIT */
/*
 * rt_shape: the dispatch from an object's kind to its shape (rt_kinds.h
 * lists what each provides). Every shape but the quad is first tested
 * against its bounding sphere, with the geometric form (closest approach,
 * then the chord), exact in 64 bits at any distance (rt_bsphere.h;
 * docs/numerics.md).
 *
 * The sphere's, quad's, box's and upright shapes' files are included
 * here, their functions static: one unit, so that the compiler inlines
 * each hit test into rt_intersect's switch, as it would in one file. A
 * call from the switch into a test in another unit (a second call, its
 * six arguments passed again) or the switch inlined into each search (each
 * search's loop grows) makes every object test dearer. Each of
 * those files compiled alone defines nothing.
 */
#include "rt_shape.h"
#include "rt_mesh.h"

#include "rt_sphere.c"
#include "rt_quad.c"
#include "rt_box.c"
#include "rt_upright.c"

/* A mesh: its bounding sphere when ray and mesh are near the origin (its
 * margin covers the triangle test's rounding there, rt_mesh_check.c),
 * then its hierarchy (rt_mesh.c); part is the triangle. */
RT_NOINLINE static int mesh_hit(const rt_object *o, const rt_ray *r,
                                fx_t tmin, fx_t tmax, fx_t *t,
                                uint16_t *part)
{
    int64_t tca, h[3];
    uint64_t disc;
    if (o->small && r->small &&
        !bsphere(&o->bc, o->br, 1, r, tmin, tmax, &tca, &disc, h))
        return 0;
    return rt_mesh_hit(o, r, tmin, tmax, t, part);
}

rt_status rt_object_prepare(rt_object *o)
{
    rt_status st;
    switch (o->kind) {
    case RT_SPHERE:
        st = sphere_prepare(o);
        break;
    case RT_QUAD:
        st = quad_prepare(o);
        break;
    case RT_BOX:
        st = box_prepare(o);
        break;
    case RT_CYLINDER:
    case RT_CONE:
        st = upright_prepare(o);
        break;
    case RT_MESH:
        st = rt_mesh_prepare(o);
        break;
    default:
        return RT_ERR_ARG;
    }
    o->small = st == RT_OK && o->br < ((fx_t)1 << 29) && fx_v3_small(o->bc);
    return st;
}

int rt_intersect(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                 fx_t *t, uint16_t *part)
{
    /* A kind this build removed never hits (rendering refuses scenes
     * with one): its case falls out of the switch. */
    switch (o->kind) {
    case RT_SPHERE:
        if (!RT_HAS_SPHERE)
            break;
        return sphere_hit(o, r, tmin, tmax, t, part);
    case RT_QUAD:
        if (!RT_HAS_QUAD)
            break;
        return quad_hit(o, r, tmin, tmax, t, part);
    case RT_BOX:
        if (!RT_HAS_BOX)
            break;
        return box_hit(o, r, tmin, tmax, t, part);
    case RT_CYLINDER:
    case RT_CONE:
        if (!RT_HAS_UPRIGHT)
            break;
        return upright_hit(o, r, tmin, tmax, t, part);
    case RT_MESH:
        if (!RT_HAS_MESH)
            break;
        return mesh_hit(o, r, tmin, tmax, t, part);
    default:
        break;
    }
    return 0;
}

int64_t rt_quad_side(const rt_object *o, fx_vec3 p, int small)
{
    return rt_quad_num(o, p, small);
}

fx_dir3 rt_normal(const rt_object *o, const rt_ray *r, fx_t t, fx_vec3 *p,
                  uint16_t part, int precise)
{
    switch (o->kind) {
    case RT_SPHERE:
        if (RT_HAS_SPHERE)
            return sphere_normal(o, *p);
        break;
    case RT_BOX:
        if (RT_HAS_BOX)
            return box_normal(o, *p, part);
        break;
    case RT_CYLINDER:
    case RT_CONE:
        if (RT_HAS_UPRIGHT)
            return rt_upright_normal(o, r, t, p, part, precise);
        break;
    case RT_MESH:
        if (RT_HAS_MESH)
            return rt_mesh_normal(o, *p, part);
        break;
    default:
        break;
    }
    return o->u.quad.normal; /* a quad's; a removed kind is never hit */
}
