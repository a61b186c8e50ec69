/* SPDX-License-Identifier: MIT */
/* Stability cases: tangents, ray origins, tiny and huge shapes, watertight
 * edges. */
#include "stability.h"

/* ==== Tangents and grazing rays ========================================== */

/* A ray that touches a sphere (discriminant exactly 0) is a hit at the
 * touching point, t = 5, with the normal (0, 1, 0); one ulp outside misses,
 * one ulp inside hits within sqrt(2^-15) of the touching point. */
void case_tangent_sphere_exact(void)
{
    rt_object s = sphere(0, 0, 5, 1);
    rt_ray r = ray_raw(V(0, 1, 0), V(0, 0, 1));
    double t;
    uint16_t part;
    if (CHECK(cast(&s, &r, &t, &part))) {
        CHECK(fabs(t - 5) <= 1.0 / 65536);
        CHECK(nerr(normal_at(&s, &r, t, part), 0, 1, 0) < 1e-4);
    }
    rt_ray out = ray_raw(fx_v3(0, FX_ONE + 1, 0), V(0, 0, 1));
    MISS(s, out);
    rt_ray in = ray_raw(fx_v3(0, FX_ONE - 1, 0), V(0, 0, 1));
    HIT_AT(s, in, 5 - sqrt(2.0 / 65536), 1.0 / 8192);
    /* Oblique rays along (0.6, 0, 0.8) pass 0.6 from the centre in the
     * xz-plane, so they touch the sphere at height 0.8: swept across that
     * height, they agree with double from 16 ulps off and beyond. */
    sweep(&s, V(-3, 0.8, 0), fx_v3(0, 1, 0), V(0.6, 0, 0.8), 64, 16,
          1.0 / 64);
}

/* Tangent to the cylinder's side (x = r): within 8 ulps of the tangent
 * line either answer is right; beyond, hit or miss agrees with double and
 * t agrees to 1/64 (the half chord grows as the square root of the
 * offset). */
void case_tangent_cylinder_side(void)
{
    rt_object c = upright(RT_CYLINDER, 0, 0, 5, 1, 2);
    sweep(&c, V(1, 1, 0), fx_v3(1, 0, 0), V(0, 0, 1), 64, 8, 1.0 / 64);
    /* The same across a tilted ray. */
    sweep(&c, V(1, 0.2, 0), fx_v3(1, 0, 0), V(0, 0.28, 0.96), 64, 8,
          1.0 / 64);
}

/* Tangent to the cone's side at height 0.5 (radius 0.5 there), level and
 * descending: as for the cylinder, agreement with double from 8 ulps off
 * the tangent line. */
void case_tangent_cone_side(void)
{
    rt_object k = upright(RT_CONE, 0, 0, 5, 1, 1);
    sweep(&k, V(0.5, 0.5, 0), fx_v3(1, 0, 0), V(0, 0, 1), 64, 8, 1.0 / 64);
    /* And a descending ray in the tangent plane at (0.5, 0.5, 5) (normal
     * along (1, 1, 0)), swept along that normal. */
    sweep(&k, V(0.5 - 5 * 0.42426407, 0.5 + 5 * 0.42426407, 1),
          fx_v3(1, 1, 0), V(0.42426407, -0.42426407, 0.8), 64, 8, 1.0 / 64);
}

/* A ray with d.n of exactly 1 ulp (= PAR, so not parallel) 0.01 above a big
 * floor quad hits it at t = 0.01 / 2^-16 = 655.36; 3 ulps gives 218.45.
 * d.n = 0 is parallel: a miss. From 1 unit above, d.n = -1 ulp would need
 * t = 65536, beyond the range: a miss, never a wrapped small t. */
void case_grazing_quad_dn_1ulp(void)
{
    rt_object q = quad(V(-1000, 0, -1000), V(0, 0, 2000), V(2000, 0, 0));
    rt_ray r1 = ray_raw(V(0, 0.01, 0), fx_v3(FX_ONE, -1, 0));
    HIT_AT(q, r1, F2D(D2F(0.01)) * 65536, 1.0 / 16);
    rt_ray r3 = ray_raw(V(0, 0.01, 0), fx_v3(FX_ONE, -3, 0));
    HIT_AT(q, r3, F2D(D2F(0.01)) * 65536 / 3, 1.0 / 16);
    rt_ray r0 = ray_raw(V(0, 0.01, 0), fx_v3(FX_ONE, 0, 0));
    MISS(q, r0);
    rt_ray far = ray_raw(V(0, 1, 0), fx_v3(FX_ONE, -1, 0));
    MISS(q, far);
    rt_ray in_plane = ray_raw(V(0, 0, 0), fx_v3(FX_ONE, -1, 0));
    MISS(q, in_plane);
}

