/* SPDX-License-Identifier: MIT */
/*
 * fx_dir: unit vectors (ray directions, surface normals, directions to
 * lights, the camera frame) with FX_UBITS fraction bits: RT_UNIT_BITS,
 * 30 by default (Q2.30), each component an int32 within +-2^FX_UBITS.
 * Positions, distances and colours stay Q16.16 (fx_vec3): the error of a
 * picture comes from its directions (docs/accuracy.md), and a
 * position-by-direction product still fits one 32x32->64 multiply.
 * fx_dir3 is its own type, so that the compiler tells a unit vector from
 * a position. Every operation states its rounding; none can overflow for
 * unit inputs.
 */
#ifndef FX_DIR_H
#define FX_DIR_H

#include "fx_vec.h"

#if RT_UNIT_BITS < 16 || RT_UNIT_BITS > 30
#error "RT_UNIT_BITS must be 16..30 (fraction bits of unit vectors)"
#endif

#define FX_UBITS RT_UNIT_BITS
#define FX_UONE ((int32_t)1 << FX_UBITS)

/* Bits a unit component has beyond Q16.16, and half of its last one. */
#define FX_USHIFT (FX_UBITS - 16)
#define FX_UHALF16 (FX_USHIFT ? (int32_t)1 << (FX_USHIFT - 1) : 0)

typedef struct {
    int32_t x, y, z;
} fx_dir3;

/* Builds a unit vector from its components (FX_UBITS fraction bits). */
static inline fx_dir3 fx_d3(int32_t x, int32_t y, int32_t z)
{
    fx_dir3 d;
    d.x = x;
    d.y = y;
    d.z = z;
    return d;
}

/* -a; exact (components are far from INT32_MIN). */
static inline fx_dir3 fx_d3_neg(fx_dir3 a)
{
    return fx_d3(-a.x, -a.y, -a.z);
}

/* The components as plain integers, for the scale-free operations (a
 * cross product's direction, a normalisation). */
static inline fx_vec3 fx_d3_raw(fx_dir3 a)
{
    return fx_v3(a.x, a.y, a.z);
}

/* One component in Q16.16, rounded to nearest (ties toward +infinity). */
static inline fx_t fx_u_to_fx(int32_t c)
{
    return (fx_t)((c + FX_UHALF16) >> FX_USHIFT);
}

/* a in Q16.16, each component rounded as fx_u_to_fx. */
static inline fx_vec3 fx_d3_to_v3(fx_dir3 a)
{
    return fx_v3(fx_u_to_fx(a.x), fx_u_to_fx(a.y), fx_u_to_fx(a.z));
}

/* a.b exact, with 2 FX_UBITS fraction bits: below 2^61 in magnitude. */
static inline int64_t fx_d3_dot_raw(fx_dir3 a, fx_dir3 b)
{
    return fx_imul64(a.x, b.x) + fx_imul64(a.y, b.y) + fx_imul64(a.z, b.z);
}

/* a.b with FX_UBITS fraction bits, rounded to nearest (ties up). */
static inline int32_t fx_d3_dotu(fx_dir3 a, fx_dir3 b)
{
    return (int32_t)((fx_d3_dot_raw(a, b) + ((int64_t)1 << (FX_UBITS - 1))) >>
                     FX_UBITS);
}

/* a.b in Q16.16, rounded to nearest (ties up). */
static inline fx_t fx_d3_dot(fx_dir3 a, fx_dir3 b)
{
    return (fx_t)((fx_d3_dot_raw(a, b) +
                   ((int64_t)1 << (2 * FX_UBITS - 17))) >>
                  (2 * FX_UBITS - 16));
}

/* p.d exact, with 16 + FX_UBITS fraction bits, for any Q16.16 p and unit
 * d: each product is below 2^61, and every partial sum is bounded by
 * |p| |d| < 2^63 (Cauchy-Schwarz), so nothing overflows. */
static inline int64_t fx_pd_dot_raw(fx_vec3 p, fx_dir3 d)
{
    return fx_imul64(p.x, d.x) + fx_imul64(p.y, d.y) + fx_imul64(p.z, d.z);
}

