/* SPDX-License-Identifier: MIT */
/*
 * test_fx: the scalar Q16.16 operations against exact integer truth
 * (__int128 rationals) and long double, at the edges and on at least
 * 1,000,000 seeded pseudo-random inputs per operation drawn from several
 * magnitude ranges. mul, div, recip, sqrt and sqrt_q32 must be correctly
 * rounded (<= 0.5 ulp) and equal the exactly rounded value; isqrt64 must be
 * the exact floor. The measured maximum error of each op is printed.
 */
#include <stdint.h>
#include <stdlib.h>

#include "fx_math.h"
#include "harness.h"

typedef __int128 i128;
typedef unsigned __int128 u128;

/* Random inputs per operation. */
#define N_RANDOM 1000000L

/* ---- Deterministic inputs ---------------------------------------------- */

static uint64_t rng_state = 0x2545F4914F6CDD1DULL;

static uint64_t rnd64(void)
{
    return th_rnd64(&rng_state);
}

static uint32_t rnd32(void)
{
    return (uint32_t)(rnd64() >> 32);
}

/* A 32-bit pattern from a mix of distributions: uniform, log-uniform
 * magnitude (any bit length 0..32) with random sign, near a power of two,
 * or near a special value. */
static int32_t rnd_fx(void)
{
    uint32_t pick = rnd32() % 8, v;
    switch (pick) {
    case 0:
    case 1:
        return (int32_t)rnd32();
    case 2:
    case 3:
    case 4: {
        int bits = (int)(rnd32() % 33);
        v = bits == 0 ? 0 : rnd32() >> (32 - bits);
        break;
    }
    case 5: { /* 2^k + small */
        int k = (int)(rnd32() % 31);
        v = (1u << k) + (rnd32() % 5) - 2;
        break;
    }
    case 6: { /* magnitudes from 2^-8 to 2^8: typical scene values */
        int bits = 8 + (int)(rnd32() % 17);
        v = rnd32() >> (32 - bits);
        break;
    }
    default: { /* near the square-overflow edge, 181.0 .. 182.0 */
        v = 0xB50000u + (rnd32() % 0x20000u);
        break;
    }
    }
    return (rnd32() & 1) ? (int32_t)(0u - v) : (int32_t)v;
}

/* A 64-bit value of random bit length 0..64 (log-uniform), or one of a
 * few structured shapes: a perfect square, or a square +-1. */
static uint64_t rnd_u64(void)
{
    uint32_t pick = rnd32() % 4;
    if (pick == 0) {
        uint64_t s = rnd64() >> (rnd32() % 32 + 32);
        uint64_t sq = s * s;
        int d = (int)(rnd32() % 3) - 1;
        return sq + (uint64_t)(int64_t)d; /* wraps only for s = 0, d = -1 */
    }
    int bits = (int)(rnd32() % 65);
    return bits == 0 ? 0 : rnd64() >> (64 - bits);
}

/* ---- Exact truth -------------------------------------------------------- */

static i128 floordiv(i128 n, i128 d) /* d > 0 */
{
    i128 q = n / d;
    if (n % d != 0 && n < 0)
        q--;
    return q;
}

static fx_t sat128(i128 v)
{
    return v > FX_MAX ? FX_MAX : v < FX_MIN ? FX_MIN : (fx_t)v;
}

/* n / d (d > 0) rounded to nearest, ties toward +infinity, saturated: how
 * fx_mul and fx_from_q32 round. */
static fx_t round_up_ties(i128 n, i128 d)
{
    return sat128(floordiv(2 * n + d, 2 * d));
}

/* n / d (d != 0) rounded to nearest, ties away from zero, saturated: how
 * fx_div and fx_recip round. */
static fx_t round_away_ties(i128 n, i128 d)
{
    if (d < 0) {
        n = -n;
        d = -d;
    }
    i128 m = n < 0 ? -n : n;
    i128 q = (2 * m + d) / (2 * d);
    return sat128(n < 0 ? -q : q);
}

/* |r - n / d| in ulps, for reporting. */
static long double err_ulp(fx_t r, i128 n, i128 d)
{
    i128 e = (i128)r * d - n;
    if (e < 0)
        e = -e;
    return (long double)e / (long double)(d < 0 ? -d : d);
}

/* Round-to-nearest square root of a (no ties exist), as an exact integer
 * test: r is right iff (2r - 1)^2 < 4a < (2r + 1)^2. */
