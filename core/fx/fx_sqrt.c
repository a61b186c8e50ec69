/* SPDX-License-Identifier: MIT */
/*
 * fx_sqrt: integer and Q16.16 square roots, exact or correctly rounded.
 *
 * Method: Zimmermann's "Karatsuba square root" (INRIA RR-3805, 1999), one
 * level deep. The input is normalised by an even shift, so its root has a
 * fixed bit length. The root of the top half comes from a table and one
 * Newton step; integer Newton never lands below floor(sqrt), and the table
 * keeps it within +1, so one fix-up makes that half-root exact. The low
 * half of the root then comes from one division of the remainder, which
 * the theorem says is exact after at most one correction. So the root and
 * the remainder are exact, and rounding decides on exact integers: no
 * loops, two 32-bit divides (single instructions on Cortex-M3).
 */
#include "fx_math.h"
#include "fx_rsqrt.h"

/* Midpoints of sqrt over [i, i+1) * 2^24 for i = 64..255: the start of the
 * Newton step for a 32-bit input with its top two bits not both zero. */
static const uint16_t sqrt_tab[192] = {
    32896, 33150, 33402, 33652, 33900, 34147, 34392, 34635,
    34876, 35116, 35354, 35590, 35825, 36059, 36290, 36521,
    36750, 36977, 37204, 37428, 37652, 37874, 38095, 38314,
    38533, 38750, 38966, 39180, 39394, 39606, 39818, 40028,
    40237, 40445, 40652, 40857, 41062, 41266, 41469, 41671,
    41871, 42071, 42270, 42468, 42665, 42861, 43057, 43251,
    43445, 43637, 43829, 44020, 44210, 44399, 44588, 44776,
    44963, 45149, 45334, 45519, 45703, 45886, 46069, 46250,
    46431, 46612, 46791, 46970, 47148, 47326, 47503, 47679,
    47855, 48030, 48204, 48378, 48551, 48723, 48895, 49067,
    49237, 49407, 49577, 49746, 49914, 50082, 50249, 50416,
    50582, 50747, 50912, 51077, 51241, 51404, 51567, 51730,
    51892, 52053, 52214, 52374, 52534, 52694, 52853, 53011,
    53169, 53327, 53484, 53640, 53797, 53952, 54107, 54262,
    54417, 54571, 54724, 54877, 55030, 55182, 55334, 55485,
    55636, 55787, 55937, 56087, 56236, 56385, 56534, 56682,
    56830, 56977, 57124, 57271, 57417, 57563, 57709, 57854,
    57999, 58143, 58287, 58431, 58574, 58717, 58860, 59002,
    59144, 59286, 59427, 59568, 59709, 59849, 59989, 60129,
    60268, 60407, 60546, 60684, 60822, 60960, 61098, 61235,
    61372, 61508, 61644, 61780, 61916, 62051, 62186, 62321,
    62456, 62590, 62724, 62857, 62991, 63124, 63256, 63389,
    63521, 63653, 63785, 63916, 64047, 64178, 64308, 64439,
    64569, 64699, 64828, 64957, 65086, 65215, 65344, 65472,
};

/* floor(sqrt(h)) for h in [2^22, 2^24); *rem = h - root^2, in [0, 2 root]. */
static inline uint32_t sqrtrem24(uint32_t h, uint32_t *rem)
{
    uint32_t y = (uint32_t)sqrt_tab[(h >> 16) - 64] >> 4;
    y = (y + h / y) >> 1; /* floor(sqrt(h)) or one more */
    uint32_t r = h - y * y;
    if ((int32_t)r < 0) { /* y was one too big; r is h - y^2 mod 2^32 */
        y--;
        r += 2 * y + 1;
    }
    *rem = r;
    return y;
}

/* floor(sqrt(m)) for m in [2^30, 2^32); *rem = m - root^2, in [0, 2 root]. */
static inline uint32_t sqrtrem32(uint32_t m, uint32_t *rem)
{
    uint32_t y = sqrt_tab[(m >> 24) - 64];
    y = (y + m / y) >> 1; /* floor(sqrt(m)) or one more; at most 2^16 */
    uint32_t r = m - y * y; /* wraps: |m - y^2| < 2^31, so the sign is right */
    if ((int32_t)r < 0) {
        y--;
        r += 2 * y + 1;
    }
    *rem = r;
    return y;
}

/* floor(sqrt(x)) for x = h * 2^24 + lo in [2^46, 2^48), lo < 2^24;
 * *rem = x - root^2, in [0, 2 root]. Base 2^12 Karatsuba step. */
static inline uint32_t sqrtrem48(uint32_t h, uint32_t lo, uint32_t *rem)
{
    uint32_t r1, s1 = sqrtrem24(h, &r1); /* s1 in [2^11, 2^12) */
    uint32_t n = (r1 << 12) | (lo >> 12); /* r1 <= 2 s1 < 2^13 */
    uint32_t q = n / (2 * s1); /* q <= 2^12 */
    uint32_t u = n - q * (2 * s1);
    uint32_t s = (s1 << 12) + q;
    /* r = u * 2^12 + (lo mod 2^12) - q^2, in (-2^24, 2^25). */
    uint32_t r = ((u << 12) | (lo & 0xFFF)) - q * q;
    if ((int32_t)r < 0) { /* s one too big: x - (s-1)^2 = r + 2s - 1 */
        s--;
        r += 2 * s + 1;
    }
    *rem = r;
    return s;
}

/* floor(sqrt(x)) for x = hi * 2^32 + lo in [2^62, 2^64); *rem = x - root^2,
 * in [0, 2 root]. Base 2^16 Karatsuba step. */
