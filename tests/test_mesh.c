/* SPDX-License-Identifier: MIT */
/*
 * Triangle meshes: the watertightness of the fixed-point ray/triangle
 * test on closed meshes (an icosphere and a torus), and the hierarchy's
 * traversal against every hit the test reports.
 *
 * Over a million rays: random rays through the meshes' boxes, rays aimed
 * at vertices and at points of edges (within rounding), and axis-aligned
 * rays that pass exactly through vertices and edge midpoints. For each
 * ray every triangle hit is listed (rt_mesh_tri_hit on the candidates of
 * a conservative double traversal). Sorted along the ray, the hits of a
 * ray from outside a closed mesh must alternate entering (front) and
 * leaving (back), starting with an entry: a ray slipping through an edge
 * leaves an entry without its exit, a double hit two entries in a row.
 * Rays aimed into the surface must hit. rt_mesh_hit must return the
 * nearest of the listed hits exactly.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "mesh_build.h"
#include "rt_shape.h"

#define F2D(x) ((double)(x) / 65536.0)

typedef struct {
    const char *name;
    rt_object o;
    rt_mesh *m;
    double scale; /* a typical size, for the origin offsets */
} test_mesh;

typedef struct {
    fx_t t;
    int side;
} hit;

static unsigned n_hits;
static hit hits[256];

static int box_near(const rt_mesh *m, const rt_mesh_node *nd, const double o[3],
                    const double d[3])
{
    const double base[3] = {F2D(m->lo.x), F2D(m->lo.y), F2D(m->lo.z)};
    const double q = ldexp(1.0, m->qshift) / 65536.0, pad = 1e-3;
    double tn = -1e30, tf = 1e30;
    for (int i = 0; i < 3; i++) {
        const double lo = base[i] + nd->box[i] * q - pad;
        const double hi = base[i] + nd->box[3 + i] * q + pad;
        if (fabs(d[i]) < 1e-12) {
            if (o[i] < lo || o[i] > hi)
                return 0;
            continue;
        }
        double t1 = (lo - o[i]) / d[i], t2 = (hi - o[i]) / d[i];
        if (t1 > t2) {
            const double x = t1;
            t1 = t2;
            t2 = x;
        }
        if (t1 > tn)
            tn = t1;
        if (t2 < tf)
            tf = t2;
    }
    return tn <= tf && tf >= -pad;
}

/* Every triangle hit with t > 0, into hits[]. */
static void all_hits(const rt_mesh *m, const rt_ray *r)
{
    const double o[3] = {F2D(r->o.x), F2D(r->o.y), F2D(r->o.z)};
    const double d[3] = {(double)r->d.x / FX_UONE, (double)r->d.y / FX_UONE,
                         (double)r->d.z / FX_UONE};
    unsigned stack[64], sp = 0;
    n_hits = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const rt_mesh_node *nd = &m->node[stack[--sp]];
        if (!box_near(m, nd, o, d))
            continue;
        if (nd->n == 0) {
            stack[sp++] = nd->a;
            stack[sp++] = (unsigned)(nd - m->node) + 1;
            continue;
        }
        for (unsigned k = nd->a; k < (unsigned)nd->a + nd->n; k++) {
            const uint16_t *ix = &m->tri[3 * k];
            fx_t t;
            int side;
            if (rt_mesh_tri_hit(m->v[ix[0]], m->v[ix[1]], m->v[ix[2]], r, 0,
                                FX_MAX, &t, &side) &&
                n_hits < 256) {
                hits[n_hits].t = t;
                hits[n_hits++].side = side;
            }
        }
    }
}

static int cmp_hit(const void *a, const void *b)
{
    const hit *x = a, *y = b;
    if (x->t != y->t)
        return x->t < y->t ? -1 : 1;
    return y->side - x->side; /* an entry before an exit at the same t */
}

static long rays_fired, bad_order, missed, nearest_wrong;

/* Fires one ray from (ox, oy, oz) along (dx, dy, dz) (exact Q16.16 and
 * unit components when raw is set) and checks its hits. */
