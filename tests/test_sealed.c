/* SPDX-License-Identifier: MIT */
/*
 * Sealed glass (core/accel/rt_sealed.c) must be exact: a ray inside
 * closed glass i that hits i never hits, up to i's hit, an object other
 * than rt_sealed_with's. Random glass shapes resting on a floor or just
 * above it, with random shapes touching them or a little way off (gaps
 * from 0 to a few times the margin), and rays inside them that start as
 * the shading loop starts them (off an entry hit, towards the inside)
 * and go every way, or aim at the objects left out.
 */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "rt_shape.h"
#include "rt_trace.h"

#define D2F(x) ((fx_t)lround((x) * 65536.0))

static uint64_t rng = 0x5ea1edULL;

static double uni(double lo, double hi)
{
    return lo + (hi - lo) * (double)(th_rnd64(&rng) >> 11) * 0x1p-53;
}

static fx_vec3 v3(double x, double y, double z)
{
    return fx_v3(D2F(x), D2F(y), D2F(z));
}

static double gap(void)
{
    static const double g[] = { 0, 1e-4, 0.005, 0.012, 0.02, 0.05, 0.3 };
    return g[th_rnd64(&rng) % (sizeof g / sizeof g[0])];
}

/* A shape of kind k (the analytic ones) of size s whose lowest point is
 * at c.y, centred on c.x and c.z. */
static void shape(rt_object *o, unsigned k, double s, double x, double y,
                  double z, unsigned material)
{
    memset(o, 0, sizeof *o);
    o->kind = (uint8_t)k;
    o->material = (uint8_t)material;
    o->caps = RT_CAP_BOTTOM | RT_CAP_TOP;
    if (k == RT_SPHERE) {
        o->u.sphere.center = v3(x, y + s, z);
        o->u.sphere.radius = D2F(s);
    } else if (k == RT_BOX) {
        o->u.box.min = v3(x - s, y, z - s * uni(0.3, 1));
        o->u.box.max = v3(x + s * uni(0.3, 1), y + s * uni(0.5, 2), z + s);
    } else if (k == RT_QUAD) { /* a wall piece, upright or tilted */
        o->u.quad.corner = v3(x - s, y, z);
        o->u.quad.edge1 = v3(2 * s, 0, uni(-s, s));
        o->u.quad.edge2 = v3(uni(-s, s), 2 * s, uni(-s, s));
    } else {
        o->u.upright.base = v3(x, y, z);
        o->u.upright.radius = D2F(s);
        o->u.upright.height = D2F(s * uni(0.5, 2));
    }
}

/* The glass object 1 on the floor 0, and up to five shapes around it,
 * each off one side of it by a random gap. */
static void random_scene(rt_scene *s)
{
    memset(s, 0, sizeof *s);
    s->n_materials = 2;
    s->mat[1].transparency = FX_ONE / 2;
    rt_object *o = s->obj;
    memset(o, 0, sizeof *o);
    o->kind = RT_QUAD; /* the floor, 40 x 40 at y = 0 */
    o->u.quad.corner = v3(-20, 0, -20);
    o->u.quad.edge1 = v3(0, 0, 40);
    o->u.quad.edge2 = v3(40, 0, 0);
    const double size = exp(uni(log(0.05), log(4)));
    const unsigned kinds[] = { RT_SPHERE, RT_BOX, RT_CYLINDER, RT_CONE };
    shape(&s->obj[1], kinds[th_rnd64(&rng) % 4], size, uni(-3, 3), gap(),
          uni(-3, 3), 1);
    s->n_objects = (uint16_t)(2 + th_rnd64(&rng) % 6);
    for (unsigned j = 2; j < s->n_objects; j++) {
        const rt_object *g = &s->obj[1];
        const double reach = size * 2.2 + gap(); /* past g's box */
        const double sj = exp(uni(log(0.05), log(4)));
        double x = g->bc.x / 65536.0, z = g->bc.z / 65536.0;
        switch (th_rnd64(&rng) % 4) {
        case 0: x += reach + sj; break;
        case 1: x -= reach + sj; break;
        case 2: z += reach + sj; break;
        default: z -= reach + sj; break;
        }
        shape(&s->obj[j], (unsigned)(th_rnd64(&rng) % RT_MESH), sj, x,
              uni(0, 0.1), z, (unsigned)(th_rnd64(&rng) % 2));
    }
    for (unsigned j = 0; j < s->n_objects; j++)
        if (rt_object_prepare(&s->obj[j]) != RT_OK)
            s->obj[j].kind = RT_SPHERE, s->obj[j].u.sphere.radius = FX_ONE,
            s->obj[j].u.sphere.center = v3(30, 30, 30),
            rt_object_prepare(&s->obj[j]);
}