/* (a - b).d exact, with 16 + FX_UBITS fraction bits, for any Q16.16 a and
 * b and unit d: each |a - b| component is below 2^32, so each product is
 * below 2^62 and every partial sum is bounded by |a - b| |d| < 2^63. */
static inline int64_t fx_pd_dot_diff_raw(fx_vec3 a, fx_vec3 b, fx_dir3 d)
{
    return ((int64_t)a.x - b.x) * d.x + ((int64_t)a.y - b.y) * d.y +
           ((int64_t)a.z - b.z) * d.z;
}

/* p.d in Q16.16, rounded to nearest (ties up); saturates. */
static inline fx_t fx_pd_dot(fx_vec3 p, fx_dir3 d)
{
    return fx_sat64((fx_pd_dot_raw(p, d) + ((int64_t)1 << (FX_UBITS - 1))) >>
                    FX_UBITS);
}

/* a + s c for a Q16.16 a and s and a unit component c (|c| <= 1): the
 * product rounded once to nearest (ties up), which fits 32 bits as
 * |s c| <= |s|; only the sum saturates. */
static inline fx_t fx_madd_u(fx_t a, int32_t c, fx_t s)
{
    int64_t p = fx_imul64(s, c);
    return fx_add(a, (fx_t)((p + ((int64_t)1 << (FX_UBITS - 1))) >> FX_UBITS));
}

/* a + s d per component (fx_madd_u): a point along a ray. */
static inline fx_vec3 fx_v3_madd_d(fx_vec3 a, fx_dir3 d, fx_t s)
{
    return fx_v3(fx_madd_u(a.x, d.x, s), fx_madd_u(a.y, d.y, s),
                 fx_madd_u(a.z, d.z, s));
}

/* fx_v3_madd_d for a point a within 2^29 (fx_v3_small) and 0 <= s < 2^30:
 * the sum stays below 2^31, so the same values without the saturating
 * add. A hit point along a ray from a small origin. */
static inline fx_vec3 fx_v3_madd_d_near(fx_vec3 a, fx_dir3 d, fx_t s)
{
    const int64_t h = (int64_t)1 << (FX_UBITS - 1);
    return fx_v3(a.x + (fx_t)((fx_imul64(s, d.x) + h) >> FX_UBITS),
                 a.y + (fx_t)((fx_imul64(s, d.y) + h) >> FX_UBITS),
                 a.z + (fx_t)((fx_imul64(s, d.z) + h) >> FX_UBITS));
}

/* The top half ah of a = ah 2^16 + al for the balanced low half al =
 * (int16_t)a in [-2^15, 2^15): a >> 16, plus 1 when al < 0, so within
 * [-2^15, 2^15] with no wrap even near INT32_MAX. */
static inline int32_t fx_hi_bal(int32_t a)
{
    return (a >> 16) - ((int32_t)(int16_t)a >> 31);
}

/* ax^2 + ay^2 + az^2, exact for any int32 values (at most 3 * 2^62).
 * Without a 32x32->64 multiply (FX_SOFT_MUL64, the M0) from balanced
 * 16-bit halves a = ah 2^16 + al (fx_hi_bal): a^2 = ah^2 2^32 + ah al
 * 2^17 + al^2. ah^2 and al^2 are at most 2^30, so their columns of three
 * sum in a word each; ah al is within [-2^30, 2^30), so two of them sum
 * in an int32 and the third joins on its own. No absolute values. */
