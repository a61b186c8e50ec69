/* SPDX-License-Identifier: MIT */
/*
 * rt_shade: the Whitted shading loop (docs/render-model.md), function for
 * function as port/posix/ref_render.c's shade: a hit's colour is its
 * ambient term, plus for each point light not in shadow a Lambert term
 * and a Phong highlight, plus the colours of the reflected and the
 * refracted (or totally internally reflected) ray, traced recursively.
 * Recursion is capped by RT_MAX_DEPTH at compile time and by the
 * caller's depth. Each effect is one call away, in the header named for
 * it; each RT_HAS_* condition is a compile-time constant (rt_config.h).
 */
#include "rt_bounce.h"
#include "rt_colour.h"
#include "rt_cutoff.h"
#include "rt_nearest.h"
#include "rt_shadow.h"
#include "rt_specular.h"
#include "rt_texture.h"

RT_NOINLINE static rt_rgb trace(const rt_tracer *tr, rt_work *wk,
                                const rt_ray *r, unsigned depth, fx_t w,
                                unsigned skip, unsigned from, unsigned grid);

/* What shade() knows of the surface at a hit. */
typedef struct {
    fx_vec3 p;         /* the hit point */
    fx_vec3 p_out;     /* where rays leaving on the ray's side start */
    fx_dir3 ng;        /* the geometric normal, facing the ray */
    fx_dir3 n;         /* the shading normal (ng, or bumped), facing it */
    int64_t dn;        /* d.n, exact (fx_d3_dot_raw) */
    unsigned off;      /* 2^off: the offset of p_out (rt_origin_log2) */
    unsigned tex;      /* which colour: 0 m->color, 1 m->color2 */
    unsigned skip_out; /* what a ray leaving on the ray's side skips */
    int outside;       /* the ray met the object's outside */
} surface;

/* The hit point of r at t, each product rounded once (fx_v3_madd_d):
 * from a small origin a hit below 2^30 cannot leave the range, so no
 * saturating add. */
static inline fx_vec3 hit_point(const rt_ray *r, fx_t t)
{
    if (FX_UBITS < 17)
        return fx_v3_madd_d(r->o, r->d, t);
    const unsigned u = FX_UBITS < 17 ? 17 : FX_UBITS; /* in range */
    const fx_t ox = fx_mul_rsh(t, r->d.x, u);
    const fx_t oy = fx_mul_rsh(t, r->d.y, u);
    const fx_t oz = fx_mul_rsh(t, r->d.z, u);
    if (r->small && t < ((fx_t)1 << 30))
        return fx_v3(r->o.x + ox, r->o.y + oy, r->o.z + oz);
    return fx_v3(fx_add(r->o.x, ox), fx_add(r->o.y, oy), fx_add(r->o.z, oz));
}

/* The shading normal of a bumped hit of material m on object o at p (the
 * geometric normal ng facing the ray r): rt_bump's, unless the material
 * reflects or transmits and that normal would send the mirror direction
 * of r into the surface or the transmitted one back out of it (the wrong
 * sign of its dot product with ng); then ng (docs/render-model.md). Such
 * a ray would meet its own surface again within rounding of t_min. Out
 * of line, with the bump, off the common path. */
RT_NOINLINE static fx_dir3 bumped_normal(const rt_material *m,
                                         const rt_object *o, const rt_ray *r,
                                         fx_vec3 p, fx_dir3 ng, int outside)
{
    const fx_dir3 n = rt_bump(m, o, p, ng);
    fx_dir3 t;
    if (!(m->reflect > 0 || m->transparency > 0))
        return n;
    if (fx_d3_dot_raw(rt_reflect_dir(r->d, n), ng) < 0)
        return ng;
    if (RT_HAS_REFRACTION && m->transparency > 0 &&
        rt_refract_dir(r->d, n, outside ? m->ior_inv : m->ior, &t) &&
        fx_d3_dot_raw(t, ng) > 0)
        return ng;
    return n;
}

/* The surface of the hit of r at t on object oi (o, of material m), part
 * part: the point, the normals facing the ray, the side, the texture's
 * colour and where rays leaving it start. */
