/* SPDX-License-Identifier: MIT */
/*
 * fx_dot: exact dot products of three int32 pairs and the rounded shifted
 * product, the operations geometry and shading build on. Each gives the
 * same bits on every CPU; where the CPU has no 64-bit multiply
 * (FX_SOFT_MUL64, fx_cpu.h) they are formed from 16-bit pieces, summed so
 * that as few carries as possible cross 32 bits.
 */
#ifndef FX_DOT_H
#define FX_DOT_H

#include "fx_dir.h"
#include "fx_rsqrt.h"

/* x0 y0 + x1 y1 + x2 y2 exact for any int32 values whose sum fits
 * int64: from 16-bit halves (x = h 2^16 + l, 0 <= l < 2^16), the high,
 * middle and low partial products summed apart (each a 32-bit product:
 * |h h| <= 2^30, |h l| < 2^31, l l < 2^32) and joined once, wrapping.
 * Without a 64-bit multiply (FX_SOFT_MUL64): one call instead of three
 * soft products; out of line, as inline it grows the frame of the
 * recursive shading loop, which every bounce level pays. */
RT_NOINLINE static int64_t fx_dot3_wide_soft(int32_t x0, int32_t x1, int32_t x2,
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

/* One term of fx_dot3_small: x y split at 16 bits with signed low
 * halves, x = xh 2^16 + xl with -2^15 <= xl < 2^15, added to the running
 * sums of the high, the two middle and the low partial products. */
#define FX_DOT_STEP(xv, yv)                                                  \
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
 * 2^31), and only the low ones (up to 2^30 each) need 64 bits. */
static inline int64_t fx_dot3_small(int32_t x0, int32_t x1, int32_t x2,
                                    int32_t y0, int32_t y1, int32_t y2)
{
    if (!FX_SOFT_MUL64)
        return fx_imul64(x0, y0) + fx_imul64(x1, y1) + fx_imul64(x2, y2);
    int32_t hh = 0, m1 = 0, m2 = 0;
    int64_t ll = 0;
    FX_DOT_STEP(x0, y0);
    FX_DOT_STEP(x1, y1);
    FX_DOT_STEP(x2, y2);
    const uint64_t mid1 = fx_pair64((uint32_t)(m1 >> 16), (uint32_t)m1 << 16);
    const uint64_t mid2 = fx_pair64((uint32_t)(m2 >> 16), (uint32_t)m2 << 16);
    return (int64_t)(fx_pair64((uint32_t)hh, 0) + mid1 + mid2 +
                     (uint64_t)ll);
}
#undef FX_DOT_STEP

/* fx_dot3_small out of line, for the shading loop on the M0: inline it
 * grew the frame every bounce level pays. */
RT_NOINLINE static int64_t fx_dot3_small_call(int32_t x0, int32_t x1,
                                             int32_t x2, int32_t y0,
                                             int32_t y1, int32_t y2)
{
    return fx_dot3_small(x0, x1, x2, y0, y1, y2);
}

/* fx_d3_dot_raw(a, b), the same exact value (fx_dot3_small_call on the
 * M0). */
static inline int64_t fx_d3_dot_exact(fx_dir3 a, fx_dir3 b)
{
    if (!FX_SOFT_MUL64)
        return fx_d3_dot_raw(a, b);
    return fx_dot3_small_call(a.x, a.y, a.z, b.x, b.y, b.z);
}

/* fx_pd_dot_raw(p, d), the same exact value (fx_dot3_wide_soft on the M0). */
static inline int64_t fx_pd_dot_exact(fx_vec3 p, fx_dir3 d)
{
    if (!FX_SOFT_MUL64)
        return fx_pd_dot_raw(p, d);
    return fx_dot3_wide_soft(p.x, p.y, p.z, d.x, d.y, d.z);
}

/* ---- Rounded and exact products for geometry (core/shapes) ---- */

