/* SPDX-License-Identifier: MIT */
/*
 * fx_vec: 3-vectors of Q16.16 values. Small helpers return structs by value.
 * Component-wise operations follow the fx_math policy of their scalar op.
 */
#ifndef FX_VEC_H
#define FX_VEC_H

#include "fx_math.h"

typedef struct {
    fx_t x, y, z;
} fx_vec3;

/* Builds a vector from its components; exact. */
static inline fx_vec3 fx_v3(fx_t x, fx_t y, fx_t z)
{
    fx_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

/* a + b per component; exact, saturates. */
static inline fx_vec3 fx_v3_add(fx_vec3 a, fx_vec3 b)
{
    return fx_v3(fx_add(a.x, b.x), fx_add(a.y, b.y), fx_add(a.z, b.z));
}

/* a - b per component; exact, saturates. */
static inline fx_vec3 fx_v3_sub(fx_vec3 a, fx_vec3 b)
{
    return fx_v3(fx_sub(a.x, b.x), fx_sub(a.y, b.y), fx_sub(a.z, b.z));
}

/* -a per component; exact, saturates only at FX_MIN. */
static inline fx_vec3 fx_v3_neg(fx_vec3 a)
{
    return fx_v3(fx_neg(a.x), fx_neg(a.y), fx_neg(a.z));
}

/* a * s per component; each rounded as fx_mul (to nearest, ties toward
 * +infinity), saturates. */
static inline fx_vec3 fx_v3_scale(fx_vec3 a, fx_t s)
{
    return fx_v3(fx_mul(a.x, s), fx_mul(a.y, s), fx_mul(a.z, s));
}

/* a * b rounded as fx_mul but not saturated: |result| <= 2^46. */
static inline int64_t fx_mul_wide(fx_t a, fx_t b)
{
    return (fx_imul64(a, b) + 0x8000) >> 16;
}

/* a + b * s with one rounding, as fx_mul (to nearest, ties toward
 * +infinity); saturates. */
static inline fx_t fx_madd1(fx_t a, fx_t b, fx_t s)
{
    int64_t p = fx_imul64(b, s) + 0x8000;
    int32_t hi = (int32_t)(p >> 32);
    /* The usual case: the rounded product fits in 32 bits, and a 32-bit
     * add with an overflow check gives the saturated sum. */
    if ((uint32_t)hi + 0x8000u <= 0xFFFFu)
        return fx_add(a, (fx_t)(((uint32_t)hi << 16) | ((uint32_t)p >> 16)));
    return fx_sat64((int64_t)a + (p >> 16));
}

/* fx_madd1 for |b| <= 1.0 (a unit vector's component) and |s| <= 2^30
 * (16384.0): the rounded product then fits 32 bits, so only the sum can
 * saturate, and the range check falls away. Same results as fx_madd1. */
static inline fx_t fx_madd1_unit(fx_t a, fx_t b, fx_t s)
{
    int64_t p = fx_imul64(b, s) + 0x8000;
    return fx_add(a, (fx_t)(p >> 16));
}

/* fx_madd1 per component. */
static inline fx_vec3 fx_v3_madd(fx_vec3 a, fx_vec3 b, fx_t s)
{
    return fx_v3(fx_madd1(a.x, b.x, s), fx_madd1(a.y, b.y, s),
                 fx_madd1(a.z, b.z, s));
}

/* fx_v3_madd for a unit vector b (|components| <= 1.0) and |s| <= 2^30:
 * the same results, cheaper (fx_madd1_unit). */
static inline fx_vec3 fx_v3_madd_unit(fx_vec3 a, fx_vec3 b, fx_t s)
{
    return fx_v3(fx_madd1_unit(a.x, b.x, s), fx_madd1_unit(a.y, b.y, s),
                 fx_madd1_unit(a.z, b.z, s));
}

/* Exact dot product as Q32.32, for operands where one side is bounded by
 * |component| <= 2^20 (4.0 or less: directions, normals). No overflow then:
 * each product is below 2^51. */
static inline int64_t fx_v3_dot_q32(fx_vec3 a, fx_vec3 b)
{
    return fx_imul64(a.x, b.x) + fx_imul64(a.y, b.y) + fx_imul64(a.z, b.z);
}

/* Dot product with a bounded operand (as fx_v3_dot_q32), rounded once as
 * fx_from_q32 (to nearest, ties toward +infinity); saturates. */
static inline fx_t fx_v3_dotn(fx_vec3 a, fx_vec3 b)
{
    return fx_from_q32(fx_v3_dot_q32(a, b));
}

/* Dot product of any two vectors: the three exact products are summed
 * without overflow for every input, then rounded once as fx_from_q32;
 * saturates. */
fx_t fx_v3_dot(fx_vec3 a, fx_vec3 b);

/* 1 if every component of v is below 2^29 (8192 units) in magnitude:
 * differences of two such points fit 32 bits. */
static inline int fx_v3_small(fx_vec3 v)
{
    const uint32_t lim = (uint32_t)1 << 30;
    return (uint32_t)v.x + (lim >> 1) < lim &&
           (uint32_t)v.y + (lim >> 1) < lim && (uint32_t)v.z + (lim >> 1) < lim;
}

/* Exact |a|^2 as unsigned Q32.32; never overflows (at most 3 * 2^62). */
uint64_t fx_v3_len2_q32(fx_vec3 a);

/* Cross product; each component exact in 64 bits, then rounded once as
 * fx_from_q32; saturates. */
fx_vec3 fx_v3_cross(fx_vec3 a, fx_vec3 b);

/* Length, correctly rounded to nearest from the exact |a|^2 (as
 * fx_sqrt_q32); saturates to FX_MAX (only for lengths that round to 32768
 * or more). */
fx_t fx_v3_length(fx_vec3 a);

/* Unit vector along a: each component within 1 ulp of the true value (at
 * most 0.5 + 2^-4 ulp; it is not correctly rounded) and never past +-1, for
 * tiny and huge vectors alike, since the squared length is exact in 64
 * bits; cannot overflow. The zero vector gives the zero vector. */
fx_vec3 fx_v3_normalize(fx_vec3 a);

/* Unit vector along a x b, from the exact 64-bit cross product, so tiny
 * vectors do not round to zero; within normalize's bound of the true unit
 * vector once the product is halved into range. The zero vector if a and
 * b are parallel. */
fx_vec3 fx_v3_cross_unit(fx_vec3 a, fx_vec3 b);

#endif /* FX_VEC_H */