static int is_rounded_sqrt(u128 a, u128 r)
{
    u128 hi = (2 * r + 1) * (2 * r + 1);
    if (!(4 * a < hi))
        return 0;
    return r == 0 || (2 * r - 1) * (2 * r - 1) < 4 * a;
}

static long double sqrt_err(long double x, uint64_t r)
{
    /* Newton polish of the long double root keeps ~64 bits. */
    long double s = x > 0 ? (long double)r + 0.5L : 0;
    for (int i = 0; i < 80 && s > 0; i++) {
        long double t = 0.5L * (s + x / s);
        if (t == s)
            break;
        s = t;
    }
    long double e = (long double)r - s;
    return e < 0 ? -e : e;
}

/* ---- Reporting ---------------------------------------------------------- */

static void report(const char *name, long double max_ulp, long n, long bad)
{
    printf("%s max error %.9Lf ulp over %ld inputs (%ld wrong)\n", name,
           max_ulp, n, bad);
}

/* Prints the first few failures of a sweep. */
static long fails_shown;
#define SHOW_FAIL(...)                                                        \
    do {                                                                      \
        if (fails_shown++ < 10)                                               \
            printf("    " __VA_ARGS__);                                       \
    } while (0)

/* ---- Tests -------------------------------------------------------------- */

/* The truth helpers themselves, on ties and signs. */
static void test_truth(void)
{
    CHECK_EQ(round_up_ties(3, 2), 2);
    CHECK_EQ(round_up_ties(-3, 2), -1);
    CHECK_EQ(round_away_ties(-3, 2), -2);
    CHECK_EQ(round_away_ties(3, -2), -2);
    CHECK_EQ(floordiv(-1, 3), -1);
}

static void test_shift_is_arithmetic(void)
{
    volatile int64_t a = -5, b = INT64_MIN;
    volatile int32_t c = -5, d = INT32_MIN;
    CHECK_EQ(a >> 1, -3);
    CHECK_EQ(b >> 63, -1);
    CHECK_EQ(c >> 1, -3);
    CHECK_EQ(d >> 31, -1);
    CHECK_EQ((int64_t)-1 >> 40, -1);
}

static void test_add_sub_neg_abs(void)
{
    CHECK_EQ(fx_add(FX_MAX, 1), FX_MAX);
    CHECK_EQ(fx_add(FX_MAX, FX_MAX), FX_MAX);
    CHECK_EQ(fx_add(FX_MIN, -1), FX_MIN);
    CHECK_EQ(fx_add(FX_MIN, FX_MIN), FX_MIN);
    CHECK_EQ(fx_add(FX_MAX, FX_MIN), -1);
    CHECK_EQ(fx_sub(FX_MIN, 1), FX_MIN);
    CHECK_EQ(fx_sub(FX_MAX, -1), FX_MAX);
    CHECK_EQ(fx_sub(0, FX_MIN), FX_MAX);
    CHECK_EQ(fx_sub(-1, FX_MAX), FX_MIN);
    CHECK_EQ(fx_neg(FX_MIN), FX_MAX);
    CHECK_EQ(fx_neg(FX_MAX), -FX_MAX);
    CHECK_EQ(fx_neg(0), 0);
    CHECK_EQ(fx_abs(FX_MIN), FX_MAX);
    CHECK_EQ(fx_abs(-1), 1);
    long bad = 0;
    for (long i = 0; i < N_RANDOM; i++) {
        fx_t a = rnd_fx(), b = rnd_fx();
        if (fx_add(a, b) != sat128((i128)a + b) ||
            fx_sub(a, b) != sat128((i128)a - b) ||
            fx_neg(a) != sat128(-(i128)a) ||
            fx_abs(a) != sat128(a < 0 ? -(i128)a : a)) {
            bad++;
            SHOW_FAIL("add/sub/neg/abs(%d, %d)\n", a, b);
        }
    }
    CHECK_EQ(bad, 0);
}

