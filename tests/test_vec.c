/* SPDX-License-Identifier: MIT */
/*
 * test_vec: the fx_vec3 operations against exact integer truth (__int128)
 * and long double, at +-max, for tiny (a few ulp), normal and huge
 * vectors, and on at least 1,000,000 seeded pseudo-random vectors per
 * operation. Dot, cross and the squared length are exact or rounded once;
 * length is correctly rounded; normalize is within 1 ulp per component.
 * The M0's exact dot products from 16-bit halves (rt_ray.h) equal the
 * 64-bit ones, and so does fx_len2_raw (here its 64-bit form; the M0's
 * halves are checked by the firmware images, tests/suite_firmware.sh).
 */
#include <math.h>
#include <stdint.h>

#include "fx_dir.h"
#include "harness.h"
#include "rt_ray.h"

typedef __int128 i128;
typedef unsigned __int128 u128;

#define N_RANDOM 1000000L

static uint64_t rng_state = 0x9E3779B97F4A7C15ULL;

static uint64_t rnd64(void)
{
    return th_rnd64(&rng_state);
}

static uint32_t rnd32(void)
{
    return (uint32_t)(rnd64() >> 32);
}

/* A component of at most `bits` bits of magnitude, random sign. */
static fx_t rnd_comp(int bits)
{
    uint32_t v = bits <= 0 ? 0 : rnd32() >> (32 - bits);
    if (bits == 32 && (rnd32() & 1))
        return (fx_t)v; /* any 32-bit pattern, FX_MIN included */
    if (bits == 32)
        v >>= 1;
    return (rnd32() & 1) ? (fx_t)(0u - v) : (fx_t)v;
}

/* A vector whose components share a random scale (0..32 bits), with one
 * of them sometimes much smaller or zero, so tiny, normal and huge vectors
 * and near-axis directions all turn up. */
static fx_vec3 rnd_vec(void)
{
    int bits = (int)(rnd32() % 33);
    fx_t c[3];
    for (int i = 0; i < 3; i++) {
        int b = bits;
        uint32_t pick = rnd32() % 8;
        if (pick == 0)
            b = 0;
        else if (pick == 1)
            b = (int)(rnd32() % (uint32_t)(bits + 1));
        c[i] = rnd_comp(b);
    }
    return fx_v3(c[0], c[1], c[2]);
}

static fx_t sat128(i128 v)
{
    return v > FX_MAX ? FX_MAX : v < FX_MIN ? FX_MIN : (fx_t)v;
}

/* n / 2^16 rounded as fx_mul and fx_from_q32 round (to nearest, ties
 * toward +infinity), not saturated. >> on i128 floors (checked). */
static i128 round16_wide(i128 n)
{
    return (n + 0x8000) >> 16;
}

/* The same, saturated. */
static fx_t round16(i128 n)
{
    return sat128(round16_wide(n));
}