/* (a c + 2^(s-1)) >> s: a c 2^-s rounded to nearest (ties up), for 1 <= s
 * <= 32, |c| <= 2^30 and a result within int32 (its low 32 bits
 * otherwise). Where 64-bit products are built from 16-bit ones and s >
 * 16, fx_mul_rsh's four 16x16 products; else the 64-bit product's two words
 * shifted as 32-bit values. */
static inline int32_t fx_mul_round(int32_t a, int32_t c, unsigned s)
{
    if (FX_SOFT_MUL64 && s > 16)
        return fx_mul_rsh(a, c, s);
    const uint64_t u = (uint64_t)fx_imul64(a, c) + ((uint64_t)1 << (s - 1));
    return (int32_t)(((uint32_t)u >> (s - 1) >> 1) |
                     ((uint32_t)(u >> 32) << ((32 - s) & 31)));
}

/* (t e + 2^(s-1)) >> s for 17 <= s <= 47: t e 2^-s rounded to nearest
 * (ties up), exact for any int32 t and e whose result fits int32. For a
 * small factor e (|e| < 2^15: a unit vector's length error) where 64-bit
 * products are built from 16-bit ones, t e = hi 2^16 + lo with hi = (t >>
 * 16) e and lo = (t mod 2^16) e, both within 2^31, and lo mod 2^16 cannot
 * carry into the result: two 32-bit products. */
static inline int32_t fx_mul_small_round(int32_t t, int32_t e, unsigned s)
{
    if (FX_SOFT_MUL64 && e >= -32768 && e <= 32767) {
        const int32_t hi = (t >> 16) * e;
        const int32_t lo = (int32_t)((uint32_t)t & 0xFFFFu) * e;
        return (hi + (lo >> 16) + (1 << ((s - 17) & 31))) >> ((s - 16) & 31);
    }
    return (int32_t)((fx_imul64(t, e) + ((int64_t)1 << ((s - 1) & 63))) >>
                     (s & 63));
}

/* (v u + 2^(s-1)) >> s, the low 32 bits, for int32 v, uint32 u and 2 <= s
 * <= 32: rounded to nearest (ties up). Where 64-bit products are built
 * from 16-bit ones and s > 16, from the product's columns (as
 * fx_iumul64_soft sums them): 2^(s-1) is a multiple of 2^16, so the low
 * 16 bits cannot reach it, and the result is hi 2^(32 - s) + (the next 16
 * bits + 2^(s - 17)) 2^(16 - s), in 32-bit values. */
static inline int32_t fx_iumul_round(int32_t v, uint32_t u, unsigned s)
{
    if (FX_SOFT_MUL64 && s > 16) {
        const unsigned k = s - 16;
        const int32_t ah = v >> 16;
        const uint32_t al = (uint32_t)v & 0xFFFFu, bh = u >> 16;
        const uint32_t bl = u & 0xFFFFu, ll = al * bl;
        const int32_t t = ah * (int32_t)bl + (int32_t)(ll >> 16);
        const uint32_t m = al * bh + ((uint32_t)t & 0xFFFFu);
        const uint32_t hi =
            (uint32_t)(ah * (int32_t)bh + (t >> 16)) + (m >> 16);
        const uint32_t w = (m & 0xFFFFu) + ((uint32_t)1 << (k - 1));
        return (int32_t)((hi << (16 - k)) + (w >> k));
    }
    const uint64_t p = (uint64_t)fx_iumul64(v, u) + ((uint32_t)1 << (s - 1));
    return (int32_t)(((uint32_t)p >> (s - 1) >> 1) |
                     ((uint32_t)(p >> 32) << ((32 - s) & 31)));
}

/* a b, exact, for |a|, |b| <= 2^30. Where 64-bit products are built from
 * 16-bit ones, the two middle partial products (each below 2^30) are
 * summed in 32 bits. */
static inline int64_t fx_imul64_30(int32_t a, int32_t b)
{
    if (!FX_SOFT_MUL64)
        return fx_imul64(a, b);
    const int32_t ah = a >> 16, bh = b >> 16;
    const uint32_t al = (uint32_t)a & 0xFFFFu, bl = (uint32_t)b & 0xFFFFu;
    const int32_t mid = ah * (int32_t)bl + (int32_t)al * bh;
    return (int64_t)(fx_pair64((uint32_t)(ah * bh), al * bl) + fx_mid64(mid));
}