static void fire(const test_mesh *tm, fx_vec3 o, fx_dir3 d, int must_hit)
{
    rt_ray r;
    rt_ray_set(&r, o, d);
    all_hits(tm->m, &r);
    qsort(hits, n_hits, sizeof hits[0], cmp_hit);
    int ok = n_hits % 2 == 0;
    for (unsigned i = 0; ok && i < n_hits; i++)
        ok = hits[i].side == (i % 2 == 0 ? 1 : -1);
    rays_fired++;
    if (!ok && bad_order++ < 5) {
        printf("    %s: hits out of order from (%d %d %d) along (%d %d %d):",
               tm->name, o.x, o.y, o.z, d.x, d.y, d.z);
        for (unsigned i = 0; i < n_hits; i++)
            printf(" %d%c", hits[i].t, hits[i].side > 0 ? 'F' : 'B');
        printf("\n");
    }
    if (must_hit && n_hits == 0 && missed++ < 5)
        printf("    %s: missed from (%d %d %d) along (%d %d %d)\n", tm->name,
               o.x, o.y, o.z, d.x, d.y, d.z);
    fx_t t = 0;
    uint16_t tri = 0;
    const int h = rt_mesh_hit(&tm->o, &r, 0, FX_MAX, &t, &tri);
    if ((h != (n_hits > 0) || (h && t != hits[0].t)) && nearest_wrong++ < 5)
        printf("    %s: rt_mesh_hit %d t %d, listed %u first %d\n", tm->name,
               h, t, n_hits, n_hits ? hits[0].t : 0);
}

static double rnd(uint64_t *s)
{
    return (double)(th_rnd64(s) >> 11) / 9007199254740992.0;
}

static fx_dir3 unit_of(double x, double y, double z)
{
    const double l = sqrt(x * x + y * y + z * z);
    return fx_d3((int32_t)lround(x / l * FX_UONE),
                 (int32_t)lround(y / l * FX_UONE),
                 (int32_t)lround(z / l * FX_UONE));
}

static fx_vec3 q16v(double x, double y, double z)
{
    return fx_v3((fx_t)lround(x * 65536), (fx_t)lround(y * 65536),
                 (fx_t)lround(z * 65536));
}

/* A ray aimed at point p (double) from just outside, against a direction
 * near the inward normal -n. */
static void fire_at(const test_mesh *tm, const double p[3], const double n[3],
                    uint64_t *s)
{
    double d[3];
    for (int i = 0; i < 3; i++)
        d[i] = -n[i] + (rnd(s) - 0.5);
    const fx_dir3 u = unit_of(d[0], d[1], d[2]);
    const double dist = tm->scale * (0.02 + 0.03 * rnd(s));
    const double ud[3] = {(double)u.x / FX_UONE, (double)u.y / FX_UONE,
                          (double)u.z / FX_UONE};
    /* The origin rounded; then the direction from it to p exactly. */
    const fx_vec3 o = q16v(p[0] - dist * ud[0], p[1] - dist * ud[1],
                           p[2] - dist * ud[2]);
    fire(tm, o,
         unit_of(p[0] - F2D(o.x), p[1] - F2D(o.y), p[2] - F2D(o.z)), 1);
}

static void vnorm(const rt_mesh *m, unsigned i, double n[3])
{
    n[0] = (double)m->vn[i].x / FX_UONE;
    n[1] = (double)m->vn[i].y / FX_UONE;
    n[2] = (double)m->vn[i].z / FX_UONE;
}

