/* SPDX-License-Identifier: MIT */
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
 *
 * Every operation gives the same bits on every target. The accuracy of
 * unit vectors is a setting (RT_UNIT_BITS, fx_dir.h); that of the Q16.16
 * operations here is not.
 */
#ifndef FX_MATH_H
#define FX_MATH_H

#include <stdint.h>

#include "rt_config.h"
#include "fx_cpu.h"
#include "fx_mul64_soft.h"

typedef int32_t fx_t;

#define FX_FRAC_BITS 16
#define FX_ONE ((fx_t)0x00010000)
#define FX_HALF ((fx_t)0x00008000)
#define FX_MAX ((fx_t)0x7FFFFFFF)
#define FX_MIN ((fx_t)(-0x7FFFFFFF - 1))

/* Q16.16 constant from a decimal literal, rounded to nearest (ties away
 * from zero): FX_CONST(1.5) is 0x18000. Only for constant expressions,
 * which the compiler folds, so no floating point reaches the target; it
 * serves initialisers (static const tables too). The core itself writes
 * raw values, as it holds no floating-point literal. */
#define FX_CONST(x)                                                           \
    ((fx_t)((x) >= 0 ? (x) * 65536.0 + 0.5 : (x) * 65536.0 - 0.5))

/* Integer to Q16.16; exact for |n| <= 32767 (callers keep it there). */
#define FX_INT(n) ((fx_t)((n) * 65536))

/* Saturates a 64-bit value to the fx_t range. */
static inline fx_t fx_sat64(int64_t v)
{
    return v > FX_MAX ? FX_MAX : (v < FX_MIN ? FX_MIN : (fx_t)v);
}

/* GCC and Clang report 32-bit overflow from the flags (adds + bvs on a
 * Cortex-M): far cheaper than saturating a 64-bit sum. Same results. */
#if defined(__GNUC__)
#define FX_HAVE_OVERFLOW_BUILTINS 1
#else
#define FX_HAVE_OVERFLOW_BUILTINS 0
#endif

/* The same, out of line (fx_math.c). A file whose functions recurse (the
 * shading loop, rt_shade.c) defines FX_MUL64_CALL 1 before its includes:
 * there a dozen inline copies crowd the registers and grow the frame that
 * every bounce level pays (several times the stack on the M0), while a
 * call costs a few instructions. */
#ifndef FX_MUL64_CALL
#define FX_MUL64_CALL 0
#endif
int64_t fx_imul64_call(int32_t a, int32_t b);
int64_t fx_iumul64_call(int32_t a, uint32_t b);
uint64_t fx_umul64_call(uint32_t a, uint32_t b);

/* The exact 64-bit products of 32-bit operands (FX_SOFT_MUL64). */
static inline int64_t fx_imul64(int32_t a, int32_t b)
{
    if (!FX_SOFT_MUL64)
        return (int64_t)a * b;
    return FX_MUL64_CALL ? fx_imul64_call(a, b) : fx_imul64_soft(a, b);
}

static inline int64_t fx_iumul64(int32_t a, uint32_t b)
{
    if (!FX_SOFT_MUL64)
        return (int64_t)a * b;
    return FX_MUL64_CALL ? fx_iumul64_call(a, b) : fx_iumul64_soft(a, b);
}

static inline uint64_t fx_umul64(uint32_t a, uint32_t b)
{
    if (!FX_SOFT_MUL64)
        return (uint64_t)a * b;
    return FX_MUL64_CALL ? fx_umul64_call(a, b) : fx_umul64_soft(a, b);
}

/* Adds; exact, saturates on overflow. */
static inline fx_t fx_add(fx_t a, fx_t b)
{
#if FX_HAVE_OVERFLOW_BUILTINS
    fx_t r;
    if (__builtin_add_overflow(a, b, &r))
        return (a >> 31) ^ FX_MAX; /* both had a's sign */
    return r;
#else
    return fx_sat64((int64_t)a + b);
#endif
}

