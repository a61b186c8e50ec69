/* SPDX-License-Identifier: MIT */
/*
 * The direction grids (core/accel/rt_dirgrid.c) must be conservative: any object
 * a shadow ray or a ray leaving an object hits must be listed in the ray's
 * cell. Random lights and shapes from tiny to huge, and rays aimed to
 * graze each object's bounding sphere, where a too-narrow cone would show
 * first. Also the reflections of camera rays in a mirror quad, culled from
 * the eye's mirror image.
 */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "rt_bounce.h"
#include "rt_shape.h"
#include "rt_trace.h"

#define D2F(x) ((fx_t)lround((x) * 65536.0))

static uint64_t rng = 0x5eed5eedULL;

static double uni(double lo, double hi)
{
    return lo + (hi - lo) * (double)(th_rnd64(&rng) >> 11) * 0x1p-53;
}

/* log-uniform in [lo, hi] */
static double logu(double lo, double hi)
{
    return exp(uni(log(lo), log(hi)));
}

static fx_vec3 v3(double x, double y, double z)
{
    return fx_v3(D2F(x), D2F(y), D2F(z));
}

static void random_object(rt_object *o, double spread)
{
    memset(o, 0, sizeof *o);
    double s = logu(1.0 / 64, 64);
    double x = uni(-spread, spread), y = uni(-spread, spread);
    double z = uni(-spread, spread);
    o->kind = (uint8_t)(th_rnd64(&rng) % RT_MESH); /* the analytic kinds */
    o->caps = RT_CAP_BOTTOM | RT_CAP_TOP;
    o->u.origin = v3(x, y, z); /* any kind's first point */
    const fx_t r = D2F(s), h = D2F(s * uni(0.2, 3));
    if (o->kind == RT_SPHERE) {
        o->u.sphere.radius = r;
    } else if (o->kind == RT_QUAD) {
        o->u.quad.edge1 = v3(uni(-s, s), uni(-s, s), uni(-s, s));
        o->u.quad.edge2 = v3(uni(-s, s), uni(-s, s), uni(-s, s));
    } else if (o->kind == RT_BOX) {
        o->u.box.max = v3(x + s * uni(0.1, 2), y + s * uni(0.1, 2),
                          z + s * uni(0.1, 2));
    } else {
        o->u.upright.radius = r;
        o->u.upright.height = h;
    }
    if (rt_object_prepare(o) != RT_OK)
        random_object(o, spread); /* degenerate draw: try again */
}

static int listed(const uint32_t *cell, unsigned i)
{
    return cell && ((cell[i / 32] >> (i % 32)) & 1u);
}

/* A point on the sphere (c, r * f), f a little under or over 1, seen
 * from q: rays from q through it graze that sphere. */
static fx_vec3 graze_point(fx_vec3 q, fx_vec3 c, fx_t r)
{
    double cx = (c.x - (double)q.x) / 65536.0;
    double cy = (c.y - (double)q.y) / 65536.0;
    double cz = (c.z - (double)q.z) / 65536.0;
    double d = sqrt(cx * cx + cy * cy + cz * cz);
    double rr = r / 65536.0 * uni(0.9, 1.02);
    double ux = uni(-1, 1), uy = uni(-1, 1), uz = uni(-1, 1);
    if (d > 0) { /* across the line of sight */
        double dot = (ux * cx + uy * cy + uz * cz) / d;
        ux -= dot * cx / d, uy -= dot * cy / d, uz -= dot * cz / d;
    }
    double ul = sqrt(ux * ux + uy * uy + uz * uz);
    if (ul == 0)
        ul = ux = 1;
    return fx_v3_add(c, v3(ux / ul * rr, uy / ul * rr, uz / ul * rr));
}

static void random_scene(rt_scene *s, double spread)
{
    memset(s, 0, sizeof *s);
    s->n_objects = (uint16_t)(1 + th_rnd64(&rng) % 12);
    for (unsigned i = 0; i < s->n_objects; i++)
        random_object(&s->obj[i], spread);
}

