/* SPDX-License-Identifier: MIT */
/* fx_dir: building unit vectors (fx_dir.h). */
#include "fx_dir.h"
#include "fx_rsqrt.h"

/* a_i 2^j R / 2^(62 - FX_UBITS) rounded to nearest (ties up), for b =
 * a_i 2^(j-1) (j >= 1): the same quotient with a constant shift, which
 * is a few instructions where a variable 64-bit one is a dozen. */
static inline int32_t unit_c(int32_t b, int32_t r)
{
    /* Without a 32x32->64 multiply (FX_SOFT_MUL64), from balanced halves
     * b = bh 2^16 + bl, r = rh 2^16 + rl (fx_hi_bal): with K = 45 -
     * FX_UBITS <= 16, the quotient is bh rh 2^(16-K) + floor(S / 2^K)
     * for S = bh rl + bl rh + floor(bl rl / 2^16) + 2^(44-FX_UBITS).
     * |bl|, |rl| <= 2^15 and 2^16 |bh| <= |b| + 2^15, so |S| <= (|b| +
     * r) / 2 + 2^16; as the result is within 1, |b| r <= 2^61 (1 +
     * 2^-31), and with |b|, r < 2^31 |b| + r stays near 3 2^30: S is
     * an int32, with no carry to keep. */
    if (FX_SOFT_MUL64 && FX_UBITS >= 29) {
        const int k = 45 - FX_UBITS;
        const int up = FX_UBITS >= 29 ? 16 - k : 0; /* never negative */
        const int32_t bh = fx_hi_bal(b), bl = (int16_t)b;
        const int32_t rh = fx_hi_bal(r), rl = (int16_t)r;
        const int32_t sv = bh * rl + bl * rh + ((bl * rl) >> 16) +
                           ((int32_t)1 << (44 - FX_UBITS));
        return (int32_t)((uint32_t)(bh * rh) * ((uint32_t)1 << up) +
                         (uint32_t)(sv >> k));
    }
    return (int32_t)((fx_imul64(b, r) + ((int64_t)1 << (60 - FX_UBITS))) >>
                     (61 - FX_UBITS));
}

/* Unit vector along the 32-bit vector a, from its exact squared length. */
fx_dir3 fx_d3_normalize3(int32_t ax, int32_t ay, int32_t az)
{
    uint32_t m;
    int j, z;
    /* Along an axis the answer is exact: +-1 there, as box and quad
     * normals and the planes they are tested against rely on. Both
     * that and the zero vector have a zero component, which most
     * vectors have not: one test of each on the way, before the squared
     * length, while the components are still in the argument registers. */
    if (ax == 0 || ay == 0 || az == 0) {
        if ((ax | ay | az) == 0)
            return fx_d3(0, 0, 0);
        if ((ax == 0) + (ay == 0) + (az == 0) == 2)
            return fx_d3(ax > 0 ? FX_UONE : (ax < 0 ? -FX_UONE : 0),
                         ay > 0 ? FX_UONE : (ay < 0 ? -FX_UONE : 0),
                         az > 0 ? FX_UONE : (az < 0 ? -FX_UONE : 0));
    }
    const uint64_t len2 = fx_len2_raw(ax, ay, az);
    const uint32_t hi = (uint32_t)(len2 >> 32), lo = (uint32_t)len2;
    /* Scale |a|^2 by 4^j into X in [2^62, 2^64) and keep its top word m,
     * in [2^30, 2^32). Then a_i / |a| = a_i 2^j / sqrt(X). Word by word,
     * as a 64-bit variable shift costs more on 32-bit cores. */
    if (hi != 0) {
        z = fx_clz32(hi) & ~1;
        m = (hi << z) | ((lo >> 1) >> (31 - z)); /* no branch on z */
    } else {
        z = 32 + (fx_clz32(lo) & ~1);
        m = lo << (z - 32);
    }
    j = z >> 1;
    /* R ~ 2^46 / sqrt(m): low by at most about 2^-30 (fx_rsqrt_q30). The
     * word m drops raises 1 / sqrt(m) above 2^16 / sqrt(X) by at most
     * 2^-31; taking one off R (at least 2^-31 of it) keeps R below the
     * truth, so no component rounds past 1. The error stays within
     * 2^-29: two ulps at 30 bits. R < 2^31, so it is an int32. */
    const int32_t r = (int32_t)(fx_rsqrt_q30(m, fx_rsqrt_q29(m)) - 1u);
    /* a_i 2^j / sqrt(X) = a_i R 2^j / 2^62. With j >= 1, a_i 2^(j-1)
     * fits int32, as |a_i| 2^j <= sqrt(X) < 2^32. */
    if (j == 0) {
        /* Plain products: a library call on the M0, but |a|^2 >= 2^62 is
         * rare, and soft ones would share the halves of a with fx_len2_raw
         * and keep them across the steps above, spilling on the common
         * path. */
        const int s = 62 - FX_UBITS;
        const int64_t half = (int64_t)1 << (s - 1);
        return fx_d3((int32_t)(((int64_t)ax * r + half) >> s),
                     (int32_t)(((int64_t)ay * r + half) >> s),
                     (int32_t)(((int64_t)az * r + half) >> s));
    }
    return fx_d3(unit_c((int32_t)((uint32_t)ax << (j - 1)), r),
                 unit_c((int32_t)((uint32_t)ay << (j - 1)), r),
                 unit_c((int32_t)((uint32_t)az << (j - 1)), r));
}

