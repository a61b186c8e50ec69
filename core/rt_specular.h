/* SPDX-License-Identifier: MIT */
/* rt_specular: the Phong highlight of a point light. Internal. */
#ifndef RT_SPECULAR_H
#define RT_SPECULAR_H

#include "rt_scene.h"

/* The highlight's weight ks (R.v)^n for unit normal n, unit direction ld
 * to the light with ndl = n.ld > 0, and unit ray direction d: 1 and *k
 * when R.v is above rv_min (rt_specular_min), else 0 (it would add 0). */
static inline int rt_highlight(const rt_material *m, fx_vec3 n, fx_vec3 ld,
                               fx_t ndl, fx_vec3 d, fx_t rv_min, fx_t *k)
{
    /* R = 2 (n.l) n - l; rv = R.v with v = -d. */
    fx_vec3 rl = fx_v3_madd_unit(fx_v3_neg(ld), n, 2 * ndl);
    fx_t rv = fx_neg(fx_v3_dotn(rl, d));
    if (rv <= rv_min)
        return 0;
    *k = fx_mul(m->specular, fx_powi(rv, m->shininess));
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