static inline void find_surface(surface *sf, const rt_object *o,
                                const rt_material *m, const rt_ray *r,
                                fx_t t, unsigned oi, uint16_t part)
{
    fx_vec3 p = hit_point(r, t);
    const fx_dir3 ng_out =
        rt_normal(o, r, t, &p, part, m->reflect > 0 || m->transparency > 0);
    sf->p = p;
    const int64_t dn = fx_d3_dot_exact(r->d, ng_out);
    sf->outside = o->kind == RT_QUAD || dn <= 0;
    sf->ng = dn > 0 ? fx_d3_neg(ng_out) : ng_out;
    /* For n = ng, d.n is -|d.ng| (negating each product is exact). */
    sf->n = sf->ng;
    sf->dn = dn > 0 ? -dn : dn;
    if (RT_HAS_BUMP && m->bump != 0) {
        sf->n = bumped_normal(m, o, r, sf->p, sf->ng, sf->outside);
        sf->dn = fx_d3_dot_exact(r->d, sf->n);
    }
    /* The texture is read just inside the surface: see render-model.md. */
    sf->tex = 0;
    if (RT_HAS_TEXTURES && m->texture != RT_TEX_NONE)
        sf->tex = rt_texel(m, o, rt_v3_madd_pow2(sf->p, ng_out, RT_EPS_LOG2, 1));
    /* Made here, not on first use: nearly every hit casts a shadow or a
     * mirror ray. Most objects take RT_EPS: its shifts are constants. */
    sf->off = rt_origin_log2(o);
    sf->p_out = sf->off == RT_EPS_LOG2
                    ? rt_v3_madd_pow2(sf->p, sf->ng, RT_EPS_LOG2, 0)
                    : rt_v3_madd_pow2(sf->p, sf->ng, sf->off, 0);
    sf->skip_out = (o->convex && sf->outside) ? oi : RT_NO_OBJECT;
}

/* Adds light li's Lambert term and Phong highlight at sf (object o) to
 * *c, unless the light is behind the surface or in shadow. The light is
 * seen from p_out, where its shadow ray starts: the shadow ray then ends
 * at the light, and a surface through the light is met only there,
 * beyond t_max. */
static inline void add_light(rt_rgb *c, const rt_tracer *tr, rt_work *wk,
                             const rt_ray *r, const surface *sf,
                             const rt_object *o, unsigned li)
{
    const rt_material *m = &tr->scene->mat[o->material];
    const rt_light *l = &tr->scene->light[li];
    const fx_vec3 lv = fx_v3_sub(l->pos, sf->p_out);
    const fx_dir3 ld = fx_d3_normalize(lv);
    /* n.ld as fx_d3_dot rounds it; the highlight takes it exact. */
    const int64_t nl = fx_d3_dot_exact(sf->n, ld);
    const fx_t ndl = rt_cos_fx(nl);
    fx_t ks;
    if (ndl <= 0)
        return;
    if (RT_HAS_SHADOWS && (tr->feat & RT_FEAT_SHADOWS) &&
        rt_in_shadow(tr, wk, li, lv, ld, sf->p_out, sf->skip_out))
        return;
    const rt_rgb base = sf->tex ? m->color2 : m->color;
    /* Lambert: |kdl| <= 1 (the parser's ranges) keeps it in range. */
    rt_rgb_madd(c,
                li == 0 ? tr->lit[o->material][sf->tex]
                        : rt_rgb_mul(base, l->color),
                fx_wmul(tr->kdl[o->material], ndl));
    if (RT_HAS_SPECULAR && m->specular > 0 &&
        rt_highlight(m, nl, sf->dn, ld, r->d, tr->spec_min[o->material],
                     &ks))
        rt_rgb_madd(c, l->color, ks); /* Phong */
}

/* The colour seen along the secondary ray from o along d of weight w
 * leaving object from: trace() one level down. */
static inline rt_rgb secondary(const rt_tracer *tr, rt_work *wk, fx_vec3 o,
                               fx_dir3 d, unsigned depth, fx_t w,
                               unsigned skip, unsigned from, unsigned grid)
{
    rt_ray sr;
    rt_ray_set(&sr, o, d);
    return trace(tr, wk, &sr, depth + 1, w, skip, from, grid);
}

/* The grid of rays leaving object oi: a camera ray's reflection in a
 * plane takes the grid from the eye's mirror image (rt_dirgrid.h), other
 * rays the object's. */
static inline unsigned leaving_grid(const rt_tracer *tr, unsigned oi,
                                    const rt_ray *r, int mirror)
{
    const unsigned g =
        mirror ? rt_dir_mirror_of(&tr->grids, oi, r->o) : RT_DIR_NONE;
    if (g != RT_DIR_NONE)
        return g;
    return rt_dir_from_object(&tr->grids, oi, tr->scene->n_objects);
}

