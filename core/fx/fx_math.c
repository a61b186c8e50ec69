/* SPDX-License-Identifier: MIT */
/*
 * fx_math: Q16.16 division and reciprocal (the inline ops live in the
 * header).
 *
 * Both work on magnitudes, so rounding is symmetric (ties away from zero),
 * and use only 32-bit divides: a 64-bit divide is a long libgcc call on
 * Cortex-M, a 32-bit one a single instruction on the M3.
 * Every quotient digit is corrected against its exact remainder, so the
 * result is the correctly rounded quotient, the same on every target.
 */
#include "fx_math.h"
#include "fx_rsqrt.h"

/* Saturated value of magnitude q with sign neg: q in [0, 2^32). */
static inline fx_t sat_signed(uint32_t q, int neg)
{
    if (neg)
        return q >= 0x80000000u ? FX_MIN : -(fx_t)q;
    return q > (uint32_t)FX_MAX ? FX_MAX : (fx_t)q;
}

fx_t fx_div(fx_t a, fx_t b)
{
    if (b == 0)
        return a >= 0 ? FX_MAX : FX_MIN;
    int neg = (a ^ b) < 0;
    uint32_t ua = a < 0 ? 0u - (uint32_t)a : (uint32_t)a; /* [0, 2^31] */
    uint32_t ub = b < 0 ? 0u - (uint32_t)b : (uint32_t)b; /* [1, 2^31] */
    /* ua * 2^16 >= ub * 2^31 exactly when the quotient is >= 2^31, which
     * saturates either way (-2^31 is FX_MIN itself). */
    if ((ua >> 15) >= ub)
        return neg ? FX_MIN : FX_MAX;
    /* Long division of ua * 2^16 by ub in two digits: q1 < 2^15, then 16
     * fraction bits q0 from the remainder r1 < ub. */
    uint32_t q1 = ua / ub, r1 = ua - q1 * ub, q0, r;
    if (ub <= 0x10000u) {
        uint32_t n = r1 << 16; /* r1 < 2^16 */
        q0 = n / ub;
        r = n - q0 * ub;
    } else {
        /* Knuth's algorithm D, one step: normalise so the divisor's top
         * bit is set, guess the digit from its top 16 bits (never too
         * small, at most 2 too big), and correct with the low 16 bits. */
        int c = fx_clz32(ub); /* 0..15 */
        uint32_t d = ub << c, n = r1 << c; /* n < d */
        uint32_t dh = d >> 16, dl = d & 0xFFFFu;
        uint32_t rh;
        q0 = n / dh;
        rh = n - q0 * dh;
        while (q0 > 0xFFFFu || q0 * dl > (rh << 16)) {
            q0--;
            rh += dh;
            if (rh > 0xFFFFu)
                break;
        }
        /* n * 2^16 - q0 * d, exact mod 2^32 and below d. */
        r = ((rh << 16) - q0 * dl) >> c;
    }
    uint32_t q = (q1 << 16) + q0;
    /* Round half up on magnitudes: remainder >= ub / 2. */
    q += r >= ub - r;
    return sat_signed(q, neg);
}

fx_t fx_recip(fx_t a)
{
    if (a == 0)
        return FX_MAX;
    uint32_t ua = a < 0 ? 0u - (uint32_t)a : (uint32_t)a;
    if (ua <= 2) /* 2^32 / ua >= 2^31 */
        return a < 0 ? FX_MIN : FX_MAX;
    /* floor(2^32 / ua) is q or q + 1 (the latter when ua divides 2^32);
     * r = 2^32 - q * ua is in [1, ua], computed mod 2^32. */
    uint32_t q = 0xFFFFFFFFu / ua;
    uint32_t r = 0u - q * ua;
    if (r >= ua) {
        q++;
        r -= ua;
    }
    q += r >= ua - r;
    return sat_signed(q, a < 0);
}

const uint8_t fx_clz_table[32] = {
    31, 22, 30, 21, 18, 10, 29, 2,  20, 17, 15, 13, 9, 6,  28, 1,
    23, 19, 11, 3,  16, 14, 7,  24, 12, 4,  8,  25, 5, 26, 27, 0};

const uint8_t fx_ctz_table[32] = {
    0,  1,  28, 2,  29, 14, 24, 3, 30, 22, 20, 15, 25, 17, 4,  8,
    31, 27, 13, 23, 21, 19, 16, 7, 26, 12, 18, 6,  11, 5,  10, 9};

/* Out of line the products are summed by columns instead: ah bl
 * plus the top of al bl, then al bh plus the low half of that, each
 * below 2^32, so no carry is needed and no 64-bit register pair ties the
 * allocation, which makes the call shorter on the M0. Inline,
 * among the caller's values, the pairs of fx_imul64_soft do better. */
