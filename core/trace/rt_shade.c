/* SPDX-License-Identifier: MIT */
/*
 * rt_shade: the Whitted shading loop (docs/render-model.md). A hit's
 * colour is its ambient term, plus for each point light not in shadow a
 * Lambert term and a Phong highlight, plus the colours of the reflected
 * and the refracted ray, traced recursively. Recursion is capped by
 * RT_MAX_DEPTH at compile time and by the caller's depth. Each effect is
 * one call away, in the header named for it; each RT_HAS_* condition is a
 * compile-time constant (rt_config.h).
 */
/* Products by call where the core has no 64-bit multiply: this file's
 * frame is paid once per bounce level (fx_math.h, FX_MUL64_CALL). */
#define FX_MUL64_CALL 1
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

/* d.n exact (fx_d3_dot_raw), given dnn, the same value formed once by
 * shade(). Where a product is a call (FX_SOFT_MUL64, the M0) reusing dnn
 * saves three per highlight and secondary ray; on the M3 a product is one
 * instruction, and holding dnn in the frame cost more (3.5 instructions
 * per pixel of the seed). */
static inline int64_t d_dot_n(fx_dir3 d, fx_dir3 n, int64_t dnn)
{
    return FX_SOFT_MUL64 ? dnn : fx_d3_dot_raw(d, n);
}

/* The shading normal of a bumped hit of material m on object o at p (the
 * geometric normal ng facing the ray r): rt_bump's, unless the material
 * reflects or transmits and that normal would send the mirror direction
 * of r into the surface or the transmitted one back out of it (the wrong
 * sign of its dot product with ng); then ng (docs/render-model.md). Such
 * a ray would meet its own surface again within rounding of t_min. Out
 * of line: inline, the test cost the shading loop's registers (33
 * instructions per pixel of the seed, which has no bumped mirror). */
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

/* The hit point of r at t, as shade() forms it (fx_v3_madd_d_near from a
 * small origin below 2^30, else fx_v3_madd_d), for the M0: products by
 * fx_mulsh, not three calls (FX_MUL64_CALL), out of line so that
 * they stay out of shade()'s frame. */
RT_NOINLINE static fx_vec3 hit_point_soft(const rt_ray *r, fx_t t)
{
    const fx_t ox = fx_mulsh(t, r->d.x, FX_UBITS);
    const fx_t oy = fx_mulsh(t, r->d.y, FX_UBITS);
    const fx_t oz = fx_mulsh(t, r->d.z, FX_UBITS);
    if (r->small && t < ((fx_t)1 << 30))
        return fx_v3(r->o.x + ox, r->o.y + oy, r->o.z + oz);
    return fx_v3(fx_add(r->o.x, ox), fx_add(r->o.y, oy), fx_add(r->o.z, oz));
}