static int vec_eq(fx_vec3 a, fx_vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

static long fails_shown;
#define SHOW_FAIL(...)                                                        \
    do {                                                                      \
        if (fails_shown++ < 10)                                               \
            printf("    " __VA_ARGS__);                                       \
    } while (0)

/* Edge components: 0, +-1, +-max, +-min, 181-ish, powers of two. */
static const fx_t edges[] = {0,       1,          -1,        FX_MAX,
                             FX_MIN,  FX_MAX - 1, FX_MIN + 1, FX_ONE,
                             -FX_ONE, FX_CONST(181.0),  FX_CONST(-182.0), 0x40000000,
                             -0x40000000, 3,      -2,        FX_HALF};
#define N_EDGES ((int)(sizeof edges / sizeof edges[0]))

static fx_vec3 edge_vec(long i)
{
    return fx_v3(edges[i % N_EDGES], edges[(i / N_EDGES) % N_EDGES],
                 edges[(i / (N_EDGES * N_EDGES)) % N_EDGES]);
}
#define N_EDGE_VECS ((long)N_EDGES * N_EDGES * N_EDGES)

static void test_componentwise(void)
{
    long bad = 0;
    CHECK_EQ(((i128)-5 >> 1), -3);
    for (long i = 0; i < N_RANDOM; i++) {
        fx_vec3 a = rnd_vec(), b = rnd_vec();
        fx_t s = rnd_comp((int)(rnd32() % 33));
        fx_vec3 add = fx_v3_add(a, b), sub = fx_v3_sub(a, b);
        fx_vec3 neg = fx_v3_neg(a), sc = fx_v3_scale(a, s);
        fx_vec3 madd = fx_v3_madd(a, b, s);
        const fx_t *pa = &a.x, *pb = &b.x;
        const fx_t *padd = &add.x, *psub = &sub.x, *pneg = &neg.x;
        const fx_t *psc = &sc.x, *pmadd = &madd.x;
        for (int k = 0; k < 3; k++) {
            i128 prod = (i128)pb[k] * s;
            if (padd[k] != sat128((i128)pa[k] + pb[k]) ||
                psub[k] != sat128((i128)pa[k] - pb[k]) ||
                pneg[k] != sat128(-(i128)pa[k]) ||
                psc[k] != round16((i128)pa[k] * s) ||
                pmadd[k] != sat128(pa[k] + round16_wide(prod))) {
                bad++;
                SHOW_FAIL("component op %d on (%d, %d, s=%d)\n", k, pa[k],
                          pb[k], s);
            }
        }
    }
    CHECK_EQ(bad, 0);
}

/* fx_v3_madd_unit against the exact answer, inside its stated domain:
 * |b| <= 1.0 and |s| <= 2^30, edges included. */
static void test_madd_unit(void)
{
    static const fx_t bs[] = { FX_ONE, -FX_ONE, FX_ONE - 1, 1, -1, 0 };
    static const fx_t ss[] = { 0x40000000, -0x40000000, 0x3FFFFFFF, 1, -1,
                               0, 1 << 17, -(1 << 17), 128, -128 };
    long bad = 0;
    for (long i = 0; i < N_RANDOM; i++) {
        fx_vec3 a = rnd_vec();
        fx_vec3 b = fx_v3((fx_t)(rnd32() % (2 * FX_ONE + 1)) - FX_ONE,
                          (fx_t)(rnd32() % (2 * FX_ONE + 1)) - FX_ONE,
                          bs[rnd32() % 6]);
        fx_t s = i % 4 == 0 ? ss[rnd32() % 10]
                            : (fx_t)((int64_t)(rnd32() % 0x80000001u) -
                                     0x40000000);
        fx_vec3 m = fx_v3_madd_unit(a, b, s);
        const fx_t *pa = &a.x, *pb = &b.x, *pm = &m.x;
        for (int k = 0; k < 3; k++)
            if (pm[k] != sat128(pa[k] + round16_wide((i128)pb[k] * s))) {
                bad++;
                SHOW_FAIL("madd_unit %d on (%d, %d, s=%d)\n", k, pa[k],
                          pb[k], s);
            }
    }
    CHECK_EQ(bad, 0);
}

static void check_dot_cross_len2(fx_vec3 a, fx_vec3 b, long *bad)
{
    i128 px = (i128)a.x * b.x, py = (i128)a.y * b.y, pz = (i128)a.z * b.z;
    i128 len2 = (i128)a.x * a.x + (i128)a.y * a.y + (i128)a.z * a.z;
    fx_t d = fx_v3_dot(a, b), want = round16(px + py + pz);
    if (d != want) {
        (*bad)++;
        SHOW_FAIL("fx_v3_dot = %d, want %d\n", d, want);
    }
    if ((u128)fx_v3_len2_q32(a) != (u128)len2) {
        (*bad)++;
        SHOW_FAIL("fx_v3_len2_q32(%d, %d, %d)\n", a.x, a.y, a.z);
    }
    fx_vec3 c = fx_v3_cross(a, b);
    fx_vec3 cw = fx_v3(round16((i128)a.y * b.z - (i128)a.z * b.y),
                       round16((i128)a.z * b.x - (i128)a.x * b.z),
                       round16((i128)a.x * b.y - (i128)a.y * b.x));
    if (!vec_eq(c, cw)) {
        (*bad)++;
        SHOW_FAIL("fx_v3_cross (%d %d %d) x (%d %d %d)\n", a.x, a.y, a.z,
                  b.x, b.y, b.z);
    }
}

static void test_dot_cross_len2(void)
{
    long bad = 0, n = 0;
    /* The three largest products: 3 * 2^62 overflows int64. */
    fx_vec3 mn = fx_v3(FX_MIN, FX_MIN, FX_MIN);
    fx_vec3 mx = fx_v3(FX_MAX, FX_MAX, FX_MAX);
    CHECK_EQ(fx_v3_dot(mn, mn), FX_MAX);
    CHECK_EQ(fx_v3_dot(mn, mx), FX_MIN);
    CHECK_EQ(fx_v3_dot(mx, mx), FX_MAX);
    CHECK_EQ(fx_v3_dot(fx_v3(FX_MIN, FX_MIN, 0), fx_v3(FX_MIN, FX_MAX, 7)),
             FX_HALF); /* 2^62 - 2^31 (2^31 - 1) = 2^31: no overflow */
    CHECK_EQ(fx_v3_dot(fx_v3(FX_MIN, FX_MAX, 0), fx_v3(FX_MIN, FX_MAX, 0)),
             FX_MAX);
    CHECK_EQ(fx_v3_dot(fx_v3(FX_MAX, FX_MIN, 0), fx_v3(FX_MAX, FX_MAX, 0)),
             -32768); /* (2^31 - 1)^2 - 2^31 (2^31 - 1) = -(2^31 - 1) */
    CHECK_EQ(fx_v3_dot(fx_v3(1, 0, 0), fx_v3(FX_HALF, 0, 0)), 1); /* tie */
    CHECK_EQ(fx_v3_dot(fx_v3(-1, 0, 0), fx_v3(FX_HALF, 0, 0)), 0);
    CHECK_EQ((u128)fx_v3_len2_q32(mn), (u128)3 << 62);
    for (long i = 0; i < N_EDGE_VECS; i++, n++)
        for (long j = 0; j < N_EDGE_VECS; j += 37)
            check_dot_cross_len2(edge_vec(i), edge_vec(j), &bad);
    for (long i = 0; i < N_RANDOM; i++, n++)
        check_dot_cross_len2(rnd_vec(), rnd_vec(), &bad);
    printf("fx_v3_dot / cross / len2_q32: exact over %ld vector pairs "
           "(%ld wrong)\n", n, bad);
    CHECK_EQ(bad, 0);
    /* dotn and dot_q32 with one bounded operand (|c| <= 2^20). */
    bad = 0;
    for (long i = 0; i < N_RANDOM; i++) {
        fx_vec3 a = rnd_vec();
        fx_vec3 b = fx_v3(rnd_comp(21) / 2, rnd_comp(21) / 2,
                          rnd_comp(21) / 2);
        i128 exact = (i128)a.x * b.x + (i128)a.y * b.y + (i128)a.z * b.z;
        if ((i128)fx_v3_dot_q32(a, b) != exact ||
            fx_v3_dotn(a, b) != round16(exact) ||
            fx_v3_dotn(b, a) != fx_v3_dot(a, b))
            bad++;
    }
    CHECK_EQ(bad, 0);
}

static void check_length(fx_vec3 a, long *bad)
{
    u128 l2 = (u128)((i128)a.x * a.x + (i128)a.y * a.y + (i128)a.z * a.z);
    fx_t l = fx_v3_length(a);
    /* Nearest root r: (2r - 1)^2 < 4 l2 < (2r + 1)^2; else FX_MAX when the
     * root rounds to 2^31 or more. */
    u128 r = (u128)(uint32_t)l;
    int ok;
    if (l == FX_MAX)
        ok = 4 * l2 > (2 * r - 1) * (2 * r - 1);
    else
        ok = l >= 0 && 4 * l2 < (2 * r + 1) * (2 * r + 1) &&
             (r == 0 || (2 * r - 1) * (2 * r - 1) < 4 * l2);
    if (!ok) {
        (*bad)++;
        SHOW_FAIL("fx_v3_length(%d, %d, %d) = %d\n", a.x, a.y, a.z, l);
    }
}

static void test_length(void)
{
    long bad = 0, n = 0;
    CHECK_EQ(fx_v3_length(fx_v3(0, 0, 0)), 0);
    CHECK_EQ(fx_v3_length(fx_v3(FX_CONST(3.0), FX_CONST(4.0), 0)), FX_CONST(5.0));
    CHECK_EQ(fx_v3_length(fx_v3(FX_ONE, 0, 0)), FX_ONE);
    CHECK_EQ(fx_v3_length(fx_v3(FX_MIN, 0, 0)), FX_MAX);
    CHECK_EQ(fx_v3_length(fx_v3(FX_MAX, 0, 0)), FX_MAX);
    CHECK_EQ(fx_v3_length(fx_v3(-FX_MAX, 0, 0)), FX_MAX);
    CHECK_EQ(fx_v3_length(fx_v3(FX_CONST(-30000.0), FX_CONST(30000.0), 0)), FX_MAX);
    CHECK_EQ(fx_v3_length(fx_v3(1, 1, 0)), 1); /* sqrt(2) ulp */
    CHECK_EQ(fx_v3_length(fx_v3(1, 1, 1)), 2); /* sqrt(3) ulp */
    for (long i = 0; i < N_EDGE_VECS; i++, n++)
        check_length(edge_vec(i), &bad);
    for (long i = 0; i < N_RANDOM; i++, n++)
        check_length(rnd_vec(), &bad);
    printf("fx_v3_length: correctly rounded over %ld vectors (%ld wrong)\n",
           n, bad);
    CHECK_EQ(bad, 0);
}

/* Largest distance, in ulps, from a component of fx_v3_normalize(a) to
 * the true a_i / |a|; -1 if a rule other than accuracy is broken. */
static long double normalize_err(fx_vec3 a)
{
    fx_vec3 u = fx_v3_normalize(a);
    const fx_t *pa = &a.x, *pu = &u.x;
    i128 l2 = (i128)a.x * a.x + (i128)a.y * a.y + (i128)a.z * a.z;
    if (l2 == 0)
        return vec_eq(u, fx_v3(0, 0, 0)) ? 0 : -1;
    long double len = sqrtl((long double)(u128)l2);
    long double worst = 0;
    for (int k = 0; k < 3; k++) {
        long double t = (long double)pa[k] * 65536.0L / len;
        long double e = fabsl((long double)pu[k] - t);
        if (e > worst)
            worst = e;
        if (pu[k] > FX_ONE || pu[k] < -FX_ONE) /* never past 1 */
            return -1;
        if ((pa[k] < 0 && pu[k] > 0) || (pa[k] > 0 && pu[k] < 0))
            return -1; /* the sign is kept */
    }
    return worst;
}

/* Largest error allowed for a component of fx_v3_normalize, in ulps. */
#define NORMALIZE_BOUND 1.0L /* 0.5 + 2^-4 measured */

static void check_normalize(fx_vec3 a, long *bad, long double *max_err,
                            fx_vec3 *worst)
{
    long double e = normalize_err(a);
    if (e < 0 || e > NORMALIZE_BOUND) {
        (*bad)++;
        SHOW_FAIL("fx_v3_normalize(%d, %d, %d): error %Lf ulp\n", a.x, a.y,
                  a.z, e);
    }
    if (e > *max_err) {
        *max_err = e;
        *worst = a;
    }
}

static void test_normalize(void)
{
    long bad = 0, n = 0;
    long double max_err = 0;
    fx_vec3 worst = fx_v3(0, 0, 0);
    fx_vec3 z = fx_v3_normalize(fx_v3(0, 0, 0));
    CHECK(vec_eq(z, fx_v3(0, 0, 0)));
    /* Lone axes of any length give exactly +-1. */
    for (int k = 0; k < 31; k++) {
        fx_t v = (fx_t)1 << k;
        CHECK(vec_eq(fx_v3_normalize(fx_v3(v, 0, 0)), fx_v3(FX_ONE, 0, 0)));
        CHECK(vec_eq(fx_v3_normalize(fx_v3(0, -v, 0)),
                     fx_v3(0, -FX_ONE, 0)));
        CHECK(vec_eq(fx_v3_normalize(fx_v3(0, 0, v + 1)),
                     fx_v3(0, 0, FX_ONE)));
    }
    CHECK(vec_eq(fx_v3_normalize(fx_v3(FX_MIN, 0, 0)), fx_v3(-FX_ONE, 0, 0)));
    CHECK(vec_eq(fx_v3_normalize(fx_v3(FX_MAX, 0, 0)), fx_v3(FX_ONE, 0, 0)));
    /* Tiny: every vector with components in [-4, 4] ulp. */
    for (int x = -4; x <= 4; x++)
        for (int y = -4; y <= 4; y++)
            for (int zc = -4; zc <= 4; zc++, n++)
                check_normalize(fx_v3(x, y, zc), &bad, &max_err, &worst);
    for (long i = 0; i < N_EDGE_VECS; i++, n++)
        check_normalize(edge_vec(i), &bad, &max_err, &worst);
    /* Huge: components near +-max. */
    for (long i = 0; i < N_RANDOM / 10; i++, n++)
        check_normalize(fx_v3(FX_MAX - (fx_t)(rnd32() % 4096) * (rnd32() & 1),
                              rnd_comp(32), FX_MIN + (fx_t)(rnd32() % 16)),
                        &bad, &max_err, &worst);
    for (long i = 0; i < N_RANDOM; i++, n++)
        check_normalize(rnd_vec(), &bad, &max_err, &worst);
    printf("fx_v3_normalize max error %.9Lf ulp over %ld vectors "
           "(%ld wrong; worst at %d, %d, %d)\n",
           max_err, n, bad, worst.x, worst.y, worst.z);
    CHECK_EQ(bad, 0);
    CHECK(max_err <= NORMALIZE_BOUND);
}

/* fx_dir: unit vectors with FX_UBITS fraction bits. Random vectors of
 * every scale (32 and 64 bits): each component within 2.5 ulps of the
 * true one, never past 1; axis directions exact; a near-unit vector
 * renormalised within the same bound. */
static void test_unit_vectors(void)
{
    long double max_err = 0, max_renorm = 0;
    long past = 0;
    for (long i = 0; i < N_RANDOM; i++) {
        fx_vec3 a = rnd_vec();
        int wide = i & 1;
        int sh = (int)(rnd32() % 31);
        int64_t x = wide ? (int64_t)a.x * ((int64_t)1 << sh) : a.x;
        int64_t y = wide ? (int64_t)a.y * ((int64_t)1 << sh) : a.y;
        int64_t z = wide ? (int64_t)a.z * ((int64_t)1 << sh) : a.z;
        if (x == 0 && y == 0 && z == 0)
            continue;
        fx_dir3 u = wide ? fx_d3_normalize64(x, y, z) : fx_d3_normalize(a);
        long double l = sqrtl((long double)x * x + (long double)y * y +
                              (long double)z * z);
        const long double one = (long double)FX_UONE;
        long double ex = fabsl(u.x - x / l * one);
        long double ey = fabsl(u.y - y / l * one);
        long double ez = fabsl(u.z - z / l * one);
        long double e = ex > ey ? (ex > ez ? ex : ez) : (ey > ez ? ey : ez);
        if (e > max_err)
            max_err = e;
        past += u.x > FX_UONE || u.x < -FX_UONE || u.y > FX_UONE ||
                u.y < -FX_UONE || u.z > FX_UONE || u.z < -FX_UONE;
        /* Off unit length by a few ulps, then renormalised. */
        fx_dir3 v = fx_d3(u.x + (int32_t)(rnd32() % 9) - 4,
                          u.y + (int32_t)(rnd32() % 9) - 4,
                          u.z + (int32_t)(rnd32() % 9) - 4);
        fx_dir3 w = fx_d3_renorm(v);
        long double lv = sqrtl((long double)v.x * v.x +
                               (long double)v.y * v.y +
                               (long double)v.z * v.z);
        long double rx = fabsl(w.x - v.x / lv * one);
        long double ry = fabsl(w.y - v.y / lv * one);
        long double rz = fabsl(w.z - v.z / lv * one);
        long double r = rx > ry ? (rx > rz ? rx : rz) : (ry > rz ? ry : rz);
        if (r > max_renorm)
            max_renorm = r;
    }
    if (!CHECK(max_err <= 2.5L) || !CHECK(max_renorm <= 2.5L) ||
        !CHECK(past == 0))
        printf("    normalise %.3Lf ulps, renormalise %.3Lf, %ld past 1\n",
               max_err, max_renorm, past);
    for (int s = 0; s < 31; s++) {
        int32_t v = (int32_t)(((uint32_t)1 << s) | (s ? 1u : 0u));
        fx_dir3 px = fx_d3_normalize(fx_v3(v, 0, 0));
        fx_dir3 ny = fx_d3_normalize64(0, -((int64_t)v << 20), 0);
        CHECK(px.x == FX_UONE && px.y == 0 && px.z == 0);
        CHECK(ny.x == 0 && ny.y == -FX_UONE && ny.z == 0);
    }
    fx_dir3 zero = fx_d3_normalize64(0, 0, 0);
    CHECK(zero.x == 0 && zero.y == 0 && zero.z == 0);
    /* Quad normals along an axis are exact (the tie with plane_t). */
    fx_dir3 n = fx_d3_cross_unit(fx_v3(0, 0, FX_INT(40)),
                                 fx_v3(FX_INT(40), 0, 0));
    CHECK(n.x == 0 && n.y == FX_UONE && n.z == 0);
}

/* A unit-vector component: anywhere within 2^30 + 2^16, often at the
 * edges of fx_dot3_small_call's range and of its 16-bit halves. */
static int32_t unit_component(void)
{
    const int64_t lim = ((int64_t)1 << 30) + (1 << 16);
    int64_t v;
    switch (rnd64() % 6) {
    case 0: /* the range's ends */
        v = lim - (int64_t)(rnd64() % 70000);
        break;
    case 1: /* low half -2^15 (the signed split's edge) */
        v = -32768 + 65536 * ((int64_t)(rnd64() % 16385) - 8192) * 2;
        break;
    case 2: /* small */
        v = (int64_t)(rnd64() % 200) - 100;
        break;
    default:
        v = (int64_t)(rnd64() % (uint64_t)(2 * lim + 1)) - lim;
    }
    v = v > lim ? lim : v;
    return (int32_t)((rnd64() & 1) ? v : -v);
}

static void test_soft_dots(void)
{
    long bad_unit = 0, bad_any = 0, bad_sq = 0;
    for (long i = 0; i < N_RANDOM; i++) {
        int32_t a[3], b[3], c[3], d[3];
        for (int k = 0; k < 3; k++) {
            a[k] = unit_component();
            b[k] = unit_component();
            c[k] = (int32_t)rnd32();
            d[k] = (int32_t)rnd32();
        }
        const int64_t ab = (int64_t)a[0] * b[0] + (int64_t)a[1] * b[1] +
                           (int64_t)a[2] * b[2];
        bad_unit += fx_dot3_small_call(a[0], a[1], a[2], b[0], b[1], b[2]) !=
                    ab;
        /* Any int32 values: the sum of three products may wrap int64 at
         * the extremes, as fx_dot3_wide_soft's contract excludes; compare
         * modulo 2^64. */
        const uint64_t cd = (uint64_t)((int64_t)c[0] * d[0]) +
                            (uint64_t)((int64_t)c[1] * d[1]) +
                            (uint64_t)((int64_t)c[2] * d[2]);
        bad_any += (uint64_t)fx_dot3_wide_soft(c[0], c[1], c[2], d[0], d[1],
                                          d[2]) != cd;
        /* Any int32 values, INT32_MIN included: at most 3 2^62. */
        int32_t e[3];
        for (int k = 0; k < 3; k++)
            e[k] = k == 0 && i % 97 == 0 ? INT32_MIN
                                          : (int32_t)rnd32() >> (rnd64() % 32);
        uint64_t sq = 0;
        for (int k = 0; k < 3; k++)
            sq += (uint64_t)((int64_t)e[k] * e[k]);
        bad_sq += fx_len2_raw(e[0], e[1], e[2]) != sq;
        bad_sq += fx_len2_raw(a[0], a[1], a[2]) !=
                  (uint64_t)((int64_t)a[0] * a[0] + (int64_t)a[1] * a[1] +
                             (int64_t)a[2] * a[2]);
    }
    CHECK_EQ(bad_unit, 0);
    CHECK_EQ(bad_any, 0);
    CHECK_EQ(bad_sq, 0);
}

int main(void)
{
    test_soft_dots();
    test_unit_vectors();
    test_componentwise();
    test_madd_unit();
    test_dot_cross_len2();
    test_length();
    test_normalize();
    return th_summary();
}
