/* SPDX-License-Identifier: MIT */
/*
 * rt_ray: a ray, the distances it is tested with, and where a ray leaving
 * a surface starts. Internal to the core.
 */
#ifndef RT_RAY_H
#define RT_RAY_H

#include "rt_scene.h"

/* Smallest hit distance and secondary-ray offset: 1/512 (see
 * docs/render-model.md and docs/numerics.md). */
#define RT_EPS ((fx_t)128)
#define RT_EPS_LOG2 7u /* RT_EPS = 2^RT_EPS_LOG2 */

/* |d.n| below this (2 FX_UBITS fraction bits, fx_d3_dot_raw) counts as
 * parallel: 2^-16. */
#define RT_PAR_DOT ((int64_t)1 << (2 * FX_UBITS - 16))

/* An object index meaning "none" (nothing skipped, no known origin). */
#define RT_NO_OBJECT 0xFFFFu

typedef struct {
    fx_vec3 o;     /* origin */
    fx_dir3 d;     /* unit direction */
    int32_t e;     /* fx_d3_unit_err(d): |d|^2 - 1 in Q32.32 */
    uint8_t small; /* fx_v3_small(o): the 32-bit intersection paths apply */
} rt_ray;

/* Rounding leaves |d| a little off 1, by e = fx_d3_unit_err(d) (far
 * below 2^-28 for 30 fraction bits). The closest approach is
 * (oc.d) / |d|^2, not oc.d: without the factor its error is e |oc|; with
 * t (1 - e) it is e^2 |oc|. The bounding-sphere test applies it. */

/* x0 y0 + x1 y1 + x2 y2 exact for any int32 values whose sum fits
 * int64: from 16-bit halves (x = h 2^16 + l, 0 <= l < 2^16), the high,
 * middle and low partial products summed apart (each a 32-bit product:
 * |h h| <= 2^30, |h l| < 2^31, l l < 2^32) and joined once, wrapping.
 * For the M0 (FX_SOFT_MUL64): one call instead of three to a
 * 41-instruction product; out of line, as inline it grew the shading
 * loop's frame, which every bounce level pays (288 bytes of stack on the
 * seed, for 0.6 % fewer instructions). */
RT_NOINLINE static int64_t rt_dot3_soft(int32_t x0, int32_t x1, int32_t x2,
                                        int32_t y0, int32_t y1, int32_t y2)
{
    const int32_t xh0 = x0 >> 16, xh1 = x1 >> 16, xh2 = x2 >> 16;
    const int32_t yh0 = y0 >> 16, yh1 = y1 >> 16, yh2 = y2 >> 16;
    const uint32_t xl0 = (uint32_t)x0 & 0xFFFFu;
    const uint32_t xl1 = (uint32_t)x1 & 0xFFFFu;
    const uint32_t xl2 = (uint32_t)x2 & 0xFFFFu;
    const uint32_t yl0 = (uint32_t)y0 & 0xFFFFu;
    const uint32_t yl1 = (uint32_t)y1 & 0xFFFFu;
    const uint32_t yl2 = (uint32_t)y2 & 0xFFFFu;
    const int64_t hh =
        (int64_t)(xh0 * yh0) + (int64_t)(xh1 * yh1) + (int64_t)(xh2 * yh2);
    const int64_t mid = (int64_t)(xh0 * (int32_t)yl0) +
                        (int64_t)((int32_t)xl0 * yh0) +
                        (int64_t)(xh1 * (int32_t)yl1) +
                        (int64_t)((int32_t)xl1 * yh1) +
                        (int64_t)(xh2 * (int32_t)yl2) +
                        (int64_t)((int32_t)xl2 * yh2);
    const uint64_t ll =
        (uint64_t)(xl0 * yl0) + (uint64_t)(xl1 * yl1) + (uint64_t)(xl2 * yl2);
    return (int64_t)(((uint64_t)hh << 32) + ((uint64_t)mid << 16) + ll);
}