/* Colour of the hit (object oi, part, distance t) seen along r. */
static rt_rgb shade(const rt_tracer *tr, rt_work *wk, const rt_ray *r,
                    unsigned depth, fx_t w, uint16_t oi, uint16_t part, fx_t t)
{
    const rt_scene *s = tr->scene;
    const rt_object *o = &s->obj[oi];
    const rt_material *m = &s->mat[o->material];
    /* Read once: the frame keeps them, where m itself was rebuilt from
     * the object's material index at every use. */
    const fx_t kr = m->reflect, kt = m->transparency;
    /* From a small origin a hit below 2^30 cannot leave the range. */
    fx_vec3 p = FX_SOFT_MUL64 && FX_UBITS > 16 ? hit_point_soft(r, t)
                : r->small && t < ((fx_t)1 << 30)
                    ? fx_v3_madd_d_near(r->o, r->d, t)
                    : fx_v3_madd_d(r->o, r->d, t);
    const fx_dir3 ng_out =
        rt_normal(o, r, t, &p, part, kr > 0 || kt > 0);
    fx_dir3 ng = ng_out;
    const int64_t dn = fx_d3_dot_exact(r->d, ng);
    int outside = o->kind == RT_QUAD || dn <= 0;
    if (dn > 0)
        ng = fx_d3_neg(ng); /* face the ray */
    /* The shading normal *np: on the M0 ng itself unless bumped, not a
     * copy of it (#17: seed 7,391 -> 7,375 instructions a pixel, 40
     * bytes less stack); on the M3 the copy cost less. */
    fx_dir3 nb;
    const fx_dir3 *np = &nb;
    if (FX_SOFT_MUL64)
        np = &ng;
    else
        nb = ng;
    /* d.n exact, formed once for the highlights and the secondary rays:
     * for n = ng it is -|d.ng| (negating each product is exact). */
    int64_t dnn = dn > 0 ? -dn : dn;
    if (RT_HAS_BUMP && m->bump != 0) {
        nb = bumped_normal(m, o, r, p, ng, outside);
        np = &nb;
        dnn = fx_d3_dot_exact(r->d, nb);
    }
    unsigned tex = 0; /* which colour: m->color, or color2 */
    /* The texture is read just inside the surface: see render-model.md. */
    if (RT_HAS_TEXTURES && m->texture != RT_TEX_NONE)
        tex = rt_texel(m, o, rt_v3_madd_pow2(p, ng_out, RT_EPS_LOG2, 1));
    const rt_rgb base = tex ? m->color2 : m->color;
    /* Where rays leaving on the ray's side start. Made here, not on
     * first use: nearly every hit casts a shadow or a mirror ray, and the
     * flag of a lazy one cost more than the few it saved. */
    const unsigned off = rt_origin_log2(o); /* 2^off: the offset */
    /* Most objects take RT_EPS: its shifts are then constants. */
    const fx_vec3 p_out = off == RT_EPS_LOG2
                              ? rt_v3_madd_pow2(p, ng, RT_EPS_LOG2, 0)
                              : rt_v3_madd_pow2(p, ng, off, 0);
    unsigned skip_out = (o->convex && outside) ? oi : RT_NO_OBJECT;

    rt_rgb c = tr->amb[o->material][tex];
    const fx_t kdl = tr->kdl[o->material];
    const unsigned n_lights =
        RT_HAS_MULTILIGHT ? s->n_lights : (s->n_lights ? 1u : 0u);
    /* Inside a closed object every light outside it is hidden. */
    const int dark = !outside && rt_sealed_dark(&tr->sealed, oi);
    /* Lights are seen from P_out, where their shadow rays start: a shadow
     * ray then ends at its light, and a surface through the light (a
     * light on a surface) is met only there, beyond t_max. */
    for (unsigned li = 0; !dark && li < n_lights; li++) {
        const rt_light *l = &s->light[li];
        fx_vec3 lv = fx_v3_sub(l->pos, p_out);
        /* The unit vector to the light: on the M3 an array element,
         * which the compiler keeps in the frame where the call writes it
         * and reads at each use, not split into registers that spilled
         * (#17: seed 2,591.8 -> 2,588.0 instructions a pixel, glass
         * 4,768.8 -> 4,738.6, 144 bytes less stack); on the M0 the value
         * (the array cost the mirrors 0.4 %). */
        fx_dir3 ldv, ldm[1];
        if (FX_SOFT_MUL64) {
            ldv = fx_d3_normalize(lv);
        } else {
            ldm[0] = fx_d3_normalize(lv);
            ldv = ldm[0]; /* set for the analysers; not read */
            (void)ldv;
        }
        /* n.ld as fx_d3_dot rounds it; the highlight takes it exact. */
        const int64_t nl = fx_d3_dot_exact(*np, FX_SOFT_MUL64 ? ldv : ldm[0]);
        fx_t ndl = rt_cos_fx(nl);
        if (ndl <= 0)
            continue;
        if (RT_HAS_SHADOWS && (tr->feat & RT_FEAT_SHADOWS) &&
            rt_in_shadow(tr, wk, li, lv, FX_SOFT_MUL64 ? ldv : ldm[0], p_out,
                         skip_out))
            continue;
        rt_rgb lc =
            li == 0 ? tr->lit[o->material][tex] : rt_rgb_mul(base, l->color);
        /* Lambert: fx_mul's value, which |kdl| <= 1 (the parser's ranges)
         * keeps from saturating at any ndl (rt_wmul: no test). */
        rt_rgb_madd(&c, lc, rt_wmul(kdl, ndl));
        fx_t ks;
        if (RT_HAS_SPECULAR && m->specular > 0 &&
            rt_highlight(m, nl, d_dot_n(r->d, *np, dnn),
                         FX_SOFT_MUL64 ? ldv : ldm[0], r->d,
                         tr->spec_min[o->material], &ks))
            rt_rgb_madd(&c, l->color, ks); /* Phong */
    }
    if (depth >= tr->max_depth)
        return c;

    if (RT_HAS_REFLECTION) {
        fx_t wr = rt_child_weight(w, kr);
        if (kr > 0 && rt_worth_tracing(tr, wk, wr, depth + 1)) {
            rt_ray rr;
            /* A camera ray's reflection in a plane: the grid from the
             * eye's mirror image (rt_dirgrid.h), else the object's. */
            unsigned g = rt_dir_mirror_of(&tr->grids, oi, r->o);
            if (g == RT_DIR_NONE)
                g = rt_dir_from_object(&tr->grids, oi, s->n_objects);
            rt_ray_set(&rr, p_out,
                       rt_reflect_dir_dn(r->d, *np, d_dot_n(r->d, *np, dnn)));
            RT_COUNT(wk, reflection);
            rt_rgb_madd(&c,
                        trace(tr, wk, &rr, depth + 1, wr, skip_out, oi, g),
                        kr);
        }
    }
    if (RT_HAS_REFRACTION) {
        fx_t wt = rt_child_weight(w, kt);
        if (kt > 0 && rt_worth_tracing(tr, wk, wt, depth + 1)) {
            fx_t eta = outside ? m->ior_inv : m->ior;
            fx_dir3 td;
            rt_ray tr2;
            if (!rt_refract_dn(r->d, *np, d_dot_n(r->d, *np, dnn), eta, &td)) {
                /* total internal reflection */
                rt_ray_set(&tr2, p_out,
                           rt_reflect_dir_dn(r->d, *np,
                                             d_dot_n(r->d, *np, dnn)));
                RT_COUNT(wk, reflection);
                rt_rgb_madd(&c,
                            trace(tr, wk, &tr2, depth + 1, wt, skip_out, oi,
                                  rt_dir_from_object(&tr->grids, oi,
                                                     s->n_objects)),
                            kt);
            } else {
                unsigned skip_in =
                    (o->convex && (!outside || o->kind == RT_QUAD))
                        ? oi
                        : RT_NO_OBJECT;
                rt_ray_set(&tr2, rt_v3_madd_pow2(p, ng, off, 1), td);
                RT_COUNT(wk, refraction);
                rt_rgb_madd(&c,
                            trace(tr, wk, &tr2, depth + 1, wt, skip_in, oi,
                                  rt_dir_from_object(&tr->grids, oi,
                                                     s->n_objects)),
                            kt);
            }
        }
    }
    return c;
}

/* rt_trace, out of line: folded into shade()'s recursion it made every
 * level's frame larger (and the seed 0.7 % dearer on the Cortex-M3). */
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
