/* SPDX-License-Identifier: MIT */
/*
 * Each primitive's intersection and normal in the fixed-point core against
 * closed-form double answers: hit, miss, from inside, tangent, behind the
 * origin. Then random rays at every primitive, where the core's hit/miss
 * must agree with double except within a hair of the silhouette, and t
 * within a stated tolerance.
 */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "rt_shape.h"

#define D2F(x) ((fx_t)lround((x) * 65536.0))
#define F2D(x) ((double)(x) / 65536.0)
#define U2D(x) ((double)(x) / (double)FX_UONE) /* unit components */

static rt_object make(int kind, double ax, double ay, double az, double r,
                      double h)
{
    rt_object o;
    memset(&o, 0, sizeof o);
    o.kind = (uint8_t)kind;
    o.u.origin = fx_v3(D2F(ax), D2F(ay), D2F(az)); /* any kind's first */
    if (kind == RT_SPHERE)
        o.u.sphere.radius = D2F(r);
    if (kind == RT_CYLINDER || kind == RT_CONE) {
        o.u.upright.radius = D2F(r);
        o.u.upright.height = D2F(h);
    }
    o.caps = RT_CAP_BOTTOM | RT_CAP_TOP;
    return o;
}

static rt_ray ray(double ox, double oy, double oz, double dx, double dy,
                  double dz)
{
    rt_ray r;
    double l = sqrt(dx * dx + dy * dy + dz * dz);
    r.o = fx_v3(D2F(ox), D2F(oy), D2F(oz));
    r.d = fx_d3((int32_t)lround(dx / l * FX_UONE),
                (int32_t)lround(dy / l * FX_UONE),
                (int32_t)lround(dz / l * FX_UONE));
    r.e = fx_d3_unit_err(r.d);
    r.small = (uint8_t)fx_v3_small(r.o);
    return r;
}

/* Hits at t_want (within tol world units) with outward normal n_want. */
static void expect_hit(const rt_object *o, rt_ray r, double t_want,
                       double nx, double ny, double nz, double tol,
                       int line)
{
    fx_t t;
    uint16_t part;
    int hit = rt_intersect(o, &r, RT_EPS, FX_MAX, &t, &part);
    if (!th_check(hit, __FILE__, line, "expected a hit"))
        return;
    if (!th_check(fabs(F2D(t) - t_want) <= tol, __FILE__, line,
                  "hit distance"))
        printf("    t = %.6f, want %.6f\n", F2D(t), t_want);
    fx_vec3 p = fx_v3_madd_d(r.o, r.d, t);
    fx_dir3 n = rt_normal(o, &r, t, &p, part, 1);
    double err = fabs(U2D(n.x) - nx) + fabs(U2D(n.y) - ny) +
                 fabs(U2D(n.z) - nz);
    if (!th_check(err < 1e-3, __FILE__, line, "normal"))
        printf("    n = (%.4f %.4f %.4f), want (%.4f %.4f %.4f)\n",
               U2D(n.x), U2D(n.y), U2D(n.z), nx, ny, nz);
}

static void expect_miss(const rt_object *o, rt_ray r, int line)
{
    fx_t t;
    uint16_t part;
    th_check(!rt_intersect(o, &r, RT_EPS, FX_MAX, &t, &part), __FILE__, line,
             "expected a miss");
}

#define HIT(o, r, t, nx, ny, nz) expect_hit(&(o), r, t, nx, ny, nz, 1e-3, __LINE__)
#define MISS(o, r) expect_miss(&(o), r, __LINE__)

