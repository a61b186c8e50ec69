/* fx_math: Q16.16 division and reciprocal (the inline ops live in the
 * header). */
#include "fx_math.h"

fx_t fx_div(fx_t a, fx_t b)
{
    if (b == 0)
        return a >= 0 ? FX_MAX : FX_MIN;
    /* Work on magnitudes so the rounding is symmetric (ties away from
     * zero); |a| << 16 < 2^48 and the quotient fits easily in 64 bits. */
    uint64_t ua = a < 0 ? (uint64_t)0 - (uint64_t)(int64_t)a : (uint64_t)a;
    uint64_t ub = b < 0 ? (uint64_t)0 - (uint64_t)(int64_t)b : (uint64_t)b;
    uint64_t q = ((ua << 16) + (ub >> 1)) / ub;
    int neg = (a < 0) != (b < 0);
    if (neg)
        return q > (uint64_t)0x80000000u ? FX_MIN : (fx_t)(0 - (int64_t)q);
    return q > (uint64_t)FX_MAX ? FX_MAX : (fx_t)q;
}

fx_t fx_recip(fx_t a)
{
    return fx_div(FX_ONE, a);
}