/* d.n within a few ulps of 0 on a tilted quad (normal (0, -0.6, -0.8)):
 * the core and double agree on hit or miss and on t (relative 2^-10)
 * whenever |d.n| is not within 1 ulp of PAR, where either is right. */
void case_plane_parallel_few_ulps(void)
{
    rt_object q = quad(V(-50, -40, -30), V(100, 0, 0), V(0, -80, 60));
    fx_dir3 n = q.u.quad.normal;
    /* A direction in the plane: n x (1, 0, 0), then tilted by k ulps of
     * Q16.16 (the PAR threshold is 2^-16). */
    fx_dir3 in = fx_d3_cross_unit(fx_d3_raw(n), fx_v3(FX_ONE, 0, 0));
    const int32_t ulp = (int32_t)1 << FX_USHIFT;
    for (int k = -6; k <= 6; k++) {
        fx_dir3 d = fx_d3(in.x, in.y + k * ulp, in.z);
        rt_ray r;
        rt_ray_set(&r, V(0, 0.001, 0.0), d);
        int64_t dn = fx_d3_dot_raw(d, n);
        double t, tr;
        int h = cast(&q, &r, &t, NULL), hr = cast_ref(&q, &r, &tr, NULL);
        if (llabs(llabs(dn) - RT_PAR_DOT) <= RT_PAR_DOT)
            continue; /* on the PAR boundary: either answer */
        if (!CHECK(h == hr))
            printf("    k = %d, d.n = %g: core %d, reference %d\n", k,
                   (double)dn / 4.0 / (double)((int64_t)1 << (2 * FX_UBITS - 2)), h, hr);
        else if (h && !CHECK(fabs(t - tr) <= tr / 1024))
            printf("    k = %d: t %.4f, reference %.4f\n", k, t, tr);
    }
}

/* Rays along +z at y = 1 + k ulps past the top face of a box (y <= 1):
 * above the face (k > 0) they miss, below it (k < 0) they hit the front
 * face at t = 4, as the reference does. In the face's plane (k = 0) the
 * box is closed, so the ray hits, as it does in the plane of the bottom
 * face (y = -1): the two faces behave alike. Nearly grazing rays (d.y a
 * few ulps) agree with double. */
void case_grazing_box_face(void)
{
    rt_object b = box(-1, -1, 4, 1, 1, 6);
    for (int k = -3; k <= 3; k++) {
        rt_ray r = ray_raw(fx_v3(0, FX_ONE + k, 0), V(0, 0, 1));
        if (k > 0)
            MISS(b, r);
        else if (k < 0)
            HIT_AT(b, r, 4, 1.0 / 65536);
        else
            HIT_AT(b, r, 4, 1.0 / 65536); /* in the face's plane */
        rt_ray low = ray_raw(fx_v3(0, -FX_ONE + k, 0), V(0, 0, 1));
        if (k < 0)
            MISS(b, low);
        else
            HIT_AT(b, low, 4, 1.0 / 65536);
    }
    for (int k = 1; k <= 4; k++) {
        /* From (0, 1 + 0.05, 0) descending by k ulps per unit. */
        rt_ray r = ray_raw(V(0, 1.05, 0), fx_v3(0, -k, FX_ONE));
        double t, tr;
        int h = cast(&b, &r, &t, NULL), hr = cast_ref(&b, &r, &tr, NULL);
        if (CHECK(h == hr) && h)
            CHECK(fabs(t - tr) < 1.0 / 256);
    }
    /* A ray parallel to a face inside its slab is unconstrained by it. */
    rt_ray inside = ray_raw(V(0, 0.999, 0), V(0, 0, 1));
    HIT_AT(b, inside, 4, 1.0 / 65536);
}

/* Rays parallel to a cylinder's axis just inside its side (r - k ulps, k =
 * 1..4) hit the top cap at t = 1; an open cylinder lets them through.
 * Outside by 16 ulps and more they miss (within a few ulps of the rim the
 * cap may reach past the side by a couple of frame ulps, which keeps the
 * rim watertight). A ray grazing the side along z agrees with double 8
 * ulps away from the tangent. */
