/* SPDX-License-Identifier: MIT */
/*
 * rt_trace: one ray's colour. The tracer (rt_tracer) is what a render
 * derives from the scene once and only reads while it traces; the work
 * (rt_work) is what changes during the render: the cut-off's budget, the
 * shadow rays' blocker cache and the counters. Internal to the core.
 */
#ifndef RT_TRACE_H
#define RT_TRACE_H

#include "rt_options.h"
#include "rt_cull.h"
#include "rt_dirgrid.h"
#include "rt_sealed.h"

typedef struct {
    const rt_scene *scene;
    unsigned max_depth; /* <= RT_MAX_DEPTH */
    uint32_t feat;      /* RT_FEAT_* of the scene */
    /* Per material and texture colour (0: color, 1: color2): */
    rt_rgb amb[RT_MAX_MATERIALS][2]; /* ambient term */
    rt_rgb lit[RT_MAX_MATERIALS][2]; /* colour x light 0 */
    fx_t kdl[RT_MAX_MATERIALS];      /* wl * kd */
    rt_sealed sealed;                /* closed glass (rt_sealed.h) */
    /* The largest cosine rv whose highlight ks rv^n rounds to 0. */
    fx_t spec_min[RT_MAX_MATERIALS];
    /* bound[k]: no channel of the colour of a ray with k bounces left
     * reaches it (Q16.16, rounding included; rt_cutoff.h). */
    uint32_t bound[RT_MAX_DEPTH + 1];
    /* The cut-off budget at the start of each sample: RT_CUT_BUDGET / spp,
     * or 0 to trace every ray. */
    uint32_t cut_budget;
    rt_dir_grids grids; /* what shadow and secondary rays may hit */
    /* Per light, bit sets of the quads whose plane the light lies more
     * than RT_SIDE_MARGIN off (sided), and of those the ones it lies in
     * front of, on the side the normal points to (front): a shadow ray
     * from the light's side cannot cross the quad (rt_shadow.h). */
    uint32_t quad_sided[RT_MAX_LIGHTS][(RT_MAX_OBJECTS + 31) / 32];
    uint32_t quad_front[RT_MAX_LIGHTS][(RT_MAX_OBJECTS + 31) / 32];
} rt_tracer;

/* With 16 + FX_UBITS fraction bits: 2^(36 - FX_UBITS) ulps plus 2^-8
 * unit. A shadow ray's direction is rounded to 2^-FX_UBITS, so its far
 * end strays from the light, and its length is off, by under 2^(2 -
 * FX_UBITS) of its length (below 2^33 ulps) each. */
#define RT_SIDE_MARGIN (((int64_t)1 << 36) + ((int64_t)1 << (FX_UBITS + 8)))

/* Called on each hit the tracer shades, when set (rt_work.on_hit):
 * object oi of scene s, met at distance t along r by a ray of weight w
 * (FX_ONE for a camera ray). ctx is the installer's; the tracer does not
 * know what the hook is for (a draft render tells its pixels apart by
 * their hits, rt_draft.c). */
typedef void (*rt_hit_hook)(void *ctx, const rt_scene *s, unsigned oi,
                            const rt_ray *r, fx_t t, fx_t w);

typedef struct {
    rt_stats *stats; /* may be NULL */
    /* The current sample's allowance for untraced colour (Q32.32): a ray
     * of weight w and bound B is skipped when w B is below it, and w B is
     * then taken off (rt_cutoff.h). */
    uint32_t budget;
    uint16_t blocker[RT_MAX_LIGHTS]; /* per light: what last blocked it */
    rt_hit_hook on_hit; /* NULL: none */
    void *hit_ctx;      /* on_hit's context */
} rt_work;

/* Sets up *tr for rendering scene s (valid: rt_render_rows checks it)
 * with options o: the per-material and per-light constants, the colour
 * bounds, the sealed glass and the direction grids. */
void rt_tracer_init(rt_tracer *tr, const rt_scene *s, const rt_options *o);

/* Empty work: no blockers known, a budget of 0, no hook. */
void rt_work_init(rt_work *wk, rt_stats *stats);

/* Adds one to a counter of wk's rt_stats, if counting (RT_STATS). */
#define RT_COUNT(wk, field)                                                   \
    do {                                                                      \
        if (RT_STATS && (wk)->stats)                                          \
            (wk)->stats->field++;                                             \
    } while (0)

/* Colour seen along r (unclamped). depth counts bounces so far; w is the
 * ray's weight in its sample (the product of the coefficients along its
 * path, rounded up); skip is an object index the ray must ignore
 * (RT_NO_OBJECT for none); from is the object the ray starts on
 * (RT_NO_OBJECT for none), whose direction grid may narrow the search.
 * Recursion depth is at most tr->max_depth <= RT_MAX_DEPTH. */
rt_rgb rt_trace(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                unsigned depth, fx_t w, unsigned skip, unsigned from);

/* Colour seen along camera ray r of pixel column x, testing only the
 * objects whose row span covers x (rt_cull_row); starts a new sample's
 * cut-off budget. Same result as rt_trace (depth 0, nothing skipped). */
rt_rgb rt_trace_camera(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                       const rt_row_spans *rs, unsigned x);

/* The nearest hit of a camera ray (rt_probe_camera). */
typedef struct {
    fx_t t;       /* distance along the ray; FX_MAX for none */
    uint16_t obj; /* object index, RT_NO_OBJECT for none */
    uint16_t part; /* which face, cap or side; a mesh's triangle */
} rt_hit;

/* The first half of rt_trace_camera: the nearest hit of camera ray r of
 * pixel column x among the row's spans, into *h. Returns 1 on a hit. */
int rt_probe_camera(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                    const rt_row_spans *rs, unsigned x, rt_hit *h);

/* The second half: the colour of camera ray r with nearest hit *h (from
 * rt_probe_camera); starts a new sample's cut-off budget. Together the
 * two give rt_trace_camera's colour. */
rt_rgb rt_shade_camera(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                       const rt_hit *h);

#endif /* RT_TRACE_H */
