/* SPDX-License-Identifier: MIT */
/*
 * rt_bsphere: the bounding-sphere test every shape but the quad starts
 * with (bsphere), and the rounded products the hit tests share. Static
 * inline, in each shape's unit: the test's common rejection costs less
 * than a call with its nine arguments would.
 */
#ifndef RT_BSPHERE_H
#define RT_BSPHERE_H

#include "rt_ray.h"

/* Half of a unit vector's last bit, for products rounded to Q16.16. */
#define UHALF ((int64_t)1 << (FX_UBITS - 1))

/* Near a bounding sphere's silhouette, whether |h| < r is decided by the
 * Q16.16 rounding of h (about an ulp per component), that is, by up to
 * 1e-5 units. There h is formed again with e more fraction bits, as many
 * as keep r 2^e within 30 bits (at most those the unit vector has):
 * oc - t d with the rounded t, whose error is along d and so changes
 * |h|^2 only by its square. Returns the squared half chord r^2 - |h|^2
 * as Q32.32 (below 2^58), or RT_BSPHERE_MISS for a miss. Rare, and out
 * of line (rt_bsphere.c); a value, not a pointer to the caller's, so that
 * no local of the caller escapes and its own last call can be a jump. */
#define RT_BSPHERE_MISS UINT64_MAX
uint64_t rt_bsphere_fine(const fx_vec3 *c, int64_t t, const rt_ray *ray,
                         fx_t r);

/* Accepts t if tmin < t < tmax and nearer than the best so far. */
static inline int take(int64_t t, fx_t tmin, fx_t *best)
{
    if (t > tmin && t < *best) {
        *best = (fx_t)t;
        return 1;
    }
    return 0;
}

/* t d 2^-FX_UBITS rounded to nearest (ties up), for |t| < 7 2^28 and
 * |d| <= 2^FX_UBITS (a distance and a unit component). */
static inline int32_t mul_round_u(int32_t t, int32_t d)
{
    return fx_mul_round(t, d, FX_UBITS);
}

/* q p, exact (the caller keeps it within 64 bits): a 32-bit q takes
 * fx_imul64, which needs no 64-bit multiply. */
static inline int64_t mul_q(int64_t q, int32_t p)
{
    if (q == (int32_t)q)
        return fx_imul64((int32_t)q, p);
    return q * p;
}

/* bsphere's closest approach t and h = c - (o + t d) with |h|^2 in *h2,
 * for a sphere or ray beyond the 32-bit range: 0 when the ray surely
 * misses it or meets it only outside (tmin, tmax). */
static inline int bsphere_wide(const fx_vec3 *cp, fx_t r, const rt_ray *ray,
                               fx_t tmin, fx_t tmax, int64_t *tp,
                               int64_t h[3], uint64_t *h2)
{
    const fx_vec3 c = *cp;
    const int64_t ox = (int64_t)c.x - ray->o.x;
    const int64_t oy = (int64_t)c.y - ray->o.y;
    const int64_t oz = (int64_t)c.z - ray->o.z;
    /* Each |oc| component is below 2^32 and |d| is 1: every partial sum
     * is below |oc| 2^FX_UBITS < 2^63. */
    const int64_t q = ox * ray->d.x + oy * ray->d.y + oz * ray->d.z;
    int64_t t = (q + UHALF) >> FX_UBITS;
    t -= (t * ray->e + ((int64_t)1 << 31)) >> 32;
    if (t + r <= tmin || t - r >= tmax)
        return 0; /* wholly behind the origin or beyond tmax */
    h[0] = ox - ((t * ray->d.x + UHALF) >> FX_UBITS);
    h[1] = oy - ((t * ray->d.y + UHALF) >> FX_UBITS);
    h[2] = oz - ((t * ray->d.z + UHALF) >> FX_UBITS);
    const int64_t rs = (int64_t)r + 1;
    if (h[0] > rs || h[0] < -rs || h[1] > rs || h[1] < -rs || h[2] > rs ||
        h[2] < -rs)
        return 0;
    *h2 = (uint64_t)(h[0] * h[0]) + (uint64_t)(h[1] * h[1]) +
          (uint64_t)(h[2] * h[2]);
    *tp = t;
    return 1;
}

/* Closest approach of the ray to the bounding sphere (c, r). Returns 0 when
 * the ray misses it or meets it only outside (tmin, tmax); else *tca
 * (Q16.16, may exceed the fx_t range), *disc = r^2 - |h|^2 (Q32.32, the
 * squared half chord) and h = c - (o + tca d). Cheap rejections come first:
 * most tests end at the first comparison (rt_bsphere_fine decides the rays
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
        /* The common case, in 32-bit operands: the same values as the
         * general path below. */
        int32_t ox = c.x - ray->o.x, oy = c.y - ray->o.y, oz = c.z - ray->o.z;
        int64_t q = fx_dot3_small(ox, oy, oz, ray->d.x, ray->d.y, ray->d.z);
        /* |t| <= |oc| < sqrt(3) 2^30, so t fits; t +- r may not. */
        int32_t t32 = (int32_t)((q + UHALF) >> FX_UBITS);
        /* In units of |d|: t (1 - e); nothing for an exact unit d. */
        if (ray->e != 0)
            t32 -= fx_mul_small_round(t32, ray->e, 32);
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
        int32_t hx = ox - mul_round_u(t32, ray->d.x);
        int32_t hy = oy - mul_round_u(t32, ray->d.y);
        int32_t hz = oz - mul_round_u(t32, ray->d.z);
        /* One ulp of slack (r < 2^29 here): the rounding of h cannot
         * decide this. One unsigned compare a component: h + rs, mod
         * 2^32, is at most 2 rs exactly when |h| <= rs, as |h| < 2^31
         * and rs < 2^30. */
        const uint32_t urs = (uint32_t)r + 1u;
        if ((uint32_t)hx + urs > 2u * urs || (uint32_t)hy + urs > 2u * urs ||
            (uint32_t)hz + urs > 2u * urs)
            return 0;
        h[0] = hx;
        h[1] = hy;
        h[2] = hz;
        /* Squares of 32-bit values (fx_len2_raw). */
        h2 = fx_len2_raw(hx, hy, hz);
        t = t32;
    } else if (!bsphere_wide(&c, r, ray, tmin, tmax, &t, h, &h2)) {
        return 0;
    }
    uint64_t r2 = (uint64_t)(fx_imul64(r, r));
    /* |h|^2 is off by at most about 2 |h| + 1 (Q32.32): a ray that close
     * to the silhouette is decided by rt_bsphere_fine. */
    const uint64_t margin = 2 * (uint64_t)r + 8;
    if (FX_USHIFT > 0 && r < ((fx_t)1 << 29) &&
        (h2 > r2 ? h2 - r2 : r2 - h2) <= margin) {
        const uint64_t d = rt_bsphere_fine(cp, t, ray, r);
        if (d == RT_BSPHERE_MISS)
            return 0;
        *disc = d;
    } else {
        if (h2 > r2)
            return 0;
        *disc = r2 - h2;
    }
    *tca = t;
    return 1;
}

#endif /* RT_BSPHERE_H */
