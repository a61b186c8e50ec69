/* SPDX-License-Identifier: MIT */
/*
 * rt_sphere: spheres (rt_sphere: centre c, radius r). The sphere is its
 * own bounding sphere, so its hit is the bounding test's chord; its normal
 * is (p - c) scaled by a reciprocal of r prepared once.
 *
 * Part of the dispatch unit: rt_shape.c includes this file (its comment
 * says why); compiled alone it defines nothing.
 */
#include "rt_bsphere.h"
#include "rt_kinds.h"

static inline rt_status sphere_prepare(rt_object *o)
{
    rt_sphere *s = &o->u.sphere;
    if (s->radius <= 0)
        return RT_ERR_DEGENERATE;
    o->bc = s->center;
    o->br = s->radius;
    o->convex = 1;
    /* (2^(31 + b) - 1) / r is below 2^32 as r >= 2^(b - 1). */
    const int b = 32 - fx_clz32((uint32_t)s->radius);
    s->inv_radius = fx_udiv64_32(((uint64_t)1 << (31 + b)) - 1u,
                                 (uint32_t)s->radius);
    return RT_OK;
}

static inline int sphere_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                  fx_t *t, uint16_t *part)
{
    int64_t tca, h[3];
    uint64_t disc;
    fx_t best = tmax;
    if (!bsphere(&o->u.sphere.center, o->u.sphere.radius, o->small, r,
                 tmin, tmax, &tca, &disc, h))
        return 0;
    /* sq <= r < 2^31, as disc <= r^2. */
    const uint32_t sq = fx_sqrt_round(disc);
    /* In units of |d| = sqrt(1 + e): thc (1 - e / 2). For any int32 e
     * that is in [0, 2^31 + 2^29], so the 32-bit difference is exact. */
    const int64_t thc =
        (uint32_t)(sq - (uint32_t)fx_mul_small_round((int32_t)sq, r->e, 33));
    if (!take(tca - thc, tmin, &best) && !take(tca + thc, tmin, &best))
        return 0;
    *t = best;
    *part = 0;
    return 1;
}

static inline fx_dir3 sphere_normal(const rt_object *o, fx_vec3 p)
{
    const rt_sphere *s = &o->u.sphere;
    /* (p - c) / r as (p - c) inv_radius 2^-sh (sh = b + 1), then one
     * Newton step (|p - c| is r to within the rounding of p, a relative 2^-16 / r;
     * fx_d3_renorm normalises in full when that is more than 2^-15). */
    const unsigned sh = 33u - (unsigned)fx_clz32((uint32_t)s->radius);
    /* p is on the sphere to within its rounding: for a small one (c and
     * r within 2^29) each p - c is within 2^30, so a plain subtraction
     * needs no saturation. */
    const fx_vec3 c = s->center;
    const fx_vec3 v = o->small ? fx_v3(p.x - c.x, p.y - c.y, p.z - c.z)
                               : fx_v3_sub(p, c);
    return fx_d3_renorm(fx_d3(fx_iumul_round(v.x, s->inv_radius, sh),
                              fx_iumul_round(v.y, s->inv_radius, sh),
                              fx_iumul_round(v.z, s->inv_radius, sh)));
}