static inline uint64_t fx_len2_raw(int32_t ax, int32_t ay, int32_t az)
{
    if (!FX_SOFT_MUL64)
        return (uint64_t)fx_imul64(ax, ax) + (uint64_t)fx_imul64(ay, ay) +
               (uint64_t)fx_imul64(az, az);
    const int32_t xh = fx_hi_bal(ax), xl = (int16_t)ax, yh = fx_hi_bal(ay);
    const int32_t yl = (int16_t)ay, zh = fx_hi_bal(az), zl = (int16_t)az;
    const uint32_t hh = (uint32_t)(xh * xh) + (uint32_t)(yh * yh) +
                        (uint32_t)(zh * zh); /* <= 3 * 2^30 */
    const uint32_t ll = (uint32_t)(xl * xl) + (uint32_t)(yl * yl) +
                        (uint32_t)(zl * zl); /* <= 3 * 2^30 */
    const int32_t mxy = xh * xl + yh * yl, mz = zh * zl;
    /* m 2^17 = (m >> 15) 2^32 + (m mod 2^15) 2^17; the sum is the exact
     * (non-negative) value, so the top word wraps back. */
    return fx_pair64(hh + (uint32_t)(mxy >> 15) + (uint32_t)(mz >> 15), ll) +
           ((uint32_t)mxy << 17) + ((uint32_t)mz << 17);
}

/* |d|^2 - 1 of a unit vector in Q32.32, rounded down: what rounding left
 * of its length (rt_ray.h). Each component within two ulps: far below
 * 2^31 for every FX_UBITS. */
static inline int32_t fx_d3_unit_err(fx_dir3 d)
{
    /* The value fits an int32, and 2^(2 FX_UBITS) is a multiple of the
     * divisor: it is bits 2 FX_UBITS - 32 and up of |d|^2, mod 2^32.
     * For FX_UBITS = 30 on the M0, from the halves of fx_len2_raw: |d|^2
     * = hh 2^32 + mm 2^17 + ll, so the bits are 16 hh + floor((mm +
     * floor(ll / 2^17)) / 2^11): |ch cl| <= (|c| + 2^15) / 2 keeps mm
     * and the sum within an int32 while |d.x| + |d.y| + |d.z| < 2^32 -
     * 2^17, as for any unit vector, and no 64-bit value is formed. */
    if (FX_SOFT_MUL64 && FX_UBITS == 30) {
        const int32_t xh = fx_hi_bal(d.x), xl = (int16_t)d.x;
        const int32_t yh = fx_hi_bal(d.y), yl = (int16_t)d.y;
        const int32_t zh = fx_hi_bal(d.z), zl = (int16_t)d.z;
        const uint32_t hh = (uint32_t)(xh * xh) + (uint32_t)(yh * yh) +
                            (uint32_t)(zh * zh);
        const uint32_t ll = (uint32_t)(xl * xl) + (uint32_t)(yl * yl) +
                            (uint32_t)(zl * zl);
        const int32_t mm = xh * xl + yh * yl + zh * zl;
        return (int32_t)(hh * 16u +
                         (uint32_t)((mm + (int32_t)(ll >> 17)) >> 11));
    }
    return (int32_t)(uint32_t)(fx_len2_raw(d.x, d.y, d.z) >>
                               (2 * FX_UBITS - 32));
}

/* Unit vector along (x, y, z), at any scale; the zero vector gives zero.
 * Each component is within 2 ulps (2^-FX_UBITS) of the true value and
 * never past +-1. Inputs beyond 31 bits are first rounded to 31 bits
 * (a relative change below 2^-31). */
fx_dir3 fx_d3_normalize64(int64_t x, int64_t y, int64_t z);

/* Unit vector along (x, y, z), 32-bit components (as fx_d3_normalize64). */
fx_dir3 fx_d3_normalize3(int32_t x, int32_t y, int32_t z);

/* Unit vector along v (any scale, as fx_d3_normalize64). Inline, so that
 * the call takes the components in registers, with no wrapper and no
 * copy of the struct on the way. */
static inline fx_dir3 fx_d3_normalize(fx_vec3 v)
{
    return fx_d3_normalize3(v.x, v.y, v.z);
}

/* c e / 2, rounded, for one component of fx_d3_renorm: c (1 - e / 2)
 * is c less this. On the M0, with |e| <= 2^(FX_UBITS - 15) and |c| <
 * 2^31, c e = ch e 2^16 + cl e in two 32-bit products (cl e within
 * +-2^(FX_UBITS + 1)); the rounding term is a multiple of 2^16, so the
 * shift splits exactly. Elsewhere the top word of c e 2^(32 -
 * FX_UBITS) (|e 2^(32 - FX_UBITS)| <= 2^17) is h = floor(c e /
 * 2^FX_UBITS), and the rounded quotient is floor((h + 1) / 2): one
 * multiply and no 64-bit add or shift. */