/* (a c + 2^(s-1)) >> s modulo 2^32, for 17 <= s <= 32 and |c| <= 2^30
 * (a unit component), in 32-bit pieces: with a = ah 2^16 + al and c = ch
 * 2^16 + cl (al, cl unsigned), a c = hh 2^32 + (b1 + b2) 2^16 + l; only
 * the terms below 2^k (k = s - 16) are added before the shift, each
 * below 2^31 in magnitude as |ch| <= 2^14, and 2^(s-1) is a multiple of
 * 2^16. Four 16x16 multiplies inline: where the core has no 64-bit
 * multiply (FX_SOFT_MUL64, the M0) not a call (FX_MUL64_CALL) and the
 * 64-bit rounding shift. */
static inline int32_t rt_mulsh_soft(int32_t a, int32_t c, unsigned s)
{
    const unsigned k = s - 16;
    const int32_t ah = a >> 16, ch = c >> 16;
    const uint32_t al = (uint32_t)a & 0xFFFFu, cl = (uint32_t)c & 0xFFFFu;
    const int32_t hh = ah * ch, b1 = ah * (int32_t)cl, b2 = (int32_t)al * ch;
    const uint32_t lr = ((al * cl) >> 16) + ((1u << (s - 1)) >> 16);
    const int32_t low = (b1 & (int32_t)((1u << k) - 1)) + b2 + (int32_t)lr;
    return (int32_t)(((uint32_t)hh << (16 - k)) + (uint32_t)(b1 >> k) +
                     (uint32_t)(low >> k));
}

/* One term of rt_dot3_small: x y split at 16 bits with signed low
 * halves, x = xh 2^16 + xl with -2^15 <= xl < 2^15, added to the running
 * sums of the high, the two middle and the low partial products. */
#define RT_DOT_STEP(xv, yv)                                                  \
    do {                                                                     \
        const int32_t xl_ = (int16_t)(xv), yl_ = (int16_t)(yv);              \
        const int32_t xh_ = ((xv)-xl_) >> 16, yh_ = ((yv)-yl_) >> 16;        \
        hh += xh_ * yh_;                                                     \
        m1 += xh_ * yl_;                                                     \
        m2 += xl_ * yh_;                                                     \
        ll += xl_ * yl_;                                                     \
    } while (0)

/* x0 y0 + x1 y1 + x2 y2 exact for components within 2^30 + 2^16 (unit
 * vectors, and offsets below 2^30 against them). Where 64-bit products
 * are built from 16-bit ones (the M0), from signed low halves: |xh| <=
 * 2^14 + 1 and |xl| <= 2^15, so the three high products and each set of
 * three middle ones sum below 2^31 in 32 bits (3 (2^14 + 1) 2^15 <
 * 2^31), and only the low ones (up to 2^30 each) need 64 bits (#17: 125
 * -> 94 instructions a call on the M0). */
static inline int64_t rt_dot3_small(int32_t x0, int32_t x1, int32_t x2,
                                    int32_t y0, int32_t y1, int32_t y2)
{
    if (!FX_SOFT_MUL64)
        return fx_imul64(x0, y0) + fx_imul64(x1, y1) + fx_imul64(x2, y2);
    int32_t hh = 0, m1 = 0, m2 = 0;
    int64_t ll = 0;
    RT_DOT_STEP(x0, y0);
    RT_DOT_STEP(x1, y1);
    RT_DOT_STEP(x2, y2);
    const uint64_t mid1 = fx_pair64((uint32_t)(m1 >> 16), (uint32_t)m1 << 16);
    const uint64_t mid2 = fx_pair64((uint32_t)(m2 >> 16), (uint32_t)m2 << 16);
    return (int64_t)(fx_pair64((uint32_t)hh, 0) + mid1 + mid2 +
                     (uint64_t)ll);
}
#undef RT_DOT_STEP

/* rt_dot3_small out of line, for the shading loop on the M0: inline it
 * grew the frame every bounce level pays. */