void case_grazing_cylinder_side(void)
{
    rt_object c = upright(RT_CYLINDER, 0, 0, 0, 1, 2);
    rt_object open = c;
    open.caps = 0;
    CHECK_EQ(rt_object_prepare(&open), RT_OK);
    for (int k = 1; k <= 4; k++) {
        rt_ray in = ray_raw(fx_v3(FX_ONE - k, FX_INT(3), 0), V(0, -1, 0));
        rt_ray out = ray_raw(fx_v3(FX_ONE + 16 * k, FX_INT(3), 0),
                             V(0, -1, 0));
        HIT_AT(c, in, 1, 1.0 / 8192);
        MISS(c, out);
        MISS(open, in);
    }
    sweep(&c, V(1, 1.5, -4), fx_v3(1, 0, 0), V(0, 0.01, 1), 48, 8, 1.0 / 64);
}

/* A ray parallel to one of the cone's generators (the quadratic's leading
 * coefficient is 0): 0.01 outside it misses, 0.02 inside it enters through
 * the base cap (from below) and meets the side once; both as double. */
void case_grazing_cone_generator(void)
{
    rt_object k = upright(RT_CONE, 0, 0, 0, 1, 1);
    /* Generator from (1, 0, 0) to the apex (0, 1, 0): direction (-1, 1). */
    fx_vec3 d = V(-0.70710678, 0.70710678, 0);
    double t, tr;
    rt_ray out = ray_raw(V(1.5 + 0.01, -0.5, 0), d);
    CHECK_EQ(cast(&k, &out, &t, NULL), cast_ref(&k, &out, &tr, NULL));
    MISS(k, out);
    rt_ray in = ray_raw(V(1.5 - 0.02, -0.5, 0), d);
    int h = cast(&k, &in, &t, NULL), hr = cast_ref(&k, &in, &tr, NULL);
    CHECK(h && hr);
    if (h && hr && !CHECK(fabs(t - tr) < 1.0 / 256))
        printf("    t %.6f, reference %.6f\n", t, tr);
    /* A sweep across the generator line, 16 ulps of certainty. */
    sweep(&k, V(1.5, -0.5, 0), fx_v3(1, 0, 0), d, 48, 16, 1.0 / 64);
    /* From inside the cone along a generator direction (the leading
     * coefficient is exactly 0: one root) it meets the far side at
     * (-0.15, 0.85, 0), t = 0.65 sqrt 2, as the reference does. */
    rt_ray along = ray_raw(V(0.5, 0.2, 0), fx_v3(-46341, 46341, 0));
    HIT_AT(k, along, 0.65 * sqrt(2), 1.0 / 1024);
}

/* ==== Ray origins on a surface =========================================== */

/* From a point on a sphere: outward misses (the root at t = 0 is below
 * EPS), inward hits the far side at t = 2, along the tangent plane misses
 * (both roots are within EPS of 0). */
void case_origin_on_sphere(void)
{
    rt_object s = sphere(0, 0, 5, 1);
    rt_ray out = ray_raw(V(0, 0, 4), V(0, 0, -1));
    rt_ray in = ray_raw(V(0, 0, 4), V(0, 0, 1));
    rt_ray tan = ray_raw(V(0, 0, 4), V(1, 0, 0));
    MISS(s, out);
    HIT_AT(s, in, 2, 1.0 / 8192);
    MISS(s, tan);
}

/* From a point in a quad's plane, any direction misses: t = 0 <= EPS. */
void case_origin_on_quad(void)
{
    rt_object q = quad(V(-1, 0, -1), V(0, 0, 2), V(2, 0, 0));
    rt_ray down = ray(0.3, 0, 0.2, 0.1, -1, 0.2);
    rt_ray up = ray(0.3, 0, 0.2, 0.1, 1, 0.2);
    rt_ray along = ray(0.3, 0, 0.2, 1, 0, 0);
    MISS(q, down);
    MISS(q, up);
    MISS(q, along);
}

/* From a point on a box face: outward misses; inward hits the opposite
 * face at t = 2; from an edge and from a corner inward along the diagonal
 * the exit is the opposite edge or corner. */