static void sphere_cases(void)
{
    rt_object s = make(RT_SPHERE, 0, 0, 5, 1, 0);
    CHECK_EQ(rt_object_prepare(&s), RT_OK);
    HIT(s, ray(0, 0, 0, 0, 0, 1), 4, 0, 0, -1);               /* hit */
    MISS(s, ray(0, 2, 0, 0, 0, 1));                           /* miss */
    HIT(s, ray(0, 0, 5, 0, 1, 0), 1, 0, 1, 0);                /* inside */
    MISS(s, ray(0, 0, 10, 0, 0, 1));                          /* behind */
    HIT(s, ray(0, 0.9999, 0, 0, 0, 1), 5 - sqrt(1 - 0.9999 * 0.9999),
        0, 0.9999, -sqrt(1 - 0.9999 * 0.9999));               /* near tangent */
    MISS(s, ray(0, 1.0001, 0, 0, 0, 1));                      /* past tangent */
    /* Far sphere: 20000 units away, radius 100. */
    rt_object f = make(RT_SPHERE, 0, 0, 20000, 100, 0);
    CHECK_EQ(rt_object_prepare(&f), RT_OK);
    HIT(f, ray(0, 0, 0, 0, 0, 1), 19900, 0, 0, -1);
    /* Tiny sphere: radius 1/256. */
    rt_object tiny = make(RT_SPHERE, 0, 0, 1, 1.0 / 256, 0);
    CHECK_EQ(rt_object_prepare(&tiny), RT_OK);
    HIT(tiny, ray(0, 0, 0, 0, 0, 1), 1 - 1.0 / 256, 0, 0, -1);
}

static void quad_cases(void)
{
    rt_object q = make(RT_QUAD, -1, 0, -1, 0, 0);
    q.u.quad.edge1 = fx_v3(0, 0, D2F(2));   /* edge1 along +z */
    q.u.quad.edge2 = fx_v3(D2F(2), 0, 0);   /* edge2 along +x: normal +y */
    CHECK_EQ(rt_object_prepare(&q), RT_OK);
    HIT(q, ray(0, 3, 0, 0, -1, 0), 3, 0, 1, 0);
    HIT(q, ray(0.5, -2, 0.5, 0, 1, 0), 2, 0, 1, 0); /* from below */
    MISS(q, ray(1.5, 3, 0, 0, -1, 0));              /* beside */
    MISS(q, ray(0, 3, 0, 0, 1, 0));                 /* behind */
    MISS(q, ray(-5, 0, 0, 1, 0, 0));                /* in the plane */
    /* grazing: t = y / sin, from the origin's Q16.16 height */
    HIT(q, ray(-5, 0.01, 0, 1, -0.002, 0),
        F2D(D2F(0.01)) / 0.002 * sqrt(1 + 0.002 * 0.002), 0, 1, 0);
    rt_object bad = make(RT_QUAD, 0, 0, 0, 0, 0);
    bad.u.quad.edge1 = fx_v3(FX_ONE, 0, 0);
    bad.u.quad.edge2 = fx_v3(2 * FX_ONE, 0, 0);
    CHECK_EQ(rt_object_prepare(&bad), RT_ERR_DEGENERATE);
}

static void box_cases(void)
{
    rt_object b = make(RT_BOX, -1, -1, -1, 0, 0);
    b.u.box.max = fx_v3(FX_ONE, FX_ONE, FX_ONE);
    CHECK_EQ(rt_object_prepare(&b), RT_OK);
    HIT(b, ray(0, 0, -5, 0, 0, 1), 4, 0, 0, -1);
    HIT(b, ray(5, 0.5, 0.5, -1, 0, 0), 4, 1, 0, 0);
    HIT(b, ray(0, 0, 0, 0, 1, 0), 1, 0, 1, 0);   /* inside */
    MISS(b, ray(0, 2, -5, 0, 0, 1));
    MISS(b, ray(0, 0, 5, 0, 0, 1));              /* behind */
    HIT(b, ray(0, 0.999, -5, 0, 0, 1), 4, 0, 0, -1); /* near an edge */
    rt_object flat = make(RT_BOX, 0, 0, 0, 0, 0);
    flat.u.box.max = fx_v3(FX_ONE, 0, FX_ONE);
    CHECK_EQ(rt_object_prepare(&flat), RT_ERR_DEGENERATE);
}