RT_NOINLINE static int64_t rt_dot3_unit_soft(int32_t x0, int32_t x1,
                                             int32_t x2, int32_t y0,
                                             int32_t y1, int32_t y2)
{
    return rt_dot3_small(x0, x1, x2, y0, y1, y2);
}

/* fx_d3_dot_raw(a, b), the same exact value (rt_dot3_unit_soft on the
 * M0). */
static inline int64_t rt_dot_raw(fx_dir3 a, fx_dir3 b)
{
    if (!FX_SOFT_MUL64)
        return fx_d3_dot_raw(a, b);
    return rt_dot3_unit_soft(a.x, a.y, a.z, b.x, b.y, b.z);
}

/* fx_pd_dot_raw(p, d), the same exact value (rt_dot3_soft on the M0). */
static inline int64_t rt_pd_dot_raw(fx_vec3 p, fx_dir3 d)
{
    if (!FX_SOFT_MUL64)
        return fx_pd_dot_raw(p, d);
    return rt_dot3_soft(p.x, p.y, p.z, d.x, d.y, d.z);
}

/* Sets a ray's origin and unit direction, and the two values its tests
 * derive from them (fx_d3_unit_err, fx_v3_small). */
static inline void rt_ray_set(rt_ray *r, fx_vec3 o, fx_dir3 d)
{
    r->o = o;
    r->d = d;
    r->e = fx_d3_unit_err(d);
    r->small = (uint8_t)fx_v3_small(o);
}

/* How far along the normal a ray leaving object o starts off its surface,
 * 2^k (this k; a power of two, so offsetting needs no product):
 * shading offsets secondary and shadow rays by it, and the direction grids
 * (rt_dirgrid.c) widen their cones by it, so the two must agree.
 * Cylinders and cones are solved in a frame whose unit is 2^ushift ulps,
 * so a ray's root on its own surface is off by about that much over the
 * cosine of its angle to the surface. Starting it 4 frame units off the
 * surface (never less than RT_EPS) keeps that root behind it at any angle:
 * no acne on large open shapes' inner walls. At most 2^17. */
static inline unsigned rt_origin_log2(const rt_object *o)
{
    if ((o->kind == RT_CYLINDER || o->kind == RT_CONE) && o->ushift > 4)
        return (unsigned)o->ushift + 2u;
    return RT_EPS_LOG2;
}

/* The offset itself, 2^rt_origin_log2(o) (7 to 17). */
static inline fx_t rt_origin_offset(const rt_object *o)
{
    return (fx_t)1 << rt_origin_log2(o);
}

/* One component of a + s c for s = +-2^k (sign neg), k <= 17, and a unit
 * component c, rounded as fx_madd_u: s c 2^-FX_UBITS + 1/2 rounded down
 * is (+-c + 2^(U-1-k)) >> (U - k) exactly (U = FX_UBITS), or +-c 2^(k-U)
 * for k >= U: a shift instead of a 64-bit product (a call on the M0). */
static inline fx_t rt_madd_pow2(fx_t a, int32_t c, unsigned k, int neg)
{
    const int32_t v = neg ? -c : c; /* exact: |c| <= 2^FX_UBITS */
    if (FX_UBITS <= 17 && k >= FX_UBITS) /* k <= 17 */
        return fx_add(a, v * ((int32_t)1 << (k - FX_UBITS)));
    return fx_add(a, (v + ((int32_t)1 << (FX_UBITS - 1 - k))) >>
                         (FX_UBITS - k));
}

/* fx_v3_madd_d(a, d, neg ? -2^k : 2^k), by rt_madd_pow2. */
static inline fx_vec3 rt_v3_madd_pow2(fx_vec3 a, fx_dir3 d, unsigned k,
                                      int neg)
{
    return fx_v3(rt_madd_pow2(a.x, d.x, k, neg),
                 rt_madd_pow2(a.y, d.y, k, neg),
                 rt_madd_pow2(a.z, d.z, k, neg));
}

#endif /* RT_RAY_H */
