/* SPDX-License-Identifier: MIT */
/*
 * rt_intersect: ray-shape intersection and surface normals.
 *
 * Every shape is first tested against its bounding sphere with the
 * geometric form (closest approach, then the chord), which is exact in
 * 64 bits for any distance and culls most rays cheaply. Cylinders and cones
 * are then solved in a frame centred on that sphere and scaled by a power
 * of two, so their quadratic has coefficients near 1 whatever the object's
 * size or distance: the discriminant keeps its precision for small and far
 * objects alike. See docs/numerics.md.
 */
#include "rt_shape.h"

/* Q16.16 ulps (plus 2^-(FX_UBITS + 1) of the size) by which quads reach
 * past their edges. */
#define RT_QUAD_SLACK 2

/* Cylinders and cones are solved in a frame centred on the bounding
 * sphere and scaled by 2^-ushift, so that the sphere's radius is between
 * 1/2 and 1 there, with RT_FRAME_BITS (rt_scene.h) fraction bits: a frame
 * value is a world raw value times 2^(RT_FRAME_BITS - 16 - ushift). 24
 * bits keep every product below 2^63 for cone slopes up to 64. */

/* Frame ulps by which a cylinder's side reaches past its caps' planes,
 * and world ulps (at least frame ulps) by which the caps reach past the
 * side's radius: a cap's distance is a world value, so its point in the
 * frame is known only to a world ulp. No ray passes between the two. */
#define RT_RIM_SLACK 2

/* Below these (2^-8, as frame values with 16 fraction bits; see
 * RT_FRAME_BITS) a ray is within rounding of a cone's generator
 * direction: no linear root, and not treated as steep. */
#define RT_LINEAR_MIN_B ((int64_t)256 << (RT_FRAME_BITS - 16))
#define RT_STEEP_MIN_A 256

/* Half of a unit vector's last bit, for products rounded to Q16.16. */
#define UHALF ((int64_t)1 << (FX_UBITS - 1))

/* Near a bounding sphere's silhouette, whether |h| < r is decided by the
 * Q16.16 rounding of h (about an ulp per component), that is, by up to
 * 1e-5 units. There h is formed again with e more fraction bits, as many
 * as keep r 2^e within 30 bits (at most those the unit vector has):
 * oc - t d with the rounded t, whose error is along d and so changes
 * |h|^2 only by its square. Returns 0 for a miss, else 1 with the squared
 * half chord r^2 - |h|^2 as Q32.32 in *disc. */
RT_NOINLINE static int bsphere_fine(const fx_vec3 *c, int64_t t,
                                    const rt_ray *ray, fx_t r,
                                    uint64_t *disc)
{
    const int64_t ox = (int64_t)c->x - ray->o.x;
    const int64_t oy = (int64_t)c->y - ray->o.y;
    const int64_t oz = (int64_t)c->z - ray->o.z;
    int e = fx_clz32((uint32_t)r) - 2; /* >= 1, as r < 2^29 */
    if (e > FX_USHIFT)
        e = FX_USHIFT;
    const int sh = FX_UBITS - e; /* >= 16 */
    const int64_t sc = (int64_t)1 << e, half = (int64_t)1 << (sh - 1);
    /* |h| is near r, so each fine component is below 2^30 + 2^e. */
    const int64_t hx = ox * sc - ((t * ray->d.x + half) >> sh);
    const int64_t hy = oy * sc - ((t * ray->d.y + half) >> sh);
    const int64_t hz = oz * sc - ((t * ray->d.z + half) >> sh);
    const uint64_t h2 = (uint64_t)(hx * hx) + (uint64_t)(hy * hy) +
                        (uint64_t)(hz * hz);
    const uint64_t re = (uint64_t)r << e;
    const uint64_t r2 = re * re;
    if (h2 > r2)
        return 0;
    *disc = (r2 - h2) >> (2 * e);
    return 1;
}

/* Closest approach of the ray to the bounding sphere (c, r). Returns 0 when
 * the ray misses it or meets it only outside (tmin, tmax); else *tca
 * (Q16.16, may exceed the fx_t range), *disc = r^2 - |h|^2 (Q32.32, the
 * squared half chord) and h = c - (o + tca d). Cheap rejections come first:
 * most tests end at the first comparison (bsphere_fine decides the rays
 * that pass within rounding of the silhouette).
 * small: the object's centre and radius are fx_v3_small (rt_object.small).
 * Inlined into each shape's test: the call and its nine arguments cost
 * more than the common rejection itself. */