static void cylinder_cases(void)
{
    rt_object c = make(RT_CYLINDER, 0, 0, 0, 1, 2);
    CHECK_EQ(rt_object_prepare(&c), RT_OK);
    HIT(c, ray(0, 1, -5, 0, 0, 1), 4, 0, 0, -1);          /* side */
    HIT(c, ray(0, 5, 0, 0, -1, 0), 3, 0, 1, 0);           /* top cap */
    HIT(c, ray(0.5, -3, 0, 0, 1, 0), 3, 0, -1, 0);        /* bottom cap */
    HIT(c, ray(0, 1, 0, 1, 0, 0), 1, 1, 0, 0);            /* inside */
    MISS(c, ray(0, 3, -5, 0, 0, 1));                      /* above */
    MISS(c, ray(0, 1, 5, 0, 0, 1));                       /* behind */
    MISS(c, ray(1.001, 1, -5, 0, 0, 1));                  /* past tangent */
    rt_object open = c;
    open.caps = 0;
    CHECK_EQ(rt_object_prepare(&open), RT_OK);
    CHECK_EQ(open.convex, 1); /* its solid is convex: see render-model.md */
    MISS(open, ray(0, 5, 0, 0, -1, 0)); /* down the open axis */
    /* In through the open top, out to the inner wall at x = 1. */
    HIT(open, ray(0, 2.5, 0, 1, -1, 0), sqrt(2), 1, 0, 0);
}

static void cone_cases(void)
{
    rt_object k = make(RT_CONE, 0, 0, 0, 1, 2);
    CHECK_EQ(rt_object_prepare(&k), RT_OK);
    /* At y = 1 the radius is 0.5; normal (1, 0.5, 0)/|.| on the -z side. */
    double s = 1 / sqrt(1.25);
    HIT(k, ray(0, 1, -5, 0, 0, 1), 4.5, 0, 0.5 * s, -s);
    HIT(k, ray(0, -3, 0, 0, 1, 0), 3, 0, -1, 0);          /* base cap */
    MISS(k, ray(0, 2.5, -5, 0, 0, 1));                    /* above apex */
    MISS(k, ray(0.6, 1, -5, 0, 0, 1));                    /* outside */
    HIT(k, ray(0, 0.5, 0, 0, 0, 1), 0.75, 0, 0.5 * s, s); /* inside */
}

/* Random rays: hit/miss agrees with the sphere's double answer away from
 * the silhouette, and the hit point lies on the side facing the ray within
 * 2^-13 + 2^-15 t of the surface. The t-proportional part is the unit
 * direction's own quantisation (|d| = 1 +- 2^-16), not the intersection. */
static void random_spheres(void)
{
    uint32_t x = 12345;
    int bad_t = 0, bad_hit = 0, n = 0;
    for (int i = 0; i < 200000; i++) {
        x ^= x << 13; x ^= x >> 17; x ^= x << 5;
        double cx = (int)(x % 2001) / 100.0 - 10;
        x ^= x << 13; x ^= x >> 17; x ^= x << 5;
        double cz = (int)(x % 2001) / 10.0 + 5;
        x ^= x << 13; x ^= x >> 17; x ^= x << 5;
        double r = (int)(x % 1000) / 100.0 + 0.05;
        rt_object s = make(RT_SPHERE, cx, 0, cz, r, 0);
        rt_object_prepare(&s);
        x ^= x << 13; x ^= x >> 17; x ^= x << 5;
        double dx = ((int)(x % 2001) - 1000) / 2000.0;
        rt_ray ry = ray(0, 0, 0, dx, 0, 1);
        double l = sqrt(dx * dx + 1), ddx = dx / l, ddz = 1 / l;
        double ccx = F2D(s.u.sphere.center.x), ccz = F2D(s.u.sphere.center.z), rr = F2D(s.u.sphere.radius);
        double b = ccx * ddx + ccz * ddz;
        double hx = ccx - b * ddx, hz = ccz - b * ddz;
        double h2 = hx * hx + hz * hz, disc = rr * rr - h2;
        fx_t t;
        uint16_t part;
        int hit = rt_intersect(&s, &ry, RT_EPS, FX_MAX, &t, &part);
        n++;
        if (fabs(sqrt(h2) - rr) < 1e-3)
            continue; /* the silhouette: either answer is right */
        if (hit != (disc > 0)) {
            bad_hit++;
            continue;
        }
        if (hit) {
            /* The hit point lies on the surface, on the near side. */
            double px = F2D(ry.o.x) + F2D(t) * U2D(ry.d.x) - ccx;
            double pz = F2D(ry.o.z) + F2D(t) * U2D(ry.d.z) - ccz;
            double off = sqrt(px * px + pz * pz) - rr;
            /* Far side when starting inside, or when the near root lies
             * below t_min. */
            int inside = ccx * ccx + ccz * ccz < rr * rr ||
                         b - sqrt(disc) <= F2D(RT_EPS) + 1e-6;
            if (fabs(off) > 1.0 / 8192 + F2D(t) / 32768 ||
                (px * ddx + pz * ddz > 0) != inside)
                bad_t++;
        }
    }
    CHECK_EQ(bad_hit, 0);
    CHECK_EQ(bad_t, 0);
    printf("random sphere rays: %d, hit/miss disagreements %d, hit points "
           "off the surface beyond the bound: %d\n", n, bad_hit, bad_t);
}

