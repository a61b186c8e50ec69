/* rt_trace: one ray's colour; used by rt_render. Internal to the core. */
#ifndef RT_TRACE_H
#define RT_TRACE_H

#include "rt_cull.h"
#include "rt_dirgrid.h"

/* The cut-off of faint rays: only in builds that have secondary rays. */
#if !defined(RT_NO_REFLECTION) || !defined(RT_NO_REFRACTION)
#define RT_CUTOFF 1
#else
#define RT_CUTOFF 0
#endif

/* Culling for closed glass (rt_tracer.alone and .dark), off with the
 * direction grids (RT_DIR_GRID 0) so that suite_cull compares it too. */
#if RT_DIR_GRIDS && !defined(RT_NO_REFRACTION)
#define RT_SEALED 1
#else
#define RT_SEALED 0
#endif

typedef struct {
    const rt_scene *scene;
    unsigned max_depth; /* <= RT_MAX_DEPTH */
    uint32_t feat;      /* RT_FEAT_* of the scene */
    rt_stats *stats;    /* may be NULL */
    uint16_t *blocker;  /* per light: the object that last blocked it */
    /* Per material and texture colour (0: color, 1: color2): */
    rt_rgb amb[RT_MAX_MATERIALS][2]; /* ambient term */
    rt_rgb lit[RT_MAX_MATERIALS][2]; /* colour x light 0 */
    fx_t kdl[RT_MAX_MATERIALS];      /* wl * kd */
#if RT_SEALED
    /* Bit sets over objects. alone: closed convex (a sphere, a box, a
     * capped cylinder or cone) whose bounding sphere no other object's
     * meets, so a ray inside it can hit only it. dark: closed convex with
     * every light outside its bounding sphere and shadows on, so no light
     * reaches its inside. */
    uint32_t alone[(RT_MAX_OBJECTS + 31) / 32];
    uint32_t dark[(RT_MAX_OBJECTS + 31) / 32];
#endif
    /* The largest cosine rv whose highlight ks rv^n rounds to 0. */
    fx_t spec_min[RT_MAX_MATERIALS];
#if RT_CUTOFF
    /* bound[k]: no channel of the colour of a ray with k bounces left
     * reaches it (Q16.16, rounding included). */
    uint32_t bound[RT_MAX_DEPTH + 1];
    /* The current sample's allowance for untraced colour (Q32.32): a ray
     * of weight w and bound B is skipped when w B is below it, and w B is
     * then taken off. cut_budget is its value at the start of each
     * sample: RT_CUT_BUDGET / spp, or 0 to trace every ray. */
    uint32_t *budget;
    uint32_t cut_budget;
#endif
#if RT_DIR_GRIDS
    rt_dir_grids grids; /* what shadow and secondary rays may hit */
#endif
} rt_tracer;

/* Fills the per-material and per-light constants of tr and the colour
 * bounds (after tr->scene and tr->max_depth are set). */
void rt_tracer_prepare(rt_tracer *tr);

#if RT_STATS
#define RT_COUNT(tr, field)                                                   \
    do {                                                                      \
        if ((tr)->stats)                                                      \
            (tr)->stats->field++;                                             \
    } while (0)
#else
#define RT_COUNT(tr, field) ((void)0)
#endif

/* Sets a ray's origin and unit direction, and what its tests need. */
static inline void rt_ray_set(rt_ray *r, fx_vec3 o, fx_vec3 d)
{
    r->o = o;
    r->d = d;
    r->e = rt_unit_err(d);
    r->small = (uint8_t)rt_small3(o);
}

/* Budget for untraced colour at 1 spp: 2^-9 (Q32.32), under half an 8-bit
 * level (1/510). rt_render divides it by the samples per pixel. */
#define RT_CUT_BUDGET ((uint32_t)1 << 23)

/* Colour seen along r (unclamped). depth counts bounces so far; w is the
 * ray's weight in its sample (the product of the coefficients along its
 * path, rounded up); skip is an object index the ray must ignore (0xFFFF
 * for none); from is the object the ray starts on (0xFFFF for none), whose
 * direction grid may narrow the search. Recursion depth is at most
 * tr->max_depth <= RT_MAX_DEPTH. */
rt_rgb rt_trace(const rt_tracer *tr, const rt_ray *r, unsigned depth,
                fx_t w, unsigned skip, unsigned from);

/* Colour seen along camera ray r of pixel column x, testing only the
 * objects whose row span covers x (rt_cull_row). Same result as rt_trace
 * (depth 0, nothing skipped). */
rt_rgb rt_trace_camera(const rt_tracer *tr, const rt_ray *r,
                       const rt_span *spans, unsigned n_spans, unsigned x);

#endif /* RT_TRACE_H */
