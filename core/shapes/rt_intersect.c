/* SPDX-License-Identifier: MIT */
/*
 * rt_intersect: ray-shape intersection (the normals are rt_normal.c's).
 *
 * Every shape is first tested against its bounding sphere with the
 * geometric form (closest approach, then the chord), which is exact in
 * 64 bits for any distance and culls most rays cheaply. Cylinders and cones
 * are then solved in a frame centred on that sphere and scaled by a power
 * of two, so their quadratic has coefficients near 1 whatever the object's
 * size or distance: the discriminant keeps its precision for small and far
 * objects alike (rt_upright.h). See docs/numerics.md.
 */
#include "fx_rsqrt.h"
#include "rt_bsphere.h"
#include "rt_mesh.h"
#include "rt_shape.h"

/* Q16.16 ulps (plus 2^-(FX_UBITS + 1) of the size) by which quads reach
 * past their edges. */
#define RT_QUAD_SLACK 2

/* Distance along the unit component d (d != 0) from coordinate o to the
 * plane at coordinate p, (p - o) / d rounded to nearest: hit_quad's value for an
 * axis-aligned quad, so that shapes lying in such a quad's plane tie with
 * it exactly. A distance of 2^32 or more (beyond any tmax) comes back as
 * INT64_MAX or -INT64_MAX. */
static int64_t plane_t(int64_t p, fx_t o, int32_t d)
{
    int64_t dp = p - o; /* |p - o| < 2^33 */
    int neg = (dp < 0) != (d < 0);
    uint64_t adp = (uint64_t)(dp < 0 ? -dp : dp);
    uint32_t ud = (uint32_t)(d < 0 ? -(int64_t)d : d); /* <= 2^FX_UBITS */
    /* t = |p - o| 2^FX_UBITS / |d| in Q16.16; at |p - o| >= 2^32 it is
     * 2^32 or more, as |d| <= 2^FX_UBITS. */
    if ((adp >> 32) != 0 || ((adp << FX_UBITS) >> 32) >= ud)
        return neg ? -INT64_MAX : INT64_MAX;
    /* Rounded: floor((n + floor(d / 2)) / d), as in hit_quad. */
    uint64_t un = (adp << FX_UBITS) + (ud >> 1);
    if ((un >> 32) >= ud)
        return neg ? -INT64_MAX : INT64_MAX;
    int64_t q = fx_udiv64_32(un, ud);
    return neg ? -q : q;
}

/* Accepts t if tmin < t < tmax and nearer than the best so far. */
static int take(int64_t t, fx_t tmin, fx_t *best)
{
    if (t > tmin && t < *best) {
        *best = (fx_t)t;
        return 1;
    }
    return 0;
}

/* fx_sqrt_q32(n), round(sqrt(n)), for 0 < n < 2^40 where 32-bit divides
 * and 64-bit products are library calls (the M0): with m in [2^30, 2^32)
 * the top bits of n and n within [m, m + 1) 2^2j, y = m R / 2^32 for R =
 * fx_rsqrt_q29(m) is sqrt(m) 2^13, never above and below by at most
 * 2^-20 relative and 1, so s = y >> (13 - j) is floor(sqrt(n)) or up to
 * two less (sqrt(n) < 2^20). n - s^2 is then below 2^32, so its low word
 * is exact, and it says how many (#17: seed 160x120 6,889.1 -> 6,853.8
 * instructions a pixel on the M0, for 340 bytes; dearer on the M3). */
static inline uint32_t sqrt_round_small(uint64_t n)
{
    const uint32_t hi = (uint32_t)(n >> 32), lo = (uint32_t)n;
    /* hi < 2^8, so z is 24 to 30 when hi != 0, and n is m 2^-z (j =
     * -z / 2) or within [m, m + 1) 2^(32 - z) (j = 16 - z / 2). */
    const int z = fx_clz32(hi != 0 ? hi : lo) & ~1;
    const uint32_t m =
        hi != 0 ? (hi << z) | (lo >> ((32 - z) & 31)) : lo << z;
    const int sh = hi != 0 ? z / 2 - 3 : z / 2 + 13; /* 13 - j */
    uint32_t s = fx_umulhi32(m, (uint32_t)fx_rsqrt_q29(m)) >> sh;
    uint32_t rem = lo - s * s; /* n - s^2, in [0, 2^32) */
    while (rem > 2 * s) {
        rem -= 2 * s + 1;
        s++;
    }
    /* round(sqrt(n)) = s + 1 exactly when n >= s^2 + s + 1/4 */
    return s + (rem > s);
}

