/* SPDX-License-Identifier: MIT */
/*
 * rt_quad: parallelograms. Below, a is the corner, e1 and e2 the edges,
 * n the unit normal, pu and pv the unit in-plane axes (axis_u, axis_v)
 * and lu and lv the quad's extents along them (len_u, len_v: rt_quad in
 * rt_scene.h). A quad is tested against its plane first, which costs as
 * little as a bounding sphere and rejects a ray leaving the plane's side
 * at once, then by its in-plane coordinates along pu and pv. The normal
 * is the prepared n. A flat quad (normal along y, axes along x and z: a
 * floor) skips the zero terms.
 *
 * Part of the dispatch unit: rt_shape.c includes this file (its comment
 * says why); compiled alone it defines nothing.
 */
#include "rt_bsphere.h"
#include "rt_kinds.h"

/* Q16.16 ulps (plus 2^-(FX_UBITS + 1) of the size) by which quads reach
 * past their edges. */
#define RT_QUAD_SLACK 2

static int is_zero(fx_vec3 v)
{
    return v.x == 0 && v.y == 0 && v.z == 0;
}

static inline rt_status quad_prepare(rt_object *o)
{
    rt_quad *qd = &o->u.quad;
    qd->flat = 0;
    fx_vec3 e1 = qd->edge1, e2 = qd->edge2;
    if (is_zero(e1) || is_zero(e2))
        return RT_ERR_DEGENERATE;
    qd->normal = fx_d3_cross_unit(e1, e2);
    if (qd->normal.x == 0 && qd->normal.y == 0 && qd->normal.z == 0)
        return RT_ERR_DEGENERATE; /* parallel edges */
    qd->axis_u = fx_d3_cross_unit(e2, fx_d3_raw(qd->normal));
    qd->axis_v = fx_d3_cross_unit(fx_d3_raw(qd->normal), e1);
    qd->len_u = fx_pd_dot(e1, qd->axis_u);
    qd->len_v = fx_pd_dot(e2, qd->axis_v);
    if (qd->len_u <= 0 || qd->len_v <= 0)
        return RT_ERR_DEGENERATE;
    qd->dist = fx_pd_dot(qd->corner, qd->normal);
    if (qd->normal.x == 0 && qd->normal.z == 0 && qd->axis_u.y == 0 &&
        qd->axis_v.y == 0) {
        if (qd->axis_u.x == 0 && qd->axis_v.z == 0)
            qd->flat = 1; /* pu along z, pv along x */
        else if (qd->axis_u.z == 0 && qd->axis_v.x == 0)
            qd->flat = 2; /* pu along x, pv along z */
    }
    /* Centre a + (e1 + e2) / 2, radius half the longer diagonal. */
    fx_vec3 half1 = fx_v3(e1.x / 2, e1.y / 2, e1.z / 2);
    fx_vec3 half2 = fx_v3(e2.x / 2, e2.y / 2, e2.z / 2);
    o->bc = fx_v3_add(qd->corner, fx_v3_add(half1, half2));
    fx_t d1 = fx_v3_length(fx_v3_add(half1, half2));
    fx_t d2 = fx_v3_length(fx_v3_sub(half1, half2));
    /* The margin covers the halving above (under an ulp per component of
     * bc and of the diagonals) and the rounding of the closest approach
     * in the bounding test (about an ulp each). */
    o->br = fx_add(d1 > d2 ? d1 : d2, RT_BOUND_MARGIN);
    o->convex = 1;
    return RT_OK;
}

/* The distance t (Q16.16) to the plane of quad o, or 2^32 - 1
 * for none (a ray parallel to it or leaving its side, or t >= 2^32). */
