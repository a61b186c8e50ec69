/* SPDX-License-Identifier: MIT */
/*
 * exhaustive: host-only checks too slow for the test suite (about 2 min).
 * It includes the core sources to reach their static helpers.
 *   gcc -std=gnu99 -O2 -Icore bench/fxbench/exhaustive.c -lm -o /tmp/ex && /tmp/ex
 * 1. fx_sqrt on every positive input (2^31 values).
 * 2. fx_isqrt64 / fx_sqrt_q32 with every top word in [2^30, 2^32) (this is
 *    every input of the table + Newton stage), low words 0, all ones or
 *    pseudo-random.
 * 3. rsqrt_q29 (fx_v3_normalize) for every m: never above 2^45 / sqrt(m)
 *    and at most 2^-20 below it.
 */
#include <math.h>
#include <stdio.h>

#include "../../core/fx_math.c"
#include "../../core/fx_sqrt.c"
#include "../../core/fx_vec.c"

typedef unsigned __int128 u128;

int main(void)
{
    long bad = 0;
    for (int64_t a = 1; a <= 0x7FFFFFFF; a++) {
        uint64_t r = (uint64_t)fx_sqrt((fx_t)a), x4 = (uint64_t)a << 18;
        if (!(x4 < (2 * r + 1) * (2 * r + 1) && (2 * r - 1) * (2 * r - 1) < x4))
            bad++;
    }
    printf("fx_sqrt, every input: %ld wrong\n", bad);

    bad = 0;
    uint64_t st = 88172645463325252ULL;
    for (uint64_t m = 1ull << 30; m < (1ull << 32); m++) {
        st ^= st << 13;
        st ^= st >> 7;
        st ^= st << 17;
        uint64_t lo = (m & 1) ? (st & 0xFFFFFFFFu) : ((m & 2) ? 0xFFFFFFFFu : 0);
        uint64_t a = (m << 32) | lo;
        uint32_t f = fx_isqrt64(a), r = fx_sqrt_q32(a);
        u128 A = (u128)a * 4;
        int okf = (u128)f * f <= a && ((u128)f + 1) * ((u128)f + 1) > a;
        int okr = (A < ((u128)2 * r + 1) * ((u128)2 * r + 1) || r == 0xFFFFFFFFu) &&
                  ((u128)2 * r - 1) * ((u128)2 * r - 1) < A;
        bad += !okf || !okr;
    }
    printf("fx_isqrt64 / fx_sqrt_q32, every top word: %ld wrong\n", bad);

    long double lo = 1, hi = -1;
    for (uint64_t m = 1u << 30; m < (1ull << 32); m++) {
        long double t = 35184372088832.0L / sqrtl((long double)m); /* 2^45 */
        long double rel = (rsqrt_q29((uint32_t)m) - t) / t;
        if (rel < lo)
            lo = rel;
        if (rel > hi)
            hi = rel;
    }
    printf("rsqrt_q29, every m: relative error in [%.3Le, %.3Le] "
           "(must be in [-2^-20 = -9.537e-07, 0))\n", lo, hi);
    return 0;
}
