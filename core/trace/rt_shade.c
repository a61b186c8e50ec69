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

static rt_rgb trace(const rt_tracer *tr, rt_work *wk,
                                const rt_ray *r, unsigned depth, fx_t w,
                                unsigned skip, unsigned from, unsigned grid);

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

/* Where rays leaving p on the side of unit normal ng start: 2^off
 * along it. Most objects take RT_EPS, whose shifts are then constants. */
static inline fx_vec3 offset_point(fx_vec3 p, fx_dir3 ng, unsigned off)
{
    return off == RT_EPS_LOG2 ? rt_v3_madd_pow2(p, ng, RT_EPS_LOG2, 0)
                              : rt_v3_madd_pow2(p, ng, off, 0);
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

/* Which colour of material m the texture gives object o at p, the hit
 * of r at t (the outward normal ng_out): 0 m->color, 1 m->color2. The
 * texture is read just inside the surface: see render-model.md. */
static inline unsigned texture(const rt_material *m, const rt_object *o,
                               const rt_ray *r, fx_t t, fx_vec3 p,
                               fx_dir3 ng_out)
{
    if (!RT_HAS_TEXTURES || m->texture == RT_TEX_NONE)
        return 0;
    return rt_texel(m, o, r, t, ng_out,
                    rt_v3_madd_pow2(p, ng_out, RT_EPS_LOG2, 1));
}

/* Adds light li's Lambert term and Phong highlight at the hit of r on
 * object o of material m (colour tex, unit normal n facing the ray, d.n
 * rounded to FX_UBITS fraction bits in dn) to *c, unless the light is
 * behind the surface or in shadow. The light is seen from p_out, where
 * its shadow ray starts (skipping skip): the shadow ray then ends at the
 * light, and a surface through the light is met only there, beyond
 * t_max. */
static inline void add_light(rt_rgb *c, const rt_tracer *tr, rt_work *wk,
                             const rt_ray *r, const rt_object *o,
                             const rt_material *m, unsigned tex, fx_dir3 n,
                             int32_t dn, fx_vec3 p_out, unsigned skip,
                             unsigned li)
{
    const rt_light *l = &tr->scene->light[li];
    const fx_vec3 lv = fx_v3_sub(l->pos, p_out);
    /* ld an array element, which the compiler keeps in the frame where
     * the call writes it, not in registers that would spill: a smaller
     * frame at every bounce level. */
    fx_dir3 ld[1];
    ld[0] = fx_d3_normalize(lv);
    /* n.ld as fx_d3_dot rounds it; the highlight takes it exact. */
    const int64_t nl = fx_d3_dot_exact(n, ld[0]);
    const fx_t ndl = rt_cos_fx(nl);
    fx_t ks;
    if (ndl <= 0)
        return;
    if (RT_HAS_SHADOWS && (tr->feat & RT_FEAT_SHADOWS) &&
        rt_in_shadow(tr, wk, li, lv, ld[0], p_out, skip))
        return;
    const rt_rgb base = tex ? m->color2 : m->color;
    /* Lambert: |kdl| <= 1 (the parser's ranges) keeps it in range. */
    rt_rgb_madd(c,
                li == 0 ? tr->lit[o->material][tex]
                        : rt_rgb_mul(base, l->color),
                fx_wmul(tr->kdl[o->material], ndl));
    if (RT_HAS_SPECULAR && m->specular > 0 &&
        rt_highlight(m, nl, dn, ld[0], r->d, tr->spec_min[o->material], &ks))
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
    fx_vec3 p = hit_point(r, t);
    const fx_dir3 ng_out = rt_normal(o, r, t, &p, part, kr > 0 || kt > 0);
    const int64_t dn_out = fx_d3_dot_exact(r->d, ng_out);
    const int outside = o->kind == RT_QUAD || dn_out <= 0;
    const fx_dir3 ng = dn_out > 0 ? fx_d3_neg(ng_out) : ng_out; /* facing */
    fx_dir3 nb; /* a bumped normal */
    const fx_dir3 *np = &ng; /* the shading normal */
    /* d.n rounded, as the highlights and the secondary rays take it: for
     * n = ng from -|d.ng| (negating each product is exact). */
    int32_t dn = rt_dotu_of(dn_out > 0 ? -dn_out : dn_out);
    if (RT_HAS_BUMP && m->bump != 0) {
        nb = bumped_normal(m, o, r, p, ng, outside);
        np = &nb;
        dn = rt_dotu_of(fx_d3_dot_exact(r->d, nb));
    }
    const unsigned tex = texture(m, o, r, t, p, ng_out);
    const unsigned off = rt_origin_log2(o); /* rays leave 2^off off */
    const fx_vec3 p_out = offset_point(p, ng, off);
    const unsigned skip_out = (o->convex && outside) ? oi : RT_NO_OBJECT;
    rt_rgb c = tr->amb[o->material][tex];
    const unsigned n_lights =
        RT_HAS_MULTILIGHT ? s->n_lights : (s->n_lights ? 1u : 0u);
    /* Inside a closed object every light outside it is hidden. */
    const int dark = !outside && rt_sealed_dark(&tr->sealed, oi);
    for (unsigned li = 0; !dark && li < n_lights; li++)
        add_light(&c, tr, wk, r, o, m, tex, *np, dn, p_out, skip_out, li);
    if (depth >= tr->max_depth)
        return c;
    fx_t wr, wt;
    if (RT_HAS_REFLECTION && kr > 0 &&
        rt_worth_tracing(tr, wk, wr = rt_child_weight(w, kr), depth + 1)) {
        RT_COUNT(wk, reflection);
        rt_rgb_madd(&c,
                    secondary(tr, wk, p_out, rt_reflect_dir_dn(r->d, *np, dn),
                              depth, wr, skip_out, oi,
                              leaving_grid(tr, oi, r, 1)),
                    kr);
    }
    if (RT_HAS_REFRACTION && kt > 0 &&
        rt_worth_tracing(tr, wk, wt = rt_child_weight(w, kt), depth + 1)) {
        /* n faces the ray either way, so eta flips with the side. */
        const fx_t eta = outside ? m->ior_inv : m->ior;
        fx_vec3 from = p_out;
        fx_dir3 d;
        unsigned skip = skip_out;
        if (!rt_refract_dn(r->d, *np, dn, eta, &d)) {
            RT_COUNT(wk, reflection); /* total internal reflection */
            d = rt_reflect_dir_dn(r->d, *np, dn);
        } else {
            RT_COUNT(wk, refraction);
            from = rt_v3_madd_pow2(p, ng, off, 1);
            /* A convex object skips itself on the way out, and a quad
             * (both of whose sides are its outside) either way. */
            skip = (o->convex && (!outside || o->kind == RT_QUAD))
                       ? oi : RT_NO_OBJECT;
        }
        rt_rgb_madd(&c,
                    secondary(tr, wk, from, d, depth, wt, skip, oi,
                              leaving_grid(tr, oi, r, 0)),
                    kt);
    }
    return c;
}

/* rt_trace with the direction grid of the ray already chosen: the nearest
 * hit, the hook, then shade(). */
static rt_rgb trace(const rt_tracer *tr, rt_work *wk,
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