RT_ALWAYS_INLINE static inline int bsphere(const fx_vec3 *cp, fx_t r, int small,
                          const rt_ray *ray, fx_t tmin, fx_t tmax,
                          int64_t *tca, uint64_t *disc, int64_t h[3])
{
    const fx_vec3 c = *cp;
    int64_t t;
    if (small && ray->small) {
        /* The common case, in 32-bit operands (smull/smlal on a Cortex-M3):
         * the same values as the general path below. */
        int32_t ox = c.x - ray->o.x, oy = c.y - ray->o.y, oz = c.z - ray->o.z;
        int64_t q = fx_imul64(ox, ray->d.x) + fx_imul64(oy, ray->d.y) +
                    fx_imul64(oz, ray->d.z);
        /* |t| <= |oc| < sqrt(3) 2^30, so t fits; t +- r may not. */
        int32_t t32 = (int32_t)((q + UHALF) >> FX_UBITS);
        t32 -= (int32_t)((fx_imul64(t32, ray->e) + ((int64_t)1 << 31)) >> 32);
#if FX_HAVE_OVERFLOW_BUILTINS
        /* The same tests in 32 bits (r >= 0): t32 + r <= tmin is
         * t32 <= tmin - r, false when that underflows; t32 - r >= tmax is
         * false when t32 - r underflows. */
        fx_t lim, lo;
        if (!__builtin_sub_overflow(tmin, r, &lim) && t32 <= lim)
            return 0;
        if (!__builtin_sub_overflow(t32, r, &lo) && lo >= tmax)
            return 0;
#else
        if ((int64_t)t32 + r <= tmin || (int64_t)t32 - r >= tmax)
            return 0;
#endif
        /* Each h component is bounded by |oc| (h is a projection). */
        int32_t hx = ox - (int32_t)((fx_imul64(t32, ray->d.x) + UHALF) >> FX_UBITS);
        int32_t hy = oy - (int32_t)((fx_imul64(t32, ray->d.y) + UHALF) >> FX_UBITS);
        int32_t hz = oz - (int32_t)((fx_imul64(t32, ray->d.z) + UHALF) >> FX_UBITS);
        /* One ulp of slack (r < 2^29 here): the rounding of h cannot
         * decide this. */
        const int32_t rs = r + 1;
        if (hx > rs || hx < -rs || hy > rs || hy < -rs || hz > rs ||
            hz < -rs)
            return 0;
        h[0] = hx;
        h[1] = hy;
        h[2] = hz;
        t = t32;
    } else {
        int64_t ox = (int64_t)c.x - ray->o.x;
        int64_t oy = (int64_t)c.y - ray->o.y;
        int64_t oz = (int64_t)c.z - ray->o.z;
        /* Each |oc| component is below 2^32 and |d| is 1: every partial
         * sum is below |oc| 2^FX_UBITS < 2^63. */
        int64_t q = ox * ray->d.x + oy * ray->d.y + oz * ray->d.z;
        t = (q + UHALF) >> FX_UBITS;
        t -= (t * ray->e + ((int64_t)1 << 31)) >> 32;
        if (t + r <= tmin || t - r >= tmax)
            return 0; /* wholly behind the origin or beyond tmax */
        h[0] = ox - ((t * ray->d.x + UHALF) >> FX_UBITS);
        h[1] = oy - ((t * ray->d.y + UHALF) >> FX_UBITS);
        h[2] = oz - ((t * ray->d.z + UHALF) >> FX_UBITS);
        const int64_t rs = (int64_t)r + 1;
        if (h[0] > rs || h[0] < -rs || h[1] > rs || h[1] < -rs ||
            h[2] > rs || h[2] < -rs)
            return 0;
    }
    uint64_t h2 = (uint64_t)(h[0] * h[0]) + (uint64_t)(h[1] * h[1]) +
                  (uint64_t)(h[2] * h[2]);
    uint64_t r2 = (uint64_t)(fx_imul64(r, r));
    /* |h|^2 is off by at most about 2 |h| + 1 (Q32.32): a ray that close
     * to the silhouette is decided by bsphere_fine. */
    const uint64_t margin = 2 * (uint64_t)r + 8;
    if (FX_USHIFT > 0 && r < ((fx_t)1 << 29) &&
        (h2 > r2 ? h2 - r2 : r2 - h2) <= margin) {
        if (!bsphere_fine(cp, t, ray, r, disc))
            return 0;
    } else {
        if (h2 > r2)
            return 0;
        *disc = r2 - h2;
    }
    *tca = t;
    return 1;
}

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