/* Uniform in -1..1, from a xorshift state. */
static double unif(uint32_t *x)
{
    *x ^= *x << 13;
    *x ^= *x >> 17;
    *x ^= *x << 5;
    return (double)(*x % 2000001) / 1000000.0 - 1.0;
}

/* Random rays at random cylinders (radius 0.05 to 8), from outside and
 * inside: a side hit's normal (precise, as for a hit that casts secondary
 * rays) within 2^-24 / r of the true normal where the ray meets the side
 * where the cosine of the angle of incidence is 0.05 or more, within
 * 2^-20 / r down to 0.01, and the hit point within 0.5 Q16.16 ulps (plus
 * 2^-24) of that point. The normal from the rounded hit point is off by
 * 2^-17 / r and more near tangent: printed for comparison. */
static void random_cylinder_normals(void)
{
    uint32_t x = 777;
    double worst = 0, worst_graze = 0, worst_p = 0, worst_plain = 0;
    int n = 0, unprepared = 0;
    for (int i = 0; i < 200000; i++) {
        double r = 0.05 + 8.0 * (unif(&x) + 1) / 2;
        rt_object c = make(RT_CYLINDER, 3 * unif(&x), -2, 3 * unif(&x), r, 4);
        if (rt_object_prepare(&c) != RT_OK) {
            unprepared++;
            continue;
        }
        double ax = F2D(c.u.upright.base.x), az = F2D(c.u.upright.base.z), rr = F2D(c.u.upright.radius);
        /* From outside (i even) or inside, towards a point on the side. */
        double ang = 3.14159265 * unif(&x), u = 1.5 * unif(&x);
        double tx = ax + rr * cos(ang), ty = u, tz = az + rr * sin(ang);
        double ox = i & 1 ? ax + 0.5 * rr * unif(&x) : tx + 20 * unif(&x);
        double oz = i & 1 ? az + 0.5 * rr * unif(&x) : tz + 20 * unif(&x);
        double oy = 2 * unif(&x);
        rt_ray ry = ray(ox, oy, oz, tx - ox, ty - oy, tz - oz);
        fx_t t;
        uint16_t part;
        if (!rt_intersect(&c, &ry, RT_EPS, FX_MAX, &t, &part) || part != 0)
            continue;
        /* The fixed-point ray exactly, in double: its side root nearest
         * the core's t. */
        double rox = F2D(ry.o.x) - ax, roz = F2D(ry.o.z) - az;
        double dx = U2D(ry.d.x), dy = U2D(ry.d.y), dz = U2D(ry.d.z);
        double qa = dx * dx + dz * dz, qb = rox * dx + roz * dz;
        double qc = rox * rox + roz * roz - rr * rr;
        double disc = qb * qb - qa * qc;
        if (disc < 0)
            continue;
        double t0 = (-qb - sqrt(disc)) / qa, t1 = (-qb + sqrt(disc)) / qa;
        double te = fabs(t0 - F2D(t)) < fabs(t1 - F2D(t)) ? t0 : t1;
        double hx = rox + te * dx, hz = roz + te * dz;
        double cosi = fabs(hx * dx + hz * dz) / rr;
        if (cosi < 0.01)
            continue; /* within 0.01 of tangent */
        fx_vec3 p = fx_v3_madd_d(ry.o, ry.d, t);
        fx_dir3 plain = rt_normal(&c, &ry, t, &p, part, 0);
        fx_dir3 nrm = rt_normal(&c, &ry, t, &p, part, 1);
        double e =
            fmax(fabs(U2D(nrm.x) - hx / rr), fabs(U2D(nrm.z) - hz / rr));
        double ep = fmax(fabs(U2D(plain.x) - hx / rr),
                         fabs(U2D(plain.z) - hz / rr));
        double py = F2D(ry.o.y) + te * dy;
        double dp = fmax(fabs(F2D(p.y) - py),
                         fmax(fabs(F2D(p.x) - ax - hx),
                              fabs(F2D(p.z) - az - hz)));
        double en = (e + fabs(U2D(nrm.y))) * rr;
        if (cosi >= 0.05)
            worst = fmax(worst, en);
        else
            worst_graze = fmax(worst_graze, en);
        worst_plain = fmax(worst_plain, ep);
        worst_p = fmax(worst_p, dp);
        n++;
    }
    CHECK_EQ(unprepared, 0);
    CHECK(n > 100000);
    CHECK(worst < 1.0 / (1 << 24));
    CHECK(worst_graze < 1.0 / (1 << 20));
    CHECK(worst_p < 0.5 / 65536 + 1.0 / (1 << 24));
    printf("random cylinder side hits: %d, normal within %.3g / r (%.3g / r "
           "where the cosine is below 0.05; from the rounded hit point: "
           "%.3g), hit point within %.3f ulps\n",
           n, worst, worst_graze, worst_plain, worst_p * 65536);
}