void case_origin_on_box_face(void)
{
    rt_object b = box(-1, -1, 4, 1, 1, 6);
    rt_ray out = ray_raw(V(1, 0, 5), V(1, 0, 0));
    rt_ray in = ray_raw(V(1, 0, 5), V(-1, 0, 0));
    rt_ray edge = ray(1, 1, 5, -1, -1, 0);
    rt_ray corner = ray(1, 1, 6, -1, -1, -1);
    MISS(b, out);
    HIT_AT(b, in, 2, 1.0 / 65536);
    HIT_AT(b, edge, 2 * sqrt(2), 1.0 / 4096);
    HIT_AT(b, corner, 2 * sqrt(3), 1.0 / 4096);
}

/* From a point on a cylinder's top rim: outward and upward miss; inward and
 * down it meets the far side or the bottom cap as double does. */
void case_origin_on_cylinder_rim(void)
{
    rt_object c = upright(RT_CYLINDER, 0, 0, 0, 1, 2);
    rt_ray out = ray(1, 2, 0, 1, 0.5, 0);
    rt_ray up = ray(1, 2, 0, 0, 1, 0);
    MISS(c, out);
    MISS(c, up);
    const double dirs[][3] = { { -1, -0.5, 0 }, { -1, -2, 0 },
                               { -1, -0.2, 0.3 }, { -0.2, -1, 0.1 } };
    for (int i = 0; i < 4; i++) {
        rt_ray r = ray(1, 2, 0, dirs[i][0], dirs[i][1], dirs[i][2]);
        double t, tr;
        int h = cast(&c, &r, &t, NULL), hr = cast_ref(&c, &r, &tr, NULL);
        if (CHECK(h && hr) && !CHECK(fabs(t - tr) < 1.0 / 1024))
            printf("    dir %d: t %.6f, reference %.6f\n", i, t, tr);
    }
}

/* ==== Tiny shapes ======================================================== */

/* A sphere of radius 3 ulps one unit away: the axial ray hits at exactly
 * t = 1 - 3 ulps with normal (0, 0, -1); 2 ulps off the axis hits, 4 ulps
 * off misses (|h|^2 = 16 > 9, exact in 64 bits). */
void case_tiny_sphere_3ulp(void)
{
    rt_object s = obj(RT_SPHERE, 0, 0, 1);
    s.u.sphere.radius = 3;
    CHECK_EQ(rt_object_prepare(&s), RT_OK);
    rt_ray r = ray_raw(fx_v3(0, 0, 0), fx_v3(0, 0, FX_ONE));
    double t;
    uint16_t part;
    if (CHECK(cast(&s, &r, &t, &part))) {
        CHECK_EQ(D2F(t), FX_ONE - 3);
        CHECK(nerr(normal_at(&s, &r, t, part), 0, 0, -1) < 1e-4);
    }
    rt_ray near = ray_raw(fx_v3(2, 0, 0), fx_v3(0, 0, FX_ONE));
    rt_ray off = ray_raw(fx_v3(4, 0, 0), fx_v3(0, 0, FX_ONE));
    HIT_AT(s, near, 1, 4.0 / 65536);
    MISS(s, off);
}

/* A cylinder and a cone of radius and height 4 ulps: straight down the
 * axis from y = 1 the cylinder's top cap is at t = 1 - 4 ulps and the
 * cone's apex too (normal (0, 1, 0) there); sideways through the middle the
 * cylinder's side is 4 ulps before the axis. 6 ulps off the axis both
 * miss. */