static int hit_sphere(const rt_object *o, const rt_ray *r, fx_t tmin,
                      fx_t tmax, fx_t *t, uint8_t *part)
{
    int64_t tca, h[3];
    uint64_t disc;
    fx_t best = tmax;
    if (!bsphere(&o->a, o->r, o->small, r, tmin, tmax, &tca, &disc, h))
        return 0;
    int64_t thc = fx_sqrt_q32(disc);
    /* In units of |d| = sqrt(1 + e): thc (1 - e / 2). */
    thc -= (thc * r->e + ((int64_t)1 << 32)) >> 33;
    if (!take(tca - thc, tmin, &best) && !take(tca + thc, tmin, &best))
        return 0;
    *t = best;
    *part = 0;
    return 1;
}

static int hit_quad(const rt_object *o, const rt_ray *r, fx_t tmin,
                    fx_t tmax, fx_t *t, uint8_t *part)
{
    /* A flat quad (rt_object.flat) has n = (0, n.y, 0): the same sums
     * without the zero terms. */
    const int flat = o->flat;
    int64_t den = flat ? fx_imul64(r->d.y, o->n.y) : fx_d3_dot_raw(r->d, o->n);
    if (den < RT_PAR_DOT && den > -RT_PAR_DOT)
        return 0;
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
        return 0;
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
        return 0;
    /* Rounded to nearest; for an axis-aligned quad ud is even or sd = 0,
     * so this is plane_t's floor((n + floor(d / 2)) / d) exactly. */
    const uint64_t n2 = (un << lsh) + (ud >> 1);
    if ((n2 >> 32) >= ud)
        return 0;
    uint32_t tq = fx_udiv64_32(n2, ud);
    if ((int64_t)tq <= tmin || (int64_t)tq >= tmax)
        return 0;
    const fx_t tt = (fx_t)tq; /* below tmax, so it fits */
    int64_t qx = (int64_t)r->o.x - o->a.x +
                 ((fx_imul64(tt, r->d.x) + UHALF) >> FX_UBITS);
    int64_t qz = (int64_t)r->o.z - o->a.z +
                 ((fx_imul64(tt, r->d.z) + UHALF) >> FX_UBITS);
    /* A point of the quad is a + s e1 + t e2 with s, t in [0, 1]: each
     * component of q = p - a is below 2^32. Past that it is outside, and
     * below it each product with a unit axis is below 2^62. */
    const int64_t qlim = (int64_t)1 << 32;
    if (qx >= qlim || qx <= -qlim || qz >= qlim || qz <= -qlim)
        return 0;
    int64_t u, v; /* 16 + FX_UBITS fraction bits */
    if (flat == 1) { /* pu = (0, 0, pu.z), pv = (pv.x, 0, 0) */
        u = qz * o->pu.z;
        v = qx * o->pv.x;
    } else if (flat == 2) { /* pu = (pu.x, 0, 0), pv = (0, 0, pv.z) */
        u = qx * o->pu.x;
        v = qz * o->pv.z;
    } else {
        int64_t qy = (int64_t)r->o.y - o->a.y +
                     ((fx_imul64(tt, r->d.y) + UHALF) >> FX_UBITS);
        if (qx == (int32_t)qx && qy == (int32_t)qy && qz == (int32_t)qz) {
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
            /* |q| < 2^33 and |pu| = 1: every partial sum below 2^63. */
            u = qx * o->pu.x + qy * o->pu.y + qz * o->pu.z;
            v = qx * o->pv.x + qy * o->pv.y + qz * o->pv.z;
        }
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
                   fx_t *t, uint8_t *part)
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


/* Bit length of v (0 for 0). */
static int rt_bitlen64_i(uint64_t v)
{
    return v ? 64 - fx_clz64(v) : 0;
}

/* v 2^-n: rounded to nearest for n > 0, exact for n <= 0 (the callers
 * keep v 2^-n within 64 bits). */
static int64_t shift_round(int64_t v, int n)
{
    if (n <= 0)
        return v * ((int64_t)1 << -n);
    return (v + ((int64_t)1 << (n - 1))) >> n;
}

/* A product of two frame values back to RT_FRAME_BITS fraction bits,
 * rounded to nearest. */
static inline int64_t frame_round(int64_t v)
{
    return (v + ((int64_t)1 << (RT_FRAME_BITS - 1))) >> RT_FRAME_BITS;
}

/* n 2^RT_FRAME_BITS / d, truncated, for |n| < 2^31 and d != 0 (|d| <
 * 2^31); a quotient of 2^32 or more (256 frame units, far outside the
 * bounding sphere) comes back as +-2^32. */
static int64_t frame_div(int64_t n, int64_t d)
{
    const int neg = (n < 0) != (d < 0);
    const uint64_t un = (uint64_t)(n < 0 ? -n : n) << RT_FRAME_BITS;
    const uint32_t ud = (uint32_t)(d < 0 ? -d : d);
    int64_t q = (un >> 32) >= ud ? (int64_t)1 << 32
                                 : (int64_t)fx_udiv64_32(un, ud);
    return neg ? -q : q;
}

/* Roots of a t^2 + 2 b t + c = 0 (RT_FRAME_BITS fraction bits),
 * cancellation-free: q = -(b + sign(b) sqrt(b^2 - ac)), roots q / a and
 * c / q. Returns the count: one root when a = 0 (a ray along a cone's
 * generator). a, b and c are each rounded to half an ulp, so b^2 - ac is
 * known only to |b| + (|a| + |c|) / 2 (plus the rounding of the
 * products): a discriminant negative by less is a double root (a
 * tangent), not a miss; a wider tolerance would admit rays passing beside
 * a cone's apex. `real`: the roots are known to be real (a ray steeper
 * than a cone's side meets both nappes), so any negative discriminant is
 * rounding. */
RT_ALWAYS_INLINE static inline int quadratic(int64_t a, int64_t b,
                                             int64_t c, int real,
                                             int64_t root[2])
{
    /* A common scale brings the coefficients within 30 bits (only a
     * flat cone's need it); the roots do not change. */
    const uint64_t ua = (uint64_t)(a < 0 ? -a : a);
    const uint64_t ub = (uint64_t)(b < 0 ? -b : b);
    const uint64_t uc = (uint64_t)(c < 0 ? -c : c);
    const uint64_t any = ua | ub | uc;
    const int sh = any >> 30 ? 34 - fx_clz64(any) : 0;
    int64_t lin_min = RT_LINEAR_MIN_B;
    if (sh > 0) {
        a = shift_round(a, sh);
        b = shift_round(b, sh);
        c = shift_round(c, sh);
        lin_min >>= sh;
    }
    if (a == 0) {
        /* One root, -c / 2b; b and c both shrink as the ray nears the
         * generator itself, and their ratio becomes noise: none then. */
        if (b > -lin_min && b < lin_min)
            return 0;
        root[0] = root[1] = frame_div(-c, 2 * b);
        return 1;
    }
    int64_t disc = b * b - a * c; /* each product below 2^60 */
    if (disc < 0) {
        int64_t aa = a < 0 ? -a : a, ab = b < 0 ? -b : b;
        int64_t ac = c < 0 ? -c : c;
        if (!real && disc < -(ab + (aa + ac) / 2 + 1))
            return 0;
        disc = 0;
    }
    const int64_t sq = (int64_t)fx_isqrt64((uint64_t)disc);
    const int64_t q = b >= 0 ? -(b + sq) : sq - b; /* |q| < 2^31 */
    if (q == 0) {
        root[0] = root[1] = 0;
        return 1;
    }
    int64_t r0 = frame_div(q, a), r1 = frame_div(c, q);
    root[0] = r0 < r1 ? r0 : r1;
    root[1] = r0 < r1 ? r1 : r0;
    return 2;
}

/* A cylinder's or cone's frame for one ray (hit_upright): the frame is
 * centred on the bounding sphere and scaled by 2^-ushift, with
 * RT_FRAME_BITS fraction bits; a frame value is a world raw value times
 * 2^sf. */
typedef struct {
    int sf;
    int32_t p[3];   /* the ray's point at tca, o + tca d - bc */
    int32_t d[3];   /* its direction */
    int32_t yb, yt; /* the base's and the top's (apex's) height */
} upright_frame;

/* Sets *f for object o and ray r, whose bounding-sphere tca is given. */
RT_ALWAYS_INLINE static inline void frame_set(upright_frame *f,
                                              const rt_object *o,
                                              const rt_ray *r, int64_t tca)
{
    const int sf = RT_FRAME_BITS - 16 - o->ushift;
    f->sf = sf;
    /* The closest point p = o + tca d - bc in the frame, from the exact
     * o - bc and tca d (not bsphere's rounded h). Frame values near the
     * sphere are below 2^25: 32-bit operands. */
    const int dsh = FX_UBITS - sf;
    f->p[0] = (int32_t)(shift_round(tca * r->d.x, dsh) -
                        shift_round((int64_t)o->bc.x - r->o.x, -sf));
    f->p[1] = (int32_t)(shift_round(tca * r->d.y, dsh) -
                        shift_round((int64_t)o->bc.y - r->o.y, -sf));
    f->p[2] = (int32_t)(shift_round(tca * r->d.z, dsh) -
                        shift_round((int64_t)o->bc.z - r->o.z, -sf));
    /* The direction with RT_FRAME_BITS fraction bits. */
    const int ush = FX_UBITS - RT_FRAME_BITS;
    f->d[0] = (int32_t)shift_round(r->d.x, ush);
    f->d[1] = (int32_t)shift_round(r->d.y, ush);
    f->d[2] = (int32_t)shift_round(r->d.z, ush);
    /* Base and top, exact from the object's fields (the centre bc.y is
     * a.y + h/2 rounded down). */
    f->yb = (int32_t)shift_round((int64_t)o->a.y - o->bc.y, -sf);
    f->yt = (int32_t)shift_round((int64_t)o->a.y + o->h - o->bc.y, -sf);
}

/* A cone's side root where its radius k (yt - y) is below this (2^-6 of
 * the frame, as a frame value), near the apex or anywhere on a needle, is
 * solved again in a finer frame (thin_side); rt_object.rinv holds the
 * height below the apex where that is. */
#define RT_THIN_SIDE ((int64_t)1 << (RT_FRAME_BITS - 6))

/* A ray steeper than a cone's side by more than rounding (its a < 0):
 * it meets each nappe once. */
static int cone_steep(int64_t a)
{
    return a < -((int64_t)RT_STEEP_MIN_A << (RT_FRAME_BITS - 16));
}

/* Where a cone is thin, near its apex or along a needle, the side's
 * quadratic formed at the ray's point nearest the bounding sphere's
 * centre is ill-conditioned: the roots there split as the square root of
 * the discriminant, whose rounding (an ulp of the frame, for coefficients
 * far larger than the radius there) moves them by about 2^-12 of the
 * frame, and decides whether a ray passing the apex, or grazing a needle,
 * meets the cone: a shadow ray towards a light at the apex or on a
 * needle's rim passes it at up to EPS. thin_side solves the side again
 * about the ray's point at frame distance s0 from tca (a root of the
 * first solve): from that point, exact in 64 bits (world units with 16 +
 * FX_UBITS fraction bits, from the ray's own integers), it takes x, z and
 * the radius w = k (yt - y) there, all small, in a frame 2^e times finer
 * than the cone's, e as large as keeps them within 2^23: the rounding then
 * moves the roots 2^-e as much. Returns 1 with *best set for a side hit, 0
 * for none, or -1 when that point is not thin after all or a root leaves
 * the fine frame's range (a ray within rounding of a generator's
 * direction): then the first solve's roots stand. */
static int thin_side(const rt_object *o, const rt_ray *r, int64_t tca,
                     const upright_frame *fr, int64_t s0, fx_t tmin,
                     fx_t *best)
{
    const upright_frame f = *fr;
    const int32_t *d = f.d;
    const int sf = f.sf;
    const int64_t ta = tca + shift_round(s0, sf); /* world, Q16.16 */
    /* o - bc and ta d are each below 2^62 with FX_UBITS more fraction
     * bits (|o - bc| < 2^32, |ta| < 2^32 raw), and their sum is a point
     * within the bounding sphere: x and z from the axis, and y46 the
     * height below the apex. */
    const int64_t ay = (int64_t)o->a.y + o->h - o->bc.y;
    const int64_t x46 = ((int64_t)r->o.x - o->bc.x) * FX_UONE + ta * r->d.x;
    const int64_t z46 = ((int64_t)r->o.z - o->bc.z) * FX_UONE + ta * r->d.z;
    const int64_t y46 =
        ay * FX_UONE - (((int64_t)r->o.y - o->bc.y) * FX_UONE + ta * r->d.y);
    /* w46 = k y46, k with RT_FRAME_BITS fraction bits: y46 split so that
     * neither product overflows (k < 2^30). */
    const int64_t yh = y46 >> RT_FRAME_BITS;
    const int64_t yl = y46 - yh * ((int64_t)1 << RT_FRAME_BITS);
    if (yh > (INT64_MAX >> 31) || yh < -(INT64_MAX >> 31))
        return -1;
    const int64_t w46 = o->k * yh + ((o->k * yl) >> RT_FRAME_BITS);
    uint64_t m = 0;
    m |= (uint64_t)(x46 < 0 ? -x46 : x46);
    m |= (uint64_t)(z46 < 0 ? -z46 : z46);
    m |= (uint64_t)(w46 < 0 ? -w46 : w46);
    /* A frame value is a 46-bit world value times 2^(sf - FX_UBITS); the
     * fine frame's 2^e more. Not thin after all: the first solve stands. */
    const int64_t fm = shift_round((int64_t)m, FX_UBITS - sf);
    if (fm >= 2 * RT_THIN_SIDE)
        return -1;
    int e = 23 + FX_UBITS - sf - rt_bitlen64_i(m);
    e = e < 0 ? 0 : (e > 24 ? 24 : e);
    const int n = FX_UBITS - sf - e;
    const int32_t qx = (int32_t)shift_round(x46, n);
    const int32_t qz = (int32_t)shift_round(z46, n);
    const int64_t qw = shift_round(w46, n);
    const int64_t qy = shift_round(y46, n); /* height below the apex */
    /* The cone's coefficients there, as in hit_upright; a is the same at
     * any scale. */
    const int32_t kdy = (int32_t)frame_round(fx_imul64(o->k, d[1]));
    const int64_t a = frame_round(fx_imul64(d[0], d[0]) +
                                  fx_imul64(d[2], d[2])) -
                      frame_round(fx_imul64(kdy, kdy));
    const int64_t b = frame_round(fx_imul64(qx, d[0]) + fx_imul64(qz, d[2])) +
                      frame_round(qw * kdy);
    const int64_t c =
        frame_round(fx_imul64(qx, qx) + fx_imul64(qz, qz) - qw * qw);
    const int steep = cone_steep(a);
    int64_t root[2];
    int nr = quadratic(a, b, c, steep, root);
    if (steep && nr == 2) {
        if ((d[1] > 0) != (root[0] < root[1]))
            root[0] = root[1];
        nr = 1;
    }
    const int64_t lim = (int64_t)1 << 32; /* frame_div's saturation */
    for (int i = 0; i < nr; i++)
        if (root[i] >= lim || root[i] <= -lim)
            return -1;
    /* The base plane (with the rim slack) in fine units below the apex. */
    const int64_t base =
        ((int64_t)f.yt - f.yb + RT_RIM_SLACK) * ((int64_t)1 << e);
    for (int i = 0; i < nr; i++) {
        const int64_t y = qy - frame_round(root[i] * d[1]);
        if ((y < 0 && !steep) || y > base)
            continue; /* the mirrored nappe, or below the base */
        if (take(ta + shift_round(root[i], sf + e), tmin, best))
            return 1;
    }
    return 0;
}

/* The caps of a cylinder or cone seen by the ray of frame f (discs at the
 * base, bottom, and at the top, a cylinder's only) nearer than *best: 1
 * with *best and *part (1 + cap) set for a hit. ur is the radius in the
 * frame. */
RT_ALWAYS_INLINE static inline int upright_caps(const rt_object *o,
                                                const rt_ray *r, int64_t tca,
                                                const upright_frame *f,
                                                int32_t ur, fx_t tmin,
                                                fx_t *best, uint8_t *part)
{
    const int sf = f->sf;
    const int64_t rim = (int64_t)RT_RIM_SLACK << (sf > 0 ? sf : 0);
    int found = 0;
    if (r->d.y == 0)
        return 0;
    for (int cap = 0; cap < 2; cap++) {
        if (!(o->caps & (cap ? RT_CAP_TOP : RT_CAP_BOTTOM)))
            continue;
        /* t in world units, as hit_quad computes it for a plane y =
         * const: a cap in a floor quad's plane (a shape standing on the
         * floor) gives the very same t, so the tie goes to the earlier
         * object instead of flipping with rounding. */
        int64_t cy = cap ? (int64_t)o->a.y + o->h : o->a.y;
        int64_t tw = plane_t(cy, r->o.y, r->d.y);
        if (tw <= tmin || tw >= *best)
            continue; /* take() would refuse it */
        if (tw - tca > o->br || tca - tw > o->br)
            continue; /* outside the bounding sphere; keeps tl small */
        const int64_t tl = shift_round(tw - tca, -sf);
        const int64_t x = f->p[0] + frame_round(tl * f->d[0]);
        const int64_t z = f->p[2] + frame_round(tl * f->d[2]);
        /* The caps reach RT_RIM_SLACK world ulps (at least as many frame
         * ulps) past the side's radius for a ray that meets them from
         * outside, which the side might let through at the rim. A ray
         * that meets a cap from inside the solid (up at the top, down at
         * the bottom) crossed the side first if it passed outside the
         * rim: no slack, or a ray passing just outside would see the
         * cap's inner face. */
        const int64_t slack = (cap ? r->d.y < 0 : r->d.y > 0) ? 2 * rim : 0;
        if (x * x + z * z > fx_imul64(ur, ur) + ur * slack)
            continue;
        if (take(tw, tmin, best)) {
            *part = (uint8_t)(1 + cap);
            found = 1;
        }
    }
    return found;
}

/* hit_upright's answer again for a cone whose side had a root s0 where
 * the cone is thin: the side's hit is thin_side's, and the caps are
 * tested again against it; or, if thin_side declines, the answer found
 * (with *t and *part) stands. */
RT_COLD static int upright_thin(const rt_object *o, const rt_ray *r,
                                int64_t tca, int64_t s0, fx_t tmin,
                                fx_t tmax, int found, fx_t *t, uint8_t *part)
{
    fx_t best = tmax;
    uint8_t pt = 0;
    upright_frame f;
    frame_set(&f, o, r, tca);
    int side = thin_side(o, r, tca, &f, s0, tmin, &best);
    if (side < 0)
        return found;
    const int32_t ur = (int32_t)shift_round(o->r, -f.sf);
    found = upright_caps(o, r, tca, &f, ur, tmin, &best, &pt) | side;
    if (found) {
        *t = best;
        *part = pt;
    }
    return found;
}

/* Cylinder (kind RT_CYLINDER) or cone, in the object's frame. */
static int hit_upright(const rt_object *o, const rt_ray *r, fx_t tmin,
                       fx_t tmax, fx_t *t, uint8_t *part)
{
    int64_t tca, h[3];
    uint64_t disc;
    fx_t best = tmax;
    int64_t root[2];
    int found = 0, cone = RT_HAS_CONE && o->kind == RT_CONE;
    if (!bsphere(&o->bc, o->br, o->small, r, tmin, tmax, &tca, &disc, h))
        return 0;
    upright_frame f;
    frame_set(&f, o, r, tca);
    const int32_t px = f.p[0], py = f.p[1], pz = f.p[2];
    const int32_t dx = f.d[0], dy = f.d[1], dz = f.d[2];
    const int32_t yb = f.yb, yt = f.yt;
    /* The radius in the frame, exact. */
    const int32_t ur = (int32_t)shift_round(o->r, -f.sf);
    const int64_t one = (int64_t)1 << RT_FRAME_BITS;

    /* Side: x^2 + z^2 = R(y)^2, R = ur (cylinder) or k (yt - y) (cone). */
    const int64_t pp = fx_imul64(px, px) + fx_imul64(pz, pz);
    int64_t a = frame_round(fx_imul64(dx, dx) + fx_imul64(dz, dz));
    int64_t b = frame_round(fx_imul64(px, dx) + fx_imul64(pz, dz));
    int64_t c = frame_round(pp - fx_imul64(ur, ur));
    if (cone) {
        /* o->k is the slope with RT_FRAME_BITS fraction bits, below 2^30;
         * ky below 2^31 (|yt - py| < 2^25). */
        const int32_t kdy = (int32_t)frame_round(fx_imul64(o->k, dy));
        const int64_t ky = frame_round(fx_imul64(o->k, yt - py));
        a -= frame_round(fx_imul64(kdy, kdy));
        b += frame_round(ky * kdy);
        c = frame_round(pp - ky * ky);
    }
    /* Clearly steeper than the side (not within rounding of a
     * generator's direction, where one root is far and saturates). */
    const int steep = cone && cone_steep(a);
    int n = quadratic(a, b, c, steep, root);
    if (steep && n == 2) {
        /* A ray steeper than the side meets each nappe once: the root
         * with the lower y is on the cone, however near the apex rounding
         * puts it (a y <= top threshold there lets rays through). */
        if ((dy > 0) != (root[0] < root[1]))
            root[0] = root[1];
        n = 1;
    }
    for (int i = 0; i < n; i++) {
        /* Roots of a real hit lie within the bounding sphere's chord. */
        if (root[i] > 4 * one || root[i] < -4 * one)
            continue;
        int64_t y = py + frame_round(root[i] * dy);
        /* The side reaches RT_RIM_SLACK frame ulps past each cap's
         * plane, as the caps reach past the side's radius below: the
         * two are rounded separately, and no ray may pass between. A
         * cone's apex meets no cap, so it gets no slack: past it lies
         * the mirrored nappe. */
        if (y < yb - RT_RIM_SLACK ||
            (y > yt + (cone ? 0 : RT_RIM_SLACK) && !steep))
            continue;
        /* World distance: tca + root 2^(ushift - (F - 16)). */
        if (take(tca + shift_round(root[i], f.sf), tmin, &best)) {
            *part = 0;
            found = 1;
            break;
        }
    }
    found |= upright_caps(o, r, tca, &f, ur, tmin, &best, part);
    if (found)
        *t = best;
    /* A side root where a cone is thin (near its apex, or on a needle) is
     * as much rounding's as the ray's: the answer is then upright_thin's.
     * (A ray within rounding of the cone there has a root: quadratic()
     * takes a discriminant within its rounding for a tangent's.) */
    for (int i = 0; cone && i < n; i++)
        if (root[i] <= 4 * one && root[i] >= -4 * one &&
            py + frame_round(root[i] * dy) > yt - (int64_t)o->rinv)
            return upright_thin(o, r, tca, root[i], tmin, tmax, found, t,
                                part);
    return found;
}

int rt_intersect(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                 fx_t *t, uint8_t *part)
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
    default:
        break;
    }
    return 0;
}

