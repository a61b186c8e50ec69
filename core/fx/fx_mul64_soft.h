/* SPDX-License-Identifier: MIT */
/*
 * fx_mul64_soft: exact 64-bit products of 32-bit operands from four 16x16
 * products, for the back-ends without a 32x32->64 multiply (fx_cpu.h). On
 * ARMv6-M the compiler's own 64-bit product is a 64x64 library call; these
 * need only 32-bit multiplies and adds with carry. Portable C: they give
 * the same bits as (int64_t)a * b on every CPU, and the tests compare them.
 */
#ifndef FX_MUL64_SOFT_H
#define FX_MUL64_SOFT_H

#include <stdint.h>

/* hi 2^32 + lo, as the register pair it is. */
static inline uint64_t fx_pair64(uint32_t hi, uint32_t lo)
{
    return ((uint64_t)hi << 32) | lo;
}

/* m 2^16 for a signed 32-bit m, mod 2^64: its two words by two shifts
 * (a 64-bit shift of a widened m costs twice that on the M0). */
static inline uint64_t fx_mid64(int32_t m)
{
    return fx_pair64((uint32_t)(m >> 16), (uint32_t)m << 16);
}

/* a * b, exact, from 16-bit halves (the low halves unsigned): each of the
 * four partial products fits 32 bits, and the two middle ones are added
 * to the pair hh:ll by adds and adcs. The sum is the product mod
 * 2^64, which fits int64. */
static inline int64_t fx_imul64_soft(int32_t a, int32_t b)
{
    int32_t ah = a >> 16, bh = b >> 16;
    uint32_t al = (uint32_t)a & 0xFFFFu, bl = (uint32_t)b & 0xFFFFu;
    uint64_t p = fx_pair64((uint32_t)(ah * bh), al * bl);
    p += fx_mid64(ah * (int32_t)bl);
    p += fx_mid64((int32_t)al * bh);
    return (int64_t)p;
}

/* a * b for an unsigned b below 2^32, exact, from the same four partial
 * products summed by columns (as fx_imul64_call, fx_math.c): ah bl plus
 * the top of al bl, then al bh plus the low half of that, each within 32
 * bits, so no carry is needed. Inline this form does better than the
 * pairs for this product, not for the other two. */
static inline int64_t fx_iumul64_soft(int32_t a, uint32_t b)
{
    int32_t ah = a >> 16;
    uint32_t al = (uint32_t)a & 0xFFFFu, bh = b >> 16, bl = b & 0xFFFFu;
    uint32_t ll = al * bl;
    int32_t t = ah * (int32_t)bl + (int32_t)(ll >> 16);
    uint32_t u = al * bh + ((uint32_t)t & 0xFFFFu);
    uint32_t hi = (uint32_t)(ah * (int32_t)bh + (t >> 16)) + (u >> 16);
    return (int64_t)fx_pair64(hi, (u << 16) | (ll & 0xFFFFu));
}

/* a * b for unsigned a and b, exact, as fx_imul64_soft. */
static inline uint64_t fx_umul64_soft(uint32_t a, uint32_t b)
{
    uint32_t ah = a >> 16, al = a & 0xFFFFu, bh = b >> 16, bl = b & 0xFFFFu;
    uint32_t m1 = ah * bl, m2 = al * bh;
    uint64_t p = fx_pair64(ah * bh, al * bl);
    p += fx_pair64(m1 >> 16, m1 << 16);
    return p + fx_pair64(m2 >> 16, m2 << 16);
}

#endif /* FX_MUL64_SOFT_H */