static int hit_sphere(const rt_object *o, const rt_ray *r, fx_t tmin,
                      fx_t tmax, fx_t *t, uint16_t *part)
{
    int64_t tca, h[3];
    uint64_t disc;
    fx_t best = tmax;
    if (!bsphere(&o->a, o->r, o->small, r, tmin, tmax, &tca, &disc, h))
        return 0;
    /* sq <= r < 2^31, as disc <= r^2. */
    const uint32_t sq =
        FX_SOFT_MUL64 && disc != 0 && disc < ((uint64_t)1 << 40)
            ? sqrt_round_small(disc)
            : fx_sqrt_q32(disc);
    /* In units of |d| = sqrt(1 + e): thc (1 - e / 2). For any int32 e
     * that is in [0, 2^31 + 2^29], so the 32-bit difference is exact
     * (#17: seed 2,591.8 -> 2,588.8 instructions a pixel on the M3,
     * with unit_corr's 32-bit form 7,005.1 -> 6,977.5 on the M0). */
    const int64_t thc = (uint32_t)(sq - (uint32_t)unit_corr((int32_t)sq,
                                                             r->e, 33));
    if (!take(tca - thc, tmin, &best) && !take(tca + thc, tmin, &best))
        return 0;
    *t = best;
    *part = 0;
    return 1;
}

/* q p, exact (the caller keeps it within 64 bits): where 64-bit products
 * are a library call (the M0), 32-bit operands take fx_imul64's inline
 * one when q fits. */
static inline int64_t mul_q(int64_t q, int32_t p)
{
    if (FX_SOFT_MUL64 && q == (int32_t)q)
        return fx_imul64((int32_t)q, p);
    return q * p;
}

/* hit_quad's distance t (Q16.16) to the plane of quad o, or 2^32 - 1
 * for none (a ray parallel to it or leaving its side, or t >= 2^32). */
static uint32_t quad_t(const rt_object *o, const rt_ray *r)
{
    const int flat = o->flat;
    int64_t den = flat ? fx_imul64(r->d.y, o->n.y) : fx_d3_dot_raw(r->d, o->n);
    if (den < RT_PAR_DOT && den > -RT_PAR_DOT)
        return 0xFFFFFFFFu;
    /* num = (a - o).n, the plane's distance from the origin, with 16 +
     * FX_UBITS fraction bits (|num| < 2^63): exact, as a grazing ray
     * needs it (a light on a tilted quad, seen nearly in its plane), and
     * at any distance from the scene's origin (n.a may leave Q16.16). A
     * flat quad's dist = n.a is exact; a small tilted quad and ray
     * (rt_object.small) have a - o within 32 bits. den = d.n with 2
     * FX_UBITS fraction bits. */
    int64_t num;
    if (flat)
        num = (int64_t)o->dist * FX_UONE - fx_imul64(r->o.y, o->n.y);
    else if (o->small && r->small)
        num = fx_imul64(o->a.x - r->o.x, o->n.x) +
              fx_imul64(o->a.y - r->o.y, o->n.y) +
              fx_imul64(o->a.z - r->o.z, o->n.z);
    else
        num = fx_pd_dot_diff_raw(o->a, r->o, o->n);
    if ((num < 0) != (den < 0))
        return 0xFFFFFFFFu;
    /* t = num 2^FX_UBITS / den in Q16.16, both of one sign, rounded: a
     * 64/32 division by den's top 32 bits (2^-31 relative, so grazing
     * rays keep their precision). A quotient of 2^32 or more is beyond
     * any tmax. The sd bits den drops are zero for an axis-aligned quad
     * (den = d.y 2^FX_UBITS, sd <= FX_UBITS), so there t is plane_t's. */
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
     * so this is plane_t's floor((n + floor(d / 2)) / d) exactly. */
    const uint64_t n2 = (un << lsh) + (ud >> 1);
    if ((n2 >> 32) >= ud)
        return 0xFFFFFFFFu;
    return fx_udiv64_32(n2, ud);
}

/* hit_quad's u and v for a quad or ray beyond the small range, or t
 * from 2^29: 0 when the point is surely outside. */
