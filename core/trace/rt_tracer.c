/* SPDX-License-Identifier: MIT */
/*
 * rt_tracer: what a render derives from the scene before the first ray
 * (rt_trace.h): colour tables per material, the highlight cut-offs, the
 * colour bounds of the faint-ray cut-off, the side of each quad each
 * light lies on, the sealed glass and the direction grids; and the
 * per-render work.
 */
#include "rt_libc.h"
#include "rt_colour.h"
#include "rt_cutoff.h"
#include "rt_shape.h"
#include "rt_specular.h"

void rt_tracer_init(rt_tracer *tr, const rt_scene *s, const rt_options *o)
{
    memset(tr, 0, sizeof *tr); /* every field defined, grids included */
    tr->scene = s;
    tr->max_depth = o->depth;
    tr->feat = rt_scene_features(s, o->spp);
    tr->cut_budget = o->trace_all ? 0 : RT_CUT_BUDGET / o->spp;
    for (unsigned i = 0; i < s->n_materials; i++) {
        const rt_material *m = &s->mat[i];
        fx_t wl = fx_sub(fx_sub(FX_ONE, m->reflect), m->transparency);
        if (wl < 0)
            wl = 0;
        for (unsigned k = 0; k < 2; k++) {
            rt_rgb base = k ? m->color2 : m->color, c = rt_rgb3(0, 0, 0);
            rt_rgb_madd(&c, rt_rgb_mul(base, s->ambient),
                        fx_mul(wl, m->ambient));
            tr->amb[i][k] = c;
            tr->lit[i][k] =
                s->n_lights ? rt_rgb_mul(base, s->light[0].color) : c;
        }
        tr->kdl[i] = fx_mul(wl, m->diffuse);
        if (RT_HAS_SPECULAR)
            tr->spec_min[i] = rt_specular_min(m);
    }
    if (RT_CUTOFF)
        rt_cutoff_bounds(tr->bound, s);
    for (unsigned li = 0; RT_HAS_QUAD && li < s->n_lights; li++) {
        const fx_vec3 lp = s->light[li].pos;
        for (unsigned i = 0; i < s->n_objects; i++) {
            const rt_object *q = &s->obj[i];
            /* A floor's own test rejects a ray off its side as soon. */
            if (q->kind != RT_QUAD ||
                (q->u.quad.flat && (q->u.quad.normal.y == FX_UONE ||
                                    q->u.quad.normal.y == -FX_UONE)))
                continue;
            /* (corner - lp).normal: negative with the light in front. */
            const int64_t num = rt_quad_side(q, lp, fx_v3_small(lp));
            const uint32_t bit = (uint32_t)1 << (i % 32);
            if (num < -RT_SIDE_MARGIN)
                tr->quad_front[li][i / 32] |= bit;
            if (num < -RT_SIDE_MARGIN || num > RT_SIDE_MARGIN)
                tr->quad_sided[li][i / 32] |= bit;
        }
    }
    rt_sealed_find(&tr->sealed, s, (tr->feat & RT_FEAT_SHADOWS) != 0);
    rt_dir_grids_prepare(&tr->grids, s);
}

void rt_work_init(rt_work *wk, rt_stats *stats)
{
    wk->stats = stats;
    wk->budget = 0;
    wk->on_hit = 0;
    wk->hit_ctx = 0;
    for (unsigned i = 0; i < RT_MAX_LIGHTS; i++)
        wk->blocker[i] = RT_NO_OBJECT;
}
