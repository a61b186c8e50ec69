/* fx_vec: the vector operations too large to inline. */
#include "fx_vec.h"

fx_t fx_v3_dot(fx_vec3 a, fx_vec3 b)
{
    /* Each exact product is at most 2^62 in magnitude; three of them can
     * overflow int64. Halve each (floor), keep the dropped low bits apart,
     * and fold them back in when rounding. */
    int64_t p0 = (int64_t)a.x * b.x, p1 = (int64_t)a.y * b.y;
    int64_t p2 = (int64_t)a.z * b.z;
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
    int64_t x = (int64_t)a.y * b.z - (int64_t)a.z * b.y;
    int64_t y = (int64_t)a.z * b.x - (int64_t)a.x * b.z;
    int64_t z = (int64_t)a.x * b.y - (int64_t)a.y * b.x;
    return fx_v3(fx_from_q32(x), fx_from_q32(y), fx_from_q32(z));
}

fx_t fx_v3_length(fx_vec3 a)
{
    uint32_t l = fx_sqrt_q32(fx_v3_len2_q32(a));
    return l > (uint32_t)FX_MAX ? FX_MAX : (fx_t)l;
}

/* round(v * 2^(16 + s) / len), where len = |v_raw| * 2^s; |v| <= |vector|. */
static fx_t unit_component(fx_t v, uint32_t len, int s)
{
    uint64_t mag = v < 0 ? (uint64_t)0 - (uint64_t)(int64_t)v : (uint64_t)v;
    uint64_t num = s >= 0 ? mag << (16 + s) : mag << 15;
    uint64_t q = (num + (len >> 1)) / len;
    if (q > (uint64_t)FX_ONE)
        q = FX_ONE; /* rounding of len can push a lone axis past 1 */
    return v < 0 ? (fx_t)(0 - (int64_t)q) : (fx_t)q;
}

fx_vec3 fx_v3_normalize(fx_vec3 a)
{
    uint64_t len2 = fx_v3_len2_q32(a);
    int s = 0;
    if (len2 == 0)
        return fx_v3(0, 0, 0);
    /* Bring the exact |a|^2 to [2^60, 2^62) so its root has 30-31
     * significant bits whether a is a few ulps long or near 32768. */
    if (len2 >= (uint64_t)1 << 62) {
        len2 >>= 2;
        s = -1;
    } else {
        while (len2 < (uint64_t)1 << 60) {
            len2 <<= 2;
            s++;
        }
    }
    uint32_t len = fx_isqrt64(len2);
    return fx_v3(unit_component(a.x, len, s), unit_component(a.y, len, s),
                 unit_component(a.z, len, s));
}