void case_tiny_upright_4ulp(void)
{
    rt_object c = obj(RT_CYLINDER, 0, 0, 0), k = obj(RT_CONE, 0, 0, 0);
    c.u.upright.radius = c.u.upright.height = 4;
    k.u.upright.radius = k.u.upright.height = 4;
    CHECK_EQ(rt_object_prepare(&c), RT_OK);
    CHECK_EQ(rt_object_prepare(&k), RT_OK);
    rt_ray down = ray_raw(fx_v3(0, FX_ONE, 0), fx_v3(0, -FX_ONE, 0));
    double t;
    uint16_t part;
    if (CHECK(cast(&c, &down, &t, &part))) {
        CHECK_NEAR(D2F(t), FX_ONE - 4, 1);
        CHECK(nerr(normal_at(&c, &down, t, part), 0, 1, 0) < 1e-4);
    }
    if (CHECK(cast(&k, &down, &t, &part))) {
        CHECK_NEAR(D2F(t), FX_ONE - 4, 1);
        CHECK(nerr(normal_at(&k, &down, t, part), 0, 1, 0) < 1e-4);
    }
    rt_ray side = ray_raw(fx_v3(-FX_ONE, 2, 0), fx_v3(FX_ONE, 0, 0));
    if (CHECK(cast(&c, &side, &t, &part))) {
        CHECK_NEAR(D2F(t), FX_ONE - 4, 1);
        CHECK(nerr(normal_at(&c, &side, t, part), -1, 0, 0) < 1e-4);
    }
    rt_ray off = ray_raw(fx_v3(6, FX_ONE, 0), fx_v3(0, -FX_ONE, 0));
    MISS(c, off);
    MISS(k, off);
}

/* A quad with 1-ulp edges still has a unit normal (from the exact 64-bit
 * cross product); a ray through its far corner hits (edges are inclusive),
 * 3 ulps past it misses (quads may reach a couple of ulps past their edges
 * so that neighbours leave no crack). A box 1 ulp on a side: its far
 * corner hits, one ulp past misses. (The bounding sphere that culls rays
 * first must not be smaller than the shape.) */
void case_tiny_quad_box_1ulp(void)
{
    rt_object q = quad(fx_v3(0, 0, FX_ONE), fx_v3(1, 0, 0), fx_v3(0, 1, 0));
    CHECK(nerr(q.u.quad.normal, 0, 0, 1) < 1e-4);
    rt_ray corner = ray_raw(fx_v3(1, 1, 0), fx_v3(0, 0, FX_ONE));
    rt_ray past = ray_raw(fx_v3(4, 1, 0), fx_v3(0, 0, FX_ONE));
    HIT_AT(q, corner, 1, 1.0 / 65536);
    MISS(q, past);
    past = ray_raw(fx_v3(2, 1, 0), fx_v3(0, 0, FX_ONE));
    rt_object b = obj(RT_BOX, 0, 0, 0);
    b.u.box.min = fx_v3(0, 0, FX_ONE);
    b.u.box.max = fx_v3(1, 1, FX_ONE + 1);
    CHECK_EQ(rt_object_prepare(&b), RT_OK);
    HIT_AT(b, corner, 1, 1.0 / 65536);
    MISS(b, past);
}

/* ==== Huge coordinates =================================================== */

/* Near +-32767 nothing wraps:
 * - a sphere 63900 units away is beyond the far plane: a miss;
 * - a unit sphere at (30000, 30000, 30000) seen from 10 units is hit at
 *   exactly t = 9;
 * - a box spanning the whole range, from inside: the exit face at
 *   32766.99 is hit; at exactly FX_MAX (t = t_max) it is not;
 * - a hit point beyond the range saturates at FX_MAX (madd), not wraps. */
void case_huge_coords_saturate(void)
{
    rt_object far = sphere(32000, 0, 0, 100);
    rt_ray r = ray_raw(V(-32000, 0, 0), V(1, 0, 0));
    MISS(far, r);
    rt_ray back = ray_raw(V(-32000, 0, 0), V(-1, 0, 0));
    MISS(far, back);
    rt_object s = sphere(30000, 30000, 30000, 1);
    rt_ray r2 = ray_raw(V(29990, 30000, 30000), V(1, 0, 0));
    HIT_AT(s, r2, 9, 0);
    rt_object all = obj(RT_BOX, 0, 0, 0);
    all.u.box.min = fx_v3(FX_MIN, FX_MIN, FX_MIN);
    all.u.box.max = fx_v3(FX_MAX, FX_MAX, FX_MAX);
    CHECK_EQ(rt_object_prepare(&all), RT_OK);
    rt_ray in = ray_raw(V(1, 0, 0), V(1, 0, 0));
    HIT_AT(all, in, F2D(FX_MAX) - 1, 1.0 / 65536);
    rt_ray edge = ray_raw(V(0, 0, 0), V(1, 0, 0));
    MISS(all, edge);
    rt_ray diag = ray(-30000, -30000, -30000, 1, 1, 1);
    MISS(all, diag); /* exit 60000 * sqrt(3) away */
    fx_vec3 p = fx_v3_madd(V(32000, -32000, 0), V(1, -1, 0), FX_INT(30000));
    CHECK_EQ(p.x, FX_MAX);
    CHECK_EQ(p.y, FX_MIN);
}

