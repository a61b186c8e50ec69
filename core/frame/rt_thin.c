/* SPDX-License-Identifier: MIT */
/*
 * rt_thin: objects that may hide between a draft render's lattice pixels
 * (rt_thin.h).
 */
#include "rt_thin.h"
#include "rt_shape.h"

void rt_thin_init(rt_thin *t, const rt_scene *s)
{
    t->n_quads = 0;
    for (unsigned i = 0; i < s->n_objects; i++) {
        const rt_object *ob = &s->obj[i];
        const int64_t lim = FX_INT(16384);
        int64_t px = (int64_t)ob->bc.x - s->cam.eye.x;
        int64_t py = (int64_t)ob->bc.y - s->cam.eye.y;
        int64_t pz = (int64_t)ob->bc.z - s->cam.eye.z;
        /* Inflated as rt_cull inflates it, and 1/16 unit more. */
        int64_t r = (int64_t)ob->br + ob->br / 64 + 1024 + 4096, n = 0;
        if (px > -lim && px < lim && py > -lim && py < lim && pz > -lim &&
            pz < lim)
            n = (int64_t)fx_sqrt_q32(fx_v3_len2_q32(
                    fx_v3((fx_t)px, (fx_t)py, (fx_t)pz))) - r;
        t->near[i] = n > 0 ? (fx_t)n : 0;
        t->quad_bit[i] = RT_THIN_QUADS;
        if (ob->kind == RT_QUAD && t->n_quads < RT_THIN_QUADS) {
            t->quad_bit[i] = (uint8_t)t->n_quads;
            t->quad_obj[t->n_quads] = (uint16_t)i;
            t->quad_d0[t->n_quads] =
                fx_pd_dot(fx_v3_sub(s->cam.eye, ob->u.quad.corner),
                          ob->u.quad.normal);
            t->n_quads++;
        }
    }
}

/* 1 if no ray of sample row k can hit quad o: its four corners lie on
 * one side of the plane through the eye that holds those rays (with 1/16
 * unit to spare, far above their rounding). */
static int quad_off_row(const rt_object *o, const rt_scene *s,
                        const rt_cam_frame *cf, int32_t k)
{
    const rt_cam_ray b = rt_cam_row_base(cf, rt_cam_soff(cf, k));
    const fx_dir3 f = fx_d3_normalize64(b.x, b.y, b.z);
    const fx_dir3 nr = fx_d3_cross_unit(fx_d3_raw(f), fx_d3_raw(cf->right));
    const rt_quad *q = &o->u.quad;
    const fx_t s0 = fx_pd_dot(fx_v3_sub(q->corner, s->cam.eye), nr);
    const fx_t s1 = fx_pd_dot(q->edge1, nr), s2 = fx_pd_dot(q->edge2, nr);
    const int64_t c[4] = { s0, (int64_t)s0 + s1, (int64_t)s0 + s2,
                           (int64_t)s0 + s1 + s2 };
    int above = 1, below = 1;
    for (unsigned i = 0; i < 4; i++) {
        above &= c[i] > 4096;
        below &= c[i] < -4096;
    }
    return above || below;
}

void rt_thin_row(rt_aa_spans *rs, const rt_scene *s, const rt_cam_frame *cf,
                 unsigned height, unsigned y)
{
    unsigned kept = 0;
    rs->lo = INT32_MAX;
    rs->hi = -1;
    for (unsigned i = 0; i < rs->hit.count; i++) {
        const rt_span sp = rs->hit.span[i];
        const rt_object *o = &s->obj[sp.obj];
        int off = o->kind == RT_QUAD;
        for (unsigned j = 0; off && j < cf->n; j++)
            off = quad_off_row(o, s, cf, rt_cam_row_k(height, cf->n, y, j));
        if (off)
            continue;
        rs->hit.span[kept++] = sp;
        rs->lo = sp.x0 < rs->lo ? sp.x0 : rs->lo;
        rs->hi = sp.x1 > rs->hi ? sp.x1 : rs->hi;
    }
    rs->hit.count = kept;
}

uint16_t rt_thin_front(const rt_thin *t, const rt_scene *s, const rt_ray *r,
                       fx_t tmax)
{
    uint16_t bits = 0;
    for (unsigned q = 0; q < t->n_quads; q++) {
        const fx_t d0 = t->quad_d0[q];
        const fx_t nd =
            fx_d3_dot(s->obj[t->quad_obj[q]].u.quad.normal, r->d);
        /* Along the ray n . (p - a) goes from d0 at the eye to
         * d0 + t nd: the ray stays on the eye's side while they agree. */
        const int64_t end = (int64_t)d0 + (((int64_t)tmax * nd) >> 16);
        const int away = d0 > 0 ? nd >= 0 : nd <= 0;
        const int stays = d0 > 0 ? end > 256 : end < -256;
        if ((d0 > 256 || d0 < -256) && (away || (tmax != FX_MAX && stays)))
            bits |= (uint16_t)(1u << q);
    }
    return bits;
}

int rt_thin_hit(const rt_thin *t, const rt_tracer *tr, rt_work *wk,
                const rt_cam_frame *cf, const rt_aa_spans *rs, unsigned width,
                unsigned x, unsigned i, fx_t tmax, rt_ray *r, int *have_ray)
{
    fx_t ti;
    uint16_t pi;
    (void)t;
    if (cf->n != 1)
        return 1;
    if (!*have_ray) {
        rt_thin_ray(tr->scene, cf, &rs->base[0], rt_cam_col_k(width, 1, x, 0),
                    r);
        *have_ray = 1;
    }
    RT_COUNT(wk, tests);
    return rt_intersect(&tr->scene->obj[i], r, RT_EPS,
                        tmax > FX_MAX - 4096 ? FX_MAX : tmax + 4096, &ti, &pi);
}
