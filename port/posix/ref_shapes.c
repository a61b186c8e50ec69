/* SPDX-License-Identifier: MIT */
/*
 * ref_shapes: the reference renderer's shapes in plain double (the
 * "Shapes" section of docs/render-model.md): the set-up from rt_object's
 * primary fields, and each shape's ray intersection and outward normal.
 * The formulas are the textbook ones, not the fixed-point core's
 * rearrangements.
 */
#include <math.h>
#include <string.h>
#include "ref_internal.h"
#include "rt_mesh.h"

void ref_shape_from_object(const rt_object *obj, ref_shape *sh)
{
    const unsigned both = RT_CAP_BOTTOM | RT_CAP_TOP;
    memset(sh, 0, sizeof *sh);
    sh->kind = obj->kind;
    sh->caps = obj->caps & both;
    sh->a = fxv(obj->u.origin); /* every kind's first point */
    switch (sh->kind) {
    case RT_SPHERE:
        sh->r = fxd(obj->u.sphere.radius);
        break;
    case RT_QUAD:
        sh->b = fxv(obj->u.quad.edge1);
        sh->c = fxv(obj->u.quad.edge2);
        break;
    case RT_BOX:
        sh->b = fxv(obj->u.box.max);
        break;
    case RT_CYLINDER:
    case RT_CONE:
        sh->r = fxd(obj->u.upright.radius);
        sh->h = fxd(obj->u.upright.height);
        break;
    default: /* RT_MESH */
        sh->mesh = obj->u.mesh.tables;
        break;
    }
    if (sh->kind == RT_CONE)
        sh->caps &= RT_CAP_BOTTOM; /* a cone has no top cap */
    /* Every shape bounds a convex solid (an open cylinder or cone too):
     * a ray leaving its outside cannot meet it again. A mesh need not. */
    sh->convex = sh->kind != RT_MESH;
}

/* Keeps t if it is a nearer acceptable hit than *best. */
static int closer(double t, double tmin, double best)
{
    return t > tmin && t < best;
}

/* Roots of A t^2 + 2 B t + C = 0 given disc = B^2 - A C >= 0, computed
 * without cancellation; a root that does not exist is -1 (never accepted). */
static void stable_roots(double A, double B, double C, double disc,
                         double *t0, double *t1)
{
    double q = -(B + copysign(sqrt(disc), B));
    *t0 = A != 0 ? q / A : -1.0;
    *t1 = q != 0 ? C / q : -1.0;
}

static int hit_sphere(const ref_shape *s, vec o, vec d, double tmax,
                      ref_hit *hit)
{
    /* Geometric form (Ray Tracing Gems, ch. 7): the discriminant comes
     * from the distance of the centre to the line, not from b^2 - c. */
    vec f = sub(o, s->a);
    double b = -dot(f, d);
    vec perp = madd(f, d, b); /* f - (f.d) d */
    double disc = s->r * s->r - dot(perp, perp);
    double c = dot(f, f) - s->r * s->r;
    double t0, t1, t = tmax;
    if (disc < 0)
        return 0;
    stable_roots(1.0, -b, c, disc, &t0, &t1);
    if (closer(t0, REF_EPS, t))
        t = t0;
    if (closer(t1, REF_EPS, t))
        t = t1;
    if (!(t < tmax))
        return 0;
    hit->t = t;
    hit->n_out = scale(sub(madd(o, d, t), s->a), 1.0 / s->r);
    return 1;
}

static int hit_quad(const ref_shape *s, vec o, vec d, double tmax,
                    ref_hit *hit)
{
    vec N = cross(s->b, s->c), n = norm(N);
    double denom = dot(d, n);
    double t, nn = dot(N, N), u, v;
    vec w;
    if (fabs(denom) < REF_PAR)
        return 0; /* parallel to the plane */
    t = dot(sub(s->a, o), n) / denom;
    if (!closer(t, REF_EPS, tmax))
        return 0;
    /* Solve w = u e1 + v e2 in the plane. */
    w = sub(madd(o, d, t), s->a);
    u = dot(cross(w, s->c), N) / nn;
    v = dot(cross(s->b, w), N) / nn;
    if (u < 0 || u > 1 || v < 0 || v > 1)
        return 0;
    hit->t = t;
    hit->n_out = n;
    return 1;
}

static int hit_box(const ref_shape *s, vec o, vec d, double tmax,
                   ref_hit *hit)
{
    double tn = -HUGE_VAL, tf = HUGE_VAL, dn = 0, df = 0;
    int an = -1, af = -1, i;
    for (i = 0; i < 3; i++) {
        double oi = comp(o, i), di = comp(d, i);
        double lo = comp(s->a, i), hi = comp(s->b, i), t1, t2;
        if (fabs(di) < REF_PAR) { /* parallel to both faces of the slab */
            if (oi < lo || oi > hi)
                return 0;
            continue;
        }
        t1 = (lo - oi) / di;
        t2 = (hi - oi) / di;
        if (t1 > t2) {
            double tmp = t1;
            t1 = t2;
            t2 = tmp;
        }
        if (t1 > tn) {
            tn = t1;
            an = i;
            dn = di;
        }
        if (t2 < tf) {
            tf = t2;
            af = i;
            df = di;
        }
    }
    if (tn > tf)
        return 0;
    if (an >= 0 && closer(tn, REF_EPS, tmax)) {
        hit->t = tn; /* entering face: its normal opposes d */
        hit->n_out = axis_vec(an, dn > 0 ? -1.0 : 1.0);
        return 1;
    }
    if (af >= 0 && closer(tf, REF_EPS, tmax)) {
        hit->t = tf; /* exit face, seen from inside: normal along d */
        hit->n_out = axis_vec(af, df > 0 ? 1.0 : -1.0);
        return 1;
    }
    return 0;
}