static uint32_t quad_t(const rt_object *o, const rt_ray *r)
{
    const rt_quad *qd = &o->u.quad;
    const int flat = qd->flat;
    int64_t den = flat ? fx_imul64(r->d.y, qd->normal.y)
                       : fx_d3_dot_raw(r->d, qd->normal);
    if (den < RT_PAR_DOT && den > -RT_PAR_DOT)
        return 0xFFFFFFFFu;
    /* num = (a - o).n, the plane's distance from the origin, with 16 +
     * FX_UBITS fraction bits (|num| < 2^63): exact, as a grazing ray
     * needs it (a light on a tilted quad, seen nearly in its plane), and
     * at any distance from the scene's origin (n.a may leave Q16.16). A
     * flat quad's dist = n.a is exact; a small tilted quad and ray
     * (rt_object.small) have a - o within 32 bits. den = d.n with 2
     * FX_UBITS fraction bits. */
    const int64_t num = rt_quad_num(o, r->o, r->small);
    if ((num < 0) != (den < 0))
        return 0xFFFFFFFFu;
    /* t = num 2^FX_UBITS / den in Q16.16, both of one sign, rounded: a
     * 64/32 division by den's top 32 bits (2^-31 relative, so grazing
     * rays keep their precision). A quotient of 2^32 or more is beyond
     * any tmax. The sd bits den drops are zero for an axis-aligned quad
     * (den = d.y 2^FX_UBITS, sd <= FX_UBITS), so there t is rt_plane_t's. */
    uint64_t un = (uint64_t)(num < 0 ? -num : num);
    uint64_t uden = (uint64_t)(den < 0 ? -den : den);
    int sd = 32 - fx_clz64(uden);
    if (sd < 0)
        sd = 0;
    const uint32_t ud = (uint32_t)(uden >> sd);
    const int lsh = FX_UBITS - sd; /* 0..FX_UBITS, as |den| <= 2^61 */
    if ((un >> (32 - lsh)) >= ud)
        return 0xFFFFFFFFu;
    /* Rounded to nearest; for an axis-aligned quad ud is even or sd = 0,
     * so this is rt_plane_t's floor((n + floor(d / 2)) / d) exactly. */
    const uint64_t n2 = (un << lsh) + (ud >> 1);
    if ((n2 >> 32) >= ud)
        return 0xFFFFFFFFu;
    return fx_udiv64_32(n2, ud);
}

/* quad_t for a flat quad with n.y = +-2^FX_UBITS: num = 2^FX_UBITS m
 * and den = 2^FX_UBITS s d.y for m = dist - s o.y, so the rounded
 * quotient is floor((|m| 2^FX_UBITS + floor(|d.y| / 2)) / |d.y|)
 * whatever shift normalises den: the same t without the 64-bit shifts
 * (the floor quad of most scenes, which every camera ray tests). */
static inline uint32_t floor_quad_t(const rt_object *o, const rt_ray *r)
{
    const rt_quad *qd = &o->u.quad;
    const int up = qd->normal.y > 0;
    const int32_t sdy = up ? r->d.y : -r->d.y;
    const uint32_t ud = (uint32_t)(sdy < 0 ? -sdy : sdy);
    const int64_t m = (int64_t)qd->dist - (up ? r->o.y : -(int64_t)r->o.y);
    /* The side first: a ray heading away from the plane needs no more. */
    if ((m < 0) != (sdy < 0))
        return 0xFFFFFFFFu;
    /* |den| < RT_PAR_DOT */
    if (ud < ((uint32_t)1 << (FX_UBITS - 16)))
        return 0xFFFFFFFFu;
    /* |m| <= 2^32: below 2^62 */
    const uint64_t n2 = ((uint64_t)(m < 0 ? -m : m) << FX_UBITS) + (ud >> 1);
    if ((n2 >> 32) >= ud)
        return 0xFFFFFFFFu;
    return fx_udiv64_32(n2, ud);
}

/* quad_uv for a quad or ray beyond the small range, or t
 * from 2^29: 0 when the point is surely outside. */
static inline int quad_uv_wide(const rt_object *o, const rt_ray *r,
                               fx_t tt, int64_t *pu64, int64_t *pv64)
{
    const rt_quad *qd = &o->u.quad;
    const int flat = qd->flat;
    int64_t u, v;
    int64_t qx = (int64_t)r->o.x - qd->corner.x +
                 ((fx_imul64(tt, r->d.x) + UHALF) >> FX_UBITS);
    int64_t qz = (int64_t)r->o.z - qd->corner.z +
                 ((fx_imul64(tt, r->d.z) + UHALF) >> FX_UBITS);
    /* A point of the quad is a + s e1 + t e2 with s, t in [0, 1]:
     * each component of q = p - a is below 2^32. Past that it is
     * outside, and below it each product with a unit axis is below
     * 2^62. */
    const int64_t qlim = (int64_t)1 << 32;
    if (qx >= qlim || qx <= -qlim || qz >= qlim || qz <= -qlim)
        return 0;
    if (flat == 1) { /* pu = (0, 0, pu.z), pv = (pv.x, 0, 0) */
        u = mul_q(qz, qd->axis_u.z);
        v = mul_q(qx, qd->axis_v.x);
    } else if (flat == 2) { /* pu = (pu.x, 0, 0), pv = (0, 0, pv.z) */
        u = mul_q(qx, qd->axis_u.x);
        v = mul_q(qz, qd->axis_v.z);
    } else {
        int64_t qy = (int64_t)r->o.y - qd->corner.y +
                     ((fx_imul64(tt, r->d.y) + UHALF) >> FX_UBITS);
        if (qx == (int32_t)qx && qy == (int32_t)qy &&
            qz == (int32_t)qz) {
            /* The usual case: 32-bit operands, the same sums. */
            const int32_t x = (int32_t)qx, y = (int32_t)qy;
            const int32_t z = (int32_t)qz;
            u = fx_imul64(x, qd->axis_u.x) + fx_imul64(y, qd->axis_u.y) +
                fx_imul64(z, qd->axis_u.z);
            v = fx_imul64(x, qd->axis_v.x) + fx_imul64(y, qd->axis_v.y) +
                fx_imul64(z, qd->axis_v.z);
        } else {
            if (qy >= qlim || qy <= -qlim)
                return 0;
            /* |q| < 2^33 and |pu| = 1: every partial sum below
             * 2^63. */
            u = qx * qd->axis_u.x + qy * qd->axis_u.y + qz * qd->axis_u.z;
            v = qx * qd->axis_v.x + qy * qd->axis_v.y + qz * qd->axis_v.z;
        }
    }
    *pu64 = u;
    *pv64 = v;
    return 1;
}

