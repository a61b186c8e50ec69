/* SPDX-License-Identifier: MIT */
/*
 * Shadow rays skip the quads they cannot cross (rt_shadow.h's
 * rt_uncrossed): a quad whose plane has the ray's origin on the light's
 * side, or on it. That must be exact: every quad dropped is one the
 * quad's own test misses. Random quads (floors, walls, tilted ones, tiny
 * to huge), lights just past the margin or far off their planes, and
 * origins on the light's side, on the plane itself and a few ulps off
 * it, the shadow ray built as rt_in_shadow builds it.
 */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "rt_render.h"
#include "rt_shadow.h"

#define D2F(x) ((fx_t)lround((x) * 65536.0))

static uint64_t rng = 0x51de5ULL;

static double uni(double lo, double hi)
{
    return lo + (hi - lo) * (double)(th_rnd64(&rng) >> 11) * 0x1p-53;
}

static fx_vec3 v3(double x, double y, double z)
{
    return fx_v3(D2F(x), D2F(y), D2F(z));
}

/* A quad: a floor, an upright wall along x or z, or any tilt. */
static void random_quad(rt_object *o)
{
    memset(o, 0, sizeof *o);
    o->kind = RT_QUAD;
    const double s = exp(uni(log(0.01), log(200)));
    o->u.quad.corner = v3(uni(-50, 50), uni(-50, 50), uni(-50, 50));
    switch (th_rnd64(&rng) % 4) {
    case 0:
        o->u.quad.edge1 = v3(0, 0, s);
        o->u.quad.edge2 = v3(s * uni(0.2, 2), 0, 0);
        break;
    case 1:
        o->u.quad.edge1 = v3(s, 0, 0);
        o->u.quad.edge2 = v3(0, s * uni(0.2, 2), 0);
        break;
    case 2:
        o->u.quad.edge1 = v3(0, s, 0);
        o->u.quad.edge2 = v3(0, 0, s * uni(0.2, 2));
        break;
    default:
        o->u.quad.edge1 = v3(uni(-s, s), uni(-s, s), uni(-s, s));
        o->u.quad.edge2 = v3(uni(-s, s), uni(-s, s), uni(-s, s));
        break;
    }
    if (rt_object_prepare(o) != RT_OK)
        random_quad(o);
}

/* p moved by k ulps along each axis, k in [-3, 3]. */
static fx_vec3 jitter(fx_vec3 p)
{
    return fx_v3(p.x + (fx_t)(th_rnd64(&rng) % 7) - 3,
                 p.y + (fx_t)(th_rnd64(&rng) % 7) - 3,
                 p.z + (fx_t)(th_rnd64(&rng) % 7) - 3);
}

/* A point of quad o's plane (inside the quad or beyond its edges). */
static fx_vec3 plane_point(const rt_object *o)
{
    const rt_quad *q = &o->u.quad;
    return fx_v3_add(q->corner,
                     fx_v3_add(fx_v3_scale(q->edge1, D2F(uni(-1, 2))),
                               fx_v3_scale(q->edge2, D2F(uni(-1, 2)))));
}

int main(void)
{
    static rt_scene s;
    static rt_tracer tr;
    rt_options opt;
    long dropped = 0, kept = 0, crossed = 0, wrong = 0;
    for (int trial = 0; trial < 4000; trial++) {
        rt_scene_init(&s);
        s.n_materials = 1;
        /* Quads in pairs: one the light sits in front of, one behind. */
        s.n_objects = (uint16_t)(1 + th_rnd64(&rng) % 4);
        for (unsigned i = 0; i < s.n_objects; i++)
            random_quad(&s.obj[i]);
        const unsigned qi = (unsigned)(th_rnd64(&rng) % s.n_objects);
        const rt_object *q = &s.obj[qi];
        /* The light: within ulps of the plane, just past the margin,
         * or anywhere. */
        fx_vec3 lp = plane_point(q);
        const unsigned where = (unsigned)(th_rnd64(&rng) % 3);
        const double off = where == 0   ? uni(-3e-4, 3e-4)
                           : where == 1 ? uni(0.004, 0.02)
                                        : uni(-100, 100);
        lp = fx_v3_madd_d(lp, q->u.quad.normal, D2F(off));
        s.n_lights = 1;
        s.light[0].pos = lp;
        rt_options_from_scene(&opt, &s);
        rt_tracer_init(&tr, &s, &opt);
        for (int k = 0; k < 100; k++) {
            /* On the plane, within ulps of it, or anywhere near. */
            fx_vec3 p = plane_point(q);
            if (k % 3 == 1)
                p = jitter(p);
            else if (k % 3 == 2)
                p = fx_v3_add(p, v3(uni(-20, 20), uni(-20, 20),
                                    uni(-20, 20)));
            const fx_vec3 lv = fx_v3_sub(lp, p);
            if (lv.x == 0 && lv.y == 0 && lv.z == 0)
                continue;
            const fx_dir3 ld = fx_d3_normalize(lv);
            rt_ray r;
            rt_ray_set(&r, p, ld);
            const fx_t len = fx_sat64((rt_lv_dot(lv, ld) +
                                       ((int64_t)1 << (FX_UBITS - 1))) >>
                                      FX_UBITS);
            const uint32_t all = (1u << s.n_objects) - 1u;
            const uint32_t left = rt_uncrossed(&tr, 0, 0, all, &r);
            for (unsigned i = 0; i < s.n_objects; i++) {
                fx_t t;
                uint16_t part;
                const int hit = rt_intersect(&s.obj[i], &r, RT_EPS,
                                             fx_sub(len, RT_EPS), &t, &part);
                crossed += hit;
                if ((left >> i) & 1u) {
                    kept++;
                } else {
                    dropped++;
                    if (hit && ++wrong <= 5)
                        printf("trial %d: dropped quad %u is hit at %d\n",
                               trial, i, t);
                }
            }
        }
    }
    printf("%ld shadow rays: %ld quads dropped, %ld kept, %ld hits\n",
           dropped + kept, dropped, kept, crossed);
    CHECK_EQ(wrong, 0);
    CHECK(dropped > 100000);
    CHECK(kept > 50000);
    CHECK(crossed > 5000);
    return th_summary();
}
