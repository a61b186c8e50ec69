/*
 * fx_math: Q16.16 fixed-point scalar arithmetic.
 *
 * fx_t is a signed 32-bit value with 16 fractional bits: range
 * [-32768, 32768 - 2^-16], step 2^-16 (one "ulp"). Every operation below
 * states its rounding and what it does on overflow. Nothing here relies on
 * signed overflow (undefined in C): results that do not fit are computed in
 * 64 bits and saturated to [FX_MIN, FX_MAX].
 *
 * Right shifts of negative values are arithmetic on every compiler we build
 * with (GCC, Clang, for x86-64, ARM and RISC-V); the tests check it.
 */
#ifndef FX_MATH_H
#define FX_MATH_H

#include <stdint.h>

typedef int32_t fx_t;

#define FX_FRAC_BITS 16
#define FX_ONE ((fx_t)0x00010000)
#define FX_HALF ((fx_t)0x00008000)
#define FX_MAX ((fx_t)0x7FFFFFFF)
#define FX_MIN ((fx_t)(-0x7FFFFFFF - 1))

/* Compile-time constant from a decimal literal, rounded to nearest (ties
 * away from zero). The compiler folds it: only for constant expressions. */
#define FX(x) ((fx_t)((x) >= 0 ? (x) * 65536.0 + 0.5 : (x) * 65536.0 - 0.5))

/* Integer to Q16.16; exact for |n| <= 32767 (callers keep it there). */
#define FX_INT(n) ((fx_t)((n) * 65536))

/* Saturates a 64-bit value to the fx_t range. */
static inline fx_t fx_sat64(int64_t v)
{
    return v > FX_MAX ? FX_MAX : (v < FX_MIN ? FX_MIN : (fx_t)v);
}

/* Adds; exact, saturates on overflow. */
static inline fx_t fx_add(fx_t a, fx_t b)
{
    return fx_sat64((int64_t)a + b);
}

/* Subtracts; exact, saturates on overflow. */
static inline fx_t fx_sub(fx_t a, fx_t b)
{
    return fx_sat64((int64_t)a - b);
}

/* Negates; exact, -FX_MIN saturates to FX_MAX. */
static inline fx_t fx_neg(fx_t a)
{
    return a == FX_MIN ? FX_MAX : -a;
}

/* Absolute value; exact, |FX_MIN| saturates to FX_MAX. */
static inline fx_t fx_abs(fx_t a)
{
    return a < 0 ? fx_neg(a) : a;
}

/* Multiplies, rounding to nearest (ties toward +infinity); saturates on
 * overflow. The 64-bit product is exact, so the error is at most 0.5 ulp. */
static inline fx_t fx_mul(fx_t a, fx_t b)
{
    int64_t p = (int64_t)a * b + 0x8000; /* |p| < 2^62 + 2^15: no overflow */
    int32_t hi = (int32_t)(p >> 32);
    /* p >> 16 fits in 32 bits exactly when hi is in [-2^15, 2^15): one
     * compare on the high word instead of two 64-bit compares. */
    if ((uint32_t)(hi + 0x8000) > 0xFFFFu)
        return (hi >> 31) ^ FX_MAX; /* FX_MIN if negative, else FX_MAX */
    return (fx_t)(((uint32_t)hi << 16) | ((uint32_t)p >> 16));
}

/* Rounds a Q32.32 value held in an int64 to Q16.16, to nearest (ties toward
 * +infinity); saturates. Used after exact 64-bit dot products. */
static inline fx_t fx_from_q32(int64_t q)
{
    /* Adding the half bit after the shift cannot overflow, unlike
     * q + 2^15, for any q. */
    return fx_sat64((q >> 16) + ((q >> 15) & 1));
}

/* Number of leading zero bits of x (0..31); exact. x must not be 0. */
static inline int fx_clz32(uint32_t x)
{
#if defined(__GNUC__)
    return __builtin_clz(x); /* one instruction where the core has CLZ */
#else
    int n = 0;
    if (x < 0x10000u) { n += 16; x <<= 16; }
    if (x < 0x1000000u) { n += 8; x <<= 8; }
    if (x < 0x10000000u) { n += 4; x <<= 4; }
    if (x < 0x40000000u) { n += 2; x <<= 2; }
    return n + (x < 0x80000000u);
#endif
}

/* Number of leading zero bits of x (0..63); exact. x must not be 0. */
static inline int fx_clz64(uint64_t x)
{
    uint32_t hi = (uint32_t)(x >> 32);
    return hi ? fx_clz32(hi) : 32 + fx_clz32((uint32_t)x);
}

/* Divides a by b, correctly rounded to nearest (ties away from zero), so
 * the error is at most 0.5 ulp; saturates on overflow. b == 0 gives FX_MAX
 * for a >= 0 and FX_MIN for a < 0. */
fx_t fx_div(fx_t a, fx_t b);

/* Reciprocal 1/a: the same value as fx_div(FX_ONE, a), so correctly
 * rounded (ties away from zero) and saturated; 1/0 gives FX_MAX. */
fx_t fx_recip(fx_t a);

/* Square root, correctly rounded to nearest (there are no ties), so the
 * error is below 0.5 ulp; cannot overflow (sqrt(FX_MAX) < 182). Negative
 * input gives 0. */
fx_t fx_sqrt(fx_t a);

/* Square root of an unsigned Q32.32 value (for example an exact 64-bit sum
 * of squared Q16.16 values), correctly rounded to nearest (no ties), as an
 * unsigned Q16.16 value. Saturates: a root that rounds to 2^32 (a >=
 * 2^64 - 2^32) gives 2^32 - 1. */
uint32_t fx_sqrt_q32(uint64_t a);

/* Integer square root: floor(sqrt(a)), exact for every input; cannot
 * overflow (the result is below 2^32). */
uint32_t fx_isqrt64(uint64_t a);

/* floor(x), as an integer (exact). */
static inline int32_t fx_floor_int(fx_t x)
{
    return x >> 16;
}

/* Rounds a Q16.16 value in [0, 1] to 0..255 (to nearest, ties up);
 * clamps values outside [0, 1]. */
static inline uint8_t fx_to_u8(fx_t c)
{
    if (c <= 0)
        return 0;
    if (c >= FX_ONE)
        return 255;
    return (uint8_t)(((int64_t)c * 255 + 0x8000) >> 16);
}

#endif /* FX_MATH_H */