static inline int32_t fx_renorm_p(int32_t c, int32_t e)
{
    if (FX_SOFT_MUL64)
        return ((c >> 16) * e +
                (((int32_t)((uint32_t)c & 0xFFFFu) * e) >> 16) +
                (FX_UONE >> 16)) >> (FX_UBITS - 15);
    const int32_t e2 = e * ((int32_t)1 << (32 - FX_UBITS));
    return ((int32_t)(fx_imul64(c, e2) >> 32) + 1) >> 1;
}

/* v kept within +-1 in one test: v ^ sg is |v| - 1 for v < 0 and v
 * otherwise, below FX_UONE unless |v| > FX_UONE or v = FX_UONE, and then
 * the result is +-FX_UONE with the sign of v. */
static inline int32_t fx_unit_clamp(int32_t v)
{
    const int32_t sg = v >> 31;
    if ((uint32_t)(v ^ sg) < (uint32_t)FX_UONE)
        return v;
    return (FX_UONE ^ sg) - sg;
}

/* (x, y, z), each kept within +-1 (fx_unit_clamp): out of line, for the
 * rare vector that needs it. */
fx_dir3 fx_d3_clamp(int32_t x, int32_t y, int32_t z);

/* Unit vector along u, a vector already within 2^-15 of unit length (a
 * mirror direction, a sphere's scaled offset): one Newton step u (3 -
 * |u|^2) / 2, which leaves an error of about (|u| - 1)^2, for a fraction
 * of a normalisation's work. Farther from unit length it normalises in
 * full. e = |u|^2 - 1 with FX_UBITS fraction bits, rounded down, from s
 * = the exact |u|^2 - 1 + 2^-(FX_UBITS + 1) in units of 2^-2 FX_UBITS:
 * its range test is one unsigned compare (s + L below 2 L + 2^FX_UBITS
 * for L = 2^(2 FX_UBITS - 15)), and e a 32-bit value from s's two words,
 * so that each c e is one 32-bit factor (from a 64-bit e the compiler
 * forms each product as a 64x64 one). */
static inline fx_dir3 fx_d3_renorm(fx_dir3 u)
{
    const uint64_t s = fx_len2_raw(u.x, u.y, u.z) -
                       ((uint64_t)1 << (2 * FX_UBITS)) +
                       ((uint64_t)1 << (FX_UBITS - 1));
    const uint64_t lim = (uint64_t)1 << (2 * FX_UBITS - 15);
    if (s + lim >= 2 * lim + ((uint64_t)1 << FX_UBITS))
        return fx_d3_normalize(fx_d3_raw(u));
    const int32_t e = (int32_t)(((uint32_t)s >> FX_UBITS) |
                                ((uint32_t)(s >> 32) << (32 - FX_UBITS)));
    /* One test for the three clamps, which a renormalised vector nearly
     * never needs: each c - p within [-1, 1) is one unsigned compare of
     * the biased value (wrapping), and 2 FX_UONE is a power of two, so the
     * three can be or-ed together. */
    const int32_t x = u.x - fx_renorm_p(u.x, e);
    const int32_t y = u.y - fx_renorm_p(u.y, e);
    const int32_t z = u.z - fx_renorm_p(u.z, e);
    if ((((uint32_t)x + (uint32_t)FX_UONE) |
         ((uint32_t)y + (uint32_t)FX_UONE) |
         ((uint32_t)z + (uint32_t)FX_UONE)) < 2u * (uint32_t)FX_UONE)
        return fx_d3(x, y, z);
    return fx_d3_clamp(x, y, z);
}

/* Unit vector along a x b, from the exact 64-bit cross product (any
 * scale of a and b, so a unit vector's fx_d3_raw may be passed); the zero
 * vector if a and b are parallel. */
fx_dir3 fx_d3_cross_unit(fx_vec3 a, fx_vec3 b);

#endif /* FX_DIR_H */