fx_dir3 rt_normal(const rt_object *o, fx_vec3 p, uint8_t part)
{
    switch (o->kind) {
    case RT_SPHERE: {
        /* (p - a) / r, then one Newton step (|p - a| is r to within the
         * rounding of p, a relative 2^-16 / r; fx_d3_renorm normalises in
         * full when that is more than 2^-15). */
        const int sh = 33 - fx_clz32((uint32_t)o->r); /* b + 1 */
        const int64_t half = (int64_t)1 << (sh - 1);
        const fx_vec3 v = fx_v3_sub(p, o->a);
        return fx_d3_renorm(
            fx_d3((int32_t)((fx_iumul64(v.x, o->rinv) + half) >> sh),
                  (int32_t)((fx_iumul64(v.y, o->rinv) + half) >> sh),
                  (int32_t)((fx_iumul64(v.z, o->rinv) + half) >> sh)));
    }
    case RT_QUAD:
        return o->n;
    case RT_BOX: {
        /* part is the axis of the face; its side is the one p lies on. */
        const fx_t pc[3] = { p.x, p.y, p.z };
        const fx_t cc[3] = { o->bc.x, o->bc.y, o->bc.z };
        int32_t v[3] = { 0, 0, 0 };
        v[part] = pc[part] > cc[part] ? FX_UONE : -FX_UONE;
        return fx_d3(v[0], v[1], v[2]);
    }
    default: {
        if (part == 1)
            return fx_d3(0, -FX_UONE, 0);
        if (part == 2)
            return fx_d3(0, FX_UONE, 0);
        fx_t x = fx_sub(p.x, o->a.x), z = fx_sub(p.z, o->a.z);
        fx_t y = 0;
        if (o->kind == RT_CONE) {
            fx_t rho = (fx_t)fx_sqrt_q32((uint64_t)(fx_imul64(x, x)) +
                                         (uint64_t)(fx_imul64(z, z)));
            if (rho == 0)
                return fx_d3(0, FX_UONE, 0); /* apex */
            /* y = k rho, o->k with RT_FRAME_BITS fraction bits. */
            return fx_d3_normalize64(x, frame_round(fx_imul64(o->k, rho)),
                                     z);
        }
        return fx_d3_normalize(fx_v3(x, y, z));
    }
    }
}
