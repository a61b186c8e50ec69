/* SPDX-License-Identifier: MIT */
/*
 * ref_mesh: the reference renderer's triangle meshes in plain double,
 * kept apart from the core's: the Moller-Trumbore test on each triangle
 * (no shear, no integer edge functions), and for speed its own boxes
 * around runs of consecutive triangles (the core stores them in leaf
 * order, so a run is compact), not the core's hierarchy. The normal is
 * the face's, or with vertex normals their barycentric blend.
 */
#include <stdlib.h>
#include <string.h>

#include "ref_internal.h"
#include "rt_mesh.h"

/* Triangles per box, and boxes per group box (a group's box holds its
 * boxes, so a ray that misses it misses every triangle in it). */
#define RUN 8
#define GROUP 8

struct ref_mesh_boxes {
    unsigned n;
    vec (*lo), (*hi); /* n boxes, box k around triangles k*RUN.. */
    vec (*glo), (*ghi); /* (n + GROUP - 1) / GROUP groups of boxes */
};

static vec vert(const rt_mesh *m, unsigned i) { return fxv(m->v[i]); }

int ref_mesh_setup(ref_shape *sh)
{
    const rt_mesh *m = sh->mesh;
    const unsigned n = (m->n_tris + RUN - 1) / RUN;
    struct ref_mesh_boxes *b = malloc(sizeof *b);
    if (!b)
        return -1;
    const unsigned ng = (n + GROUP - 1) / GROUP;
    b->n = n;
    b->lo = malloc(n * sizeof *b->lo);
    b->hi = malloc(n * sizeof *b->hi);
    b->glo = malloc(ng * sizeof *b->glo);
    b->ghi = malloc(ng * sizeof *b->ghi);
    sh->boxes = b;
    if (!b->lo || !b->hi || !b->glo || !b->ghi) {
        ref_mesh_release(sh);
        return -1;
    }
    for (unsigned k = 0; k < n; k++) {
        vec lo = v3(HUGE_VAL, HUGE_VAL, HUGE_VAL), hi = scale(lo, -1.0);
        for (unsigned t = k * RUN; t < m->n_tris && t < (k + 1) * RUN; t++)
            for (int j = 0; j < 3; j++) {
                const vec p = vert(m, m->tri[3 * t + j]);
                lo = v3(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
                hi = v3(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
            }
        b->lo[k] = lo;
        b->hi[k] = hi;
        if (k % GROUP == 0) {
            b->glo[k / GROUP] = lo;
            b->ghi[k / GROUP] = hi;
        }
        lo = b->glo[k / GROUP];
        hi = b->ghi[k / GROUP];
        b->glo[k / GROUP] = v3(fmin(lo.x, b->lo[k].x),
                               fmin(lo.y, b->lo[k].y),
                               fmin(lo.z, b->lo[k].z));
        b->ghi[k / GROUP] = v3(fmax(hi.x, b->hi[k].x),
                               fmax(hi.y, b->hi[k].y),
                               fmax(hi.z, b->hi[k].z));
    }
    return 0;
}

void ref_mesh_release(ref_shape *sh)
{
    if (sh->boxes) {
        free(sh->boxes->lo);
        free(sh->boxes->hi);
        free(sh->boxes->glo);
        free(sh->boxes->ghi);
        free(sh->boxes);
        sh->boxes = NULL;
    }
}

/* Slab test, padded by a micro-unit. */
static int box_meets(vec lo, vec hi, vec o, vec inv, double tmax)
{
    const double pad = 1e-6;
    double tn = 0, tf = tmax;
    for (int i = 0; i < 3; i++) {
        const double a = (comp(lo, i) - pad - comp(o, i)) * comp(inv, i);
        const double b = (comp(hi, i) + pad - comp(o, i)) * comp(inv, i);
        if (a != a || b != b) /* 0 * inf: the ray lies in the slab's face */
            continue;
        tn = fmax(tn, fmin(a, b));
        tf = fmin(tf, fmax(a, b));
    }
    return tn <= tf;
}

/* Moller-Trumbore: t and the barycentric u, v of b and c. */
static int tri(vec a, vec b, vec c, vec o, vec d, double *t, double *u,
               double *v)
{
    const vec e1 = sub(b, a), e2 = sub(c, a), p = cross(d, e2);
    const double det = dot(e1, p);
    if (det == 0)
        return 0;
    const double inv = 1.0 / det;
    const vec s = sub(o, a);
    *u = dot(s, p) * inv;
    if (*u < 0 || *u > 1)
        return 0;
    const vec q = cross(s, e1);
    *v = dot(d, q) * inv;
    if (*v < 0 || *u + *v > 1)
        return 0;
    *t = dot(e2, q) * inv;
    return 1;
}

int ref_mesh_hit(const ref_shape *sh, ref_vec3 o, ref_vec3 d, double tmax,
                 ref_hit *hit)
{
    const rt_mesh *m = sh->mesh;
    const struct ref_mesh_boxes *bx = sh->boxes;
    const vec inv = v3(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
    double best = tmax, bu = 0, bv = 0;
    long found = -1;
    const unsigned runs = (m->n_tris + RUN - 1) / RUN;
    for (unsigned k = 0; k < runs; k++) {
        /* Rounding is monotone, so a group's slab interval holds each of
         * its boxes' intervals: skipping on it changes no hit. */
        if (bx && k % GROUP == 0 &&
            !box_meets(bx->glo[k / GROUP], bx->ghi[k / GROUP], o, inv,
                       best)) {
            k += GROUP - 1;
            continue;
        }
        if (bx && !box_meets(bx->lo[k], bx->hi[k], o, inv, best))
            continue;
        for (unsigned i = k * RUN; i < m->n_tris && i < (k + 1) * RUN; i++) {
            const uint16_t *ix = &m->tri[3 * i];
            double t, u, v;
            if (tri(vert(m, ix[0]), vert(m, ix[1]), vert(m, ix[2]), o, d, &t,
                    &u, &v) &&
                t > REF_EPS && t < best) {
                best = t;
                bu = u;
                bv = v;
                found = i;
            }
        }
    }
    if (found < 0)
        return 0;
    const uint16_t *ix = &m->tri[3 * found];
    const vec a = vert(m, ix[0]), b = vert(m, ix[1]), c = vert(m, ix[2]);
    vec n = norm(cross(sub(b, a), sub(c, a)));
    if (m->vn) {
        vec s = v3(0, 0, 0);
        const double w[3] = {1 - bu - bv, bu, bv};
        for (int j = 0; j < 3; j++) {
            const fx_dir3 q = m->vn[ix[j]];
            s = madd(s, v3((double)q.x, (double)q.y, (double)q.z), w[j]);
        }
        if (len(s) > 0)
            n = norm(s);
    }
    hit->t = best;
    hit->n_out = n;
    return 1;
}