/* Subtracts; exact, saturates on overflow. */
static inline fx_t fx_sub(fx_t a, fx_t b)
{
#if FX_HAVE_OVERFLOW_BUILTINS
    fx_t r;
    if (__builtin_sub_overflow(a, b, &r))
        return (a >> 31) ^ FX_MAX; /* the result has a's sign */
    return r;
#else
    return fx_sat64((int64_t)a - b);
#endif
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
    int64_t p = fx_imul64(a, b);
    p += 0x8000; /* half an ulp; |p| < 2^62 + 2^15: no overflow */
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
    /* q >> 16 fits in 32 bits exactly when the high word is in
     * [-2^15, 2^15); then only FX_MAX plus the half bit can overflow. */
    int32_t hi = (int32_t)(q >> 32);
    if ((uint32_t)hi + 0x8000u > 0xFFFFu) /* unsigned: any hi */
        return (hi >> 31) ^ FX_MAX;
    fx_t r = (fx_t)(((uint32_t)hi << 16) | ((uint32_t)q >> 16));
    return r == FX_MAX ? r : r + (fx_t)(((uint32_t)q >> 15) & 1);
}

/* fx_clz32's and fx_ctz32's tables (FX_SOFT_CLZ; fx_math.c). */
extern const uint8_t fx_clz_table[32], fx_ctz_table[32];

/* Number of leading zero bits of x (0..31); exact. x must not be 0.
 * Without CLZ (FX_SOFT_CLZ) __builtin_clz is a library call of about 20
 * instructions: there x with every bit below its top one set, 2^(32 -
 * clz) - 1, times a de Bruijn constant puts a distinct 5-bit index in
 * the top bits. */
