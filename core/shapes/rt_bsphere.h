/* SPDX-License-Identifier: MIT */
/*
 * rt_bsphere: the bounding-sphere test every shape but the quad starts
 * with (bsphere), and the small exact products it is built from. Static
 * inline: included once, by core/shapes/rt_intersect.c, where each shape's test
 * inlines it (the call and its nine arguments cost more than the common
 * rejection itself).
 */
#ifndef RT_BSPHERE_H
#define RT_BSPHERE_H

#include "rt_shape.h"

/* Half of a unit vector's last bit, for products rounded to Q16.16. */
#define UHALF ((int64_t)1 << (FX_UBITS - 1))

/* Near a bounding sphere's silhouette, whether |h| < r is decided by the
 * Q16.16 rounding of h (about an ulp per component), that is, by up to
 * 1e-5 units. There h is formed again with e more fraction bits, as many
 * as keep r 2^e within 30 bits (at most those the unit vector has):
 * oc - t d with the rounded t, whose error is along d and so changes
 * |h|^2 only by its square. Returns 0 for a miss, else 1 with the squared
 * half chord r^2 - |h|^2 as Q32.32 in *disc. Rare: compiled for size, and
 * as unlikely for its callers (RT_COLD; #17: 24 bytes less flash on the
 * an385, and 1.2 and 1.8 instructions a pixel fewer on the M3 and M0). */
RT_COLD static int bsphere_fine(const fx_vec3 *c, int64_t t,
                                const rt_ray *ray, fx_t r, uint64_t *disc)
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

/* t d 2^-FX_UBITS rounded to nearest (ties up), for |t| < 7 2^28 and
 * |d| <= 2^FX_UBITS (a closest approach and a unit component). Where
 * 64-bit products are built from 16-bit ones (the M0), the rounding is
 * taken from the partial products: t d = th dh 2^32 + (a + b) 2^16 +
 * tl dl for the middle ones a and b, whose sum may need 33 bits: each is
 * split at bit sh = FX_UBITS - 16 and the low parts summed with the top
 * of tl dl, all in 32 bits (#17: 10 instructions a pixel on the M0, as
 * against their 64-bit sum). */
static inline int32_t mul_round_u(int32_t t, int32_t d)
{
    if (FX_SOFT_MUL64 && FX_UBITS > 16) {
        const int32_t th = t >> 16, dh = d >> 16;
        const uint32_t tl = (uint32_t)t & 0xFFFFu, dl = (uint32_t)d & 0xFFFFu;
        const int sh = (FX_UBITS - 16) & 31;
        const int32_t a = th * (int32_t)dl, b = (int32_t)tl * dh;
        const uint32_t lo = (((uint32_t)a & ((1u << sh) - 1u)) +
                             ((uint32_t)b & ((1u << sh) - 1u)) +
                             ((tl * dl) >> 16) + (1u << ((sh - 1) & 31))) >>
                            sh;
        /* |th dh 2^(32 - FX_UBITS)| < 7 2^28. (The & 31 keeps the shifts
         * of the branch not taken non-negative for static analysis.) */
        return th * dh * (1 << (32 - FX_UBITS)) + (a >> sh) + (b >> sh) +
               (int32_t)lo;
    }
    return (int32_t)((fx_imul64(t, d) + UHALF) >> FX_UBITS);
}

/* mul_round_u for bsphere's h, where on the M0 the partial products
 * give the result another way: with sh = FX_UBITS - 16, ra = th dh 2^(32
 * - FX_UBITS) + a >> sh + b >> sh + tl dl >> FX_UBITS is below it by the
 * three dropped fractions plus a half, 0 to 3, which the result mod
 * 2^(32 - FX_UBITS) >= 4 gives: the top bits of the low word of t d +
 * 2^(FX_UBITS - 1), one 32-bit product. Each term is within 2^31; the
 * sum is taken mod 2^32, where the result is exact (#17: seed 6,933.8 ->
 * 6,925.5 instructions a pixel on the M0; in hit_quad's two products
 * mul_round_u does better). */
