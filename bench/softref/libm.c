/* SPDX-License-Identifier: MIT */
/*
 * libm.c: the few libm functions port/posix/ref_render.c calls, for its
 * bench-only bare-metal build (bench/softref). There is no newlib for
 * arm-none-eabi here. Built as double (soft double on Cortex-M), or with
 * -Ddouble=float -DSOFTREF_F32 as float (soft float, or the FPU on the
 * Cortex-M4F). sqrt is correctly rounded, as on the host; tan and pow are
 * within a few ulps, which moves a ray by far less than a pixel.
 */
#include <stdint.h>
#include <math.h>

#ifdef SOFTREF_F32
typedef uint32_t bits_t;
typedef int32_t sbits_t;
#define MANT_BITS 23
#define EXP_BITS 8
#else
typedef uint64_t bits_t;
typedef int64_t sbits_t;
#define MANT_BITS 52
#define EXP_BITS 11
#endif
#define SIGN_BIT ((bits_t)1 << (MANT_BITS + EXP_BITS))
#define EXP_MASK ((((bits_t)1 << EXP_BITS) - 1) << MANT_BITS)
#define IMPLICIT ((bits_t)1 << MANT_BITS)
#define BIAS ((1 << (EXP_BITS - 1)) - 1)

#define PI 3.14159265358979323846
#define LN2 0.69314718055994530942

static bits_t to_bits(double x)
{
    union {
        double d;
        bits_t b;
    } u;
    u.d = x;
    return u.b;
}

static double from_bits(bits_t b)
{
    union {
        double d;
        bits_t b;
    } u;
    u.b = b;
    return u.d;
}

double fabs(double x)
{
    return from_bits(to_bits(x) & ~SIGN_BIT);
}

double copysign(double x, double y)
{
    return from_bits((to_bits(x) & ~SIGN_BIT) | (to_bits(y) & SIGN_BIT));
}

double fmax(double x, double y)
{
    if (x != x)
        return y;
    if (y != y)
        return x;
    return x > y ? x : y;
}

double floor(double x)
{
    /* From 2^MANT_BITS up every value is an integer (and NaN fails). */
    if (!(fabs(x) < (double)IMPLICIT))
        return x;
    double t = (double)(sbits_t)x; /* toward zero, exact */
    return t > x ? t - 1 : t;
}

double sqrt(double x)
{
    bits_t b = to_bits(x);
    if (x != x || x == 0 || b == EXP_MASK)
        return x; /* NaN, +-0, +infinity */
    if (b & SIGN_BIT)
        return from_bits(EXP_MASK | (IMPLICIT >> 1)); /* a quiet NaN */
    int e = (int)(b >> MANT_BITS);
    bits_t m = b & (IMPLICIT - 1);
    if (e == 0) { /* subnormal: normalise */
        e = 1;
        while (!(m & IMPLICIT)) {
            m <<= 1;
            e--;
        }
    } else {
        m |= IMPLICIT;
    }
    /* x = m 2^E with m in [2^M, 2^(M+1)). The root of R = m 2^s, s = M + 2,
     * has M + 2 bits (the mantissa and a guard bit) when m is in [2^M,
     * 2^(M+2)); make E - s even by doubling m if needed. */
    const int s = MANT_BITS + 2;
    int E = e - BIAS - MANT_BITS;
    if ((E - s) & 1) {
        m <<= 1;
        E--;
    }
    /* Digit by digit: two bits of R per step, root and remainder exact. */
    bits_t root = 0, rem = 0;
    for (int i = MANT_BITS + 1; i >= 0; i--) {
        int sh = 2 * i - s; /* R's bits 2i+1, 2i are m's bits sh+1, sh */
        bits_t pair = sh >= 0 ? (m >> sh) & 3 : (m << -sh) & 3;
        bits_t trial;
        rem = (rem << 2) | pair;
        trial = (root << 2) | 1;
        root <<= 1;
        if (rem >= trial) {
            rem -= trial;
            root |= 1;
        }
    }
    /* Round to nearest, ties to even, on the guard bit and the remainder. */
    bits_t mant = root >> 1;
    int k = (E - s) / 2 + 1; /* x^(1/2) = mant 2^k */
    if ((root & 1) && (rem != 0 || (mant & 1)))
        mant++;
    if (mant == IMPLICIT << 1) {
        mant >>= 1;
        k++;
    }
    /* Adding mant carries its implicit bit into the exponent field. */
    return from_bits(((bits_t)(k + MANT_BITS + BIAS - 1) << MANT_BITS) + mant);
}

double tan(double x)
{
    /* tan has period pi: reduce to [-pi/2, pi/2], then sin / cos. */
    double r = x - floor(x / PI + 0.5) * PI, r2 = r * r;
    double s = r, c = 1, ts = r, tc = 1;
    for (int n = 1; n < 20; n++) {
        ts *= -r2 / ((2 * n) * (2 * n + 1));
        tc *= -r2 / ((2 * n - 1) * (2 * n));
        s += ts;
        c += tc;
    }
    return s / c;
}

/* e^y: y = k ln 2 + r with |r| <= ln 2 / 2, Taylor for e^r, then 2^k. */
static double exp_(double y)
{
    if (y > 1000)
        return HUGE_VAL;
    if (y < -1000)
        return 0;
    double k = floor(y / LN2 + 0.5), r = y - k * LN2, t = 1, sum = 1;
    for (int n = 1; n < 20; n++) {
        t *= r / n;
        sum += t;
    }
    int ik = (int)k;
    for (; ik > 0; ik--)
        sum *= 2;
    for (; ik < 0; ik++)
        sum *= 0.5;
    return sum;
}

/* ln x for x > 0: x = m 2^e with m in [sqrt(1/2), sqrt(2)), then
 * ln m = 2 atanh((m - 1) / (m + 1)). */
static double log_(double x)
{
    int e = 0;
    while (x >= 1.41421356237309504880) {
        x *= 0.5;
        e++;
    }
    while (x < 0.70710678118654752440) {
        x *= 2;
        e--;
    }
    double z = (x - 1) / (x + 1), z2 = z * z, t = z, sum = 0;
    for (int n = 1; n < 40; n += 2) {
        sum += t / n;
        t *= z2;
    }
    return 2 * sum + e * LN2;
}

double pow(double x, double y)
{
    if (y == floor(y) && fabs(y) < 2147483648.0) {
        int32_t n = (int32_t)y;
        uint32_t u = n < 0 ? 0u - (uint32_t)n : (uint32_t)n;
        double r = 1, b = x;
        while (u) {
            if (u & 1)
                r *= b;
            u >>= 1;
            if (u)
                b *= b;
        }
        return n < 0 ? 1 / r : r;
    }
    if (x < 0)
        return from_bits(EXP_MASK | (IMPLICIT >> 1)); /* NaN */
    if (x == 0)
        return y > 0 ? 0 : HUGE_VAL;
    return exp_(y * log_(x));
}
