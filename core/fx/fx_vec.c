/* SPDX-License-Identifier: MIT */
/* fx_vec: the vector operations too large to inline. */
#include "fx_vec.h"
#include "fx_rsqrt.h"

fx_t fx_v3_dot(fx_vec3 a, fx_vec3 b)
{
    /* Each exact product is at most 2^62 in magnitude; three of them can
     * overflow int64. Halve each (floor), keep the dropped low bits apart,
     * and fold them back in when rounding. */
    int64_t p0 = fx_imul64(a.x, b.x), p1 = fx_imul64(a.y, b.y);
    int64_t p2 = fx_imul64(a.z, b.z);
    int64_t half = (p0 >> 1) + (p1 >> 1) + (p2 >> 1);
    int64_t lows = (p0 & 1) + (p1 & 1) + (p2 & 1);
    /* round((2*half + lows) / 2^16) = floor((half + (lows + 2^15) / 2) / 2^15) */
    return fx_sat64((half + ((lows + 0x8000) >> 1)) >> 15);
}

uint64_t fx_v3_len2_q32(fx_vec3 a)
{
    int64_t x = a.x, y = a.y, z = a.z;
    return (uint64_t)(x * x) + (uint64_t)(y * y) + (uint64_t)(z * z);
}

fx_vec3 fx_v3_cross(fx_vec3 a, fx_vec3 b)
{
    /* a.y*b.z - a.z*b.y: each product is below 2^62, the difference below
     * 2^63, so int64 holds it exactly. */
    int64_t x = fx_imul64(a.y, b.z) - fx_imul64(a.z, b.y);
    int64_t y = fx_imul64(a.z, b.x) - fx_imul64(a.x, b.z);
    int64_t z = fx_imul64(a.x, b.y) - fx_imul64(a.y, b.x);
    return fx_v3(fx_from_q32(x), fx_from_q32(y), fx_from_q32(z));
}

fx_t fx_v3_length(fx_vec3 a)
{
    uint32_t l = fx_sqrt_q32(fx_v3_len2_q32(a));
    return l > (uint32_t)FX_MAX ? FX_MAX : (fx_t)l;
}

/* round(b * R / 2^44), ties toward +infinity: the high word of the exact
 * product, then 12 more bits. */
static inline fx_t unit_component(int32_t b, int32_t r)
{
    int32_t hi = (int32_t)((fx_imul64(b, r)) >> 32);
    return (hi + 0x800) >> 12;
}

fx_vec3 fx_v3_normalize(fx_vec3 a)
{
    uint64_t len2 = fx_v3_len2_q32(a);
    uint32_t hi = (uint32_t)(len2 >> 32), lo = (uint32_t)len2, m;
    int sh, z;
    /* Scale |a|^2 by 4^j into X in [2^62, 2^64) and keep its top word
     * m = X / 2^32 (30-32 significant bits). Scale a by 2^(j-1), so each
     * |b| <= sqrt(X) / 2 < 2^31; for j = 0 that is a halving, which drops
     * at most 2^-31 of the length. Then b / sqrt(X / 4) is the unit
     * component. Shifting the two words apart avoids a 64-bit shift. */
    if (hi == 0) {
        if (lo == 0)
            return fx_v3(0, 0, 0);
        z = fx_clz32(lo) & ~1;
        m = lo << z;
        sh = 15 + z / 2;
    } else {
        z = fx_clz32(hi) & ~1;
        m = z ? (hi << z) | (lo >> (32 - z)) : hi;
        sh = z / 2 - 1;
    }
    int32_t bx, by, bz;
    if (sh >= 0) {
        /* |a| * 2^sh < 2^31, so the unsigned shift is the exact value. */
        bx = (int32_t)((uint32_t)a.x << sh);
        by = (int32_t)((uint32_t)a.y << sh);
        bz = (int32_t)((uint32_t)a.z << sh);
    } else {
        bx = a.x >> 1;
        by = a.y >> 1;
        bz = a.z >> 1;
    }
    /* u = b * 2^17 / sqrt(m * 2^32) = b * (2^45 / sqrt(m)) / 2^44. R is
     * an underestimate by at most 2^-20, so |u| never rounds past 1 and
     * each component is within 0.5 + 2^-4 ulp of the truth. */
    int32_t r = fx_rsqrt_q29(m);
    return fx_v3(unit_component(bx, r), unit_component(by, r),
                 unit_component(bz, r));
}

/* Unit vector along an exact 64-bit vector (for normals from cross
 * products of tiny edges, which would round to zero in Q16.16). */
static fx_vec3 norm64(int64_t x, int64_t y, int64_t z)
{
    while (x > FX_MAX / 2 || x < FX_MIN / 2 || y > FX_MAX / 2 ||
           y < FX_MIN / 2 || z > FX_MAX / 2 || z < FX_MIN / 2) {
        x /= 2;
        y /= 2;
        z /= 2;
    }
    return fx_v3_normalize(fx_v3((fx_t)x, (fx_t)y, (fx_t)z));
}

fx_vec3 fx_v3_cross_unit(fx_vec3 a, fx_vec3 b)
{
    return norm64(fx_imul64(a.y, b.z) - fx_imul64(a.z, b.y),
                  fx_imul64(a.z, b.x) - fx_imul64(a.x, b.z),
                  fx_imul64(a.x, b.y) - fx_imul64(a.y, b.x));
}
