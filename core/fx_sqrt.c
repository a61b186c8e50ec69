/* fx_sqrt: integer and Q16.16 square roots, exact or correctly rounded. */
#include "fx_math.h"

uint32_t fx_isqrt64(uint64_t a)
{
    /* Digit-by-digit (binary restoring) square root: exact floor. */
    uint64_t rem = a, root = 0;
    uint64_t bit = (uint64_t)1 << 62;
    while (bit > rem)
        bit >>= 2;
    while (bit != 0) {
        if (rem >= root + bit) {
            rem -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    return (uint32_t)root;
}

uint32_t fx_sqrt_q32(uint64_t a)
{
    uint32_t r = fx_isqrt64(a);
    /* Round to nearest: sqrt(a) >= r + 1/2 exactly when a >= r^2 + r + 1/4,
     * i.e. a > r^2 + r for integers. r^2 + r < 2^64 since r < 2^32. */
    uint64_t r2 = (uint64_t)r * r + r;
    if (a > r2 && r != 0xFFFFFFFFu)
        r++;
    return r;
}

fx_t fx_sqrt(fx_t a)
{
    if (a <= 0)
        return 0;
    /* sqrt(a / 2^16) * 2^16 = sqrt(a * 2^16). */
    return (fx_t)fx_sqrt_q32((uint64_t)a << 16);
}
