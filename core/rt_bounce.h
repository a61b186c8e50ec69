/* SPDX-License-Identifier: MIT */
/*
 * rt_bounce: the directions of secondary rays: the mirror direction and
 * Snell's law, with total internal reflection. Internal.
 */
#ifndef RT_BOUNCE_H
#define RT_BOUNCE_H

#include "fx_vec.h"

/* Mirror direction d - 2 (d.n) n of unit d about unit n, renormalised. */
static inline fx_vec3 rt_reflect_dir(fx_vec3 d, fx_vec3 n)
{
    /* d and n are unit vectors: |2 d.n| <= 2. */
    return fx_v3_normalize(fx_v3_madd_unit(d, n, -2 * fx_v3_dotn(d, n)));
}

/* Transmitted direction of unit d through a surface of unit normal n
 * (facing the ray) with eta = n1 / n2, by Snell's law: 1 and *t, or 0 on
 * total internal reflection. */
static inline int rt_refract_dir(fx_vec3 d, fx_vec3 n, fx_t eta, fx_vec3 *t)
{
    fx_t cosi = fx_neg(fx_v3_dotn(d, n));
    fx_t sin2 = fx_sub(FX_ONE, fx_mul(cosi, cosi));
    fx_t k = fx_sub(FX_ONE, fx_mul(fx_mul(eta, eta), sin2));
    if (k < 0)
        return 0;
    fx_t f = fx_sub(fx_mul(eta, cosi), fx_sqrt(k));
    *t = fx_v3_normalize(fx_v3_madd(fx_v3_scale(d, eta), n, f));
    return 1;
}

#endif /* RT_BOUNCE_H */