static inline int fx_clz32(uint32_t x)
{
#if defined(__GNUC__)
    if (FX_SOFT_CLZ) {
        x |= x >> 1;
        x |= x >> 2;
        x |= x >> 4;
        x |= x >> 8;
        x |= x >> 16;
        return fx_clz_table[(x * 0x07C4ACDDu) >> 27];
    }
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

/* Number of trailing zero bits of x (0..31); exact. x must not be 0.
 * Without CLZ (FX_SOFT_CLZ) __builtin_ctz is a library call of about 20
 * instructions: there the lowest set bit times a de Bruijn constant puts
 * a distinct 5-bit index in the top bits. */
static inline int fx_ctz32(uint32_t x)
{
#if defined(__GNUC__)
    if (FX_SOFT_CLZ)
        return fx_ctz_table[((x & (0u - x)) * 0x077CB531u) >> 27];
    return __builtin_ctz(x);
#else
    return 31 - fx_clz32(x & (0u - x));
#endif
}

/* Number of leading zero bits of x (0..63); exact. x must not be 0. */
static inline int fx_clz64(uint64_t x)
{
    uint32_t hi = (uint32_t)(x >> 32);
    return hi ? fx_clz32(hi) : 32 + fx_clz32((uint32_t)x);
}

/* Divides a by b, correctly rounded to nearest (ties away from zero), so
 * the error is at most 0.5 ulp. Saturates on overflow. b == 0 gives FX_MAX
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
 * unsigned Q16.16 value. Saturates: a root that rounds to 2^32
 * (a >= 2^64 - 2^32) gives 2^32 - 1. */
uint32_t fx_sqrt_q32(uint64_t a);

/* Integer square root: floor(sqrt(a)), exact for every input; cannot
 * overflow (the result is below 2^32). */
uint32_t fx_isqrt64(uint64_t a);

/* floor(n / d) for d > 0 and n < d * 2^32 (the quotient fits 32 bits),
 * exact, with two 32-bit divides (a 64-bit divide is a library call on
 * Cortex-M). */
uint32_t fx_udiv64_32(uint64_t n, uint32_t d);

/* floor(n / d) for d > 0 and any n, exact: a 32-bit divide of the high
 * word, then fx_udiv64_32 of the rest (its quotient fits 32 bits). */
uint64_t fx_udiv64(uint64_t n, uint32_t d);

/* tan(deg / 2) for an angle of 0 < deg < 180 degrees, as Q32.32 (32
 * fraction bits, so that a small field of view keeps its precision):
 * relative error about 2^-28 before the final rounding to nearest;
 * saturates to 2^47 - 1 (just below 32768) near 180; deg <= 0 gives 0. */
int64_t fx_tan_half_deg_q32(fx_t deg);

/* x^n for 0 <= x <= 1 by repeated squaring; each product rounds as fx_mul,
 * so the result is within about n ulps and never above 1. Every factor is
 * in [0, 1], so a product is at most 2^32 and never saturates: an unsigned
 * 32x32->64 multiply and the rounding shift give fx_mul's bits without
 * its range checks (a Phong power is one per light and hit). */
static inline fx_t fx_powi(fx_t x, unsigned n)
{
    uint32_t r = FX_ONE, b = (uint32_t)x;
    while (n) {
        if (n & 1)
            r = (uint32_t)((fx_umul64(r, b) + 0x8000u) >> 16);
        n >>= 1;
        if (n)
            b = (uint32_t)((fx_umul64(b, b) + 0x8000u) >> 16);
    }
    return (fx_t)r;
}

/* floor(x), as an integer (exact). */
static inline int32_t fx_floor_int(fx_t x)
{
    return x >> 16;
}

/* The reciprocal fx_floor_div needs: floor((2^32 - 1) / d) for d > 0. */
static inline uint32_t fx_floor_rcp(fx_t d)
{
    return 0xFFFFFFFFu / (uint32_t)d;
}

/* floor(n / d) for d > 0 (any two raw values: the quotient of two Q16.16
 * numbers is a plain integer), exact for every |n| < 2^32; the remainder
 * n - q d, in [0, d), goes to *rem. rcp is fx_floor_rcp(d). For |n| <
 * 2^31, n rcp / 2^32 lies within 1 of n / d (below it for n >= 0, above
 * for n < 0), so one step corrects it with no division; the remainder is
 * formed in unsigned arithmetic, which wraps by definition, and a
 * remainder out of [0, d) reads as >= d either way. Larger n (points over
 * 32,768 units from a texture's origin) take a 64-bit division. */
static inline int64_t fx_floor_div(int64_t n, fx_t d, uint32_t rcp,
                                   fx_t *rem)
{
    if (n < INT32_MIN || n > INT32_MAX) {
        int64_t q = n / d, r = n - q * d;
        if (r < 0) {
            q--;
            r += d;
        }
        *rem = (fx_t)r;
        return q;
    }
    int32_t q = (int32_t)(fx_iumul64((int32_t)n, rcp) >> 32);
    uint32_t r = (uint32_t)n - (uint32_t)q * (uint32_t)d;
    if (r >= (uint32_t)d) {
        if (n >= 0) {
            q++;
            r -= (uint32_t)d;
        } else {
            q--;
            r += (uint32_t)d;
        }
    }
    *rem = (fx_t)r;
    return q;
}

/* Rounds a Q16.16 value in [0, 1] to 0..255 (to nearest, ties up);
 * clamps values outside [0, 1]. */
static inline uint8_t fx_to_u8(fx_t c)
{
    if (c <= 0)
        return 0;
    if (c >= FX_ONE)
        return 255;
    /* c < 2^16, so the product fits 32 bits. */
    return (uint8_t)(((uint32_t)c * 255u + 0x8000u) >> 16);
}

/* a w, rounded to nearest (ties toward +infinity), not saturated: for a
 * product that fits int32 (a colour channel times a weight). Cheapest
 * for a weight 0 <= w <= 1: without a 64-bit multiply (FX_SOFT_MUL64) it
 * is then two 32-bit products, as with a = ah 2^16 + al (0 <= al <
 * 2^16) a w + 2^15 = ah w 2^16 + (al w + 2^15), each part within 32
 * bits, rounded as floor((floor(x / 2^15) + 1) / 2) = floor((x + 2^15) /
 * 2^16), which needs no constant 2^15 in a register; any other weight
 * takes the out-of-line product. */
static inline fx_t fx_wmul(fx_t a, fx_t w)
{
    if (!FX_SOFT_MUL64)
        return (fx_t)(((int64_t)a * w + 0x8000) >> 16);
    if ((uint32_t)w <= (uint32_t)FX_ONE) {
        const int32_t ah = a >> 16;
        const uint32_t al = (uint32_t)a & 0xFFFFu;
        return ah * w + (fx_t)((((al * (uint32_t)w) >> 15) + 1u) >> 1);
    }
    return (fx_t)((fx_imul64_call(a, w) + 0x8000) >> 16);
}

/* (a c + 2^(s-1)) >> s modulo 2^32, for 17 <= s <= 32 and |c| <= 2^30
 * (a unit component): a product rounded to nearest (ties up), exact
 * wherever it fits int32. Where the CPU multiplies 32x32->64, from that
 * product; else inline, in 32-bit pieces: with a = ah 2^16 + al and c =
 * ch 2^16 + cl (al, cl unsigned), a c = hh 2^32 + (b1 + b2) 2^16 + l;
 * only the terms below 2^k (k = s - 16) are added before the shift, each
 * below 2^31 in magnitude as |ch| <= 2^14, and 2^(s-1) is a multiple of
 * 2^16. */
static inline int32_t fx_mul_rsh(int32_t a, int32_t c, unsigned s)
{
    if (!FX_SOFT_MUL64)
        return (int32_t)(((int64_t)a * c + ((int64_t)1 << (s - 1))) >> s);
    const unsigned k = s - 16;
    const int32_t ah = a >> 16, ch = c >> 16;
    const uint32_t al = (uint32_t)a & 0xFFFFu, cl = (uint32_t)c & 0xFFFFu;
    const int32_t hh = ah * ch, b1 = ah * (int32_t)cl, b2 = (int32_t)al * ch;
    const uint32_t lr = ((al * cl) >> 16) + ((1u << (s - 1)) >> 16);
    const int32_t low = (b1 & (int32_t)((1u << k) - 1)) + b2 + (int32_t)lr;
    return (int32_t)(((uint32_t)hh << (16 - k)) + (uint32_t)(b1 >> k) +
                     (uint32_t)(low >> k));
}

/* fx_powi(x, n), the same value, cheapest for 0 <= x <= 1 (a cosine).
 * Where the CPU has no 64-bit multiply (FX_SOFT_MUL64) by 32-bit
 * products there: every factor stays in [0, 1], so a b + 2^15 is below
 * 2^32 unless a = b = 1; a larger x takes out-of-line products. */
static inline fx_t fx_powi_unit(fx_t x, unsigned n)
{
    if (!FX_SOFT_MUL64)
        return fx_powi(x, n);
    const int unit = (uint32_t)x <= (uint32_t)FX_ONE;
    uint32_t r = FX_ONE, b = (uint32_t)x;
    while (n) {
        if (n & 1)
            r = !unit ? (uint32_t)((fx_umul64_call(r, b) + 0x8000u) >> 16)
                : (r & b & (uint32_t)FX_ONE) ? (uint32_t)FX_ONE
                                             : (r * b + 0x8000u) >> 16;
        n >>= 1;
        if (n)
            b = !unit ? (uint32_t)((fx_umul64_call(b, b) + 0x8000u) >> 16)
                : (b & (uint32_t)FX_ONE) ? (uint32_t)FX_ONE
                                         : (b * b + 0x8000u) >> 16;
    }
    return (fx_t)r;
}

#endif /* FX_MATH_H */