/* Random rays at random cones (radius 0.05 to 8, radius / height 0.1 to
 * 16), from outside and inside, towards a point on the side between a
 * tenth and nine tenths of the way down from the apex: a side hit's
 * normal (precise) times the cone's radius rho there within 2^-22 where
 * the cosine of incidence is 0.05 or more (2^-19 down to 0.01), and the
 * hit point within 0.5 Q16.16 ulps (plus 2^-22) of the ray's true hit.
 * The normal from the rounded point is printed for comparison. */
static void random_cone_normals(void)
{
    uint32_t x = 4242;
    double worst = 0, worst_graze = 0, worst_p = 0, worst_plain = 0;
    int n = 0, unprepared = 0;
    for (int i = 0; i < 200000; i++) {
        double r = 0.05 + 8.0 * (unif(&x) + 1) / 2;
        double slope = exp(log(0.1) + (log(16) - log(0.1)) *
                                          (unif(&x) + 1) / 2);
        rt_object c = make(RT_CONE, 3 * unif(&x), -2, 3 * unif(&x), r,
                           r / slope);
        if (rt_object_prepare(&c) != RT_OK) {
            unprepared++;
            continue;
        }
        double ax = F2D(c.u.upright.base.x), az = F2D(c.u.upright.base.z), rr = F2D(c.u.upright.radius);
        double ya = F2D(c.u.upright.base.y) + F2D(c.u.upright.height), k = rr / F2D(c.u.upright.height);
        double f = 0.5 + 0.4 * unif(&x), ang = 3.14159265 * unif(&x);
        double tx = ax + rr * f * cos(ang), tz = az + rr * f * sin(ang);
        double ty = ya - F2D(c.u.upright.height) * f;
        double ox = i & 1 ? ax + 0.3 * rr * f * unif(&x) : tx + 20 * unif(&x);
        double oz = i & 1 ? az + 0.3 * rr * f * unif(&x) : tz + 20 * unif(&x);
        double oy = i & 1 ? ty - 0.1 * F2D(c.u.upright.height) * (unif(&x) + 1.5)
                          : ty + 20 * unif(&x);
        rt_ray ry = ray(ox, oy, oz, tx - ox, ty - oy, tz - oz);
        fx_t t;
        uint16_t part;
        if (!rt_intersect(&c, &ry, RT_EPS, FX_MAX, &t, &part) || part != 0)
            continue;
        /* The fixed-point ray exactly, in double: its side root (below
         * the apex) nearest the core's t. */
        double rox = F2D(ry.o.x) - ax, roy = F2D(ry.o.y) - ya;
        double roz = F2D(ry.o.z) - az;
        double dx = U2D(ry.d.x), dy = U2D(ry.d.y), dz = U2D(ry.d.z);
        double qa = dx * dx + dz * dz - k * k * dy * dy;
        double qb = rox * dx + roz * dz - k * k * roy * dy;
        double qc = rox * rox + roz * roz - k * k * roy * roy;
        double disc = qb * qb - qa * qc;
        if (disc < 0 || qa == 0)
            continue;
        double t0 = (-qb - sqrt(disc)) / qa, t1 = (-qb + sqrt(disc)) / qa;
        double te = fabs(t0 - F2D(t)) < fabs(t1 - F2D(t)) ? t0 : t1;
        double hx = rox + te * dx, hy = roy + te * dy, hz = roz + te * dz;
        double rho = sqrt(hx * hx + hz * hz);
        if (hy >= 0 || rho < 1e-3)
            continue;
        double nl = sqrt(hx * hx + hz * hz + k * k * rho * rho);
        double nx = hx / nl, ny = k * rho / nl, nz = hz / nl;
        double cosi = fabs(nx * dx + ny * dy + nz * dz);
        if (cosi < 0.01)
            continue; /* within 0.01 of tangent */
        fx_vec3 p = fx_v3_madd_d(ry.o, ry.d, t);
        fx_dir3 plain = rt_normal(&c, &ry, t, &p, part, 0);
        fx_dir3 nrm = rt_normal(&c, &ry, t, &p, part, 1);
        double e = fmax(fabs(U2D(nrm.x) - nx),
                        fmax(fabs(U2D(nrm.y) - ny), fabs(U2D(nrm.z) - nz)));
        double ep = fmax(fabs(U2D(plain.x) - nx),
                         fmax(fabs(U2D(plain.y) - ny),
                              fabs(U2D(plain.z) - nz)));
        double dp = fmax(fabs(F2D(p.y) - ya - hy),
                         fmax(fabs(F2D(p.x) - ax - hx),
                              fabs(F2D(p.z) - az - hz)));
        if (cosi >= 0.05)
            worst = fmax(worst, e * rho);
        else
            worst_graze = fmax(worst_graze, e * rho);
        worst_plain = fmax(worst_plain, ep * rho);
        worst_p = fmax(worst_p, dp);
        n++;
    }
    CHECK_EQ(unprepared, 0);
    CHECK(n > 100000);
    CHECK(worst < 1.0 / (1 << 22));
    CHECK(worst_graze < 1.0 / (1 << 19));
    CHECK(worst_p < 0.5 / 65536 + 1.0 / (1 << 22));
    printf("random cone side hits: %d, normal within %.3g / rho (%.3g / "
           "rho where the cosine is below 0.05; from the rounded hit point: "
           "%.3g), hit point within %.3f ulps\n",
           n, worst, worst_graze, worst_plain, worst_p * 65536);
}