static inline int quad_uv_wide(const rt_object *o, const rt_ray *r,
                               fx_t tt, int64_t *pu64, int64_t *pv64)
{
    const int flat = o->flat;
    int64_t u, v;
    int64_t qx = (int64_t)r->o.x - o->a.x +
                 ((fx_imul64(tt, r->d.x) + UHALF) >> FX_UBITS);
    int64_t qz = (int64_t)r->o.z - o->a.z +
                 ((fx_imul64(tt, r->d.z) + UHALF) >> FX_UBITS);
    /* A point of the quad is a + s e1 + t e2 with s, t in [0, 1]:
     * each component of q = p - a is below 2^32. Past that it is
     * outside, and below it each product with a unit axis is below
     * 2^62. */
    const int64_t qlim = (int64_t)1 << 32;
    if (qx >= qlim || qx <= -qlim || qz >= qlim || qz <= -qlim)
        return 0;
    if (flat == 1) { /* pu = (0, 0, pu.z), pv = (pv.x, 0, 0) */
        u = mul_q(qz, o->pu.z);
        v = mul_q(qx, o->pv.x);
    } else if (flat == 2) { /* pu = (pu.x, 0, 0), pv = (0, 0, pv.z) */
        u = mul_q(qx, o->pu.x);
        v = mul_q(qz, o->pv.z);
    } else {
        int64_t qy = (int64_t)r->o.y - o->a.y +
                     ((fx_imul64(tt, r->d.y) + UHALF) >> FX_UBITS);
        if (qx == (int32_t)qx && qy == (int32_t)qy &&
            qz == (int32_t)qz) {
            /* The usual case: 32-bit operands, the same sums. */
            const int32_t x = (int32_t)qx, y = (int32_t)qy;
            const int32_t z = (int32_t)qz;
            u = fx_imul64(x, o->pu.x) + fx_imul64(y, o->pu.y) +
                fx_imul64(z, o->pu.z);
            v = fx_imul64(x, o->pv.x) + fx_imul64(y, o->pv.y) +
                fx_imul64(z, o->pv.z);
        } else {
            if (qy >= qlim || qy <= -qlim)
                return 0;
            /* |q| < 2^33 and |pu| = 1: every partial sum below
             * 2^63. */
            u = qx * o->pu.x + qy * o->pu.y + qz * o->pu.z;
            v = qx * o->pv.x + qy * o->pv.y + qz * o->pv.z;
        }
    }
    *pu64 = u;
    *pv64 = v;
    return 1;
}

/* The same out of line on the M0, where the rare path inline costs
 * hit_quad registers: compiled for size (RT_COLD; #17: seed 6,977.5 ->
 * 6,942.7 instructions a pixel, m0 text 65,000 -> 64,836). */
RT_COLD static int quad_uv_wide_cold(const rt_object *o, const rt_ray *r,
                                     fx_t tt, int64_t *pu64, int64_t *pv64)
{
    return quad_uv_wide(o, r, tt, pu64, pv64);
}

