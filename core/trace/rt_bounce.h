/* SPDX-License-Identifier: MIT */
/*
 * rt_bounce: the directions of secondary rays: the mirror direction and
 * Snell's law, with total internal reflection. Both work at the full
 * FX_UBITS of the unit vectors (fx_dir.h). Internal.
 */
#ifndef RT_BOUNCE_H
#define RT_BOUNCE_H

#include "rt_ray.h"

/* One component of d - 2 k n, rounded once from its exact value:
 * (d 2^U / 2 - k n + 2^(U-2)) >> (U - 1). Within 32 bits, as the mirror
 * image of a unit vector is one. The low U - 1 bits of d 2^U / 2 are 0,
 * so that is d + ((2^(U-2) - k n) >> (U - 1)), added in 32 bits (the
 * sum fits): given nk = -k, one multiply-accumulate and no 64-bit shift
 * of d. */
static inline int32_t rt_mirror_c(int32_t d, int32_t nk, int32_t n)
{
    const unsigned s = FX_UBITS >= 18 ? FX_UBITS - 1 : 17; /* in range */
    if (FX_UBITS >= 18)
        return (int32_t)((uint32_t)d + (uint32_t)fx_mul_rsh(nk, n, s));
    const int64_t q =
        (fx_imul64(nk, n) + ((int64_t)1 << (FX_UBITS - 2))) >> (FX_UBITS - 1);
    return (int32_t)((uint32_t)d + (uint32_t)q);
}

/* d.n with FX_UBITS fraction bits, rounded as fx_d3_dotu, from the exact
 * dn = fx_d3_dot_raw(d, n): what the mirror, Snell's law and the
 * highlight take, formed once a hit by the shading loop. */
static inline int32_t rt_dotu_of(int64_t dn)
{
    return (int32_t)((dn + ((int64_t)1 << (FX_UBITS - 1))) >> FX_UBITS);
}

/* Mirror direction d - 2 (d.n) n of unit d about unit n, given dnu =
 * rt_dotu_of(fx_d3_dot_raw(d, n)), the rounded d.n: then only
 * renormalised (fx_d3_renorm), since the reflection of a unit vector is
 * one. */
static inline fx_dir3 rt_reflect_dir_dn(fx_dir3 d, fx_dir3 n, int32_t dnu)
{
    const int32_t nk = -dnu; /* |k| <= 2^FX_UBITS */
    return fx_d3_renorm(fx_d3(rt_mirror_c(d.x, nk, n.x),
                           rt_mirror_c(d.y, nk, n.y),
                           rt_mirror_c(d.z, nk, n.z)));
}

/* The same, finding d.n itself. */
static inline fx_dir3 rt_reflect_dir(fx_dir3 d, fx_dir3 n)
{
    return rt_reflect_dir_dn(d, n, rt_dotu_of(fx_d3_dot_raw(d, n)));
}

/* Bit length of a non-negative value (0 for 0). */
static inline int rt_bitlen64(uint64_t v)
{
    return v ? 64 - fx_clz64(v) : 0;
}

/* Transmitted direction of unit d through a surface of unit normal n
 * (facing the ray) with eta = n1 / n2 (Q16.16, at most 100), by Snell's
 * law: 1 and *t, or 0 on total internal reflection. t = eta d + f n with
 * f = eta cos_i - sqrt(k), k = 1 - eta^2 (1 - cos_i^2). Everything is in
 * FX_UBITS fraction bits, and eta^2 stays exact (Q32.32), so the
 * total-internal-reflection decision k < 0 is not noise even for a large
 * eta. dnu is the rounded d.n, rt_dotu_of(fx_d3_dot_raw(d, n)). */
static inline int rt_refract_dn(fx_dir3 d, fx_dir3 n, int32_t dnu, fx_t eta,
                                fx_dir3 *t)
{
    const int64_t one = (int64_t)1 << FX_UBITS;
    const int32_t cosi = -dnu; /* in [0, 1] */
    const int32_t sin2 =
        (int32_t)(one - (fx_imul64(cosi, cosi) >> FX_UBITS)); /* [0, 1] */
    /* eta^2 sin2 / 2^32 with eta^2 = e1 2^16 + e0 (Q32.32): two products
     * below 2^61 instead of one of 76 bits. */
    const int64_t eta2 = fx_imul64(eta, eta); /* < 2^46 */
    const int32_t e1 = (int32_t)(eta2 >> 16), e0 = (int32_t)(eta2 & 0xFFFF);
    /* e0 sin2 / 2^16 rounded down, in 32-bit products as e0 < 2^16:
     * with sin2 = sh 2^16 + sl (0 <= sl < 2^16, sh <= 2^14) it is e0 sh +
     * floor(e0 sl / 2^16), each term within 32 bits. */
    const int32_t sh0 = sin2 >> 16;
    const uint32_t sl0 = (uint32_t)sin2 & 0xFFFFu;
    const int64_t es0 = e0 * sh0 + (int32_t)(((uint32_t)e0 * sl0) >> 16);
    const int64_t es = (fx_imul64(e1, sin2) + es0) >> 16;
    const int64_t k = one - es;
    if (k < 0)
        return 0;
    /* sqrt(k) with FX_UBITS fraction bits: k << FX_UBITS <= 2^60. */
    const int64_t sq = (int64_t)fx_isqrt64((uint64_t)k << FX_UBITS);
    /* eta cos_i to FX_UBITS fraction bits, rounded (below 2^37). */
    const int64_t ec = (fx_imul64(eta, cosi) + 0x8000) >> 16;
    int64_t ce = (int64_t)eta << FX_USHIFT; /* eta, FX_UBITS fraction bits */
    int64_t cf = ec - sq;
    /* Only the direction of ce d + cf n matters: scale both coefficients
     * into 31 bits, so each product stays below 2^61. */
    const uint64_t ace = (uint64_t)ce;
    const uint64_t acf = (uint64_t)(cf < 0 ? -cf : cf);
    const int sh = rt_bitlen64(ace > acf ? ace : acf) - 31;
    if (sh > 0) {
        ce = (ce + ((int64_t)1 << (sh - 1))) >> sh;
        cf = (cf + ((int64_t)1 << (sh - 1))) >> sh;
    }
    const int32_t a = (int32_t)ce, b = (int32_t)cf; /* now within 31 bits */
    *t = fx_d3_normalize64(fx_imul64(a, d.x) + fx_imul64(b, n.x),
                           fx_imul64(a, d.y) + fx_imul64(b, n.y),
                           fx_imul64(a, d.z) + fx_imul64(b, n.z));
    return 1;
}

/* rt_refract_dn, finding d.n itself. */
static inline int rt_refract_dir(fx_dir3 d, fx_dir3 n, fx_t eta, fx_dir3 *t)
{
    return rt_refract_dn(d, n, rt_dotu_of(fx_d3_dot_raw(d, n)), eta, t);
}

#endif /* RT_BOUNCE_H */
