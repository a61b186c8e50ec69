/* SPDX-License-Identifier: MIT */
/*
 * mesh_shapes: closed meshes of our own making (mesh_build.h), for the
 * watertightness test and for the gallery's models (tools/mkmodel.c).
 * Neighbouring triangles share vertex indices, so the meshes are closed
 * exactly, whatever the rounding of the coordinates.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "mesh_build.h"

static fx_t q16(double x)
{
    return (fx_t)lround(x * 65536.0);
}

static fx_dir3 unit(double x, double y, double z)
{
    const double l = sqrt(x * x + y * y + z * z);
    const double s = (double)FX_UONE / l;
    return fx_d3((int32_t)lround(x * s), (int32_t)lround(y * s),
                 (int32_t)lround(z * s));
}

/* Icosphere: unit-sphere points in double, projected back to the sphere
 * at every subdivision; edge midpoints are shared through a table of the
 * edges split so far (linear search per level is fine for test sizes,
 * so a sorted key table keeps it fast for large levels). */
typedef struct {
    uint64_t key;
    uint32_t v;
} edge_mid;

static int cmp_edge(const void *a, const void *b)
{
    const uint64_t x = ((const edge_mid *)a)->key;
    const uint64_t y = ((const edge_mid *)b)->key;
    return x < y ? -1 : x > y;
}