int64_t fx_imul64_call(int32_t a, int32_t b)
{
    int32_t ah = a >> 16, bh = b >> 16;
    uint32_t al = (uint32_t)a & 0xFFFFu, bl = (uint32_t)b & 0xFFFFu;
    uint32_t ll = al * bl;
    int32_t t = ah * (int32_t)bl + (int32_t)(ll >> 16);
    int32_t u = (int32_t)al * bh + (int32_t)((uint32_t)t & 0xFFFFu);
    uint32_t hi = (uint32_t)(ah * bh + (t >> 16) + (u >> 16));
    return (int64_t)fx_pair64(hi, ((uint32_t)u << 16) | (ll & 0xFFFFu));
}

int64_t fx_iumul64_call(int32_t a, uint32_t b)
{
    return fx_iumul64_soft(a, b); /* the same column form */
}

uint64_t fx_umul64_call(uint32_t a, uint32_t b)
{
    uint32_t ah = a >> 16, al = a & 0xFFFFu, bh = b >> 16, bl = b & 0xFFFFu;
    uint32_t ll = al * bl, t = ah * bl + (ll >> 16);
    uint32_t u = al * bh + (t & 0xFFFFu);
    return fx_pair64(ah * bh + (t >> 16) + (u >> 16),
                     (u << 16) | (ll & 0xFFFFu));
}

uint32_t fx_udiv64_32(uint64_t n, uint32_t d)
{
    /* Long division in base 2^16 after normalising d (Knuth's algorithm D
     * as in Hacker's Delight, divlu): two 32-bit hardware divides on a
     * Cortex-M3 instead of a 64-bit library divide. Unsigned wrap-around
     * in the intermediate products is part of the method. */
    const uint32_t b = 65536;
    uint32_t u1 = (uint32_t)(n >> 32), u0 = (uint32_t)n;
    int s = fx_clz32(d);
    uint32_t v = d << s, vn1 = v >> 16, vn0 = v & 0xFFFF;
    uint32_t un32 = s ? (u1 << s) | (u0 >> (32 - s)) : u1;
    uint32_t un10 = u0 << s, un1 = un10 >> 16, un0 = un10 & 0xFFFF;
    uint32_t q1, rhat, rc = 0;
    if (FX_SOFT_DIV) {
        /* No divide instruction (ARMv6-M): a 32-bit divide is a long
         * library call. Instead rc ~ 2^31 / vn1 (at
         * most 2^16) by one Newton step, r0 (2 - vn1 r0 / 2^30), from
         * the seed r0 ~ 2^30 / vn1 that fx_rsqrt_tab holds for vn1^2
         * (|e| < 2^22): never above 2^31 / vn1 and at most 2^-14.9 below
         * it, as checked over every vn1; x rc / 2^31 then starts at most
         * 6 below x / vn1 (below 2^17), and the remainder fixes it. */
        const uint32_t r0 = fx_rsqrt_tab[((vn1 * vn1) >> 24) - 64];
        const int32_t e = (int32_t)((1u << 30) - vn1 * r0);
        rc = (uint32_t)((int32_t)(2 * r0) +
                        (((int32_t)r0 * (e >> 8)) >> 21));
        q1 = fx_rcp_quot(un32, rc);
        rhat = un32 - q1 * vn1;
        while (rhat >= vn1) {
            q1++;
            rhat -= vn1;
        }
    } else {
        q1 = un32 / vn1;
        rhat = un32 - q1 * vn1;
    }
    while (q1 >= b || q1 * vn0 > b * rhat + un1) {
        q1--;
        rhat += vn1;
        if (rhat >= b)
            break;
    }
    uint32_t un21 = un32 * b + un1 - q1 * v;
    uint32_t q0;
    if (FX_SOFT_DIV) {
        q0 = fx_rcp_quot(un21, rc); /* as q1 */
        rhat = un21 - q0 * vn1;
        while (rhat >= vn1) {
            q0++;
            rhat -= vn1;
        }
    } else {
        q0 = un21 / vn1;
        rhat = un21 - q0 * vn1;
    }
    while (q0 >= b || q0 * vn0 > b * rhat + un0) {
        q0--;
        rhat += vn1;
        if (rhat >= b)
            break;
    }
    return q1 * b + q0;
}

uint64_t fx_udiv64(uint64_t n, uint32_t d)
{
    const uint32_t hi = (uint32_t)(n >> 32), qh = hi / d;
    /* The rest, (hi - qh d) 2^32 + the low word, is below d 2^32. */
    return fx_pair64(qh, fx_udiv64_32(fx_pair64(hi - qh * d, (uint32_t)n),
                                      d));
}