/* ==== Watertight edges =================================================== */

uint32_t rng_state = 2463534242u;

double rnd(void) /* uniform in [0, 1) */
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return (rng_state >> 8) / 16777216.0;
}

/* Casts a ray at point p (jittered by up to +-jitter/2 per axis) from
 * direction -d at distance 3: returns 1 on a hit near p (t < 3.25; a ray
 * that slips through the surface meets the far side much later), and
 * counts in *bad_t a hit farther than tol from t = 3. */
static int aim(const rt_object *o, double px, double py, double pz,
               double dx, double dy, double dz, double jitter, double tol,
               int *bad_t)
{
    double l = sqrt(dx * dx + dy * dy + dz * dz);
    dx /= l, dy /= l, dz /= l;
    px += (rnd() - 0.5) * jitter;
    py += (rnd() - 0.5) * jitter;
    pz += (rnd() - 0.5) * jitter;
    rt_ray r = ray(px - 3 * dx, py - 3 * dy, pz - 3 * dz, dx, dy, dz);
    double t;
    if (!cast(o, &r, &t, NULL) || t > 3.25)
        return 0;
    *bad_t += fabs(t - 3) > tol;
    return 1;
}

/* Rays that enter a capped cylinder through its rim (both the cap and the
 * side face them) must hit one or the other: no ray slips between them to
 * the far side. 4000 rays at the top and bottom rims, aimed within +-4
 * ulps of the rim; every one hits there, at t within 2^-10. */
void case_cylinder_cap_rim_watertight(void)
{
    rt_object c = upright(RT_CYLINDER, 0.3, -0.7, 0.2, 1.25, 2.5);
    int miss = 0, bad_t = 0;
    for (int i = 0; i < 2000; i++) {
        double ph = rnd() * 6.283185307179586, cx = cos(ph), cz = sin(ph);
        double px = 0.3 + 1.25 * cx, pz = 0.2 + 1.25 * cz;
        double e = rnd() + 0.2; /* the inward-down slope varies */
        miss += !aim(&c, px, 1.8, pz, -cx, -e, -cz, 8.0 / 65536,
                     1.0 / 1024, &bad_t);
        miss += !aim(&c, px, -0.7, pz, -cx, e, -cz, 8.0 / 65536, 1.0 / 1024,
                     &bad_t);
    }
    if (!CHECK(miss == 0 && bad_t == 0))
        printf("    %d misses, %d hits off the rim\n", miss, bad_t);
}

/* aim() for rays through a cone's apex: a hit before the far side, at
 * the reference's t for the same ray within tol (a ray barely steeper
 * than the side enters well below the apex when it passes beside it). */
static int aim_apex(const rt_object *o, double dx, double dy, double dz,
                    double tol, int *bad_t)
{
    double l = sqrt(dx * dx + dy * dy + dz * dz), t, tr;
    double px = -0.4 + (rnd() - 0.5) * 8.0 / 65536;
    double py = 2.1 + (rnd() - 0.5) * 8.0 / 65536;
    double pz = 0.6 + (rnd() - 0.5) * 8.0 / 65536;
    dx /= l, dy /= l, dz /= l;
    rt_ray r = ray(px - 3 * dx, py - 3 * dy, pz - 3 * dz, dx, dy, dz);
    if (!cast(o, &r, &t, NULL) || t > 3.25)
        return 0;
    int ok = cast_ref(o, &r, &tr, NULL) && fabs(t - tr) <= tol;
    if (!ok && verbose)
        printf("    apex ray: t %.7f, reference %.7f\n", t, tr);
    *bad_t += !ok;
    return 1;
}

/* The same at the rim of a cone's base cap (t within 2^-10), and at its
 * apex: rays steeper than the side that pass within 4 ulps of the apex
 * must hit there, not slip through to the base cap, at the reference's t
 * within 2^-14. The apex is a double root of the cone's quadratic, whose
 * rounding moved such a hit by up to 2% of this cone's height along the
 * ray; a ray passing that near is solved again about the apex in a finer
 * frame (rt_upright.c, thin_side). Straight down the axis the normal
 * there is (0, 1, 0). */
