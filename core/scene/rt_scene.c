/* SPDX-License-Identifier: MIT */
/* rt_scene: scene defaults and the per-object constants the tracer uses. */
#include "rt_libc.h"
#include "rt_scene.h"

/* Largest cone slope r / h: flatter cones lose the unit-frame precision
 * (k^2 must stay well inside Q16.16). */
#define RT_MAX_CONE_SLOPE FX_INT(64)

/* Raw ulps added to bounding-sphere radii, which must never cull a ray
 * that meets the shape. */
#define RT_BOUND_MARGIN 8

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

static int is_zero(fx_vec3 v)
{
    return v.x == 0 && v.y == 0 && v.z == 0;
}

/* Scales v by 2^-k, rounding to nearest; exact for k <= 0. */
static fx_t scale_pow2(fx_t v, int k)
{
    if (k <= 0)
        return fx_sat64((int64_t)v * ((int64_t)1 << -k));
    return (fx_t)(((int64_t)v + ((int64_t)1 << (k - 1))) >> k);
}

/* Bounding sphere and unit frame for an upright shape of radius r and
 * height h. */
static rt_status upright_bounds(rt_object *o)
{
    fx_t hh = o->h / 2;
    int k = 0;
    if (o->r <= 0 || o->h <= 0)
        return RT_ERR_DEGENERATE;
    o->bc = fx_v3(o->a.x, fx_add(o->a.y, hh), o->a.z);
    o->br = fx_add(fx_v3_length(fx_v3(o->r, hh, 0)), RT_BOUND_MARGIN);
    while (k < 15 && ((int64_t)o->br >> k) > FX_ONE)
        k++;
    while (k <= 0 && k > -15 && ((int64_t)o->br << -k) <= FX_HALF)
        k--;
    o->ushift = (int8_t)k;
    /* Radius and half height with 16 fraction bits in the frame: both
     * must be nonzero (rt_parse_obj.c states the limit). */
    if (scale_pow2(o->r, k) == 0 || scale_pow2(hh, k) == 0)
        return RT_ERR_DEGENERATE;
    return RT_OK;
}

static rt_status prepare_shape(rt_object *o);

rt_status rt_object_prepare(rt_object *o)
{
    o->flat = 0;
    rt_status st = prepare_shape(o);
    o->small = st == RT_OK && o->br < ((fx_t)1 << 29) && fx_v3_small(o->bc);
    return st;
}

static rt_status prepare_shape(rt_object *o)
{
    switch (o->kind) {
    case RT_SPHERE:
        if (o->r <= 0)
            return RT_ERR_DEGENERATE;
        o->bc = o->a;
        o->br = o->r;
        o->convex = 1;
        {
            /* (2^(31 + b) - 1) / r is below 2^32 as r >= 2^(b - 1). */
            const int b = 32 - fx_clz32((uint32_t)o->r);
            o->rinv = fx_udiv64_32(((uint64_t)1 << (31 + b)) - 1u,
                                   (uint32_t)o->r);
        }
        return RT_OK;
    case RT_QUAD: {
        fx_vec3 e1 = o->b, e2 = o->c;
        if (is_zero(e1) || is_zero(e2))
            return RT_ERR_DEGENERATE;
        o->n = fx_d3_cross_unit(e1, e2);
        if (o->n.x == 0 && o->n.y == 0 && o->n.z == 0)
            return RT_ERR_DEGENERATE; /* parallel edges */
        o->pu = fx_d3_cross_unit(e2, fx_d3_raw(o->n));
        o->pv = fx_d3_cross_unit(fx_d3_raw(o->n), e1);
        o->lu = fx_pd_dot(e1, o->pu);
        o->lv = fx_pd_dot(e2, o->pv);
        if (o->lu <= 0 || o->lv <= 0)
            return RT_ERR_DEGENERATE;
        o->dist = fx_pd_dot(o->a, o->n);
        if (o->n.x == 0 && o->n.z == 0 && o->pu.y == 0 && o->pv.y == 0) {
            if (o->pu.x == 0 && o->pv.z == 0)
                o->flat = 1; /* pu along z, pv along x */
            else if (o->pu.z == 0 && o->pv.x == 0)
                o->flat = 2; /* pu along x, pv along z */
        }
        /* Centre a + (e1 + e2) / 2, radius half the longer diagonal. */
        fx_vec3 half1 = fx_v3(e1.x / 2, e1.y / 2, e1.z / 2);
        fx_vec3 half2 = fx_v3(e2.x / 2, e2.y / 2, e2.z / 2);
        o->bc = fx_v3_add(o->a, fx_v3_add(half1, half2));
        fx_t d1 = fx_v3_length(fx_v3_add(half1, half2));
        fx_t d2 = fx_v3_length(fx_v3_sub(half1, half2));
        /* The margin covers the halving above (under an ulp per
         * component of bc and of the diagonals) and the rounding of the
         * closest approach in the bounding test (about an ulp each). */
        o->br = fx_add(d1 > d2 ? d1 : d2, RT_BOUND_MARGIN);
        o->convex = 1;
        return RT_OK;
    }
    case RT_BOX: {
        if (o->b.x <= o->a.x || o->b.y <= o->a.y || o->b.z <= o->a.z)
            return RT_ERR_DEGENERATE;
        fx_vec3 half = fx_v3((fx_t)(((int64_t)o->b.x - o->a.x) / 2),
                             (fx_t)(((int64_t)o->b.y - o->a.y) / 2),
                             (fx_t)(((int64_t)o->b.z - o->a.z) / 2));
        o->bc = fx_v3_add(o->a, half);
        o->br = fx_add(fx_v3_length(half), RT_BOUND_MARGIN);
        o->convex = 1;
        return RT_OK;
    }
    case RT_CYLINDER:
        /* Open or capped: a ray leaving the outside of the side leaves
         * the infinite solid cylinder, which is convex, and one leaving a
         * cap's outside leaves the half-space that holds the whole shape;
         * neither can meet the cylinder again. */
        o->convex = 1;
        return upright_bounds(o);
    case RT_CONE:
        o->caps &= RT_CAP_BOTTOM;
        o->convex = 1; /* as a cylinder: one nappe's solid is convex */
        if (o->r <= 0 || o->h <= 0)
            return RT_ERR_DEGENERATE;
        {
            fx_t k16 = fx_div(o->r, o->h);
            if (k16 > RT_MAX_CONE_SLOPE || k16 == 0)
                return RT_ERR_DEGENERATE;
        }
        /* The slope with RT_FRAME_BITS fraction bits, to nearest: r / h
         * <= 64 keeps it below 2^30. */
        o->k = (fx_t)fx_udiv64_32(((uint64_t)(uint32_t)o->r << RT_FRAME_BITS) +
                                      (uint32_t)o->h / 2,
                                  (uint32_t)o->h);
        /* Where the cone is thin (rt_intersect.c, thin_side): 2^-6 of
         * the frame over k, both with RT_FRAME_BITS fraction bits. */
        {
            const uint64_t th = ((uint64_t)1 << (2 * RT_FRAME_BITS - 6)) /
                                (uint32_t)o->k;
            o->rinv = th > UINT32_MAX ? UINT32_MAX : (uint32_t)th;
        }
        return upright_bounds(o);
    case RT_MESH:
        return rt_mesh_prepare(o);
    default:
        return RT_ERR_ARG;
    }
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