/* Flat quads (rt_quad.flat, normal along y) take a short path in the
 * quad test: it must give what the general path gives, bit for bit, for
 * both edge orders, both normal signs, and rays from anywhere. */
static void flat_quads(void)
{
    uint64_t st = 0x9E3779B97F4A7C15ull;
    long n = 0, bad = 0, hits = 0, flats[3] = { 0, 0, 0 };
    for (int q = 0; q < 400; q++) {
        double sz = 0.01 * (double)(1 + th_rnd64(&st) % 4000);
        double cx = (double)(th_rnd64(&st) % 2001) - 1000.0;
        double cy = (double)(th_rnd64(&st) % 201) - 100.0;
        double cz = (double)(th_rnd64(&st) % 2001) - 1000.0;
        rt_object o = make(RT_QUAD, cx, cy, cz, 0, 0);
        double e1 = sz * (th_rnd64(&st) & 1 ? 1 : -1);
        double e2 = sz * 0.5 * (th_rnd64(&st) & 1 ? 1 : -1);
        int swap = (int)(th_rnd64(&st) & 1);
        o.u.quad.edge1 = swap ? fx_v3(D2F(e1), 0, 0) : fx_v3(0, 0, D2F(e1));
        o.u.quad.edge2 = swap ? fx_v3(0, 0, D2F(e2)) : fx_v3(D2F(e2), 0, 0);
        if (rt_object_prepare(&o) != RT_OK)
            continue;
        flats[o.u.quad.flat]++;
        rt_object g = o;
        g.u.quad.flat = 0;
        for (int k = 0; k < 500; k++) {
            double ox = cx + (double)(th_rnd64(&st) % 4001) / 100.0 - 20;
            double oy = cy + (double)(th_rnd64(&st) % 4001) / 100.0 - 20;
            double oz = cz + (double)(th_rnd64(&st) % 4001) / 100.0 - 20;
            /* A target on the quad's plane, in it or just past an edge. */
            double a = (double)(th_rnd64(&st) % 1201) / 1000.0 - 0.1;
            double b = (double)(th_rnd64(&st) % 1201) / 1000.0 - 0.1;
            double tx = cx + a * F2D(o.u.quad.edge1.x) + b * F2D(o.u.quad.edge2.x);
            double tz = cz + a * F2D(o.u.quad.edge1.z) + b * F2D(o.u.quad.edge2.z);
            rt_ray r = ray(ox, oy, oz, tx - ox, cy - oy + 1e-3, tz - oz);
            fx_t t1 = 0, t2 = 0;
            uint16_t p1 = 0, p2 = 0;
            int h1 = rt_intersect(&o, &r, RT_EPS, FX_MAX, &t1, &p1);
            int h2 = rt_intersect(&g, &r, RT_EPS, FX_MAX, &t2, &p2);
            n++;
            hits += h1;
            bad += h1 != h2 || (h1 && (t1 != t2 || p1 != p2));
        }
    }
    CHECK_EQ(bad, 0);
    CHECK(flats[1] > 50 && flats[2] > 50 && hits > 100000);
    printf("flat quads: %ld rays (%ld hits) on %ld + %ld quads, %ld differ "
           "from the general path\n", n, hits, flats[1], flats[2], bad);
}