static inline int32_t mul_round_w(int32_t t, int32_t d)
{
    if (FX_SOFT_MUL64 && FX_UBITS > 16 && FX_UBITS <= 30) {
        const int32_t th = t >> 16, dh = d >> 16;
        const uint32_t tl = (uint32_t)t & 0xFFFFu, dl = (uint32_t)d & 0xFFFFu;
        const int sh = (FX_UBITS - 16) & 31, u = FX_UBITS & 31;
        const int32_t a = th * (int32_t)dl, b = (int32_t)tl * dh;
        const uint32_t ra = ((uint32_t)(th * dh) << ((32 - FX_UBITS) & 31)) +
                            (uint32_t)(a >> sh) + (uint32_t)(b >> sh) +
                            ((tl * dl) >> u);
        const uint32_t w = (uint32_t)t * (uint32_t)d + (1u << (u - 1));
        return (int32_t)(ra + (((w >> u) - ra) &
                               ((1u << ((32 - FX_UBITS) & 31)) - 1u)));
    }
    return (int32_t)((fx_imul64(t, d) + UHALF) >> FX_UBITS);
}

/* t e 2^-s rounded (ties up), s = 32 or 33: bsphere's closest approach
 * in units of |d| (s = 32) and hit_sphere's half chord (s = 33). e =
 * |d|^2 - 1 (rt_ray.e) is a few Q32.32 ulps: where 64-bit products are
 * built from 16-bit ones (the M0), t e = hi 2^16 + lo for hi = (t >> 16)
 * e and lo = (t mod 2^16) e, so the result is (hi + floor(lo / 2^16) +
 * 2^(s - 17)) >> (s - 16), as lo mod 2^16 cannot carry into it: all in
 * 32 bits, |hi| <= 2^30 and |lo| < 2^31 (#17: 26 -> 12 instructions a
 * call on the M0). */
static inline int32_t unit_corr(int32_t t, int32_t e, int s)
{
    if (FX_SOFT_MUL64 && e >= -32768 && e <= 32767) {
        const int32_t hi = (t >> 16) * e;
        const int32_t lo = (int32_t)((uint32_t)t & 0xFFFFu) * e;
        return (hi + (lo >> 16) + (1 << ((s - 17) & 31))) >> ((s - 16) & 31);
    }
    return (int32_t)((fx_imul64(t, e) + ((int64_t)1 << ((s - 1) & 63))) >>
                     (s & 63));
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
    uint64_t h2;
    if (small && ray->small) {
        /* The common case, in 32-bit operands (smull/smlal on a Cortex-M3):
         * the same values as the general path below. */
        int32_t ox = c.x - ray->o.x, oy = c.y - ray->o.y, oz = c.z - ray->o.z;
        int64_t q = fx_dot3_small(ox, oy, oz, ray->d.x, ray->d.y, ray->d.z);
        /* |t| <= |oc| < sqrt(3) 2^30, so t fits; t +- r may not. */
        int32_t t32 = (int32_t)((q + UHALF) >> FX_UBITS);
        /* Nothing for an exact unit d (e = 0; #17: 5 instructions a
         * pixel on either core). */
        if (ray->e != 0)
            t32 -= unit_corr(t32, ray->e, 32);
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
        int32_t hx = ox - mul_round_w(t32, ray->d.x);
        int32_t hy = oy - mul_round_w(t32, ray->d.y);
        int32_t hz = oz - mul_round_w(t32, ray->d.z);
        /* One ulp of slack (r < 2^29 here): the rounding of h cannot
         * decide this. On the M0 one unsigned compare a component: h +
         * rs, mod 2^32, is at most 2 rs exactly when |h| <= rs, as |h| <
         * 2^31 and rs < 2^30 (#17: 24 instructions a pixel; on the M3 2
         * more). */
        const int32_t rs = r + 1;
        const uint32_t urs = (uint32_t)rs;
        if (FX_SOFT_MUL64 ? (uint32_t)hx + urs > 2u * urs ||
                                (uint32_t)hy + urs > 2u * urs ||
                                (uint32_t)hz + urs > 2u * urs
                          : hx > rs || hx < -rs || hy > rs || hy < -rs ||
                                hz > rs || hz < -rs)
            return 0;
        h[0] = hx;
        h[1] = hy;
        h[2] = hz;
        /* 32-bit squares: one multiply each on a Cortex-M3, three
         * 16-bit ones inline on an M0 (fx_len2_raw). */
        h2 = fx_len2_raw(hx, hy, hz);
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
        h2 = (uint64_t)(h[0] * h[0]) + (uint64_t)(h[1] * h[1]) +
             (uint64_t)(h[2] * h[2]);
    }
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

#endif /* RT_BSPHERE_H */