int mesh_icosphere(double r, unsigned level, fx_vec3 **v_out,
                   fx_dir3 **vn_out, unsigned *n_verts, uint32_t **tri_out,
                   unsigned *n_tris)
{
    static const uint32_t ico[20][3] = {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
        {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
        {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
        {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    const double g = (1.0 + sqrt(5.0)) / 2.0;
    const double p0[12][3] = {
        {-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
        {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
        {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    unsigned nt = 20, nv = 12;
    unsigned tmax = 20u << (2 * level), vmax = 10u * (1u << (2 * level)) + 2;
    double (*p)[3] = malloc(vmax * sizeof *p);
    uint32_t *t = malloc(3u * tmax * sizeof *t);
    uint32_t *t2 = malloc(3u * tmax * sizeof *t2);
    edge_mid *em = malloc(3u * tmax * sizeof *em);
    if (!p || !t || !t2 || !em)
        goto oom;
    for (unsigned i = 0; i < 12; i++) {
        const double l = sqrt(p0[i][0] * p0[i][0] + p0[i][1] * p0[i][1] +
                              p0[i][2] * p0[i][2]);
        for (int j = 0; j < 3; j++)
            p[i][j] = p0[i][j] / l;
    }
    for (unsigned i = 0; i < 60; i++)
        t[i] = ico[i / 3][i % 3];
    for (unsigned lv = 0; lv < level; lv++) {
        /* Every edge once (the smaller index first), sorted; then its
         * new midpoint vertex. */
        unsigned ne = 0;
        for (unsigned k = 0; k < nt; k++)
            for (int j = 0; j < 3; j++) {
                uint32_t a = t[3 * k + j], b = t[3 * k + (j + 1) % 3];
                if (a > b) {
                    uint32_t x = a;
                    a = b;
                    b = x;
                }
                em[ne].key = ((uint64_t)a << 32) | b;
                em[ne++].v = 0;
            }
        qsort(em, ne, sizeof *em, cmp_edge);
        unsigned u = 0;
        for (unsigned k = 0; k < ne; k++) {
            if (u > 0 && em[u - 1].key == em[k].key)
                continue;
            const uint32_t a = (uint32_t)(em[k].key >> 32);
            const uint32_t b = (uint32_t)em[k].key;
            double m[3], l = 0;
            for (int j = 0; j < 3; j++) {
                m[j] = p[a][j] + p[b][j];
                l += m[j] * m[j];
            }
            l = sqrt(l);
            for (int j = 0; j < 3; j++)
                p[nv][j] = m[j] / l;
            em[u].key = em[k].key;
            em[u++].v = nv++;
        }
        unsigned nt2 = 0;
        for (unsigned k = 0; k < nt; k++) {
            uint32_t c[3], mid[3];
            for (int j = 0; j < 3; j++)
                c[j] = t[3 * k + j];
            for (int j = 0; j < 3; j++) {
                uint32_t a = c[j], b = c[(j + 1) % 3];
                if (a > b) {
                    uint32_t x = a;
                    a = b;
                    b = x;
                }
                edge_mid key = {((uint64_t)a << 32) | b, 0};
                const edge_mid *f = bsearch(&key, em, u, sizeof *em, cmp_edge);
                mid[j] = f->v;
            }
            const uint32_t nw[4][3] = {{c[0], mid[0], mid[2]},
                                       {c[1], mid[1], mid[0]},
                                       {c[2], mid[2], mid[1]},
                                       {mid[0], mid[1], mid[2]}};
            for (int q = 0; q < 4; q++)
                for (int j = 0; j < 3; j++)
                    t2[3 * nt2 + q * 3 + j] = nw[q][j];
            nt2 += 4;
        }
        uint32_t *x = t;
        t = t2;
        t2 = x;
        nt = nt2;
    }
    fx_vec3 *v = malloc(nv * sizeof *v);
    fx_dir3 *vn = malloc(nv * sizeof *vn);
    if (!v || !vn) {
        free(v);
        free(vn);
        goto oom;
    }
    for (unsigned i = 0; i < nv; i++) {
        v[i] = fx_v3(q16(r * p[i][0]), q16(r * p[i][1]), q16(r * p[i][2]));
        vn[i] = unit(p[i][0], p[i][1], p[i][2]);
    }
    free(p);
    free(t2);
    free(em);
    *v_out = v;
    *vn_out = vn;
    *n_verts = nv;
    *tri_out = t;
    *n_tris = nt;
    return 0;
oom:
    free(p);
    free(t);
    free(t2);
    free(em);
    return -1;
}

int mesh_torus(double R, double r, unsigned n_u, unsigned n_v,
               fx_vec3 **v_out, fx_dir3 **vn_out, unsigned *n_verts,
               uint32_t **tri_out, unsigned *n_tris)
{
    const double pi = 3.14159265358979323846;
    const unsigned nv = n_u * n_v, nt = 2 * n_u * n_v;
    fx_vec3 *v = malloc(nv * sizeof *v);
    fx_dir3 *vn = malloc(nv * sizeof *vn);
    uint32_t *t = malloc(3u * nt * sizeof *t);
    if (!v || !vn || !t) {
        free(v);
        free(vn);
        free(t);
        return -1;
    }
    for (unsigned i = 0; i < n_u; i++) {
        const double a = 2 * pi * i / n_u;
        for (unsigned j = 0; j < n_v; j++) {
            const double b = 2 * pi * j / n_v;
            const double nx = cos(b) * cos(a), ny = sin(b);
            const double nz = cos(b) * sin(a);
            const double cx = R * cos(a), cz = R * sin(a);
            v[i * n_v + j] = fx_v3(q16(cx + r * nx), q16(r * ny),
                                   q16(cz + r * nz));
            vn[i * n_v + j] = unit(nx, ny, nz);
        }
    }
    unsigned k = 0;
    for (unsigned i = 0; i < n_u; i++) {
        const unsigned i1 = (i + 1) % n_u;
        for (unsigned j = 0; j < n_v; j++) {
            const unsigned j1 = (j + 1) % n_v;
            const uint32_t a = i * n_v + j, b = i1 * n_v + j;
            const uint32_t c = i1 * n_v + j1, d = i * n_v + j1;
            /* Counter-clockwise from outside: u runs one way round the
             * axis, v up the outer wall. */
            t[k++] = a;
            t[k++] = d;
            t[k++] = c;
            t[k++] = a;
            t[k++] = c;
            t[k++] = b;
        }
    }
    *v_out = v;
    *vn_out = vn;
    *n_verts = nv;
    *tri_out = t;
    *n_tris = nt;
    return 0;
}