/* Every object the ray hits within tmax must be in its cell. */
static void check_ray(const rt_scene *s, const rt_ray *r, fx_t tmax,
                      const uint32_t *cell, long *hits, long *missing)
{
    for (unsigned i = 0; i < s->n_objects; i++) {
        fx_t t;
        uint16_t part;
        if (!rt_intersect(&s->obj[i], r, RT_EPS, tmax, &t, &part))
            continue;
        ++*hits;
        if (!listed(cell, i) && ++*missing <= 5)
            printf("object %u (kind %d) is hit but not listed\n", i,
                   s->obj[i].kind);
    }
}

static rt_ray make_ray(fx_vec3 o, fx_dir3 d)
{
    rt_ray r;
    rt_ray_set(&r, o, d);
    return r;
}

/* Shadow rays: from surface points beyond a grazed object towards a
 * light anywhere, sometimes right beside (or in) an object. */
static void shadow_trial(double spread, long *hits, long *missing)
{
    static rt_scene s;
    static rt_dir_grid g;
    static uint32_t cell[2 * RT_DIR_GRID * RT_DIR_GRID];
    random_scene(&s, spread);
    const rt_object *near = &s.obj[th_rnd64(&rng) % s.n_objects];
    fx_vec3 lp = th_rnd64(&rng) % 4 == 0
        ? fx_v3_add(near->bc, v3(uni(-2, 2), uni(-2, 2), uni(-2, 2)))
        : v3(uni(-spread, spread), uni(-spread, spread),
             uni(-spread, spread));
    rt_dir_grid_prepare(&g, cell, 1, &s, lp, 0, 0, RT_NO_OBJECT);
    for (int k = 0; k < 400; k++) {
        const rt_object *b = &s.obj[th_rnd64(&rng) % s.n_objects];
        fx_vec3 q = graze_point(lp, b->bc, b->br);
        /* p: on the line from the light through q, beyond q. */
        fx_vec3 p = fx_v3_add(
            lp, fx_v3_scale(fx_v3_sub(q, lp), D2F(uni(1.0, 3.0))));
        fx_vec3 lv = fx_v3_sub(lp, p);
        fx_dir3 ld = fx_d3_normalize(lv);
        /* Origin offset as shade() gives it: EPS along some normal. */
        fx_dir3 n = fx_d3_normalize(v3(uni(-1, 1), uni(-1, 1), uni(-1, 1)));
        rt_ray sr = make_ray(fx_v3_madd_d(p, n, RT_EPS), ld);
        fx_t tmax = fx_sub(fx_pd_dot(lv, ld), RT_EPS);
        check_ray(&s, &sr, tmax,
                  rt_dir_cell(&g, fx_u_to_fx(-ld.x), fx_u_to_fx(-ld.y),
                              fx_u_to_fx(-ld.z), 1),
                  hits, missing);
    }
}

/* Rays leaving an object: from anywhere in its bounding sphere (offset as
 * shade() does), aimed to graze another object's. */
static void leaving_trial(double spread, long *hits, long *missing)
{
    static rt_scene s;
    static rt_dir_grid g;
    static uint32_t cell[2 * RT_DIR_GRID * RT_DIR_GRID];
    random_scene(&s, spread);
    const rt_object *from = &s.obj[th_rnd64(&rng) % s.n_objects];
    rt_dir_grid_prepare(&g, cell, 1, &s, from->bc, from->br, 1,
                        RT_NO_OBJECT);
    for (int k = 0; k < 400; k++) {
        const rt_object *b = &s.obj[th_rnd64(&rng) % s.n_objects];
        fx_vec3 o = graze_point(from->bc, from->bc, from->br);
        o = fx_v3_add(from->bc,
                      fx_v3_scale(fx_v3_sub(o, from->bc), D2F(uni(0, 1))));
        fx_dir3 n = fx_d3_normalize(v3(uni(-1, 1), uni(-1, 1), uni(-1, 1)));
        o = fx_v3_madd_d(o, n, RT_EPS);
        fx_vec3 aim = graze_point(o, b->bc, b->br);
        fx_dir3 d = fx_d3_normalize(fx_v3_sub(aim, o));
        rt_ray r = make_ray(o, d);
        check_ray(&s, &r, FX_MAX,
                  rt_dir_cell(&g, fx_u_to_fx(d.x), fx_u_to_fx(d.y),
                              fx_u_to_fx(d.z), 1),
                  hits, missing);
    }
}

