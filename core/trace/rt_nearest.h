/* SPDX-License-Identifier: MIT */
/*
 * rt_nearest: the nearest hit along a ray, by whichever search applies:
 * the object itself and at most one other inside sealed glass
 * (rt_sealed.h), the
 * candidates of a direction grid (rt_dirgrid.h), the camera row's spans
 * (rt_cull.h), or every object. Objects go in index order in each, so
 * exact ties resolve alike and the image does not depend on the search.
 * Static inline: called once per ray, in the shading loop's unit.
 */
#ifndef RT_NEAREST_H
#define RT_NEAREST_H

#include "rt_shape.h"
#include "rt_trace.h"

/* Tests object i for a nearer hit than *best, of a ray leaving object
 * from. The common miss inline (rt_passes_by), without the call: 5.9
 * of the seed's 8 tests a pixel are these rays', most passing by. Not
 * for from itself: a ray from its surface starts within its bounding
 * sphere, so its line never passes it by. */
static inline void rt_try_nearest(rt_work *wk, const rt_object *objs,
                                  const rt_ray *r, unsigned i,
                                  unsigned from, int near, fx_t *best,
                                  uint16_t *obj, uint16_t *part)
{
    fx_t ti;
    uint16_t pi;
    RT_COUNT(wk, tests);
    if ((i == from || !rt_passes_by(&objs[i], r, near)) &&
        rt_intersect(&objs[i], r, RT_EPS, *best, &ti, &pi)) {
        *best = ti;
        *obj = (uint16_t)i;
        *part = pi;
    }
}

/* Nearest hit among all objects but `skip`, of a ray leaving object
 * `from` (RT_NO_OBJECT: unknown), among the candidates of direction grid
 * `grid` (RT_DIR_NONE: every object). Returns 1 and sets *t, *obj and
 * *part on a hit. */
static inline int rt_nearest(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                             unsigned skip, unsigned from, unsigned grid,
                             fx_t *t, uint16_t *obj, uint16_t *part)
{
    const rt_scene *s = tr->scene;
    fx_t best = FX_MAX;
    /* The ray's origin within 2^22, as every object (rt_passes_by). */
    const uint32_t lim = (uint32_t)1 << 22;
    const int near = tr->grids.near &&
                     (uint32_t)r->o.x + lim < 2 * lim &&
                     (uint32_t)r->o.y + lim < 2 * lim &&
                     (uint32_t)r->o.z + lim < 2 * lim;
    /* A closed convex object skips itself exactly for rays leaving its
     * outside, so this ray runs inside `from`: sealed glass can hit only
     * itself and rt_sealed_with's object, tested in index order. When
     * `from` is not the nearest of the two, search again. */
    const unsigned with = skip == RT_NO_OBJECT && from < s->n_objects
                              ? rt_sealed_with(&tr->sealed, from)
                              : RT_SEALED_NONE;
    if (with != RT_SEALED_NONE) {
        const unsigned last = with < from ? from : with;
        for (unsigned i = with < from ? with : from;; i = last) {
            rt_try_nearest(wk, s->obj, r, i, from, near, &best, obj, part);
            if (i == last)
                break;
        }
        if (best != FX_MAX && *obj == from) {
            *t = best;
            return 1;
        }
        best = FX_MAX;
    }
    if (grid != RT_DIR_NONE) {
        const uint32_t *cand = rt_dir_candidates(&tr->grids, grid, r->d);
        /* Loaded once, not after every store through obj, which the
         * compiler must assume may alias it. */
        const unsigned words = tr->grids.words;
        for (unsigned w = 0; cand && w < words; w++) {
            for (uint32_t m = cand[w]; m; m &= m - 1) {
                unsigned i = w * 32 + (unsigned)fx_ctz32(m);
                if (i != skip)
                    rt_try_nearest(wk, s->obj, r, i, from, near, &best, obj,
                                   part);
            }
        }
    } else {
        for (unsigned i = 0; i < s->n_objects; i++)
            if (i != skip)
                rt_try_nearest(wk, s->obj, r, i, from, near, &best, obj,
                               part);
    }
    *t = best;
    return best != FX_MAX;
}

/* Nearest hit of camera ray r in pixel column x among the row's spans. */
static inline int rt_nearest_camera(const rt_tracer *tr, rt_work *wk,
                                    const rt_ray *r, const rt_row_spans *rs,
                                    unsigned x, fx_t *t, uint16_t *obj,
                                    uint16_t *part)
{
    const rt_scene *s = tr->scene;
    fx_t best = FX_MAX;
    int found = 0;
    const rt_span *spans = rs->span;
    const unsigned n_spans = rs->count;
    for (unsigned k = 0; k < n_spans; k++) {
        fx_t ti;
        uint16_t pi;
        if (x < (unsigned)spans[k].x0 || x > (unsigned)spans[k].x1)
            continue;
        RT_COUNT(wk, tests);
        if (rt_intersect(&s->obj[spans[k].obj], r, RT_EPS, best, &ti, &pi)) {
            best = ti;
            *obj = spans[k].obj;
            *part = pi;
            found = 1;
        }
    }
    *t = best;
    return found;
}

#endif /* RT_NEAREST_H */