/* A horizontal disc of radius r centred at c, facing ny (+1 or -1). */
static void hit_disc(vec c, double r, double ny, vec o, vec d, double *best,
                     ref_hit *hit)
{
    double t, x, z;
    if (fabs(d.y) < REF_PAR)
        return; /* parallel to the cap's plane */
    t = (c.y - o.y) / d.y;
    if (!closer(t, REF_EPS, *best))
        return;
    x = o.x + t * d.x - c.x;
    z = o.z + t * d.z - c.z;
    if (x * x + z * z > r * r)
        return;
    *best = t;
    hit->n_out = v3(0, ny, 0);
}

/* The side root t is on the surface part ay <= y <= ay + h. */
static int in_height(const ref_shape *s, vec o, vec d, double t)
{
    double y = o.y + t * d.y;
    return y >= s->a.y && y <= s->a.y + s->h;
}

static int hit_cylinder(const ref_shape *s, vec o, vec d, double tmax,
                        ref_hit *hit)
{
    double best = tmax, px = o.x - s->a.x, pz = o.z - s->a.z;
    double A = d.x * d.x + d.z * d.z;
    /* The side is parallel to the ray when the ray's horizontal part is
     * below PAR: then |d . n| < PAR for every side normal n. */
    if (sqrt(A) >= REF_PAR) {
        double B = px * d.x + pz * d.z, C = px * px + pz * pz - s->r * s->r;
        double fx = px - (B / A) * d.x, fz = pz - (B / A) * d.z;
        double disc = A * (s->r * s->r - (fx * fx + fz * fz));
        double t[2];
        int i;
        if (disc >= 0) {
            stable_roots(A, B, C, disc, &t[0], &t[1]);
            for (i = 0; i < 2; i++) {
                if (closer(t[i], REF_EPS, best) && in_height(s, o, d, t[i])) {
                    best = t[i];
                    hit->n_out = norm(v3(px + t[i] * d.x, 0, pz + t[i] * d.z));
                }
            }
        }
    }
    if (s->caps & RT_CAP_BOTTOM)
        hit_disc(s->a, s->r, -1.0, o, d, &best, hit);
    if (s->caps & RT_CAP_TOP)
        hit_disc(v3(s->a.x, s->a.y + s->h, s->a.z), s->r, 1.0, o, d, &best,
                 hit);
    if (!(best < tmax))
        return 0;
    hit->t = best;
    return 1;
}

static int hit_cone(const ref_shape *s, vec o, vec d, double tmax,
                    ref_hit *hit)
{
    /* |(x, z) - axis|^2 = k^2 Y^2 with Y = ay + h - y the depth below the
     * apex; along the ray Y = Y0 - t dy. */
    double k = s->r / s->h, k2 = k * k, best = tmax;
    double px = o.x - s->a.x, pz = o.z - s->a.z, Y0 = s->a.y + s->h - o.y;
    double A = d.x * d.x + d.z * d.z - k2 * d.y * d.y;
    double B = px * d.x + pz * d.z + k2 * Y0 * d.y;
    double C = px * px + pz * pz - k2 * Y0 * Y0;
    double disc = B * B - A * C, t[2];
    int i;
    if (disc >= 0) {
        /* A = 0 (ray along a generator) leaves the one root C / q. */
        stable_roots(A, B, C, disc, &t[0], &t[1]);
        for (i = 0; i < 2; i++) {
            if (closer(t[i], REF_EPS, best) && in_height(s, o, d, t[i])) {
                double x = px + t[i] * d.x, z = pz + t[i] * d.z;
                double rho = sqrt(x * x + z * z);
                best = t[i];
                hit->n_out = rho == 0 ? v3(0, 1, 0) : norm(v3(x, k * rho, z));
            }
        }
    }
    if (s->caps & RT_CAP_BOTTOM)
        hit_disc(s->a, s->r, -1.0, o, d, &best, hit);
    if (!(best < tmax))
        return 0;
    hit->t = best;
    return 1;
}

int ref_intersect(const ref_shape *sh, ref_vec3 o, ref_vec3 d, double tmax,
                  ref_hit *hit)
{
    switch (sh->kind) {
    case RT_SPHERE:
        return hit_sphere(sh, o, d, tmax, hit);
    case RT_QUAD:
        return hit_quad(sh, o, d, tmax, hit);
    case RT_BOX:
        return hit_box(sh, o, d, tmax, hit);
    case RT_CYLINDER:
        return hit_cylinder(sh, o, d, tmax, hit);
    case RT_CONE:
        return hit_cone(sh, o, d, tmax, hit);
    case RT_MESH:
        return ref_mesh_hit(sh, o, d, tmax, hit);
    default:
        return 0;
    }
}

int ref_shape_ok(const ref_shape *sh)
{
    switch (sh->kind) {
    case RT_SPHERE:
        return sh->r > 0;
    case RT_QUAD:
        return len(cross(sh->b, sh->c)) > 0;
    case RT_BOX:
        return sh->b.x > sh->a.x && sh->b.y > sh->a.y && sh->b.z > sh->a.z;
    case RT_MESH:
        return sh->mesh != NULL && sh->mesh->n_tris > 0;
    default:
        return sh->r > 0 && sh->h > 0;
    }
}