static void test_sat_from_q32_misc(void)
{
    CHECK_EQ(fx_sat64(INT64_MAX), FX_MAX);
    CHECK_EQ(fx_sat64(INT64_MIN), FX_MIN);
    CHECK_EQ(fx_sat64((int64_t)FX_MAX + 1), FX_MAX);
    CHECK_EQ(fx_sat64((int64_t)FX_MIN - 1), FX_MIN);
    CHECK_EQ(fx_sat64(-7), -7);
    CHECK_EQ(fx_from_q32(INT64_MAX), FX_MAX);
    CHECK_EQ(fx_from_q32(INT64_MIN), FX_MIN);
    CHECK_EQ(fx_from_q32((int64_t)1 << 32), FX_ONE);
    CHECK_EQ(fx_from_q32(0x8000), 1);   /* tie: toward +infinity */
    CHECK_EQ(fx_from_q32(-0x8000), 0);  /* tie: toward +infinity */
    CHECK_EQ(fx_from_q32(-0x8001), -1);
    CHECK_EQ(fx_floor_int(FX_CONST(-0.5)), -1);
    CHECK_EQ(fx_floor_int(FX_CONST(2.75)), 2);
    CHECK_EQ(fx_floor_int(FX_MIN), -32768);
    CHECK_EQ(fx_to_u8(-1), 0);
    CHECK_EQ(fx_to_u8(FX_ONE), 255);
    CHECK_EQ(fx_to_u8(FX_MAX), 255);
    CHECK_EQ(fx_to_u8(FX_HALF), 128); /* 127.5 ties up */
    CHECK_EQ(fx_to_u8(FX_ONE - 1), 255);
    CHECK_EQ(fx_to_u8(1), 0);
    CHECK_EQ(FX_CONST(1.5), 0x18000);
    CHECK_EQ(FX_CONST(-1.5), -0x18000);
    CHECK_EQ(FX_INT(-3), -3 * 65536);
    long bad = 0;
    for (long i = 0; i < N_RANDOM; i++) {
        int64_t q = (int64_t)rnd64() >> (rnd32() % 64);
        if (fx_from_q32(q) != round_up_ties(q, 65536)) {
            bad++;
            SHOW_FAIL("fx_from_q32(%lld)\n", (long long)q);
        }
    }
    CHECK_EQ(bad, 0);
    for (int c = 0; c <= FX_ONE; c++) /* every in-range input */
        if (fx_to_u8(c) != (uint8_t)round_up_ties((i128)c * 255, 65536))
            bad++;
    CHECK_EQ(bad, 0);
    for (int i = 0; i < 32; i++) {
        CHECK_EQ(fx_clz32(1u << i), 31 - i);
        CHECK_EQ(fx_clz32((1u << i) | 1u), 31 - i);
        CHECK_EQ(fx_clz64((uint64_t)1 << (i + 32)), 31 - i);
        CHECK_EQ(fx_clz64((uint64_t)1 << i), 63 - i);
    }
}

/* Edge values: 0, +-1 ulp, +-max, +-min, powers of two and their
 * neighbours, and the region around 181 where squares overflow. */
