/* SPDX-License-Identifier: MIT */
/*
 * rt_cutoff: the faint-ray cut-off (docs/render-model.md). A reflected or
 * refracted ray whose weight times the bound on its colour is below what
 * is left of its sample's budget is not traced, and that product is taken
 * off the budget: all the rays a sample skips add up to less than the
 * budget per channel. RT_CUTOFF (rt_config.h): builds with secondary rays.
 */
#ifndef RT_CUTOFF_H
#define RT_CUTOFF_H

#include "rt_trace.h"

/* Budget for untraced colour at 1 spp: 2^-9 (Q32.32), under half an 8-bit
 * level (1/510). rt_tracer_init divides it by the samples per pixel. */
#define RT_CUT_BUDGET ((uint32_t)1 << 23)

/* Fills bound[k], k = 0..RT_MAX_DEPTH: above every channel of the colour
 * of a ray with k bounces left in scene s (Q16.16, rounded up). */
void rt_cutoff_bounds(uint32_t bound[RT_MAX_DEPTH + 1], const rt_scene *s);

/* Weight of a ray spawned with coefficient k by a ray of weight w, rounded
 * up so that it never understates what the ray can add, for w and k in
 * [0, 1]: every ray's weight is, as a camera ray's is 1 and rt_render_rows
 * accepts only coefficients in [0, 1]. From w's 16-bit halves in 32-bit
 * products: w k + 0xFFFF = wh k 2^16 + (wl k + 0xFFFF), the last below
 * 2^32, and the result is at most w. */
static inline fx_t rt_child_weight(fx_t w, fx_t k)
{
    const uint32_t uk = (uint32_t)k;
    return (fx_t)(((uint32_t)w >> 16) * uk +
                  ((((uint32_t)w & 0xFFFFu) * uk + 0xFFFFu) >> 16));
}

/* The ray is not traced: its cost comes off the budget. */
static inline int rt_cut_ray(rt_work *wk, uint32_t cost)
{
    wk->budget -= cost;
    RT_COUNT(wk, cut);
    return 0;
}

/* 1 if a ray of weight w at this depth must be traced. If not, its colour
 * is taken as 0 and its bound w B is taken off the sample's budget. For
 * w <= 1 (every ray, rt_child_weight), w B from B's 16-bit halves in
 * 32-bit products (w Bh below 2^31, w Bl below 2^32): a cost of 2^32 or
 * more, a high part over 16 bits or a carry, exceeds every budget, and so
 * would the cost of any heavier ray. */
static inline int rt_worth_tracing(const rt_tracer *tr, rt_work *wk, fx_t w,
                                   unsigned depth)
{
    const uint32_t b = tr->bound[tr->max_depth - depth];
    if ((uint32_t)w > (uint32_t)FX_ONE)
        return 1;
    const uint32_t hi = (uint32_t)w * (b >> 16);
    const uint32_t lo = (uint32_t)w * (b & 0xFFFFu), cost = (hi << 16) + lo;
    if (hi > 0xFFFFu || cost < lo || cost >= wk->budget)
        return 1;
    return rt_cut_ray(wk, cost);
}

#endif /* RT_CUTOFF_H */