static void run_mesh(test_mesh *tm, long rays, uint64_t seed)
{
    const rt_mesh *m = tm->m;
    uint64_t s = seed;
    const double c[3] = {F2D(tm->o.bc.x), F2D(tm->o.bc.y), F2D(tm->o.bc.z)};
    const double R = F2D(tm->o.br);
    for (long k = 0; k < rays; k++) {
        const int mode = (int)(k % 4);
        if (mode == 0) { /* from afar through the box */
            double a = rnd(&s) * 6.283185307179586, z = 2 * rnd(&s) - 1;
            double w = sqrt(1 - z * z);
            const fx_vec3 o = q16v(c[0] + 3 * R * w * cos(a),
                                   c[1] + 3 * R * w * sin(a), c[2] + 3 * R * z);
            double p[3];
            for (int i = 0; i < 3; i++)
                p[i] = c[i] + R * (2 * rnd(&s) - 1) * 0.7;
            fire(tm, o,
                 unit_of(p[0] - F2D(o.x), p[1] - F2D(o.y), p[2] - F2D(o.z)),
                 0);
        } else if (mode == 1) { /* at a vertex */
            const unsigned i = (unsigned)(th_rnd64(&s) % m->n_verts);
            double p[3] = {F2D(m->v[i].x), F2D(m->v[i].y), F2D(m->v[i].z)};
            double n[3];
            vnorm(m, i, n);
            fire_at(tm, p, n, &s);
        } else if (mode == 2) { /* at a point of an edge */
            const unsigned t = (unsigned)(th_rnd64(&s) % m->n_tris);
            const unsigned j = (unsigned)(th_rnd64(&s) % 3);
            const unsigned a = m->tri[3 * t + j], b = m->tri[3 * t + (j + 1) % 3];
            const double l = rnd(&s);
            double p[3], n[3], na[3], nb[3];
            vnorm(m, a, na);
            vnorm(m, b, nb);
            const fx_t va[3] = {m->v[a].x, m->v[a].y, m->v[a].z};
            const fx_t vb[3] = {m->v[b].x, m->v[b].y, m->v[b].z};
            for (int i = 0; i < 3; i++) {
                p[i] = F2D(va[i]) + l * (F2D(vb[i]) - F2D(va[i]));
                n[i] = na[i] + nb[i];
            }
            fire_at(tm, p, n, &s);
        } else { /* exactly through a vertex or an edge midpoint */
            const unsigned t = (unsigned)(th_rnd64(&s) % m->n_tris);
            const unsigned j = (unsigned)(th_rnd64(&s) % 3);
            const unsigned a = m->tri[3 * t + j], b = m->tri[3 * t + (j + 1) % 3];
            const int axis = (int)(th_rnd64(&s) % 3);
            const int mid = (int)(th_rnd64(&s) & 1);
            int64_t pa[3] = {m->v[a].x, m->v[a].y, m->v[a].z};
            const int64_t pb[3] = {m->v[b].x, m->v[b].y, m->v[b].z};
            const int32_t na[3] = {m->vn[a].x, m->vn[a].y, m->vn[a].z};
            const int32_t nb[3] = {m->vn[b].x, m->vn[b].y, m->vn[b].z};
            const int32_t lim = FX_UONE / 2;
            int sgn = na[axis] > 0 ? 1 : -1;
            if (na[axis] > -lim && na[axis] < lim)
                continue; /* grazing: not a ray that must hit */
            if (mid) {
                if ((nb[axis] > 0 ? 1 : -1) != sgn ||
                    (nb[axis] > -lim && nb[axis] < lim))
                    continue;
                int ok = 1;
                for (int i = 0; i < 3; i++) {
                    if (i != axis && ((pa[i] + pb[i]) & 1))
                        ok = 0;
                    pa[i] = i == axis ? (pa[i] > pb[i]) == (sgn > 0) ? pa[i]
                                                                     : pb[i]
                                      : (pa[i] + pb[i]) / 2;
                }
                if (!ok)
                    continue;
            }
            pa[axis] += sgn * (int64_t)(tm->scale * 65536 * 0.03);
            int32_t dv[3] = {0, 0, 0};
            dv[axis] = -sgn * FX_UONE;
            fire(tm, fx_v3((fx_t)pa[0], (fx_t)pa[1], (fx_t)pa[2]),
                 fx_d3(dv[0], dv[1], dv[2]), 1);
        }
    }
}

/* Each directed edge once, its reverse once: closed and consistently
 * oriented; and the enclosed volume positive (outward faces). */
static void check_closed(const rt_mesh *m, const char *name)
{
    const unsigned ne = 3u * m->n_tris;
    uint64_t *e = malloc(ne * sizeof *e);
    double vol = 0;
    for (unsigned t = 0; t < m->n_tris; t++) {
        const uint16_t *ix = &m->tri[3 * t];
        for (int j = 0; j < 3; j++)
            e[3 * t + j] = ((uint64_t)ix[j] << 16) | ix[(j + 1) % 3];
        const fx_vec3 a = m->v[ix[0]], b = m->v[ix[1]], c = m->v[ix[2]];
        const double ax = F2D(a.x), ay = F2D(a.y), az = F2D(a.z);
        const double bx = F2D(b.x), by = F2D(b.y), bz = F2D(b.z);
        const double cx = F2D(c.x), cy = F2D(c.y), cz = F2D(c.z);
        vol += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) +
               az * (bx * cy - by * cx);
    }
    unsigned bad = 0;
    for (unsigned k = 0; k < ne; k++) {
        const uint64_t rev = ((e[k] & 0xFFFF) << 16) | (e[k] >> 16);
        unsigned same = 0, back = 0;
        for (unsigned q = 0; q < ne && ne <= 20000; q++) {
            same += e[q] == e[k];
            back += e[q] == rev;
        }
        bad += same != 1 || back != 1;
        if (k > 3000)
            break; /* a sample is enough for the larger meshes */
    }
    free(e);
    if (!CHECK(bad == 0 && vol > 0))
        printf("    %s: %u open or doubled edges, volume %g\n", name, bad,
               vol / 6);
}