/* floor((a p - b q) 2^-32) to within 2 (exact where the CPU has a 64-bit
 * multiply), for |a|, |b| < 2^30 and |p|, |q| <= 2^30. From 16-bit
 * halves (x = h 2^16 + l), the low products and the middle ones' dropped
 * bits are each below one unit, and every sum stays below 2^31. */
static inline int32_t fx_cross_hi(int32_t a, int32_t p, int32_t b, int32_t q)
{
    if (!FX_SOFT_MUL64)
        return (int32_t)((fx_imul64(a, p) + fx_imul64(b, -q)) >> 32);
    const int32_t ah = a >> 16, bh = b >> 16, ph = p >> 16, qh = q >> 16;
    const int32_t al = (int32_t)((uint32_t)a & 0xFFFFu);
    const int32_t bl = (int32_t)((uint32_t)b & 0xFFFFu);
    const int32_t pl = (int32_t)((uint32_t)p & 0xFFFFu);
    const int32_t ql = (int32_t)((uint32_t)q & 0xFFFFu);
    return ah * ph - bh * qh + ((ah * pl + al * ph) >> 16) -
           ((bh * ql + bl * qh) >> 16);
}

/* round(sqrt(n)), as fx_sqrt_q32(n), for any n. Where 32-bit divides and
 * 64-bit products are library calls, 0 < n < 2^40 is taken from
 * fx_rsqrt_q29 instead: with m in [2^30, 2^32) the top bits of n and n
 * within [m, m + 1) 2^2j, y = m R / 2^32 for R = fx_rsqrt_q29(m) is
 * sqrt(m) 2^13, never above and below by at most 2^-20 relative and 1,
 * so s = y >> (13 - j) is floor(sqrt(n)) or up to two less (sqrt(n) <
 * 2^20). n - s^2 is then below 2^32, so its low word is exact, and it
 * says how many. */
static inline uint32_t fx_sqrt_round(uint64_t n)
{
    if (!FX_SOFT_MUL64 || n == 0 || n >= ((uint64_t)1 << 40))
        return fx_sqrt_q32(n);
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

/* 1 if c = a p - b q (|a|, |b| < 2^30, p and q unit components) is surely
 * beyond +-(r + 4) 2^FX_UBITS, for 0 <= r < 2^29: a bound sure enough to
 * reject a sphere of radius r whose centre is offset (a, b) from a ray.
 * fx_cross_hi gives c 2^-32 to within 2, taken against +-(k + 2), k 2^32
 * >= (r + 5) 2^30. narrow: |a|, |b| < 2^23 and r < 2^22, where a CPU
 * without a 64-bit multiply takes c as C 2^24, C = (a >> 8) (p >> 16) -
 * (b >> 8) (q >> 16), one 32-bit product a term: |c - C 2^24| < 98308
 * 2^24, so |C| >= (floor(r / 32) + 50) 2^11 > 64 r + 98563 makes |c| >
 * (r + 4) 2^30 as well (a looser, still sure bound). */
static inline int fx_cross_beyond(int32_t a, int32_t p, int32_t b, int32_t q,
                                  fx_t r, int narrow)
{
    if (FX_SOFT_MUL64 && narrow) {
        const int32_t c = (a >> 8) * (p >> 16) - (b >> 8) * (q >> 16);
        const uint32_t t = ((uint32_t)r >> 5) + 50u;
        /* C >= k or C <= -k - 1: C + k >= 2k, unsigned. */
        return ((uint32_t)c + (t << 11)) >> 12 >= t;
    }
    const uint32_t k1 = ((uint32_t)r >> 2) + 3u; /* k + 1 */
    /* ch >= k + 2 or ch <= -k - 2, in one unsigned compare. */
    return (uint32_t)fx_cross_hi(a, p, b, q) + k1 > 2u * k1;
}

#endif /* FX_DOT_H */