/* Colour of the hit (object oi, part, distance t) seen along r. */
static rt_rgb shade(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                    unsigned depth, fx_t w, uint16_t oi, uint16_t part, fx_t t)
{
    const rt_scene *s = tr->scene;
    const rt_object *o = &s->obj[oi];
    const rt_material *m = &s->mat[o->material];
    const fx_t kr = m->reflect, kt = m->transparency;
    surface sf;
    find_surface(&sf, o, m, r, t, oi, part);
    rt_rgb c = tr->amb[o->material][sf.tex];
    const unsigned n_lights =
        RT_HAS_MULTILIGHT ? s->n_lights : (s->n_lights ? 1u : 0u);
    /* Inside a closed object every light outside it is hidden. */
    const int dark = !sf.outside && rt_sealed_dark(&tr->sealed, oi);
    for (unsigned li = 0; !dark && li < n_lights; li++)
        add_light(&c, tr, wk, r, &sf, o, li);
    if (depth >= tr->max_depth)
        return c;

    const fx_t wr = rt_child_weight(w, kr);
    if (RT_HAS_REFLECTION && kr > 0 && rt_worth_tracing(tr, wk, wr, depth + 1)) {
        RT_COUNT(wk, reflection);
        rt_rgb_madd(&c,
                    secondary(tr, wk, sf.p_out,
                              rt_reflect_dir_dn(r->d, sf.n, sf.dn), depth,
                              wr, sf.skip_out, oi,
                              leaving_grid(tr, oi, r, 1)),
                    kr);
    }
    const fx_t wt = rt_child_weight(w, kt);
    if (RT_HAS_REFRACTION && kt > 0 && rt_worth_tracing(tr, wk, wt, depth + 1)) {
        /* n faces the ray either way, so eta flips with the side. */
        const fx_t eta = sf.outside ? m->ior_inv : m->ior;
        const unsigned grid = leaving_grid(tr, oi, r, 0);
        fx_dir3 td;
        rt_rgb tc;
        if (!rt_refract_dn(r->d, sf.n, sf.dn, eta, &td)) {
            RT_COUNT(wk, reflection); /* total internal reflection */
            tc = secondary(tr, wk, sf.p_out,
                           rt_reflect_dir_dn(r->d, sf.n, sf.dn), depth, wt,
                           sf.skip_out, oi, grid);
        } else {
            /* A convex object skips itself on the way out, and a quad
             * (both of whose sides are its outside) either way. */
            const unsigned skip_in =
                (o->convex && (!sf.outside || o->kind == RT_QUAD))
                    ? oi : RT_NO_OBJECT;
            RT_COUNT(wk, refraction);
            tc = secondary(tr, wk, rt_v3_madd_pow2(sf.p, sf.ng, sf.off, 1),
                           td, depth, wt, skip_in, oi, grid);
        }
        rt_rgb_madd(&c, tc, kt);
    }
    return c;
}

/* rt_trace, out of line: folded into shade()'s recursion it would make
 * every level's frame larger. */
RT_NOINLINE static rt_rgb trace(const rt_tracer *tr, rt_work *wk,
                                const rt_ray *r, unsigned depth, fx_t w,
                                unsigned skip, unsigned from, unsigned grid)
{
    fx_t t;
    uint16_t oi = 0;
    uint16_t part = 0;
    if (!rt_nearest(tr, wk, r, skip, from, grid, &t, &oi, &part))
        return tr->scene->background;
    if (wk->on_hit)
        wk->on_hit(wk->hit_ctx, tr->scene, oi, r, t, w);
    return shade(tr, wk, r, depth, w, oi, part, t);
}

rt_rgb rt_trace(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                unsigned depth, fx_t w, unsigned skip, unsigned from)
{
    return trace(tr, wk, r, depth, w, skip, from,
                 rt_dir_from_object(&tr->grids, from, tr->scene->n_objects));
}

rt_rgb rt_trace_camera(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                       const rt_row_spans *rs, unsigned x)
{
    fx_t t;
    uint16_t oi = 0;
    uint16_t part = 0;
    if (RT_CUTOFF)
        wk->budget = tr->cut_budget; /* a new sample */
    if (!rt_nearest_camera(tr, wk, r, rs, x, &t, &oi, &part))
        return tr->scene->background;
    return shade(tr, wk, r, 0, FX_ONE, oi, part, t);
}

int rt_probe_camera(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                    const rt_row_spans *rs, unsigned x, rt_hit *h)
{
    h->obj = RT_NO_OBJECT;
    h->part = 0;
    if (rt_nearest_camera(tr, wk, r, rs, x, &h->t, &h->obj, &h->part))
        return 1;
    h->obj = RT_NO_OBJECT;
    h->t = FX_MAX;
    return 0;
}

rt_rgb rt_shade_camera(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                       const rt_hit *h)
{
    if (RT_CUTOFF)
        wk->budget = tr->cut_budget; /* a new sample */
    if (h->obj == RT_NO_OBJECT)
        return tr->scene->background;
    if (wk->on_hit)
        wk->on_hit(wk->hit_ctx, tr->scene, h->obj, r, h->t, FX_ONE);
    return shade(tr, wk, r, 0, FX_ONE, h->obj, h->part, h->t);
}