static test_mesh make_at(const char *name, int torus, double scale,
                         double dx, double dy, double dz);

static test_mesh make(const char *name, int torus, double scale)
{
    return make_at(name, torus, scale, 0, 0, 0);
}

/* A mesh thousands of units from the rays' origins, where the vertices
 * are shifted before projecting (s > 0): rays from near the world's
 * origin aimed at its vertices and at points of its edges must hit it
 * (no listing here: rt_mesh_tri_hit is for near meshes). */
static long far_missed;
static void run_far(const test_mesh *tm, long rays, uint64_t seed)
{
    const rt_mesh *m = tm->m;
    uint64_t s = seed;
    for (long k = 0; k < rays; k++) {
        const unsigned t = (unsigned)(th_rnd64(&s) % m->n_tris);
        const unsigned j = (unsigned)(th_rnd64(&s) % 3);
        const unsigned a = m->tri[3 * t + j], b = m->tri[3 * t + (j + 1) % 3];
        const double l = (k & 1) ? rnd(&s) : 0.0;
        const fx_t va[3] = {m->v[a].x, m->v[a].y, m->v[a].z};
        const fx_t vb[3] = {m->v[b].x, m->v[b].y, m->v[b].z};
        double p[3];
        for (int i = 0; i < 3; i++)
            p[i] = F2D(va[i]) + l * (F2D(vb[i]) - F2D(va[i]));
        const fx_vec3 o = q16v(100 * (rnd(&s) - 0.5), 100 * (rnd(&s) - 0.5),
                               100 * (rnd(&s) - 0.5));
        rt_ray r;
        rt_ray_set(&r, o, unit_of(p[0] - F2D(o.x), p[1] - F2D(o.y),
                                  p[2] - F2D(o.z)));
        /* Not near the silhouette, where a ray may graze past. */
        double na[3], nb[3], da = 0, db = 0;
        vnorm(m, a, na);
        vnorm(m, b, nb);
        const double dd[3] = {(double)r.d.x / FX_UONE,
                              (double)r.d.y / FX_UONE,
                              (double)r.d.z / FX_UONE};
        for (int i = 0; i < 3; i++) {
            da += na[i] * dd[i];
            db += nb[i] * dd[i];
        }
        if (fabs(da) < 0.3 || fabs(db) < 0.3)
            continue;
        fx_t th;
        uint16_t tri;
        rays_fired++;
        if (!rt_mesh_hit(&tm->o, &r, 0, FX_MAX, &th, &tri) &&
            far_missed++ < 5)
            printf("    %s: missed from (%d %d %d) along (%d %d %d)\n",
                   tm->name, o.x, o.y, o.z, r.d.x, r.d.y, r.d.z);
    }
}

static test_mesh make_at(const char *name, int torus, double scale,
                         double dx, double dy, double dz)
{
    test_mesh tm;
    fx_vec3 *v;
    fx_dir3 *vn;
    uint32_t *tri;
    unsigned nv, nt;
    char msg[128];
    int rc = torus ? mesh_torus(1.0 * scale, 0.4 * scale, 48, 24, &v, &vn,
                                &nv, &tri, &nt)
                   : mesh_icosphere(scale, 3, &v, &vn, &nv, &tri, &nt);
    memset(&tm, 0, sizeof tm);
    tm.name = name;
    tm.scale = torus ? 0.4 * scale : scale;
    CHECK(rc == 0);
    for (unsigned i = 0; rc == 0 && i < nv; i++)
        v[i] = fx_v3(v[i].x + (fx_t)lround(dx * 65536),
                     v[i].y + (fx_t)lround(dy * 65536),
                     v[i].z + (fx_t)lround(dz * 65536));
    tm.m = mesh_build(v, nv, vn, tri, nt, msg, sizeof msg);
    if (!CHECK(tm.m != NULL))
        printf("    %s\n", msg);
    free(v);
    free(vn);
    free(tri);
    tm.o.kind = RT_MESH;
    tm.o.u.mesh.tables = tm.m;
    CHECK_EQ(rt_object_prepare(&tm.o), RT_OK);
    return tm;
}

