/* SPDX-License-Identifier: MIT */
/*
 * Tests of the host reference tools: the double renderer's intersections
 * (hand-computed hits, misses, hits from inside, tangents and hits behind
 * the origin for every shape), its noise, and its pixels and counters on
 * tiny scenes. The PPM reader and writer are tested in test_ppm.c, the
 * image comparison in test_compare.c.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "ref_render.h"

/* |a - b| <= tol for doubles; prints both on failure. */
#define CHECK_DBL(a, b, tol)                                                  \
    do {                                                                      \
        double td_a_ = (a), td_b_ = (b);                                      \
        if (!th_check(fabs(td_a_ - td_b_) <= (tol), __FILE__, __LINE__,       \
                      #a " ~ " #b))                                           \
            printf("    got %.17g, want %.17g\n", td_a_, td_b_);             \
    } while (0)

#define CHECK_VEC(v, X, Y, Z)                                                 \
    do {                                                                      \
        CHECK_DBL((v).x, (X), 1e-12);                                         \
        CHECK_DBL((v).y, (Y), 1e-12);                                         \
        CHECK_DBL((v).z, (Z), 1e-12);                                         \
    } while (0)

static ref_vec3 V(double x, double y, double z)
{
    ref_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

static ref_vec3 unit(double x, double y, double z)
{
    double l = sqrt(x * x + y * y + z * z);
    return V(x / l, y / l, z / l);
}

static ref_shape shape(int kind, ref_vec3 a, ref_vec3 b, ref_vec3 c,
                       double r, double h, unsigned caps)
{
    ref_shape s;
    memset(&s, 0, sizeof s);
    s.kind = kind;
    s.a = a;
    s.b = b;
    s.c = c;
    s.r = r;
    s.h = h;
    s.caps = caps;
    return s;
}

/* Returns the hit distance, or -1 for a miss; the normal goes to *n. */
static double cast(const ref_shape *s, ref_vec3 o, ref_vec3 d, ref_vec3 *n)
{
    ref_hit h;
    if (!ref_intersect(s, o, d, HUGE_VAL, &h))
        return -1;
    *n = h.n_out;
    return h.t;
}

static const ref_vec3 Z0 = {0, 0, 0}, ZP = {0, 0, 1}, ZM = {0, 0, -1};
static const ref_vec3 YP = {0, 1, 0}, YM = {0, -1, 0}, XP = {1, 0, 0};

static void test_sphere(void)
{
    ref_shape s = shape(RT_SPHERE, V(0, 0, 5), Z0, Z0, 1, 0, 0);
    ref_vec3 n;
    ref_hit h;
    CHECK_DBL(cast(&s, Z0, ZP, &n), 4, 1e-12); /* hit from outside */
    CHECK_VEC(n, 0, 0, -1);
    CHECK_DBL(cast(&s, V(0, 2, 0), ZP, &n), -1, 0); /* miss */
    CHECK_DBL(cast(&s, V(0, 0, 5), ZP, &n), 1, 1e-12); /* from inside */
    CHECK_VEC(n, 0, 0, 1);
    CHECK_DBL(cast(&s, V(1, 0, 0), ZP, &n), 5, 1e-12); /* tangent */
    CHECK_VEC(n, 1, 0, 0);
    CHECK_DBL(cast(&s, V(0, 0, 10), ZP, &n), -1, 0); /* behind */
    CHECK_DBL(cast(&s, V(0, 0, 4), ZP, &n), 2, 1e-12); /* on it: far side */
    CHECK_DBL(cast(&s, V(0, 0, 4), ZM, &n), -1, 0);    /* on it, leaving */
    CHECK(!ref_intersect(&s, Z0, ZP, 3.9, &h));        /* t_max excludes */
    CHECK(ref_intersect(&s, Z0, ZP, 4.1, &h));
    /* Oblique: d = (0, 0.6, 0.8) meets the r = 5 sphere at 0 (rejected,
     * below EPS) and at 8. */
    s.r = 5;
    CHECK_DBL(cast(&s, Z0, V(0, 0.6, 0.8), &n), 8, 1e-12);
    /* Far and small: the geometric discriminant keeps it exact. */
    s = shape(RT_SPHERE, V(0, 0, 1e4), Z0, Z0, 1, 0, 0);
    CHECK_DBL(cast(&s, Z0, ZP, &n), 9999, 1e-9);
    CHECK_DBL(cast(&s, V(0.999, 0, 0), ZP, &n), 1e4 - sqrt(1 - 0.998001),
              1e-9);
}

static void test_quad(void)
{
    ref_shape s = shape(RT_QUAD, V(-1, -1, 5), V(2, 0, 0), V(0, 2, 0), 0, 0,
                        0);
    ref_vec3 n;
    CHECK_DBL(cast(&s, Z0, ZP, &n), 5, 1e-12);
    CHECK_VEC(n, 0, 0, 1); /* norm(e1 x e2), not turned to the ray */
    CHECK_DBL(cast(&s, V(1.5, 0, 0), ZP, &n), -1, 0); /* miss beside */
    CHECK_DBL(cast(&s, V(1, 1, 0), ZP, &n), 5, 1e-12); /* corner counts */
    CHECK_DBL(cast(&s, V(0, 0, 10), ZM, &n), 5, 1e-12); /* from the back */
    CHECK_VEC(n, 0, 0, 1);
    CHECK_DBL(cast(&s, V(0, 0, 6), ZP, &n), -1, 0); /* behind */
    CHECK_DBL(cast(&s, V(-5, 0, 5), XP, &n), -1, 0); /* in the plane */
    /* |d . n| = 1e-6 < PAR: parallel, although it crosses a wide enough
     * quad at t ~ 1e6 (and does at 10 x PAR). */
    s = shape(RT_QUAD, V(-1e7, -1, 5), V(2e7, 0, 0), V(0, 2, 0), 0, 0, 0);
    CHECK_DBL(cast(&s, V(0, 0, 4), unit(1, 0, 1e-6), &n), -1, 0);
    CHECK(cast(&s, V(0, 0, 4), unit(1, 0, 10 * REF_PAR), &n) > 0);
    /* A sheared parallelogram: corner 0, e1 = (2,0,0), e2 = (1,1,0). */
    s = shape(RT_QUAD, Z0, V(2, 0, 0), V(1, 1, 0), 0, 0, 0);
    CHECK_DBL(cast(&s, V(2.4, 0.5, -1), ZP, &n), 1, 1e-12); /* u = .95 */
    CHECK_DBL(cast(&s, V(2.9, 0.5, -1), ZP, &n), -1, 0);    /* u = 1.2 */
    CHECK_DBL(cast(&s, V(0.2, 0.5, -1), ZP, &n), -1, 0);    /* u < 0 */
}

static void test_box(void)
{
    ref_shape s = shape(RT_BOX, V(-1, -1, 4), V(1, 1, 6), Z0, 0, 0, 0);
    ref_vec3 n, d = unit(0.1, 0, 1);
    CHECK_DBL(cast(&s, Z0, ZP, &n), 4, 1e-12);
    CHECK_VEC(n, 0, 0, -1);
    CHECK_DBL(cast(&s, V(-3, 0, 5), XP, &n), 2, 1e-12); /* x slab enters */
    CHECK_VEC(n, -1, 0, 0);
    CHECK_DBL(cast(&s, Z0, d, &n), 4 / d.z, 1e-12);
    CHECK_VEC(n, 0, 0, -1);
    CHECK_DBL(cast(&s, V(0, 2, 0), ZP, &n), -1, 0); /* miss */
    CHECK_DBL(cast(&s, V(2, 0, 0), ZP, &n), -1, 0); /* parallel, outside */
    CHECK_DBL(cast(&s, V(1, 0, 0), ZP, &n), 4, 1e-12); /* grazing a face */
    CHECK_DBL(cast(&s, V(0, 0, 5), YP, &n), 1, 1e-12); /* from inside */
    CHECK_VEC(n, 0, 1, 0);
    CHECK_DBL(cast(&s, V(0, 0, 5), ZM, &n), 1, 1e-12);
    CHECK_VEC(n, 0, 0, -1);
    CHECK_DBL(cast(&s, V(0, 0, 7), ZP, &n), -1, 0); /* behind */
    CHECK_DBL(cast(&s, V(0, 0, 6), ZP, &n), -1, 0); /* on it, leaving */
}

static void test_cylinder(void)
{
    const unsigned both = RT_CAP_BOTTOM | RT_CAP_TOP;
    ref_shape s = shape(RT_CYLINDER, V(0, 0, 5), Z0, Z0, 1, 2, 0);
    ref_vec3 n, d = unit(0, -1, 1);
    CHECK_DBL(cast(&s, V(0, 1, 0), ZP, &n), 4, 1e-12); /* side */
    CHECK_VEC(n, 0, 0, -1);
    CHECK_DBL(cast(&s, V(0, 3, 0), ZP, &n), -1, 0); /* above */
    CHECK_DBL(cast(&s, V(2, 1, 0), ZP, &n), -1, 0); /* beside */
    CHECK_DBL(cast(&s, V(0, 1, 7), ZP, &n), -1, 0); /* behind */
    CHECK_DBL(cast(&s, V(1, 1, 0), ZP, &n), 5, 1e-12); /* tangent */
    CHECK_VEC(n, 1, 0, 0);
    CHECK_DBL(cast(&s, V(0, 1, 5), XP, &n), 1, 1e-12); /* from inside */
    CHECK_VEC(n, 1, 0, 0);
    CHECK_DBL(cast(&s, V(0, 2.5, 3), d, &n), sqrt(2), 1e-12); /* oblique */
    CHECK_VEC(n, 0, 0, -1);
    /* Down the axis: open, it is missed; each cap present is hit. */
    CHECK_DBL(cast(&s, V(0, 5, 5), YM, &n), -1, 0);
    s.caps = RT_CAP_BOTTOM;
    CHECK_DBL(cast(&s, V(0, 5, 5), YM, &n), 5, 1e-12);
    CHECK_VEC(n, 0, -1, 0);
    s.caps = both;
    CHECK_DBL(cast(&s, V(0, 5, 5), YM, &n), 3, 1e-12);
    CHECK_VEC(n, 0, 1, 0);
    CHECK_DBL(cast(&s, V(0, -3, 5), YP, &n), 3, 1e-12);
    CHECK_VEC(n, 0, -1, 0);
    /* Over the rim onto the top cap; open, on to the far inside wall. */
    CHECK_DBL(cast(&s, V(0, 4, 3.5), d, &n), 2 * sqrt(2), 1e-12);
    CHECK_VEC(n, 0, 1, 0);
    s.caps = 0;
    CHECK_DBL(cast(&s, V(0, 4, 3.5), d, &n), 2.5 * sqrt(2), 1e-12);
    CHECK_VEC(n, 0, 0, 1);
}

static void test_cone(void)
{
    /* Base (0,0,5), r = 1, h = 2: apex (0,2,5), slope k = 0.5. */
    ref_shape s = shape(RT_CONE, V(0, 0, 5), Z0, Z0, 1, 2, 0);
    ref_vec3 n, d = unit(0, 2, 1);
    double r5 = 1 / sqrt(5);
    CHECK_DBL(cast(&s, V(0, 1, 0), ZP, &n), 4.5, 1e-12); /* side */
    CHECK_VEC(n, 0, r5, -2 * r5);
    CHECK_DBL(cast(&s, V(0, 2.5, 0), ZP, &n), -1, 0); /* the upper nappe */
    CHECK_DBL(cast(&s, V(2, 1, 0), ZP, &n), -1, 0);   /* beside */
    CHECK_DBL(cast(&s, V(0, 1, 7), ZP, &n), -1, 0);   /* behind */
    CHECK_DBL(cast(&s, V(0.5, 1, 0), ZP, &n), 5, 1e-12); /* tangent */
    CHECK_VEC(n, 2 * r5, r5, 0);
    CHECK_DBL(cast(&s, V(0, 0.5, 5), XP, &n), 0.75, 1e-12); /* inside */
    CHECK_VEC(n, 2 * r5, r5, 0);
    /* Up the axis: open, it meets the apex, whose normal is +y. */
    CHECK_DBL(cast(&s, V(0, -3, 5), YP, &n), 5, 1e-12);
    CHECK_VEC(n, 0, 1, 0);
    /* Parallel to a generator (A = 0): one root, on the far wall. */
    CHECK_DBL(cast(&s, V(0, -1, 4.5), d, &n), sqrt(5), 1e-12);
    CHECK_VEC(n, 0, r5, 2 * r5);
    s.caps = RT_CAP_BOTTOM;
    CHECK_DBL(cast(&s, V(0, -3, 5), YP, &n), 3, 1e-12);
    CHECK_VEC(n, 0, -1, 0);
    CHECK_DBL(cast(&s, V(0, -1, 4.5), d, &n), sqrt(5) / 2, 1e-12);
    CHECK_VEC(n, 0, -1, 0);
}

static void test_convexity(void)
{
    rt_object o;
    ref_shape s;
    static const struct {
        uint8_t kind, caps, convex;
    } cases[] = {{RT_SPHERE, 0, 1},   {RT_QUAD, 0, 1},     {RT_BOX, 0, 1},
                 {RT_CYLINDER, 0, 1}, {RT_CYLINDER, 1, 1}, {RT_CYLINDER, 2, 1},
                 {RT_CYLINDER, 3, 1}, {RT_CONE, 0, 1},     {RT_CONE, 1, 1},
                 {RT_CONE, 2, 1}}; /* every solid is convex: render-model.md */
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        memset(&o, 0, sizeof o);
        o.kind = cases[i].kind;
        o.caps = cases[i].caps;
        o.convex = (uint8_t)!cases[i].convex; /* derived: must be ignored */
        const int sphere = o.kind == RT_SPHERE;
        const int upright = o.kind == RT_CYLINDER || o.kind == RT_CONE;
        if (sphere)
            o.u.sphere.radius = FX_INT(3) / 2;
        if (upright)
            o.u.upright.radius = FX_INT(3) / 2;
        ref_shape_from_object(&o, &s);
        CHECK_EQ(s.convex, cases[i].convex);
        CHECK_DBL(s.r, sphere || upright ? 1.5 : 0, 0);
    }
}

static void test_noise(void)
{
    /* Hand-computed through the spec's hash. */
    CHECK_DBL(ref_lattice(1, 0, 0, 0), -48962 / 65536.0, 0);
    CHECK_DBL(ref_lattice(2, -1, 3, 7), -49774 / 65536.0, 0);
    CHECK_DBL(ref_lattice(3, 5, -2, -9), 38435 / 65536.0, 0);
    /* On the lattice the noise is the lattice value; halfway along x it is
     * the mean of the two ends (smoothstep(1/2) = 1/2). */
    CHECK_DBL(ref_noise(2, V(-1, 3, 7)), ref_lattice(2, -1, 3, 7), 0);
    CHECK_DBL(ref_noise(1, V(0.5, 0, 0)),
              (ref_lattice(1, 0, 0, 0) + ref_lattice(1, 1, 0, 0)) / 2, 1e-15);
}

/* ---- Rendering ------------------------------------------------------- */

typedef struct {
    uint8_t buf[4096];
    size_t used;
    int rows, stop_after;
} sink;

static int to_sink(void *ctx, int y, const uint8_t *row, size_t nbytes)
{
    sink *k = ctx;
    (void)y;
    if (k->used + nbytes <= sizeof k->buf)
        memcpy(k->buf + k->used, row, nbytes);
    k->used += nbytes;
    k->rows++;
    return k->stop_after && k->rows >= k->stop_after;
}

static rt_status render(const rt_scene *s, int w, int h, int spp, int depth,
                        sink *k, rt_stats *st)
{
    rt_options o;
    uint8_t row[4096];
    memset(&o, 0, sizeof o);
    o.width = (uint16_t)w;
    o.height = (uint16_t)h;
    o.spp = (uint8_t)spp;
    o.depth = (uint8_t)depth;
    memset(k, 0, sizeof *k);
    if (st)
        memset(st, 0, sizeof *st);
    return ref_render_rows(s, &o, 0, h, row, to_sink, k, st);
}

static rt_rgb rgb(double r, double g, double b)
{
    rt_rgb c;
    c.r = (fx_t)lround(r * 65536);
    c.g = (fx_t)lround(g * 65536);
    c.b = (fx_t)lround(b * 65536);
    return c;
}

static fx_vec3 fv(double x, double y, double z)
{
    return fx_v3((fx_t)lround(x * 65536), (fx_t)lround(y * 65536),
                 (fx_t)lround(z * 65536));
}

/* Adds an object with a fresh plain material; returns the material. */
static rt_material *add(rt_scene *s, int kind, fx_vec3 a, fx_vec3 b,
                        fx_vec3 c, double r)
{
    rt_object *o = &s->obj[s->n_objects++];
    rt_material *m = &s->mat[s->n_materials];
    o->kind = (uint8_t)kind;
    o->material = s->n_materials++;
    o->u.origin = a; /* every kind's first point */
    if (kind == RT_SPHERE)
        o->u.sphere.radius = (fx_t)lround(r * 65536);
    else if (kind == RT_QUAD) {
        o->u.quad.edge1 = b;
        o->u.quad.edge2 = c;
    } else if (kind == RT_BOX)
        o->u.box.max = b;
    else
        o->u.upright.radius = (fx_t)lround(r * 65536);
    m->color = rgb(1, 1, 1);
    m->shininess = 1;
    m->ior = FX_ONE;
    return m;
}

static void test_render_basics(void)
{
    rt_scene s;
    rt_options o;
    rt_stats st;
    sink k;
    uint8_t row[64];
    rt_scene_init(&s);
    s.background = rgb(0.5, 0.25, 1);
    CHECK_EQ(render(&s, 3, 2, 4, 5, &k, &st), RT_OK);
    CHECK_EQ(k.rows, 2);
    CHECK_EQ(k.used, 18);
    CHECK_EQ(k.buf[0], 128); /* 127.5 rounds up */
    CHECK_EQ(k.buf[1], 64);
    CHECK_EQ(k.buf[17], 255);
    CHECK_EQ(st.primary, 24);
    CHECK_EQ(st.tests, 0);
    memset(&o, 0, sizeof o); /* counts add up over calls */
    o.width = 3;
    o.height = 2;
    o.spp = 1;
    CHECK_EQ(ref_render_rows(&s, &o, 1, 2, row, to_sink, &k, &st), RT_OK);
    CHECK_EQ(st.primary, 27);
    /* RGB565: 128 >> 3 = 16, 64 >> 2 = 16, 255 >> 3 = 31: 0x821F. */
    memset(&o, 0, sizeof o);
    o.width = 2;
    o.height = 1;
    o.spp = 1;
    o.format = RT_RGB565_LE;
    memset(&k, 0, sizeof k);
    CHECK_EQ(ref_render_rows(&s, &o, 0, 1, row, to_sink, &k, NULL), RT_OK);
    CHECK_EQ(k.used, 4);
    CHECK(k.buf[0] == 0x1F && k.buf[1] == 0x82);
    o.format = RT_RGB565_BE;
    memset(&k, 0, sizeof k);
    CHECK_EQ(ref_render_rows(&s, &o, 0, 1, row, to_sink, &k, NULL), RT_OK);
    CHECK(k.buf[0] == 0x82 && k.buf[1] == 0x1F);
    /* Dither: red 130 is 16.25 steps of 8; over a 4x4 block the 5-bit
     * values must average exactly that. */
    s.background = rgb(130 / 255.0, 0, 0);
    o.width = o.height = 4;
    o.format = RT_RGB565_LE;
    o.dither = 1;
    memset(&k, 0, sizeof k);
    CHECK_EQ(ref_render_rows(&s, &o, 0, 4, row, to_sink, &k, NULL), RT_OK);
    {
        int i, sum = 0;
        for (i = 0; i < 16; i++)
            sum += k.buf[2 * i + 1] >> 3;
        CHECK_EQ(sum, 16 * 16 + 4);
    }
    /* Bad arguments, and a callback that stops the render. */
    o.dither = 0;
    CHECK_EQ(ref_render_rows(&s, &o, 0, 5, row, to_sink, &k, NULL),
             RT_ERR_ARG);
    CHECK_EQ(ref_render_rows(&s, &o, 2, 1, row, to_sink, &k, NULL),
             RT_ERR_ARG);
    o.spp = 3;
    CHECK_EQ(ref_render_rows(&s, &o, 0, 1, row, to_sink, &k, NULL),
             RT_ERR_ARG);
    o.spp = 1;
    o.depth = RT_MAX_DEPTH + 1;
    CHECK_EQ(ref_render_rows(&s, &o, 0, 1, row, to_sink, &k, NULL),
             RT_ERR_ARG);
    o.depth = 0;
    memset(&k, 0, sizeof k);
    k.stop_after = 1;
    CHECK_EQ(ref_render_rows(&s, &o, 0, 4, row, to_sink, &k, NULL),
             RT_ERR_ABORTED);
    CHECK_EQ(k.rows, 1);
}

static void test_render_shading(void)
{
    rt_scene s;
    rt_stats st;
    rt_material *m;
    sink k;
    /* One pixel looking down +z at a unit sphere, light at the eye:
     * N = L = V, so ndl = rv = 1. */
    rt_scene_init(&s);
    m = add(&s, RT_SPHERE, fv(0, 0, 0), fv(0, 0, 0), fv(0, 0, 0), 1);
    m->ambient = FX_HALF;
    CHECK_EQ(render(&s, 1, 1, 1, 5, &k, &st), RT_OK);
    CHECK_EQ(k.buf[0], 128); /* ka only: 0.5 * 255 rounds up */
    CHECK_EQ(k.buf[2], 128);
    m->ambient = 0;
    m->diffuse = FX_CONST(0.6);
    m->specular = FX_CONST(0.2);
    m->shininess = 7;
    s.n_lights = 1;
    s.light[0].pos = fv(0, 0, -10);
    s.light[0].color = rgb(1, 1, 1);
    CHECK_EQ(render(&s, 1, 1, 1, 5, &k, &st), RT_OK);
    CHECK_EQ(k.buf[0], 204); /* (0.6 + 0.2) * 255 */
    CHECK_EQ(st.shadow, 1);
    CHECK_EQ(st.tests, 1); /* the shadow ray skips the convex sphere */

    /* A wall quad at z = 0 lit from (0, 5, -5); a ball on the light path
     * (off the view ray) shadows it. */
    rt_scene_init(&s);
    m = add(&s, RT_QUAD, fv(-5, -5, 0), fv(10, 0, 0), fv(0, 10, 0), 0);
    m->diffuse = FX_ONE;
    s.n_lights = 1;
    s.light[0].pos = fv(0, 5, -5);
    s.light[0].color = rgb(1, 1, 1);
    CHECK_EQ(render(&s, 1, 1, 1, 5, &k, &st), RT_OK);
    CHECK_EQ(k.buf[0], 180); /* cos 45 degrees * 255 = 180.3 */
    add(&s, RT_SPHERE, fv(0, 2.5, -2.5), fv(0, 0, 0), fv(0, 0, 0), 0.5);
    CHECK_EQ(render(&s, 1, 1, 1, 5, &k, &st), RT_OK);
    CHECK_EQ(k.buf[0], 0);
    CHECK_EQ(st.shadow, 1);
    CHECK_EQ(st.tests, 2 + 1); /* primary: both; shadow: the ball only */
    s.shadows = 0; /* lights then reach every point facing them */
    CHECK_EQ(render(&s, 1, 1, 1, 5, &k, &st), RT_OK);
    CHECK_EQ(k.buf[0], 180);
    CHECK_EQ(st.shadow, 0);
    CHECK_EQ(st.tests, 2);

    /* A mirror facing the camera reflects the background, but only while
     * depth allows. */
    rt_scene_init(&s);
    s.background = rgb(0, 1, 0);
    m = add(&s, RT_QUAD, fv(-5, -5, 0), fv(10, 0, 0), fv(0, 10, 0), 0);
    m->reflect = FX_ONE;
    m->ambient = FX_ONE;
    CHECK_EQ(render(&s, 1, 1, 1, 1, &k, &st), RT_OK);
    CHECK(k.buf[0] == 0 && k.buf[1] == 255 && k.buf[2] == 0);
    CHECK_EQ(st.reflection, 1);
    CHECK_EQ(render(&s, 1, 1, 1, 0, &k, &st), RT_OK);
    CHECK(k.buf[0] == 0 && k.buf[1] == 0 && k.buf[2] == 0);
    CHECK_EQ(st.reflection, 0);
}

static void test_render_glass(void)
{
    rt_scene s;
    rt_stats st;
    rt_material *m;
    sink k;
    /* ior 1: straight through a clear ball to the background. */
    rt_scene_init(&s);
    s.background = rgb(0, 0, 1);
    m = add(&s, RT_SPHERE, fv(0, 0, 0), fv(0, 0, 0), fv(0, 0, 0), 1);
    m->transparency = FX_ONE;
    CHECK_EQ(render(&s, 1, 1, 1, 2, &k, &st), RT_OK);
    CHECK_EQ(k.buf[2], 255);
    CHECK_EQ(st.refraction, 2);
    CHECK_EQ(st.tests, 2); /* the exit ray skips the convex ball */
    CHECK_EQ(render(&s, 1, 1, 1, 1, &k, &st), RT_OK);
    CHECK_EQ(k.buf[2], 0); /* depth spent at the inside hit */
    CHECK_EQ(st.refraction, 1);
    /* From inside, 0.9 off the centre, looking along +z: sin^2 = 0.81,
     * eta^2 sin^2 = 1.82 > 1, total internal reflection. */
    s.cam.eye = fv(0.9, 0, 0);
    s.cam.look = fv(0.9, 0, 1);
    m->ior = FX_CONST(1.5);
    CHECK_EQ(render(&s, 1, 1, 1, 1, &k, &st), RT_OK);
    CHECK_EQ(st.reflection, 1);
    CHECK_EQ(st.refraction, 0);
    CHECK_EQ(st.tests, 2); /* from inside: the reflection may hit it */
    /* A glass pane, head on: straight through, and the transmitted ray
     * skips the quad (both its sides are outside). */
    rt_scene_init(&s);
    s.background = rgb(0, 0, 1);
    m = add(&s, RT_QUAD, fv(-5, -5, 0), fv(10, 0, 0), fv(0, 10, 0), 0);
    m->transparency = FX_ONE;
    m->ior = FX_CONST(1.5);
    CHECK_EQ(render(&s, 1, 1, 1, 2, &k, &st), RT_OK);
    CHECK_EQ(k.buf[2], 255);
    CHECK(st.refraction == 1 && st.reflection == 0 && st.tests == 1);
}

static void test_render_texture_bands(void)
{
    rt_scene s;
    rt_material *m;
    sink k, whole;
    rt_options o;
    uint8_t row[256];
    int y;
    /* A 4x1 image at fov 60 meets the wall at x = +-5.77 and +-17.3;
     * q.x = x + 100 falls in stripes 82, 94, 105, 117. */
    rt_scene_init(&s);
    m = add(&s, RT_QUAD, fv(-100, -1, 0), fv(200, 0, 0), fv(0, 2, 0), 0);
    m->ambient = FX_ONE;
    m->color = rgb(1, 0, 0);
    m->color2 = rgb(0, 0, 1);
    m->texture = RT_TEX_STRIPES;
    m->axis = 0;
    m->tex_scale = FX_ONE;
    CHECK_EQ(render(&s, 4, 1, 1, 0, &k, NULL), RT_OK);
    CHECK(k.buf[0] == 255 && k.buf[3] == 255);
    CHECK(k.buf[8] == 255 && k.buf[11] == 255);
    /* Rows are independent: one band or two give the same bytes. */
    m->bump = FX_CONST(0.3);
    m->bump_scale = FX_CONST(0.5);
    s.n_lights = 1;
    s.light[0].pos = fv(3, 4, -6);
    s.light[0].color = rgb(1, 1, 1);
    add(&s, RT_CONE, fv(0, -1, -3), fv(0, 0, 0), fv(0, 0, 0), 1)->reflect =
        FX_HALF;
    s.obj[1].u.upright.height = FX_INT(2);
    s.obj[1].caps = RT_CAP_BOTTOM;
    CHECK_EQ(render(&s, 8, 6, 4, 3, &whole, NULL), RT_OK);
    memset(&o, 0, sizeof o);
    o.width = 8;
    o.height = 6;
    o.spp = 4;
    o.depth = 3;
    memset(&k, 0, sizeof k);
    for (y = 0; y < 6; y += 4)
        CHECK_EQ(ref_render_rows(&s, &o, y, y + 4 > 6 ? 6 : y + 4, row,
                                 to_sink, &k, NULL), RT_OK);
    CHECK_EQ(k.used, whole.used);
    CHECK(memcmp(k.buf, whole.buf, whole.used) == 0);
    s.obj[1].u.upright.height = 0;
    CHECK_EQ(render(&s, 8, 6, 4, 3, &k, NULL), RT_ERR_DEGENERATE);
}

int main(void)
{
    test_sphere();
    test_quad();
    test_box();
    test_cylinder();
    test_cone();
    test_convexity();
    test_noise();
    test_render_basics();
    test_render_shading();
    test_render_glass();
    test_render_texture_bands();
    return th_summary();
}