/* 1 if |v| <= INT32_MAX: v is an int32 other than INT32_MIN. */
static inline int fits31(int64_t v)
{
    return v == (int32_t)v && (int32_t)v != INT32_MIN;
}

/* v / 2^(sh+1) rounded to nearest (ties up), kept within 31 bits, for
 * |v| < 2^(32+sh), 0 <= sh <= 32. With t = floor(v / 2^sh), in [-2^32,
 * 2^32), that is floor((t + 1) / 2); t is the sign of v above its low
 * word tl, so the result is u = floor((tl + 1) / 2) <= 2^31, less 2^31
 * when v < 0. Only 32-bit shifts: a variable 64-bit one costs a dozen
 * instructions on the M3 and a library call on the M0. */
static int32_t shrink(int64_t v, int sh)
{
    uint32_t lo = (uint32_t)v, hi = (uint32_t)((uint64_t)v >> 32);
    uint32_t tl = sh ? ((lo >> 1) >> (sh - 1)) | (hi << (32 - sh)) : lo;
    uint32_t u = (tl >> 1) + (tl & 1u);
    if (hi >> 31)
        return (int32_t)(u - 0x80000000u); /* in [-2^31, 0] */
    return u > (uint32_t)INT32_MAX ? INT32_MAX : (int32_t)u;
}

fx_dir3 fx_d3_normalize64(int64_t x, int64_t y, int64_t z)
{
    if (fits31(x) && fits31(y) && fits31(z))
        return fx_d3_normalize3((int32_t)x, (int32_t)y, (int32_t)z);
    uint64_t ux = x < 0 ? 0u - (uint64_t)x : (uint64_t)x;
    uint64_t uy = y < 0 ? 0u - (uint64_t)y : (uint64_t)y;
    uint64_t uz = z < 0 ? 0u - (uint64_t)z : (uint64_t)z;
    uint32_t top = (uint32_t)((ux | uy | uz) >> 32);
    /* Keep 31 bits of the largest component: a shift by k = 33 - its
     * bit length beyond 2^32, so sh = k - 1; k = 1 below 2^32. */
    int sh = top ? 32 - fx_clz32(top) : 0;
    return fx_d3_normalize3(shrink(x, sh), shrink(y, sh), shrink(z, sh));
}

fx_dir3 fx_d3_cross_unit(fx_vec3 a, fx_vec3 b)
{
    /* Each product is at most 2^62: the differences fit int64. */
    return fx_d3_normalize64(fx_imul64(a.y, b.z) - fx_imul64(a.z, b.y),
                             fx_imul64(a.z, b.x) - fx_imul64(a.x, b.z),
                             fx_imul64(a.x, b.y) - fx_imul64(a.y, b.x));
}

fx_dir3 fx_d3_clamp(int32_t x, int32_t y, int32_t z)
{
    return fx_d3(fx_unit_clamp(x), fx_unit_clamp(y), fx_unit_clamp(z));
}