static double dot_d(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* A point of quad o (in Q16.16) on the line from m through q, or else a
 * random point of the quad. */
static fx_vec3 quad_point(const rt_object *o, fx_vec3 m, fx_vec3 q)
{
    const double s = 1.0 / 65536, us = 1.0 / FX_UONE;
    const rt_quad *qd = &o->u.quad;
    const double n[3] = { qd->normal.x * us, qd->normal.y * us,
                          qd->normal.z * us };
    const double pu[3] = { qd->axis_u.x * us, qd->axis_u.y * us,
                           qd->axis_u.z * us };
    const double pv[3] = { qd->axis_v.x * us, qd->axis_v.y * us,
                           qd->axis_v.z * us };
    const double am[3] = { (qd->corner.x - (double)m.x) * s,
                           (qd->corner.y - (double)m.y) * s,
                           (qd->corner.z - (double)m.z) * s };
    const double qm[3] = { (q.x - (double)m.x) * s, (q.y - (double)m.y) * s,
                           (q.z - (double)m.z) * s };
    const double den = dot_d(qm, n);
    if (den != 0) {
        const double f = dot_d(am, n) / den;
        const double pa[3] = { f * qm[0] - am[0], f * qm[1] - am[1],
                               f * qm[2] - am[2] };
        const double u = dot_d(pa, pu), v = dot_d(pa, pv);
        if (f > 0 && u >= 0 && u <= qd->len_u * s && v >= 0 &&
            v <= qd->len_v * s)
            return fx_v3_add(qd->corner, v3(pa[0], pa[1], pa[2]));
    }
    return fx_v3_add(qd->corner,
                     fx_v3_add(fx_v3_scale(qd->edge1, D2F(uni(0, 1))),
                               fx_v3_scale(qd->edge2, D2F(uni(0, 1)))));
}

/* Camera rays from a random eye reflected in a mirror quad (object 0) as
 * shade() reflects them, aimed so that the reflections graze the other
 * objects' bounding spheres: each object they hit must be among the
 * candidates of the mirror-image grid. */
static void mirror_trial(double spread, long *hits, long *missing,
                         long *grids)
{
    static rt_scene s;
    static rt_dir_grids gs;
    random_scene(&s, spread);
    do
        random_object(&s.obj[0], spread);
    while (s.obj[0].kind != RT_QUAD);
    s.n_materials = 1;
    s.mat[0].reflect = FX_ONE / 2;
    const rt_object *o = &s.obj[0];
    s.cam.eye = th_rnd64(&rng) % 4 == 0
        ? fx_v3_add(o->bc, v3(uni(-2, 2), uni(-2, 2), uni(-2, 2)))
        : v3(uni(-spread, spread), uni(-spread, spread),
             uni(-spread, spread));
    rt_dir_grids_prepare(&gs, &s);
    const unsigned g = rt_dir_mirror_of(&gs, 0, s.cam.eye);
    if (g == RT_DIR_NONE)
        return;
    ++*grids;
    /* The eye's image, as the test finds it (double). */
    const double us = 1.0 / FX_UONE;
    const rt_quad *qd = &o->u.quad;
    const double n[3] = { qd->normal.x * us, qd->normal.y * us,
                          qd->normal.z * us };
    const double ea[3] = { (s.cam.eye.x - (double)qd->corner.x) / 65536,
                           (s.cam.eye.y - (double)qd->corner.y) / 65536,
                           (s.cam.eye.z - (double)qd->corner.z) / 65536 };
    const double h = 2 * dot_d(ea, n);
    const fx_vec3 m = fx_v3_sub(s.cam.eye, v3(h * n[0], h * n[1], h * n[2]));
    for (int k = 0; k < 600; k++) {
        const rt_object *b = &s.obj[th_rnd64(&rng) % s.n_objects];
        const fx_vec3 p0 = quad_point(o, m, graze_point(m, b->bc, b->br));
        const fx_vec3 e = s.cam.eye;
        if (p0.x == e.x && p0.y == e.y && p0.z == e.z)
            continue;
        rt_ray r = make_ray(e, fx_d3_normalize(fx_v3_sub(p0, e)));
        fx_t t;
        uint16_t part;
        if (!rt_intersect(o, &r, RT_EPS, FX_MAX, &t, &part))
            continue;
        const fx_vec3 p = fx_v3_madd_d(r.o, r.d, t);
        fx_dir3 ng = qd->normal;
        if (fx_d3_dot_raw(r.d, ng) > 0)
            ng = fx_d3_neg(ng);
        const rt_ray rr = make_ray(rt_v3_madd_pow2(p, ng, rt_origin_log2(o), 0),
                                   rt_reflect_dir(r.d, ng));
        const uint32_t *cand = rt_dir_candidates(&gs, g, rr.d);
        for (unsigned i = 1; i < s.n_objects; i++) {
            if (!rt_intersect(&s.obj[i], &rr, RT_EPS, FX_MAX, &t, &part))
                continue;
            ++*hits;
            if (!listed(cand, i) && ++*missing <= 5)
                printf("object %u (kind %d) is hit but not listed\n", i,
                       s.obj[i].kind);
        }
    }
}

int main(void)
{
    long hits = 0, missing = 0;
    for (int t = 0; t < 1500; t++)
        shadow_trial(t % 10 == 0 ? 4000.0 : 40.0, &hits, &missing);
    CHECK_EQ(missing, 0);
    /* The aim must actually produce blockers, or the test checks nothing. */
    CHECK(hits > 100000);
    printf("light grids: %ld blocking shadow rays, %ld not listed\n", hits,
           missing);
    hits = missing = 0;
    for (int t = 0; t < 1500; t++)
        leaving_trial(t % 10 == 0 ? 4000.0 : 40.0, &hits, &missing);
    CHECK_EQ(missing, 0);
    CHECK(hits > 100000);
    printf("object grids: %ld hits of leaving rays, %ld not listed\n", hits,
           missing);
    long grids = 0;
    hits = missing = 0;
    for (int t = 0; t < 1500; t++)
        mirror_trial(t % 10 == 0 ? 4000.0 : 40.0, &hits, &missing, &grids);
    CHECK_EQ(missing, 0);
    CHECK(grids > 1000);
    CHECK(hits > 100000);
    printf("mirror grids: %ld, %ld hits of reflected camera rays, "
           "%ld not listed\n", grids, hits, missing);
    /* Only rays from the eye are reflections of camera rays. */
    static rt_scene s1;
    static rt_dir_grids g1;
    s1.n_objects = 1;
    s1.n_materials = 1;
    s1.mat[0].reflect = FX_ONE / 2;
    do
        random_object(&s1.obj[0], 4.0);
    while (s1.obj[0].kind != RT_QUAD);
    s1.cam.eye = v3(0, 10, 0);
    rt_dir_grids_prepare(&g1, &s1);
    CHECK(rt_dir_mirror_of(&g1, 0, s1.cam.eye) != RT_DIR_NONE);
    CHECK_EQ(rt_dir_mirror_of(&g1, 0, fx_v3_add(s1.cam.eye, fx_v3(1, 0, 0))),
             RT_DIR_NONE);
    s1.mat[0].bump = FX_ONE / 4; /* a bumped mirror: no image to cull by */
    rt_dir_grids_prepare(&g1, &s1);
    CHECK_EQ(rt_dir_mirror_of(&g1, 0, s1.cam.eye), RT_DIR_NONE);
    return th_summary();
}