static int edge_values(fx_t *out)
{
    int n = 0;
    static const fx_t fixed[] = {0,        1,          -1,         2,
                                 -2,       FX_MAX,     FX_MIN,     FX_MAX - 1,
                                 FX_MIN + 1, FX_ONE,   -FX_ONE,    FX_HALF,
                                 -FX_HALF, FX_CONST(181.0),  FX_CONST(181.02), FX_CONST(181.0193),
                                 0xB504F3, 0xB504F4,   -0xB504F3,  -0xB504F4,
                                 0xB504F2, FX_CONST(182.0),  FX_CONST(-181.0), 0x7FFF8000,
                                 0x8000,   0x7FFF,     0x10001,    0xFFFF};
    for (unsigned i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
        out[n++] = fixed[i];
    for (int k = 0; k < 31; k++) {
        fx_t p = (fx_t)1 << k;
        out[n++] = p;
        out[n++] = p - 1;
        out[n++] = p + 1;
        out[n++] = -p;
        out[n++] = -p + 1;
        out[n++] = -p - 1;
    }
    return n;
}

static void test_mul(void)
{
    fx_t e[256];
    int ne = edge_values(e);
    long bad = 0, n = 0;
    long double max_err = 0;
    CHECK_EQ(fx_mul(FX_MAX, FX_MAX), FX_MAX);
    CHECK_EQ(fx_mul(FX_MIN, FX_MIN), FX_MAX);
    CHECK_EQ(fx_mul(FX_MIN, FX_MAX), FX_MIN);
    CHECK_EQ(fx_mul(FX_MIN, -FX_ONE), FX_MAX);
    CHECK_EQ(fx_mul(FX_MIN, FX_ONE), FX_MIN);
    CHECK_EQ(fx_mul(FX_CONST(181.0), FX_CONST(181.0)), FX_CONST(32761.0));
    CHECK_EQ(fx_mul(FX_CONST(182.0), FX_CONST(182.0)), FX_MAX);
    CHECK_EQ(fx_mul(FX_CONST(-182.0), FX_CONST(182.0)), FX_MIN);
    CHECK_EQ(fx_mul(1, FX_HALF), 1);   /* 0.5 ulp tie: toward +infinity */
    CHECK_EQ(fx_mul(-1, FX_HALF), 0);  /* -0.5 ulp tie: toward +infinity */
    CHECK_EQ(fx_mul(-1, FX_HALF + 1), -1);
    for (long i = 0; i < N_RANDOM + ne * ne; i++) {
        fx_t a, b;
        if (i < ne * ne) {
            a = e[i / ne];
            b = e[i % ne];
        } else {
            a = rnd_fx();
            b = rnd_fx();
        }
        fx_t r = fx_mul(a, b), want = round_up_ties((i128)a * b, 65536);
        n++;
        if (r != want) {
            bad++;
            SHOW_FAIL("fx_mul(%d, %d) = %d, want %d\n", a, b, r, want);
        }
        if (r != FX_MAX && r != FX_MIN) {
            long double er = err_ulp(r, (i128)a * b, 65536);
            if (er > max_err)
                max_err = er;
        }
    }
    report("fx_mul", max_err, n, bad);
    CHECK_EQ(bad, 0);
    CHECK(max_err <= 0.5L);
}

static void check_div(fx_t a, fx_t b, long *bad, long double *max_err)
{
    fx_t r = fx_div(a, b), want;
    if (b == 0)
        want = a >= 0 ? FX_MAX : FX_MIN;
    else
        want = round_away_ties((i128)a * 65536, b);
    if (r != want) {
        (*bad)++;
        SHOW_FAIL("fx_div(%d, %d) = %d, want %d\n", a, b, r, want);
    }
    if (b != 0 && r != FX_MAX && r != FX_MIN) {
        long double er = err_ulp(r, (i128)a * 65536, b);
        if (er > *max_err)
            *max_err = er;
    }
}

static void test_div(void)
{
    fx_t e[256];
    int ne = edge_values(e);
    long bad = 0, n = 0;
    long double max_err = 0;
    /* Division by zero: the sign of a picks the saturated end. */
    CHECK_EQ(fx_div(0, 0), FX_MAX);
    CHECK_EQ(fx_div(1, 0), FX_MAX);
    CHECK_EQ(fx_div(-1, 0), FX_MIN);
    CHECK_EQ(fx_div(FX_MIN, 0), FX_MIN);
    CHECK_EQ(fx_div(FX_MIN, -FX_ONE), FX_MAX);
    CHECK_EQ(fx_div(FX_MIN, FX_ONE), FX_MIN);
    CHECK_EQ(fx_div(FX_MAX, FX_MIN), -FX_ONE);
    CHECK_EQ(fx_div(FX_ONE, 1), FX_MAX);
    CHECK_EQ(fx_div(FX_ONE, 3), 0x55555555);
    CHECK_EQ(fx_div(1, 2 * FX_ONE), 1);   /* 0.5 ulp: away from zero */
    CHECK_EQ(fx_div(-1, 2 * FX_ONE), -1); /* -0.5 ulp: away from zero */
    CHECK_EQ(fx_div(1, 2 * FX_ONE + 1), 0);
    CHECK_EQ(fx_div(FX_CONST(-16384.0), FX_HALF), FX_MIN); /* exactly -32768 */
    CHECK_EQ(fx_div(FX_CONST(16384.0), FX_HALF), FX_MAX);
    for (int i = 0; i < ne; i++)
        for (int j = 0; j < ne; j++, n++)
            check_div(e[i], e[j], &bad, &max_err);
    /* Divisors around the 2^16 split and where the quotient digit guess
     * needs its corrections (small top half, large low half). */
    for (long i = 0; i < 200000; i++, n++) {
        uint32_t top = 0x8000u + rnd32() % 16;
        uint32_t ub = (top << 16) | (0xFFFFu - rnd32() % 64);
        int sh = (int)(rnd32() % 16);
        fx_t b = (fx_t)(ub >> sh);
        if (i % 3 == 0)
            b = (fx_t)(0x10000 + (int)(rnd32() % 64) - 32);
        check_div(rnd_fx(), (rnd32() & 1) ? b : -b, &bad, &max_err);
    }
    for (long i = 0; i < N_RANDOM; i++, n++)
        check_div(rnd_fx(), rnd_fx(), &bad, &max_err);
    /* Quotients that land in range, at every scale. */
    for (long i = 0; i < N_RANDOM; i++, n++) {
        fx_t b = rnd_fx();
        int64_t q = (int64_t)(int32_t)rnd32() >> (rnd32() % 32);
        int64_t a = ((int64_t)b * q) >> 16;
        a += (int64_t)(rnd32() % 7) - 3;
        check_div(fx_sat64(a), b, &bad, &max_err);
    }
    report("fx_div", max_err, n, bad);
    CHECK_EQ(bad, 0);
    CHECK(max_err <= 0.5L);
}

static void test_recip(void)
{
    long bad = 0, n = 0;
    long double max_err = 0;
    fx_t e[256];
    int ne = edge_values(e);
    CHECK_EQ(fx_recip(0), FX_MAX);
    CHECK_EQ(fx_recip(1), FX_MAX);
    CHECK_EQ(fx_recip(-1), FX_MIN);
    CHECK_EQ(fx_recip(2), FX_MAX);
    CHECK_EQ(fx_recip(-2), FX_MIN); /* exactly -32768 */
    CHECK_EQ(fx_recip(3), 0x55555555);
    CHECK_EQ(fx_recip(FX_MIN), -2);
    CHECK_EQ(fx_recip(FX_ONE), FX_ONE);
    CHECK_EQ(fx_recip(-FX_ONE), -FX_ONE);
    for (long i = 0; i < N_RANDOM + ne; i++, n++) {
        fx_t a = i < ne ? e[i] : rnd_fx();
        fx_t r = fx_recip(a);
        fx_t want = a == 0 ? FX_MAX : round_away_ties((i128)1 << 32, a);
        if (r != want || r != fx_div(FX_ONE, a)) {
            bad++;
            SHOW_FAIL("fx_recip(%d) = %d, want %d\n", a, r, want);
        }
        if (a != 0 && r != FX_MAX && r != FX_MIN) {
            long double er = err_ulp(r, (i128)1 << 32, a);
            if (er > max_err)
                max_err = er;
        }
    }
    report("fx_recip", max_err, n, bad);
    CHECK_EQ(bad, 0);
    CHECK(max_err <= 0.5L);
}

static void check_sqrt(fx_t a, long *bad, long double *max_err)
{
    fx_t r = fx_sqrt(a);
    if (a <= 0) {
        if (r != 0) {
            (*bad)++;
            SHOW_FAIL("fx_sqrt(%d) = %d, want 0\n", a, r);
        }
        return;
    }
    u128 x = (u128)a << 16;
    if (r < 0 || !is_rounded_sqrt(x, (u128)r)) {
        (*bad)++;
        SHOW_FAIL("fx_sqrt(%d) = %d\n", a, r);
    }
    long double er = sqrt_err((long double)x, (uint64_t)r);
    if (er > *max_err)
        *max_err = er;
}

static void test_sqrt(void)
{
    long bad = 0, n = 0;
    long double max_err = 0;
    fx_t e[256];
    int ne = edge_values(e);
    CHECK_EQ(fx_sqrt(0), 0);
    CHECK_EQ(fx_sqrt(-FX_ONE), 0);
    CHECK_EQ(fx_sqrt(FX_MIN), 0);
    CHECK_EQ(fx_sqrt(FX_ONE), FX_ONE);
    CHECK_EQ(fx_sqrt(FX_CONST(4.0)), FX_CONST(2.0));
    CHECK_EQ(fx_sqrt(FX_CONST(32761.0)), FX_CONST(181.0));
    CHECK_EQ(fx_sqrt(FX_MAX), 0xB504F3); /* 181.019... */
    CHECK_EQ(fx_sqrt(1), 256);           /* sqrt(2^-16) = 2^-8 exactly */
    for (int i = 0; i < ne; i++, n++)
        check_sqrt(e[i], &bad, &max_err);
    /* Every input below 2^20, every input of the top 2^20, and the
     * neighbourhood of every power of two. */
    for (fx_t a = 0; a < (1 << 20); a++, n++)
        check_sqrt(a, &bad, &max_err);
    for (fx_t a = FX_MAX - (1 << 20); a < FX_MAX; a++, n++)
        check_sqrt(a, &bad, &max_err);
    for (int k = 20; k < 31; k++)
        for (fx_t d = -4096; d < 4096; d++, n++)
            check_sqrt((fx_t)(1u << k) + d, &bad, &max_err);
    /* Perfect squares of Q16.16 roots, and their neighbours. */
    for (long i = 0; i < N_RANDOM / 4; i++) {
        uint32_t s = rnd32() % 0xB504F3u;
        uint64_t x = (uint64_t)s * s; /* = a * 2^16 when a is exact */
        fx_t a = (fx_t)(x >> 16);
        for (fx_t d = -1; d <= 1; d++, n++)
            check_sqrt(fx_add(a, d), &bad, &max_err);
    }
    for (long i = 0; i < N_RANDOM; i++, n++)
        check_sqrt(rnd_fx(), &bad, &max_err);
    report("fx_sqrt", max_err, n, bad);
    CHECK_EQ(bad, 0);
    CHECK(max_err <= 0.5L); /* long double cannot resolve 0.5 - 2^-35 */
}

static void check_sqrt_q32(uint64_t a, long *bad, long double *max_err)
{
    uint32_t r = fx_sqrt_q32(a), f = fx_isqrt64(a);
    /* isqrt64: exact floor. */
    if (!((u128)f * f <= a && ((u128)f + 1) * ((u128)f + 1) > a)) {
        (*bad)++;
        SHOW_FAIL("fx_isqrt64(%llu) = %u\n", (unsigned long long)a, f);
    }
    /* sqrt_q32: nearest, or 2^32 - 1 when the nearest is 2^32. */
    int ok = is_rounded_sqrt(a, r) ||
             (r == 0xFFFFFFFFu && is_rounded_sqrt(a, (u128)1 << 32));
    if (!ok) {
        (*bad)++;
        SHOW_FAIL("fx_sqrt_q32(%llu) = %u\n", (unsigned long long)a, r);
    }
    if (r != 0xFFFFFFFFu) {
        long double er = sqrt_err((long double)a, r);
        if (er > *max_err)
            *max_err = er;
    }
}

static void test_sqrt_q32_isqrt64(void)
{
    long bad = 0, n = 0;
    long double max_err = 0;
    CHECK_EQ(fx_isqrt64(0), 0);
    CHECK_EQ(fx_isqrt64(UINT64_MAX), 0xFFFFFFFFu);
    CHECK_EQ(fx_sqrt_q32(UINT64_MAX), 0xFFFFFFFFu); /* saturates */
    CHECK_EQ(fx_sqrt_q32(0), 0);
    CHECK_EQ(fx_sqrt_q32(1), 1);
    CHECK_EQ(fx_sqrt_q32(2), 1);
    CHECK_EQ(fx_sqrt_q32(3), 2);
    CHECK_EQ(fx_sqrt_q32((uint64_t)1 << 32), FX_ONE);
    CHECK_EQ(fx_isqrt64(0xFFFFFFFE00000001ULL), 0xFFFFFFFFu);
    CHECK_EQ(fx_isqrt64(0xFFFFFFFE00000000ULL), 0xFFFFFFFEu);
    /* (2^32 - 1/2)^2 = 2^64 - 2^32 + 1/4: the rounding boundary at the
     * top of the range. */
    CHECK_EQ(fx_sqrt_q32(0xFFFFFFFF00000000ULL), 0xFFFFFFFFu);
    CHECK_EQ(fx_sqrt_q32(0xFFFFFFFE00000001ULL + 0xFFFFFFFFULL),
             0xFFFFFFFFu);
    for (int k = 0; k < 64; k++)
        for (int d = -3; d <= 3; d++, n++)
            check_sqrt_q32(((uint64_t)1 << k) + (uint64_t)(int64_t)d, &bad,
                           &max_err);
    /* Perfect squares s^2 and s^2 +- 1 for s at every bit length, and the
     * round-up boundary s^2 + s. */
    for (long i = 0; i < N_RANDOM / 4; i++) {
        uint64_t s = rnd64() >> (32 + rnd32() % 32);
        uint64_t sq = s * s;
        check_sqrt_q32(sq, &bad, &max_err);
        check_sqrt_q32(sq + 1, &bad, &max_err);
        check_sqrt_q32(sq - 1, &bad, &max_err);
        check_sqrt_q32(sq + s, &bad, &max_err);
        check_sqrt_q32(sq + s + 1, &bad, &max_err);
        n += 5;
    }
    for (long i = 0; i < N_RANDOM; i++, n++)
        check_sqrt_q32(rnd_u64(), &bad, &max_err);
    for (long i = 0; i < N_RANDOM / 4; i++, n++) /* full 64-bit values */
        check_sqrt_q32(rnd64(), &bad, &max_err);
    report("fx_sqrt_q32 / fx_isqrt64", max_err, n, bad);
    CHECK_EQ(bad, 0);
    CHECK(max_err <= 0.5L); /* long double cannot resolve 0.5 - 2^-35 */
}

/* fx_floor_div: the exact floor quotient and remainder for every divisor
 * and every dividend below 2^32 in magnitude (texture and bump cells). */
static void test_floor_div(void)
{
    long bad = 0;
    for (long i = 0; i < N_RANDOM; i++) {
        fx_t d = rnd_fx();
        if (d <= 0)
            d = d == INT32_MIN ? INT32_MAX : (d == 0 ? 1 : -d);
        int64_t n = (int64_t)rnd_fx();
        if (i % 4 == 1) /* beyond Q16.16: a difference of two points */
            n = n * 2 + (int64_t)(rnd32() & 1);
        else if (i % 4 == 2) /* near a multiple of d */
            n = (int64_t)d * ((int32_t)rnd32() % 1000) +
                (int64_t)(rnd32() % 5) - 2;
        fx_t rem;
        int64_t q = fx_floor_div(n, d, fx_floor_rcp(d), &rem);
        /* The true floor quotient, from C's truncating division. */
        int64_t tq = n / d, tr = n - tq * d;
        if (tr < 0) {
            tq--;
            tr += d;
        }
        if (q != tq || rem != tr) {
            if (bad++ < 5)
                printf("floor_div(%lld, %ld): %lld rem %ld, want %lld rem "
                       "%lld\n", (long long)n, (long)d, (long long)q,
                       (long)rem,
                       (long long)tq, (long long)tr);
        }
    }
    CHECK_EQ(bad, 0);
    fx_t rem;
    CHECK_EQ(fx_floor_div(INT32_MIN, 1, fx_floor_rcp(1), &rem), INT32_MIN);
    CHECK_EQ(rem, 0);
    CHECK_EQ(fx_floor_div(INT32_MAX, 1, fx_floor_rcp(1), &rem), INT32_MAX);
    CHECK_EQ(fx_floor_div(-1, INT32_MAX, fx_floor_rcp(INT32_MAX), &rem), -1);
    CHECK_EQ(rem, INT32_MAX - 1);
    CHECK_EQ(fx_floor_div(-((int64_t)1 << 32) + 1, 3, fx_floor_rcp(3), &rem),
             -1431655765);
    CHECK_EQ(rem, 0);
}

/* The 16x16-split products the Cortex-M0 build uses (FX_SOFT_MUL64) give
 * the exact 64-bit products, the extremes included. */
static void test_soft_mul64(void)
{
    static const int32_t edge[] = { 0, 1, -1, 65535, 65536, -65536, -65537,
                                    INT32_MAX, INT32_MIN, INT32_MIN + 1 };
    const int ne = (int)(sizeof edge / sizeof edge[0]);
    uint64_t rng = 0x2545F4914F6CDD1DULL;
    long bad = 0;
    for (long i = 0; i < 2000000L + ne * ne; i++) {
        int32_t a, b;
        if (i < ne * ne) {
            a = edge[i / ne];
            b = edge[i % ne];
        } else {
            uint64_t r = th_rnd64(&rng);
            a = (int32_t)(uint32_t)r;
            b = (int32_t)(uint32_t)(r >> 32);
        }
        bad += fx_imul64_soft(a, b) != (int64_t)a * b;
        bad += fx_iumul64_soft(a, (uint32_t)b) != (int64_t)a * (uint32_t)b;
        bad += fx_umul64_soft((uint32_t)a, (uint32_t)b) !=
               (uint64_t)(uint32_t)a * (uint32_t)b;
    }
    if (!CHECK(bad == 0))
        printf("    %ld soft 64-bit products differ\n", bad);
}

int main(void)
{
    test_soft_mul64();
    test_truth();
    test_shift_is_arithmetic();
    test_add_sub_neg_abs();
    test_sat_from_q32_misc();
    test_mul();
    test_div();
    test_recip();
    test_sqrt();
    test_sqrt_q32_isqrt64();
    test_floor_div();
    return th_summary();
}
