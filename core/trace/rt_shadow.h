/* SPDX-License-Identifier: MIT */
/*
 * rt_shadow: hard shadows. A shadow ray stops at the first blocker; the
 * light's last blocker (the blocker cache in rt_work) is tried first, as
 * neighbouring shadow rays tend to share it. The answer does not depend
 * on the order, only the count of tests does. A light's direction grid
 * (rt_dirgrid.h) narrows the candidates. Static inline: the shading
 * loop's unit.
 */
#ifndef RT_SHADOW_H
#define RT_SHADOW_H

#include "rt_shape.h"
#include "rt_trace.h"

/* 1 if the bit set cand (NULL: empty) lists an object other than skip:
 * a shadow ray from a floor point often has only the floor to test. */
static inline int rt_listed_besides(const uint32_t *cand, unsigned words,
                                    unsigned skip)
{
    for (unsigned w = 0; cand && w < words; w++) {
        uint32_t m = cand[w];
        if (skip / 32 == w)
            m &= ~((uint32_t)1 << (skip % 32));
        if (m)
            return 1;
    }
    return 0;
}

/* Tests object i for a blocker of shadow ray r; remembers it. */
static inline int rt_blocks(rt_work *wk, const rt_object *objs,
                            const rt_ray *r, fx_t tmax, unsigned i,
                            unsigned light)
{
    fx_t ti;
    uint16_t pi;
    RT_COUNT(wk, tests);
    if (!rt_intersect(&objs[i], r, RT_EPS, tmax, &ti, &pi))
        return 0;
    wk->blocker[light] = (uint16_t)i;
    return 1;
}

/* Word w of the candidates m of shadow ray r towards light li, less the
 * quads it cannot cross: those whose plane has r's origin on the
 * light's side or on it. Exact: the side is rt_quad_num's sign, which
 * the quad's own test takes, and from there the ray meets the plane
 * only beyond the light, past its tmax (RT_SIDE_MARGIN). */
RT_NOINLINE static uint32_t rt_uncrossed_quads(const rt_tracer *tr,
                                               unsigned li, unsigned w,
                                               uint32_t m, const rt_ray *r)
{
    const rt_object *objs = tr->scene->obj + w * 32;
    /* Two loops, one a side: each keeps its own test of the sign. */
    for (uint32_t q = m & tr->quad_front[li][w]; q; q &= q - 1) {
        const unsigned b = (unsigned)fx_ctz32(q);
        if (rt_quad_side(&objs[b], r->o, r->small) <= 0)
            m &= ~((uint32_t)1 << b);
    }
    for (uint32_t q = m & tr->quad_sided[li][w] & ~tr->quad_front[li][w]; q;
         q &= q - 1) {
        const unsigned b = (unsigned)fx_ctz32(q);
        if (rt_quad_side(&objs[b], r->o, r->small) >= 0)
            m &= ~((uint32_t)1 << b);
    }
    return m;
}

/* The same, out of line only when m lists such a quad: the loop stays
 * out of the shading loop's frame. */
static inline uint32_t rt_uncrossed(const rt_tracer *tr, unsigned li,
                                    unsigned w, uint32_t m, const rt_ray *r)
{
    if (!(m & tr->quad_sided[li][w]))
        return m;
    return rt_uncrossed_quads(tr, li, w, m, r);
}

/* Any blocker with RT_EPS < t < tmax among the candidates (a bit set of
 * object indices, or NULL for all objects) but skip. */
static inline int rt_occluded(const rt_tracer *tr, rt_work *wk,
                              const rt_ray *r, fx_t tmax, unsigned skip,
                              unsigned light, const uint32_t *cand)
{
    const rt_scene *s = tr->scene;
    unsigned first = wk->blocker[light];
    if (first < s->n_objects && first != skip &&
        (!cand || ((cand[first / 32] >> (first % 32)) & 1u)) &&
        rt_blocks(wk, s->obj, r, tmax, first, light))
        return 1;
    if (RT_DIR_GRIDS && cand) {
        for (unsigned w = 0; w < tr->grids.words; w++) {
            uint32_t m = cand[w];
            if (skip / 32 == w)
                m &= ~((uint32_t)1 << (skip % 32));
            for (m = rt_uncrossed(tr, light, w, m, r); m; m &= m - 1) {
                unsigned i = w * 32 + (unsigned)fx_ctz32(m);
                if (i != first && rt_blocks(wk, s->obj, r, tmax, i, light))
                    return 1;
            }
        }
        return 0;
    }
    for (unsigned i = 0; i < s->n_objects; i++)
        if (i != skip && i != first &&
            rt_blocks(wk, s->obj, r, tmax, i, light))
            return 1;
    return 0;
}

/* fx_pd_dot_exact(lv, ld), the same exact value: for a light within
 * 2^14 units on every axis (each component of lv within 2^30: one
 * unsigned compare of the biased values, wrapping, or-ed together) the
 * small dot product (fx_d3_dot_exact takes such values), which is the
 * cheaper one where products are built from 16-bit ones. */
static inline int64_t rt_lv_dot(fx_vec3 lv, fx_dir3 ld)
{
    const uint32_t b = (uint32_t)1 << 30;
    if ((((uint32_t)lv.x + b) | ((uint32_t)lv.y + b) | ((uint32_t)lv.z + b)) <
        2u * b)
        return fx_d3_dot_exact(fx_d3(lv.x, lv.y, lv.z), ld);
    return fx_pd_dot_exact(lv, ld);
}

/* 1 if light li is hidden from the hit point: a shadow ray from p_out
 * (the hit point off its surface, rt_origin_log2) along unit ld, to the
 * light at lv from p_out, ignoring object skip. */
static inline int rt_in_shadow(const rt_tracer *tr, rt_work *wk, unsigned li,
                               fx_vec3 lv, fx_dir3 ld, fx_vec3 p_out,
                               unsigned skip)
{
    const uint32_t *cand = 0; /* every object */
    int any = 1;
    if (rt_dir_to_light(&tr->grids, li, ld, &cand))
        any = rt_listed_besides(cand, tr->grids.words, skip);
    RT_COUNT(wk, shadow);
    if (!any)
        return 0;
    rt_ray sr;
    rt_ray_set(&sr, p_out, ld);
    /* |lv| = lv . norm(lv): a dot product instead of a second square
     * root; its error (a few 2^-FX_UBITS of |lv|) only moves the far end
     * of the shadow ray, by far less than RT_EPS. Rounded as fx_pd_dot. */
    const fx_t len = fx_sat64(
        (rt_lv_dot(lv, ld) + ((int64_t)1 << (FX_UBITS - 1))) >> FX_UBITS);
    return rt_occluded(tr, wk, &sr, fx_sub(len, RT_EPS), skip, li, cand);
}

#endif /* RT_SHADOW_H */
