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

/* 2^14 / sqrt(x) at the midpoint of x in [i, i+1) / 256, i = 64..255, so
 * that 1 - x * r0^2 is balanced around 0 (|it| < 2^-7). */
static const uint16_t rsqrt_tab[192] = {
    32641, 32391, 32146, 31907, 31673, 31445, 31221, 31002,
    30787, 30577, 30371, 30169, 29972, 29778, 29587, 29401,
    29217, 29038, 28861, 28688, 28518, 28350, 28186, 28024,
    27866, 27709, 27556, 27405, 27256, 27110, 26966, 26825,
    26686, 26548, 26413, 26280, 26149, 26020, 25893, 25767,
    25644, 25522, 25402, 25283, 25167, 25051, 24938, 24826,
    24715, 24606, 24498, 24392, 24287, 24184, 24081, 23980,
    23881, 23782, 23685, 23589, 23494, 23400, 23307, 23216,
    23125, 23036, 22947, 22860, 22774, 22688, 22604, 22520,
    22437, 22356, 22275, 22195, 22116, 22037, 21960, 21883,
    21808, 21732, 21658, 21585, 21512, 21440, 21368, 21298,
    21228, 21159, 21090, 21022, 20955, 20888, 20822, 20757,
    20692, 20628, 20564, 20501, 20439, 20377, 20316, 20255,
    20195, 20135, 20076, 20017, 19959, 19902, 19845, 19788,
    19732, 19676, 19621, 19566, 19512, 19458, 19405, 19352,
    19299, 19247, 19196, 19144, 19093, 19043, 18993, 18943,
    18894, 18845, 18797, 18749, 18701, 18653, 18606, 18560,
    18513, 18467, 18422, 18376, 18331, 18287, 18242, 18198,
    18155, 18111, 18068, 18025, 17983, 17941, 17899, 17857,
    17816, 17775, 17734, 17694, 17654, 17614, 17574, 17535,
    17496, 17457, 17418, 17380, 17342, 17304, 17267, 17229,
    17192, 17155, 17119, 17082, 17046, 17010, 16974, 16939,
    16904, 16869, 16834, 16799, 16765, 16731, 16697, 16663,
    16629, 16596, 16563, 16530, 16497, 16465, 16432, 16400,
};

/* R ~ 2^45 / sqrt(m) for m in [2^30, 2^32), so R is in (2^29, 2^30].
 * Never above the truth, and at most 2^-20 below it (relative), as checked
 * over every m: the table seed r0, then with e = 1 - x r0^2 (x = m / 2^32)
 * the series r0 (1 - e)^-1/2 ~ r0 (1 + e/2 + 3e^2/8), whose next term is
 * below 2^-22.5. The -256 makes the result an underestimate. */
static int32_t rsqrt_q29(uint32_t m)
{
    uint32_t r0 = rsqrt_tab[(m >> 24) - 64];
    uint32_t p = (uint32_t)(((uint64_t)m * (r0 * r0)) >> 32); /* Q4.28 */
    int32_t e = (int32_t)(0x10000000u - p); /* Q.28; |e| < 2^21 */
    int32_t e7 = e >> 7;
    int32_t poly = (e >> 1) + ((3 * ((e7 * e7) >> 14)) >> 3);
    return (int32_t)(r0 << 15) + (((int32_t)r0 * (poly >> 6)) >> 7) - 256;
}

/* round(b * R / 2^44), ties toward +infinity: the high word of the exact
 * product, then 12 more bits. */
static inline fx_t unit_component(int32_t b, int32_t r)
{
    int32_t hi = (int32_t)(((int64_t)b * r) >> 32);
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
    int32_t r = rsqrt_q29(m);
    return fx_v3(unit_component(bx, r), unit_component(by, r),
                 unit_component(bz, r));
}