/* fx_udiv64_32 against the compiler's 64-bit division. */
static void division(void)
{
    uint64_t x = 88172645463325252ull;
    long bad = 0, n = 0;
    for (int i = 0; i < 1000000; i++) {
        x ^= x << 13; x ^= x >> 7; x ^= x << 17;
        uint32_t d = (uint32_t)(x >> (x & 31));
        if (d == 0)
            d = 1;
        x ^= x << 13; x ^= x >> 7; x ^= x << 17;
        uint64_t num = x % ((uint64_t)d << 32); /* quotient < 2^32 */
        if (i % 7 == 0)
            num = ((uint64_t)d << 32) - 1 - (x & 0xFF);
        n++;
        bad += fx_udiv64_32(num, d) != (uint32_t)(num / d);
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(fx_udiv64_32(0, 1), 0);
    CHECK_EQ(fx_udiv64_32(((uint64_t)0xFFFFFFFFu << 32) - 1, 0xFFFFFFFFu),
             0xFFFFFFFFu); /* the largest dividend allowed */
    CHECK_EQ(fx_udiv64_32(((uint64_t)1 << 32) - 1, 1), 0xFFFFFFFFu);
    printf("fx_udiv64_32: %ld random divisions, %ld wrong\n", n, bad);
}

int main(void)
{
    division();
    sphere_cases();
    quad_cases();
    flat_quads();
    box_cases();
    cylinder_cases();
    cone_cases();
    random_spheres();
    random_cylinder_normals();
    random_cone_normals();
    return th_summary();
}
