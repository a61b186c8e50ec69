/* SPDX-License-Identifier: MIT */
/*
 * fx_trig: the tangent the camera's field of view needs, without libm:
 * sine and cosine by Taylor series in Q2.30.
 */
#include "fx_math.h"

/* Q2.30 helpers: a * b for |a|, |b| < 2, rounded. */
static int64_t mul30(int64_t a, int64_t b)
{
    return (a * b + ((int64_t)1 << 29)) >> 30;
}

/* sin and cos of x (radians, Q2.30, 0 <= x <= pi/4) by Taylor series to
 * x^13: the first omitted term is below 2^-40 there. */
static void sincos30(int64_t x, int64_t *s, int64_t *c)
{
    const int64_t one = (int64_t)1 << 30;
    int64_t x2 = mul30(x, x);
    int64_t sn = one, cs = one;
    /* Horner from the highest term: sin = x(1 - x^2/6(1 - x^2/20(...))).
     * x2 < 2^30 (0.62 2^30), so sn and cs stay in (0, 2^30] and each
     * product in [0, 2^30]: a 32-bit divide is exact (a 64-bit one is a
     * library call on Cortex-M). */
    for (int k = 13; k >= 3; k -= 2)
        sn = one - (uint32_t)mul30(x2, sn) / (uint32_t)(k * (k - 1));
    for (int k = 14; k >= 2; k -= 2)
        cs = one - (uint32_t)mul30(x2, cs) / (uint32_t)(k * (k - 1));
    *s = mul30(x, sn);
    *c = cs;
}

int64_t fx_tan_half_deg_q32(fx_t deg)
{
    /* pi / 360 in Q2.30: half the angle, in radians. */
    const int64_t half_rad = 9370165; /* round(2^30 * pi / 360) */
    const int64_t quarter = 843314857; /* round(2^30 * pi / 4) */
    const int64_t halfpi = 1686629713; /* round(2^30 * pi / 2) */
    int64_t s, c;
    if (deg <= 0)
        return 0;
    int64_t x = ((int64_t)deg * half_rad + 0x8000) >> 16;
    if (x > halfpi)
        x = halfpi;
    if (x <= quarter) {
        sincos30(x, &s, &c);
    } else {
        sincos30(halfpi - x, &c, &s); /* tan x = cot(pi/2 - x) */
    }
    const int64_t most = ((int64_t)1 << 47) - 1;
    if (c <= 0)
        return most;
    /* s in [0, 2^31), so s 2^32 < 2^63; a quotient past 2^47 saturates.
     * c is in (0, 2^30]. */
    if (s >= (c << 15)) /* s / c >= 32768 */
        return most;
    return (int64_t)fx_udiv64(((uint64_t)s << 32) + (uint64_t)(c / 2),
                              (uint32_t)c);
}