static inline uint32_t sqrtrem64(uint32_t hi, uint32_t lo, uint64_t *rem)
{
    uint32_t r1, s1, n, q, u;
    if (FX_SOFT_DIV) {
        /* ARMv6-M has no divide instruction either: a 32-bit divide is a
         * long library call there. So both divides
         * come from R = fx_rsqrt_q29(hi) ~ 2^45 / sqrt(hi), at most 2^-20
         * below it. hi R / 2^45 is then within 2^-4 below sqrt(hi)
         * < 2^16, and without the product of the low halves and with the
         * two middle ones floored apart (each below 2^32) it loses less
         * than 2^-11 more: floor(sqrt(hi)) or one less, which one test
         * fixes. */
        const uint32_t rr = (uint32_t)fx_rsqrt_q29(hi);
        const uint32_t hh = hi >> 16, rh = rr >> 16, rl = rr & 0xFFFFu;
        s1 = (hh * rh + ((hh * rl) >> 16) + (((hi & 0xFFFFu) * rh) >> 16)) >>
             13;
        r1 = hi - s1 * s1;
        if (r1 > 2 * s1) {
            r1 -= 2 * s1 + 1;
            s1++;
        }
        n = (r1 << 15) | (lo >> 17); /* as below */
        /* With rc = floor(R / 2^14) <= 2^16, n rc / 2^31 <= n / sqrt(hi)
         * <= n / s1, and below n / s1 by a relative 2^-14 at most, with
         * n / s1 <= 2^16 + 2: so q starts at most 5 low, and the
         * remainder says how much (fx_rcp_quot). */
        q = fx_rcp_quot(n, rr >> 14);
        u = n - q * s1;
        while (u >= s1) {
            q++;
            u -= s1;
        }
    } else {
        s1 = sqrtrem32(hi, &r1); /* s1 in [2^15, 2^16) */
        /* q = (r1 * 2^16 + a1) / (2 s1) with a1 = lo >> 16, computed as
         * (r1 * 2^15 + a1 / 2) / s1 so the dividend fits: r1 <= 2^17 -
         * 2. */
        n = (r1 << 15) | (lo >> 17);
        q = n / s1; /* q <= 2^16 */
        u = n - q * s1;
    }
    /* s wraps to 0 only when it is 2^32, one above the true root (which is
     * below 2^32), so the correction below always runs and undoes it. */
    uint32_t s = (s1 << 16) + q;
    /* r = (2u + (a1 & 1)) * 2^16 + (lo mod 2^16) - q^2, in (-2^33, 2^33),
     * with u < s1: word pairs, q^2 from a 32-bit multiply (wraps to 0
     * only for q = 2^16), since a 64-bit one is a library call on
     * Cortex-M0. */
    uint64_t r = fx_pair64(u >> 15, (u << 17) | (lo & 0x1FFFF)) -
                 fx_pair64(q >> 16, q * q);
    if ((int64_t)r < 0) {
        s--;
        r += fx_pair64(s >> 31, 2 * s + 1);
    }
    *rem = r;
    return s;
}

/* Shifts a != 0 left by 2k so that its top word is in [2^30, 2^32); the
 * words come back in *hi, *lo. Returns k. Word by word, as a 64-bit
 * variable shift costs more on 32-bit cores. */
static inline int normalise64(uint64_t a, uint32_t *hi, uint32_t *lo)
{
    uint32_t h = (uint32_t)(a >> 32), l = (uint32_t)a;
    if (h == 0) {
        int z = fx_clz32(l) & ~1;
        *hi = l << z;
        *lo = 0;
        return 16 + z / 2;
    }
    int z = fx_clz32(h) & ~1;
    /* No branch on z. */
    *hi = (h << z) | ((l >> 1) >> (31 - z));
    *lo = l << z;
    return z / 2;
}

uint32_t fx_isqrt64(uint64_t a)
{
    uint32_t hi, lo;
    uint64_t r;
    if (a == 0)
        return 0;
    /* sqrt(a) = sqrt(a * 4^k) / 2^k, and floor commutes with the shift. */
    int k = normalise64(a, &hi, &lo);
    return sqrtrem64(hi, lo, &r) >> k;
}

uint32_t fx_sqrt_q32(uint64_t a)
{
    uint32_t hi, lo;
    uint64_t r;
    if (a == 0)
        return 0;
    int k = normalise64(a, &hi, &lo);
    uint32_t s = sqrtrem64(hi, lo, &r);
    if (k == 0) /* round up when sqrt(a) >= s + 1/2, i.e. r > s */
        return s + (r > s && s != 0xFFFFFFFFu);
    /* round(sqrt(x) / 2^k) = floor((floor(sqrt(x)) + 2^(k-1)) / 2^k);
     * never a tie, since a is not a quarter-integer square. Written so
     * that s = 2^32 - 1 with k = 1 cannot wrap. */
    uint32_t t = s >> (k - 1);
    return (t >> 1) + (t & 1);
}

fx_t fx_sqrt(fx_t a)
{
    uint32_t r;
    if (a <= 0)
        return 0;
    /* sqrt(a / 2^16) in Q16.16 is sqrt(a * 2^16); normalise a * 4^k to
     * m in [2^30, 2^32), so x = m * 2^16 is in [2^46, 2^48). */
    int k = fx_clz32((uint32_t)a) >> 1;
    uint32_t m = (uint32_t)a << (2 * k);
    uint32_t s = sqrtrem48(m >> 8, (m & 0xFF) << 16, &r);
    if (k == 0)
        return (fx_t)(s + (r > s));
    return (fx_t)(((s >> (k - 1)) + 1) >> 1); /* as in fx_sqrt_q32; s < 2^24 */
}