static int hit_quad(const rt_object *o, const rt_ray *r, fx_t tmin,
                    fx_t tmax, fx_t *t, uint16_t *part)
{
    /* A flat quad (rt_object.flat) has n = (0, n.y, 0): the same sums
     * without the zero terms. */
    const int flat = o->flat;
    uint32_t tq;
    if (flat && (o->n.y == FX_UONE || o->n.y == -FX_UONE)) {
        /* n.y = s 2^FX_UBITS: num = 2^FX_UBITS m and den = 2^FX_UBITS
         * s d.y for m = dist - s o.y, so the rounded quotient below is
         * floor((|m| 2^FX_UBITS + floor(|d.y| / 2)) / |d.y|) whatever
         * shift normalises den: the same t, without the 64-bit shifts
         * (the floor quad of most scenes; every camera ray tests it). */
        const int up = o->n.y > 0;
        const int32_t sdy = up ? r->d.y : -r->d.y;
        const uint32_t ud = (uint32_t)(sdy < 0 ? -sdy : sdy);
        const int64_t m =
            (int64_t)o->dist - (up ? r->o.y : -(int64_t)r->o.y);
        /* The side first: a ray heading away from the plane needs no
         * more (#17: seed 2,593.3 -> 2,591.8 instructions a pixel on the
         * M3, 7,008.1 -> 7,005.1 on the M0). */
        if ((m < 0) != (sdy < 0))
            return 0;
        /* |den| < RT_PAR_DOT */
        if (ud < ((uint32_t)1 << (FX_UBITS - 16)))
            return 0;
        /* |m| <= 2^32: below 2^62 */
        const uint64_t n2 = ((uint64_t)(m < 0 ? -m : m) << FX_UBITS) +
                            (ud >> 1);
        if ((n2 >> 32) >= ud)
            return 0;
        tq = fx_udiv64_32(n2, ud);
    } else {
        tq = quad_t(o, r);
        if (tq == 0xFFFFFFFFu)
            return 0;
    }
    /* On the M0 in 32 bits once tq fits (#17: 9 instructions a pixel;
     * on the M3 2 more). */
    if (FX_SOFT_MUL64 ? tq > (uint32_t)FX_MAX || (fx_t)tq <= tmin ||
                            (fx_t)tq >= tmax
                      : (int64_t)tq <= tmin || (int64_t)tq >= tmax)
        return 0;
    const fx_t tt = (fx_t)tq; /* below tmax, so it fits */
    int64_t u, v; /* 16 + FX_UBITS fraction bits */
    if (o->small && r->small && tq < ((uint32_t)1 << 29)) {
        /* The usual case, in 32 bits: a within 2^30 (its ball within
         * 2^29, rt_scene.c), o within 2^29 and t d rounded within 2^29,
         * so each component of q is below 2^31, and mul_round_u is the
         * rounding below (#17: 20 instructions a pixel on the M3, 2 on
         * the M0). */
        const int32_t x = r->o.x - o->a.x + mul_round_u(tt, r->d.x);
        const int32_t z = r->o.z - o->a.z + mul_round_u(tt, r->d.z);
        if (flat == 1) {
            u = fx_imul64(z, o->pu.z);
            v = fx_imul64(x, o->pv.x);
        } else if (flat == 2) {
            u = fx_imul64(x, o->pu.x);
            v = fx_imul64(z, o->pv.z);
        } else {
            const int32_t y = r->o.y - o->a.y + mul_round_u(tt, r->d.y);
            u = fx_imul64(x, o->pu.x) + fx_imul64(y, o->pu.y) +
                fx_imul64(z, o->pu.z);
            v = fx_imul64(x, o->pv.x) + fx_imul64(y, o->pv.y) +
                fx_imul64(z, o->pv.z);
        }
    } else {
        int64_t wu, wv; /* u and v themselves stay in registers */
        if (FX_SOFT_MUL64 ? !quad_uv_wide_cold(o, r, tt, &wu, &wv)
                          : !quad_uv_wide(o, r, tt, &wu, &wv))
            return 0;
        u = wu;
        v = wv;
    }
    /* The common case first, without the 64-bit bounds below: high
     * words of u and v in [0, lu 2^(FX_UBITS - 32)) and [0, lv
     * 2^(FX_UBITS - 32)) are inside them (lu, lv > 0, rt_scene.c; #17:
     * 25 and 52 instructions a pixel on the M3 and the M0). */
    if ((uint32_t)((uint64_t)u >> 32) <
            (uint32_t)o->lu >> ((32 - FX_UBITS) & 31) &&
        (uint32_t)((uint64_t)v >> 32) <
            (uint32_t)o->lv >> ((32 - FX_UBITS) & 31)) {
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
                       (((int64_t)o->lu + o->lv) >> 1);
    if (u < -sl || v < -sl || u > (int64_t)o->lu * FX_UONE + sl ||
        v > (int64_t)o->lv * FX_UONE + sl)
        return 0;
    *t = tt;
    *part = 0;
    return 1;
}

/* 1 / d for a unit component d != 0, to 32 bits whatever its size:
 * 1 / |d| = m 2^c / 2^63 for d normalised by c leading zeros. */
typedef struct {
    uint32_t m;
    int sh;  /* x / d in Q16.16 is (x m) >> sh, sh >= 2 */
    int neg; /* d < 0 */
} slab_inv;

static void slab_inv_set(slab_inv *v, int32_t d)
{
    uint32_t ud = (uint32_t)(d < 0 ? -(int64_t)d : d);
    int c = fx_clz32(ud);
    /* (2^63 - 1) / (ud 2^c) is below 2^32 as ud 2^c >= 2^31. */
    v->m = fx_udiv64_32(((uint64_t)1 << 63) - 1u, ud << c);
    v->sh = 63 - FX_UBITS - c;
    v->neg = d < 0;
}

/* x / d (Q16.16 x), within 2^-31 relative; saturates. |x m| < 2^63. */
static fx_t slab_t(const slab_inv *v, fx_t x)
{
    int64_t q = fx_iumul64(x, v->m) >> v->sh;
    return fx_sat64(v->neg ? -q : q);
}

static int hit_box(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                   fx_t *t, uint16_t *part)
{
    /* Arrays, not pointers into the structs: indexing &v.x past x is
     * undefined behaviour. */
    const fx_t lo[3] = { o->a.x, o->a.y, o->a.z };
    const fx_t hi[3] = { o->b.x, o->b.y, o->b.z };
    const fx_t org[3] = { r->o.x, r->o.y, r->o.z };
    const int32_t dir[3] = { r->d.x, r->d.y, r->d.z };
    fx_t tn = FX_MIN, tf = FX_MAX;
    int an = 0, af = 0;
    for (int i = 0; i < 3; i++) {
        if (dir[i] == 0) {
            /* Parallel to this slab: outside it, a miss; inside it (both
             * faces inclusive) no constraint on t. */
            if (org[i] < lo[i] || org[i] > hi[i])
                return 0;
            continue;
        }
        slab_inv inv;
        slab_inv_set(&inv, dir[i]);
        fx_t t1 = slab_t(&inv, fx_sub(lo[i], org[i]));
        fx_t t2 = slab_t(&inv, fx_sub(hi[i], org[i]));
        if (t1 > t2) {
            fx_t tmp = t1;
            t1 = t2;
            t2 = tmp;
        }
        if (t1 > tn) {
            tn = t1;
            an = i;
        }
        if (t2 < tf) {
            tf = t2;
            af = i;
        }
    }
    if (tn > tf)
        return 0;
    /* part: the axis of the face, entry face first, else exit face. Its
     * distance is then taken as hit_quad takes it for an axis-aligned
     * plane, so a face lying in a floor quad's plane ties with it exactly
     * (the earlier object wins, without z-fighting). */
    if (tn > tmin && tn < tmax) {
        int64_t tw = dir[an] == 0 ? tn
                     : plane_t(dir[an] > 0 ? lo[an] : hi[an], org[an],
                               dir[an]);
        if (tw > tmin && tw < tmax) {
            *t = (fx_t)tw;
            *part = (uint8_t)an;
            return 1;
        }
    }
    if (tf > tmin && tf < tmax) {
        int64_t tw = dir[af] == 0 ? tf
                     : plane_t(dir[af] > 0 ? hi[af] : lo[af], org[af],
                               dir[af]);
        if (tw > tmin && tw < tmax) {
            *t = (fx_t)tw;
            *part = (uint8_t)af;
            return 1;
        }
    }
    return 0;
}


/* The cylinder and cone solver: static functions in the unit that calls
 * them, where they are inlined as before (rt_upright.h). */
#include "rt_upright.h"

/* A mesh: its bounding sphere when ray and mesh are near the origin
 * (its margin covers the triangle test's rounding there, rt_mesh_check.c),
 * then its hierarchy; part is the triangle. */
RT_NOINLINE static int hit_mesh(const rt_object *o, const rt_ray *r,
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

int rt_intersect(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                 fx_t *t, uint16_t *part)
{
    /* A kind this build removed never hits (rendering refuses scenes
     * with one): its case falls out of the switch. */
    switch (o->kind) {
    case RT_SPHERE:
        if (!RT_HAS_SPHERE)
            break;
        return hit_sphere(o, r, tmin, tmax, t, part);
    case RT_QUAD:
        if (!RT_HAS_QUAD)
            break;
        /* The plane test itself is as cheap as a bounding sphere and
         * rejects rays leaving the plane's side at once. */
        return hit_quad(o, r, tmin, tmax, t, part);
    case RT_BOX: {
        int64_t tca, h[3];
        uint64_t disc;
        if (!RT_HAS_BOX)
            break;
        if (!bsphere(&o->bc, o->br, o->small, r, tmin, tmax, &tca, &disc, h))
            return 0;
        return hit_box(o, r, tmin, tmax, t, part);
    }
    case RT_CYLINDER:
    case RT_CONE:
        if (!RT_HAS_UPRIGHT)
            break;
        return hit_upright(o, r, tmin, tmax, t, part);
    case RT_MESH:
        if (!RT_HAS_MESH)
            break;
        return hit_mesh(o, r, tmin, tmax, t, part);
    default:
        break;
    }
    return 0;
}