/* A point of object o's bounding box, for aiming. */
static fx_vec3 some_point(const rt_object *o)
{
    return fx_v3_add(o->bc, v3(uni(-1, 1) * o->br / 65536.0,
                               uni(-1, 1) * o->br / 65536.0,
                               uni(-1, 1) * o->br / 65536.0));
}

/* An inside ray of glass object i as shading starts it: a ray from
 * outside hits i at p; the inside ray leaves p - 2^off n (n the outward
 * normal). 0 if the outside ray missed. */
static int inside_ray(const rt_scene *s, unsigned i, rt_ray *in)
{
    const rt_object *o = &s->obj[i];
    fx_vec3 from = fx_v3_add(o->bc, v3(uni(-3, 3), uni(0.2, 3),
                                       uni(-3, 3)));
    from = fx_v3_add(from, fx_v3_scale(v3(uni(-1, 1), uni(0, 1),
                                          uni(-1, 1)), o->br * 2));
    rt_ray r;
    rt_ray_set(&r, from, fx_d3_normalize(fx_v3_sub(some_point(o), from)));
    fx_t t;
    uint16_t part;
    if (!rt_intersect(o, &r, RT_EPS, FX_MAX, &t, &part))
        return 0;
    fx_vec3 p = fx_v3_madd_d(r.o, r.d, t);
    const fx_dir3 n = rt_normal(o, &r, t, &p, part, 1);
    const fx_vec3 org = rt_v3_madd_pow2(p, n, rt_origin_log2(o), 1);
    /* Every way, or at one of the other objects. */
    const rt_object *aim = &s->obj[th_rnd64(&rng) % s->n_objects];
    const fx_vec3 d = th_rnd64(&rng) % 2
                          ? v3(uni(-1, 1), uni(-1, 1), uni(-1, 1))
                          : fx_v3_sub(some_point(aim), org);
    if (d.x == 0 && d.y == 0 && d.z == 0)
        return 0;
    rt_ray_set(in, org, fx_d3_normalize(d));
    return 1;
}

int main(void)
{
    static rt_scene s;
    long sealed = 0, dropped = 0, rays = 0, beyond = 0, wrong = 0;
    for (int trial = 0; trial < 3000; trial++) {
        random_scene(&s);
        static rt_sealed sl;
        rt_sealed_find(&sl, &s, 1);
        const unsigned with = rt_sealed_with(&sl, 1);
        if (with == RT_SEALED_NONE)
            continue;
        sealed++;
        dropped += s.n_objects - 1 - (with != 1);
        for (int k = 0; k < 200; k++) {
            rt_ray r;
            fx_t ti, tj;
            uint16_t part;
            if (!inside_ray(&s, 1, &r) ||
                !rt_intersect(&s.obj[1], &r, RT_EPS, FX_MAX, &ti, &part))
                continue;
            rays++;
            for (unsigned j = 0; j < s.n_objects; j++) {
                if (j == 1 || j == with ||
                    !rt_intersect(&s.obj[j], &r, RT_EPS, FX_MAX, &tj,
                                  &part))
                    continue;
                if (tj > ti) {
                    beyond++; /* a left-out object, met past i */
                } else if (++wrong <= 5) {
                    printf("trial %d: object %u (kind %d) hit at %d, "
                           "before glass (kind %d) at %d\n",
                           trial, j, s.obj[j].kind, tj, s.obj[1].kind, ti);
                }
            }
        }
    }
    printf("sealed %ld of 3000, %ld objects left out, %ld rays, %ld hits "
           "on them past the glass\n", sealed, dropped, rays, beyond);
    CHECK_EQ(wrong, 0);
    CHECK(sealed > 1000);
    CHECK(dropped > 2000);
    CHECK(rays > 100000);
    CHECK(beyond > 10000);
    return th_summary();
}