/* A flat grid of side x side vertices, 1/16 apart in the plane y = 0,
 * and its first n triangles (two a cell, counter-clockwise from above). */
static rt_mesh *grid(unsigned side, unsigned n, char *msg, size_t cap)
{
    fx_vec3 *v = malloc(side * side * sizeof *v);
    uint32_t *tri = malloc(3u * 2 * (side - 1) * (side - 1) * sizeof *tri);
    rt_mesh *m = NULL;
    if (CHECK(v && tri && n <= 2 * (side - 1) * (side - 1))) {
        for (unsigned z = 0; z < side; z++)
            for (unsigned x = 0; x < side; x++)
                v[z * side + x] = fx_v3((fx_t)(x << 12), 0, (fx_t)(z << 12));
        unsigned k = 0;
        for (unsigned z = 0; z + 1 < side; z++)
            for (unsigned x = 0; x + 1 < side; x++) {
                const uint32_t a = z * side + x, b = a + 1, c = a + side,
                               d = c + 1;
                const uint32_t t[6] = {a, c, b, b, c, d};
                memcpy(&tri[k], t, sizeof t);
                k += 6;
            }
        m = mesh_build(v, side * side, NULL, tri, n, msg, cap);
    }
    free(v);
    free(tri);
    return m;
}

/* The documented limit, RT_MESH_MAX triangles (scene-format.md): a mesh
 * of exactly that many builds, within the 16-bit node indices, passes the
 * core's check and is hit where it lies; one more is refused by name. */
static void test_limit(void)
{
    char msg[160];
    const unsigned counts[] = {65522, RT_MESH_MAX};
    for (int i = 0; i < 2; i++) {
        rt_mesh *m = grid(183, counts[i], msg, sizeof msg);
        if (!CHECK(m != NULL)) {
            printf("    %u triangles: %s\n", counts[i], msg);
            continue;
        }
        CHECK_EQ(m->n_tris, counts[i]);
        CHECK(m->n_nodes <= RT_MESH_MAX);
        rt_object o;
        memset(&o, 0, sizeof o);
        o.kind = RT_MESH;
        o.u.mesh.tables = m;
        CHECK_EQ(rt_object_prepare(&o), RT_OK);
        /* Straight down onto the middle of a cell: t = 5 exactly. */
        rt_ray r;
        rt_ray_set(&r, q16v(5.03125, 5, 5.03125), fx_d3(0, -FX_UONE, 0));
        fx_t t = 0;
        uint16_t tri = 0;
        CHECK_EQ(rt_mesh_hit(&o, &r, 0, FX_MAX, &t, &tri), 1);
        CHECK_EQ(t, FX_INT(5));
        mesh_free(m);
    }
    rt_mesh *m = grid(183, RT_MESH_MAX + 1, msg, sizeof msg);
    CHECK(m == NULL);
    CHECK(strstr(msg, "at most 65535") != NULL);
    mesh_free(m);
}

int main(void)
{
    test_limit();
    test_mesh ms[2];
    ms[0] = make("icosphere", 0, 1.0);
    ms[1] = make("torus", 1, 1.0);
    for (int i = 0; i < 2; i++)
        check_closed(ms[i].m, ms[i].name);
    /* 1,000,000 rays or more, half on each mesh. */
    run_mesh(&ms[0], 600000, 1);
    run_mesh(&ms[1], 600000, 2);
    /* A mesh away from the origin, and a larger one. */
    test_mesh far = make("far icosphere", 0, 3.0);
    run_mesh(&far, 40000, 3);
    /* 12,000 units away in x and y: a shift of 1 or 2 bits. */
    test_mesh away = make_at("distant icosphere", 0, 40.0, 9000, 9000, 0);
    run_far(&away, 20000, 4);
    printf("    %ld rays: %ld out of order, %ld missed, %ld nearest wrong, "
           "%ld missed the distant mesh\n",
           rays_fired, bad_order, missed, nearest_wrong, far_missed);
    CHECK_EQ(far_missed, 0);
    mesh_free(away.m);
    CHECK(rays_fired >= 1000000);
    CHECK_EQ(bad_order, 0);
    CHECK_EQ(missed, 0);
    CHECK_EQ(nearest_wrong, 0);
    for (int i = 0; i < 2; i++)
        mesh_free(ms[i].m);
    mesh_free(far.m);
    return th_summary();
}
