/* SPDX-License-Identifier: MIT */
/* rt_specular: the Phong highlight of a point light. Internal. */
#ifndef RT_SPECULAR_H
#define RT_SPECULAR_H

#include "rt_colour.h"
#include "rt_ray.h"

/* v (2 FX_UBITS fraction bits, below 2^62 in magnitude) in Q16.16,
 * rounded to nearest. For FX_UBITS >= 25 from its top word alone, as the
 * half, 2^(2 FX_UBITS - 17), lies there and the low word cannot carry
 * into the bits kept: a 32-bit result the compiler sees as one, so that
 * its product with a colour is not formed as a 64-bit one. */
static inline fx_t rt_cos_fx(int64_t v)
{
    if (2 * FX_UBITS - 17 >= 32)
        return ((int32_t)(v >> 32) +
                ((int32_t)1 << ((2 * FX_UBITS - 49) & 31))) >>
               ((2 * FX_UBITS - 48) & 31);
    return (fx_t)((v + ((int64_t)1 << (2 * FX_UBITS - 17))) >>
                  (2 * FX_UBITS - 16));
}

/* The highlight's weight ks (R.v)^n for unit direction ld to the light
 * and unit ray direction d, given the exact nl = n.ld > 0 (fx_d3_dot_raw)
 * and the rounded ndu = n.d (rt_dotu_of) of the unit normal n, which the
 * shading loop has already formed: 1 and *k when R.v is above rv_min
 * (rt_specular_min), else 0 (it would add 0). */
static inline int rt_highlight(const rt_material *m, int64_t nl, int32_t ndu,
                               fx_dir3 ld, fx_dir3 d, fx_t rv_min, fx_t *k)
{
    /* R = 2 (n.l) n - l; rv = R.v with v = -d, so
     * rv = (n.l)(-2 n.d) + l.d: two exact dot products. */
    int64_t ld_d = fx_d3_dot_exact(ld, d);
    /* The product nl nd has 4 FX_UBITS fraction bits: take each to
     * FX_UBITS first (both below 1). */
    int64_t nl_u = (nl + ((int64_t)1 << (FX_UBITS - 1))) >> FX_UBITS;
    /* Both within 2^FX_UBITS (+1): one 32x32->64 product. */
    int64_t rv2 = ld_d - 2 * fx_imul64((int32_t)nl_u, ndu);
    fx_t rv = rt_cos_fx(rv2);
    if (rv <= rv_min)
        return 0;
    /* The power is in [0, 1] (fx_powi): fx_mul's value, which cannot
     * saturate for such a weight (fx_wmul: no test). */
    *k = fx_wmul(m->specular, fx_powi_unit(rv, m->shininess));
    return 1;
}

/* The largest cosine whose highlight ks rv^n rounds to 0. ks rv^n rounds
 * up monotonically in rv (each step does), so those cosines end at one
 * found by bisection. */
static inline fx_t rt_specular_min(const rt_material *m)
{
    fx_t lo = 0, hi = FX_ONE;
    while (hi - lo > 1) {
        fx_t mid = lo + (hi - lo) / 2;
        if (fx_mul(m->specular, fx_powi(mid, m->shininess)) == 0)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

#endif /* RT_SPECULAR_H */
