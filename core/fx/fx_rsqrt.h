/* SPDX-License-Identifier: MIT */
/*
 * fx_rsqrt: reciprocal square roots of a normalised 32-bit mantissa m in
 * [2^30, 2^32), the step both unit-vector builders share (fx_v3_normalize
 * in fx_vec.c, fx_d3_normalize3 in fx_dir.c). Internal to the core.
 */
#ifndef FX_RSQRT_H
#define FX_RSQRT_H

#include "fx_math.h"

extern const uint16_t fx_rsqrt_tab[192];

/* floor(a b / 2^32), exact. Without a 32x32->64 multiply
 * (FX_SOFT_MUL64), from 16-bit halves: a b = ah bh 2^32 + (ah bl + al
 * bh) 2^16 + al bl, summed by columns (Hacker's Delight, mulhu): t = al
 * bh + floor(al bl / 2^16) and w = ah bl + (t mod 2^16) are each at most
 * (2^16 - 1) 2^16, so neither wraps, and the high word is ah bh plus
 * their high halves, without the low word a full soft product joins. */
static inline uint32_t fx_umulhi32(uint32_t a, uint32_t b)
{
    if (!FX_SOFT_MUL64)
        return (uint32_t)(fx_umul64(a, b) >> 32);
    uint32_t ah = a >> 16, al = a & 0xFFFFu, bh = b >> 16, bl = b & 0xFFFFu;
    uint32_t t = al * bh + ((al * bl) >> 16);
    uint32_t w = ah * bl + (t & 0xFFFFu);
    return ah * bh + (t >> 16) + (w >> 16);
}

/* floor(x rc / 2^31) for rc <= 2^16, exact, with 32-bit products only:
 * x = xh 2^16 + xl gives floor((xh rc + floor(xl rc / 2^16)) / 2^15),
 * and the sum stays below 2^32. A quotient x / d from rc ~ 2^31 / d,
 * for cores without a divide instruction. */
static inline uint32_t fx_rcp_quot(uint32_t x, uint32_t rc)
{
    return ((x >> 16) * rc + (((x & 0xFFFFu) * rc) >> 16)) >> 15;
}

/* R ~ 2^45 / sqrt(m) for m in [2^30, 2^32), so R is in (2^29, 2^30].
 * Never above the truth, and at most 2^-20 below it (relative), as checked
 * over every m: the table seed r0, then with e = 1 - x r0^2 (x = m / 2^32)
 * the series r0 (1 - e)^-1/2 ~ r0 (1 + e/2 + 3e^2/8), whose next term is
 * below 2^-22.5. The -256 makes the result an underestimate. */
static inline int32_t fx_rsqrt_q29(uint32_t m)
{
    uint32_t r0 = fx_rsqrt_tab[(m >> 24) - 64];
    uint32_t p = fx_umulhi32(m, r0 * r0); /* Q4.28 */
    int32_t e = (int32_t)(0x10000000u - p); /* Q.28; |e| < 2^21 */
    int32_t e7 = e >> 7;
    int32_t poly = (e >> 1) + ((3 * ((e7 * e7) >> 14)) >> 3);
    return (int32_t)(r0 << 15) + (((int32_t)r0 * (poly >> 6)) >> 7) - 256;
}

/* 2^46 / sqrt(m) from r = fx_rsqrt_q29(m) by one Newton step, r (1 + e/2)
 * with e = 1 - m r^2 / 2^90 in [0, 2^-19] (r is low): below the truth by
 * at most 3e^2/8 plus truncation, about 2^-30 (relative). */
static inline uint32_t fx_rsqrt_q30(uint32_t m, int32_t r)
{
    uint32_t ur = (uint32_t)r; /* (2^29, 2^30] */
    uint32_t uh = ur >> 16, ul = ur & 0xFFFFu;
    /* p = floor(m r^2 / 2^32), at most 2^58 since r is low. e * 2^58 =
     * 2^58 - p, below 2^39: its bits 8..39, e8, are those of -p, as 2^58
     * only changes bit 58 and up (one constant less). */
    uint32_t e8;
    if (FX_SOFT_MUL64) {
        /* ur^2 = H 2^32 + L by columns, in three products: w = 2 uh ul
         * + floor(ul^2 / 2^16) < 2^31 + 2^16, H = uh^2 + floor(w / 2^16),
         * and L's halves are w and ul^2 mod 2^16, which u = floor(m L /
         * 2^32) takes as fx_umulhi32 does. p = m H + u, and e8 = -ceil(p
         * / 2^8) mod 2^32. With H = H1 2^8 + H0, floor(m H / 2^8) = m H1
         * + (m >> 8) H0 + floor(c / 2^8) for c = (m mod 2^8) H0 < 2^16,
         * each term within 32 bits mod 2^32, and m H mod 2^8 = c mod 2^8:
         * three products where m H in full takes four, and no 64-bit
         * value. */
        uint32_t sq = ul * ul, w = 2 * (uh * ul) + (sq >> 16);
        uint32_t h = uh * uh + (w >> 16), lh = w & 0xFFFFu;
        uint32_t ml = m & 0xFFFFu, ll = sq & 0xFFFFu, mh = m >> 16;
        uint32_t t = ml * lh + ((ml * ll) >> 16);
        uint32_t t2 = mh * ll + (t & 0xFFFFu);
        uint32_t u = mh * lh + (t >> 16) + (t2 >> 16), h0 = h & 0xFFu;
        uint32_t c = (m & 0xFFu) * h0;
        e8 = 0u - (m * (h >> 8) + (m >> 8) * h0 + (c >> 8) + (u >> 8) +
                   (((c & 0xFFu) + (u & 0xFFu) + 0xFFu) >> 8));
    } else {
        uint64_t r2 = fx_umul64(ur, ur); /* < 2^60 */
        uint64_t p = fx_umul64(m, (uint32_t)(r2 >> 32)) +
                     fx_umulhi32(m, (uint32_t)r2);
        e8 = (uint32_t)((0u - p) >> 8);
    }
    if (!FX_SOFT_MUL64)
        return 2 * ur + (fx_umulhi32(ur, e8) >> 18);
    /* floor(ur e8 / 2^50) by columns as fx_umulhi32: with ur <= 2^30 and
     * e8 <= 2^31, t = uh el + ul eh + floor(ul el / 2^16) stays below
     * 2^32 with no carry to keep. */
    uint32_t eh = e8 >> 16, el = e8 & 0xFFFFu;
    uint32_t t = uh * el + ul * eh + ((ul * el) >> 16);
    return 2 * ur + ((uh * eh + (t >> 16)) >> 18);
}

#endif /* FX_RSQRT_H */