/* u = (p - a).pu and v = (p - a).pv at p = o + tt d (16 + FX_UBITS
 * fraction bits): 0 when p is surely outside the quad. */
static inline int quad_uv(const rt_object *o, const rt_ray *r, fx_t tt,
                          int64_t *pu, int64_t *pv)
{
    const rt_quad *qd = &o->u.quad;
    const int flat = qd->flat;
    if (!(o->small && r->small && (uint32_t)tt < ((uint32_t)1 << 29)))
        return quad_uv_wide(o, r, tt, pu, pv);
    /* The usual case, in 32 bits: a within 2^30 (its ball within 2^29,
     * quad_prepare), o within 2^29 and t d rounded within 2^29, so each
     * component of q is below 2^31, and mul_round_u is the rounding of
     * quad_uv_wide. */
    const int32_t x = r->o.x - qd->corner.x + mul_round_u(tt, r->d.x);
    const int32_t z = r->o.z - qd->corner.z + mul_round_u(tt, r->d.z);
    if (flat == 1) {
        *pu = fx_imul64(z, qd->axis_u.z);
        *pv = fx_imul64(x, qd->axis_v.x);
    } else if (flat == 2) {
        *pu = fx_imul64(x, qd->axis_u.x);
        *pv = fx_imul64(z, qd->axis_v.z);
    } else {
        const int32_t y = r->o.y - qd->corner.y + mul_round_u(tt, r->d.y);
        *pu = fx_imul64(x, qd->axis_u.x) + fx_imul64(y, qd->axis_u.y) +
              fx_imul64(z, qd->axis_u.z);
        *pv = fx_imul64(x, qd->axis_v.x) + fx_imul64(y, qd->axis_v.y) +
              fx_imul64(z, qd->axis_v.z);
    }
    return 1;
}

static inline int quad_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                fx_t *t, uint16_t *part)
{
    const rt_quad *qd = &o->u.quad;
    /* A flat quad (rt_quad.flat) has n = (0, n.y, 0). */
    const uint32_t tq = qd->flat && (qd->normal.y == FX_UONE ||
                                     qd->normal.y == -FX_UONE)
                            ? floor_quad_t(o, r)
                            : quad_t(o, r);
    /* 0xFFFFFFFF (none) is beyond FX_MAX. */
    if (tq > (uint32_t)FX_MAX || (fx_t)tq <= tmin || (fx_t)tq >= tmax)
        return 0;
    const fx_t tt = (fx_t)tq;
    int64_t u, v; /* 16 + FX_UBITS fraction bits */
    if (!quad_uv(o, r, tt, &u, &v))
        return 0;
    /* The common case first, without the 64-bit bounds below: high words
     * of u and v in [0, lu 2^(FX_UBITS - 32)) and [0, lv 2^(FX_UBITS -
     * 32)) are inside them (lu, lv > 0, quad_prepare). */
    if ((uint32_t)((uint64_t)u >> 32) <
            (uint32_t)qd->len_u >> ((32 - FX_UBITS) & 31) &&
        (uint32_t)((uint64_t)v >> 32) <
            (uint32_t)qd->len_v >> ((32 - FX_UBITS) & 31)) {
        *t = tt;
        *part = 0;
        return 1;
    }
    /* Inclusive by RT_QUAD_SLACK ulps plus 2^-(FX_UBITS + 1) of the quad's
     * size: pu and pv are rounded to 2^-FX_UBITS, so (p - a).pu at a
     * shared edge can land just outside both neighbours, by an amount
     * that grows with the quad. Adjacent quads overlap by that much
     * instead of leaving a crack. */
    const int64_t sl = ((int64_t)RT_QUAD_SLACK << FX_UBITS) +
                       (((int64_t)qd->len_u + qd->len_v) >> 1);
    if (u < -sl || v < -sl || u > (int64_t)qd->len_u * FX_UONE + sl ||
        v > (int64_t)qd->len_v * FX_UONE + sl)
        return 0;
    *t = tt;
    *part = 0;
    return 1;
}