void case_cone_apex_and_rim(void)
{
    rt_object k = upright(RT_CONE, -0.4, 0.1, 0.6, 1, 2);
    int miss = 0, bad_t = 0, apex_miss = 0, apex_bad_t = 0;
    for (int i = 0; i < 2000; i++) {
        double ph = rnd() * 6.283185307179586, cx = cos(ph), cz = sin(ph);
        double e = rnd() + 0.2;
        miss += !aim(&k, -0.4 + cx, 0.1, 0.6 + cz, -cx, e, -cz, 8.0 / 65536,
                     1.0 / 1024, &bad_t);
        /* Apex at (-0.4, 2.1, 0.6); the side slopes at r / h = 0.5, so a
         * ray steeper than 2 (down per sideways) enters through it. */
        double s = rnd() * 0.45;
        apex_miss += !aim_apex(&k, s * cx, -1, s * cz, 1.0 / 16384,
                               &apex_bad_t);
    }
    if (!CHECK(miss == 0 && bad_t == 0))
        printf("    rim: %d rays slipped through, %d hits off the rim\n",
               miss, bad_t);
    if (!CHECK(apex_miss == 0 && apex_bad_t == 0))
        printf("    apex: %d rays slipped through, %d hits off the "
               "reference's by more than 2^-14\n", apex_miss, apex_bad_t);
    rt_ray axis = ray(-0.4, 5, 0.6, 0, -1, 0);
    double t;
    uint16_t part;
    if (CHECK(cast(&k, &axis, &t, &part))) {
        CHECK(fabs(t - 2.9) < 1.0 / 8192);
        CHECK(nerr(normal_at(&k, &axis, t, part), 0, 1, 0) < 1e-3);
    }
}

/* A camera looking down at a cone's apex from slightly off its axis: the
 * centre pixel's ray (an odd-sized image) aims 0.001 below the apex on
 * the axis, so it enters the cone within 0.001 of the apex (the exact apex
 * is singular in double too). It must show the cone's lit surface like its
 * neighbours and the reference, not the inside of the base cap through a
 * hole at the apex nor a point deep inside: the centre pixel within 64
 * levels of the reference, and no speckles. */
void case_cone_apex_centre_pixel(void)
{
    if (!parse("camera eye 0.35 5 -0.15 look 0 1.999 0 fov 20\n"
               "background 0.2 0.3 0.4\n"
               "light 1 6 -1\n"
               "material a color 0.8 0.5 0.3 specular 0\n"
               "cone base 0 0 0 radius 1 height 2 material a\n", &scene_a))
        return;
    ppm_image fx, ref;
    view vw = { 33, 33, 1, -1, 0 };
    render(&scene_a, vw, 0, &fx, NULL);
    render(&scene_a, vw, 1, &ref, NULL);
    if (!CHECK(pdiff(pix(&fx, 16, 16), pix(&ref, 16, 16)) <= LEVEL))
        printf("    centre pixel %d %d %d, reference %d %d %d\n",
               pix(&fx, 16, 16)[0], pix(&fx, 16, 16)[1], pix(&fx, 16, 16)[2],
               pix(&ref, 16, 16)[0], pix(&ref, 16, 16)[1],
               pix(&ref, 16, 16)[2]);
    CHECK_EQ(count_speckles(&fx, &ref), 0);
    ppm_free(&fx);
    ppm_free(&ref);
}

/* Rays entering a box through an edge or a corner (both or all three faces
 * face the ray) must hit it, at t within 2^-12. */
void case_box_edges_watertight(void)
{
    rt_object b = box(-1.1, -0.6, 2.3, 0.9, 1.7, 3.1);
    int miss = 0, bad_t = 0;
    for (int i = 0; i < 3000; i++) {
        double sx = rnd() < 0.5 ? -1 : 1, sy = rnd() < 0.5 ? -1 : 1;
        double sz = rnd() < 0.5 ? -1 : 1, u = rnd();
        double x = sx < 0 ? -1.1 : 0.9, y = sy < 0 ? -0.6 : 1.7;
        double z = sz < 0 ? 2.3 : 3.1;
        double dx = -sx * (0.2 + rnd()), dy = -sy * (0.2 + rnd());
        double dz = -sz * (0.2 + rnd());
        switch (i % 4) { /* an edge along x, y or z, or a corner */
        case 0: x = -1.1 + 2 * u; dx = rnd() - 0.5; break;
        case 1: y = -0.6 + 2.3 * u; dy = rnd() - 0.5; break;
        case 2: z = 2.3 + 0.8 * u; dz = rnd() - 0.5; break;
        default: break;
        }
        miss += !aim(&b, x, y, z, dx, dy, dz, 2.0 / 65536, 1.0 / 4096,
                     &bad_t);
    }
    if (!CHECK(miss == 0 && bad_t == 0))
        printf("    %d misses, %d hits off the edge\n", miss, bad_t);
}

/* Counts crack rays through the shared edge of q1 and q2 (aimed at
 * corner + s * edge for random s, from random directions): rays that miss
 * both quads although the reference, given the same quantised ray, hits
 * one of them. */
static int seam_cracks(const rt_object *q1, const rt_object *q2,
                       fx_vec3 corner, fx_vec3 edge, double dist, int *n)
{
    int crack = 0;
    *n = 0;
    for (int i = 0; i < 5000; i++) {
        double s = rnd();
        double px = F2D(corner.x) + s * F2D(edge.x);
        double py = F2D(corner.y) + s * F2D(edge.y);
        double pz = F2D(corner.z) + s * F2D(edge.z);
        double dx = rnd() - 0.5, dy = rnd() - 0.5, dz = 0.5 + rnd();
        double l = sqrt(dx * dx + dy * dy + dz * dz);
        rt_ray r = ray(px - dist * dx / l, py - dist * dy / l,
                       pz - dist * dz / l, dx, dy, dz);
        double t;
        if (fabs(F2D(fx_d3_dot(r.d, q1->u.quad.normal))) < 0.05)
            continue; /* too grazing for the plane to matter */
        (*n)++;
        if (cast(q1, &r, &t, NULL) || cast(q2, &r, &t, NULL))
            continue;
        if (!cast_ref(q1, &r, &t, NULL) && !cast_ref(q2, &r, &t, NULL))
            continue; /* passes outside the hinge's edge: a miss */
        if (verbose && crack < 4)
            printf("    crack: o (%d %d %d) d (%d %d %d)\n", r.o.x, r.o.y,
                   r.o.z, r.d.x, r.d.y, r.d.z);
        crack++;
    }
    return crack;
}

/* Two quads that share an edge exactly (the second's corner is the first's
 * corner + edge1, in exact integers): in one tilted plane, and as a hinge
 * at an angle; about 2, 16 and 128 units in size, each seen from 2 and
 * from 20 times its size. A ray through the shared edge that the
 * reference sees hit one of them must hit one in the core too: no cracks
 * between adjacent quads. */
void case_quad_seam_no_crack(void)
{
    for (int scale = 1; scale <= 64; scale *= 8) {
        fx_vec3 a = V(-1.3, 0.2, 4.1), e1 = V(1.7, 0.3, 0.4);
        fx_vec3 e2 = V(0.2, 1.9, -0.7), e1b = V(1.1, 0.1, 0.9);
        a = fx_v3(a.x * scale, a.y * scale, a.z * scale);
        e1 = fx_v3(e1.x * scale, e1.y * scale, e1.z * scale);
        e2 = fx_v3(e2.x * scale, e2.y * scale, e2.z * scale);
        e1b = fx_v3(e1b.x * scale, e1b.y * scale, e1b.z * scale);
        fx_vec3 e1c = fx_v3(e1.x / 2, e1.y / 2, e1.z / 2);
        rt_object hinge1 = quad(a, e1, e2);
        rt_object hinge2 = quad(fx_v3_add(a, e1), e1b, e2);
        rt_object flat1 = quad(a, e1c, e2);
        rt_object flat2 = quad(fx_v3_add(a, e1c), e1c, e2);
        for (int far = 0; far < 2; far++) {
            double dist = (far ? 40.0 : 4.0) * scale;
            int n, nf;
            int c = seam_cracks(&hinge1, &hinge2, fx_v3_add(a, e1), e2,
                                dist, &n);
            int cf = seam_cracks(&flat1, &flat2, fx_v3_add(a, e1c), e2,
                                 dist, &nf);
            if (!CHECK(c == 0 && cf == 0) || verbose)
                printf("    size x%d from %g: hinge %d of %d rays cracked, "
                       "plane %d of %d\n", scale, dist, c, n, cf, nf);
        }
    }
}

