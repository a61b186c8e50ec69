/* SPDX-License-Identifier: MIT */
/*
 * mesh_build: a binned surface-area-heuristic hierarchy (mesh_build.h).
 * Each split tries 16 bins of triangle centroids along each axis and
 * takes the cheapest by the expected cost of a ray that meets the parent
 * box; a node becomes a leaf when splitting would cost more than testing
 * its triangles, or at RT_MESH_DEPTH. The boxes are exact in raw Q16.16
 * and then rounded outwards to the 16-bit grid of rt_mesh_node, so each
 * still holds everything below it. Deterministic: integer boxes, and the
 * costs in double from integer extents, the same on every IEEE host.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_build.h"

#define BINS 16
/* Most leaves of one hierarchy: 2 n - 1 nodes must fit RT_MESH_MAX. */
#define MESH_MAX_LEAVES ((RT_MESH_MAX + 1) / 2)
#define COST_BOX 1.0  /* a box test, relative to ... */
#define COST_TRI 1.5  /* ... a triangle test (Cortex-M3 counts) */

typedef struct {
    int64_t lo[3], hi[3];
} box64;

static void box_empty(box64 *b)
{
    for (int i = 0; i < 3; i++) {
        b->lo[i] = INT64_MAX;
        b->hi[i] = INT64_MIN;
    }
}

static void box_grow(box64 *b, const box64 *c)
{
    for (int i = 0; i < 3; i++) {
        if (c->lo[i] < b->lo[i])
            b->lo[i] = c->lo[i];
        if (c->hi[i] > b->hi[i])
            b->hi[i] = c->hi[i];
    }
}

static double box_area(const box64 *b)
{
    if (b->lo[0] > b->hi[0])
        return 0.0;
    double e[3];
    for (int i = 0; i < 3; i++)
        e[i] = (double)(b->hi[i] - b->lo[i]);
    return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
}

typedef struct {
    const uint32_t *tri;  /* input triangles */
    const box64 *tbox;    /* per input triangle */
    const int64_t (*cen)[3]; /* centroids times 3 */
    uint32_t *perm;       /* triangle order, partitioned in place */
    rt_mesh_node *node;
    unsigned n_nodes, depth;
    int64_t base[3];
    int qshift;
} builder;

static void set_box(builder *b, rt_mesh_node *nd, const box64 *bx)
{
    for (int i = 0; i < 3; i++) {
        const int64_t lo = (bx->lo[i] - b->base[i]) >> b->qshift;
        const int64_t hi = -((-(bx->hi[i] - b->base[i])) >> b->qshift);
        nd->box[i] = (uint16_t)lo;
        nd->box[3 + i] = (uint16_t)hi;
    }
}

/* Builds the subtree over perm[first .. first + count) at node index
 * b->n_nodes, depth levels below the root, with at most `leaves` leaves
 * (at least 1). A subtree of n leaves has 2n - 1 nodes, so the root's
 * share, half of RT_MESH_MAX + 1, keeps every mesh within the 16-bit node
 * indices. A mesh of up to that many triangles is never held back by it:
 * each child gets its own count of triangles as its share, and a leaf
 * holds at least one. */
static void build(builder *b, unsigned first, unsigned count, unsigned depth,
                  unsigned leaves)
{
    const unsigned ni = b->n_nodes++;
    rt_mesh_node *nd = &b->node[ni];
    box64 bx, cb;
    box_empty(&bx);
    box_empty(&cb);
    for (unsigned k = first; k < first + count; k++) {
        const uint32_t t = b->perm[k];
        box64 c;
        box_grow(&bx, &b->tbox[t]);
        for (int i = 0; i < 3; i++)
            c.lo[i] = c.hi[i] = b->cen[t][i];
        box_grow(&cb, &c);
    }
    set_box(b, nd, &bx);
    if (depth > b->depth)
        b->depth = depth;

    /* The cheapest split of the centroid bins. */
    double best = COST_TRI * count;
    int best_axis = -1, best_cut = 0;
    if (count > 1 && depth < RT_MESH_DEPTH && leaves > 1) {
        const double pa = box_area(&bx);
        for (int ax = 0; ax < 3; ax++) {
            const int64_t lo = cb.lo[ax], ext = cb.hi[ax] - cb.lo[ax];
            if (ext == 0)
                continue;
            box64 bb[BINS];
            unsigned bn[BINS] = {0};
            for (int i = 0; i < BINS; i++)
                box_empty(&bb[i]);
            for (unsigned k = first; k < first + count; k++) {
                const uint32_t t = b->perm[k];
                int i = (int)(((double)(b->cen[t][ax] - lo) / (double)ext) *
                              BINS);
                if (i >= BINS)
                    i = BINS - 1;
                bn[i]++;
                box_grow(&bb[i], &b->tbox[t]);
            }
            double right_area[BINS];
            unsigned right_n[BINS];
            box64 acc;
            box_empty(&acc);
            unsigned n = 0;
            for (int i = BINS - 1; i > 0; i--) {
                box_grow(&acc, &bb[i]);
                n += bn[i];
                right_area[i] = box_area(&acc);
                right_n[i] = n;
            }
            box_empty(&acc);
            n = 0;
            for (int cut = 1; cut < BINS; cut++) {
                box_grow(&acc, &bb[cut - 1]);
                n += bn[cut - 1];
                if (n == 0 || right_n[cut] == 0)
                    continue;
                const double c = 2 * COST_BOX +
                                 COST_TRI * (box_area(&acc) * n +
                                             right_area[cut] * right_n[cut]) /
                                     pa;
                if (c < best) {
                    best = c;
                    best_axis = ax;
                    best_cut = cut;
                }
            }
        }
    }
    if (best_axis < 0 && count > MESH_LEAF_MAX && depth < RT_MESH_DEPTH &&
        leaves > 1)
        best_axis = 3; /* no split pays, but the leaf is too full: halve */
    if (best_axis < 0) {
        nd->a = (uint16_t)first;
        nd->n = (uint16_t)count;
        return;
    }
    unsigned mid;
    if (best_axis == 3) {
        mid = first + count / 2;
    } else {
        const int64_t lo = cb.lo[best_axis];
        const int64_t ext = cb.hi[best_axis] - lo;
        unsigned i = first, j = first + count;
        while (i < j) {
            const uint32_t t = b->perm[i];
            int bin = (int)(((double)(b->cen[t][best_axis] - lo) /
                             (double)ext) * BINS);
            if (bin >= BINS)
                bin = BINS - 1;
            if (bin < best_cut) {
                i++;
            } else {
                b->perm[i] = b->perm[--j];
                b->perm[j] = t;
            }
        }
        mid = i;
    }
    /* The children share the leaves in proportion to their triangles. */
    uint64_t left = (uint64_t)leaves * (mid - first) / count;
    if (left < 1)
        left = 1;
    if (left > leaves - 1)
        left = leaves - 1;
    nd->n = 0;
    build(b, first, mid - first, depth + 1, (unsigned)left);
    b->node[ni].a = (uint16_t)b->n_nodes;
    build(b, mid, first + count - mid, depth + 1, leaves - (unsigned)left);
}

static int fail(char *msg, size_t cap, const char *what)
{
    snprintf(msg, cap, "%s", what);
    return 0;
}

rt_mesh *mesh_build(const fx_vec3 *v, unsigned n_verts, const fx_dir3 *vn,
                    const uint32_t *tri, unsigned n_tris, char *msg,
                    size_t msg_cap)
{
    if (n_tris == 0 || n_verts == 0) {
        fail(msg, msg_cap, "the mesh has no triangles");
        return NULL;
    }
    if (n_tris > RT_MESH_MAX || n_verts > RT_MESH_MAX) {
        snprintf(msg, msg_cap, "the mesh has %u triangles and %u vertices; "
                 "at most %u of each fit", n_tris, n_verts, RT_MESH_MAX);
        return NULL;
    }
    box64 all;
    box_empty(&all);
    for (unsigned k = 0; k < 3 * n_tris; k++) {
        if (tri[k] >= n_verts) {
            fail(msg, msg_cap, "a triangle names a vertex that is not there");
            return NULL;
        }
        const fx_vec3 p = v[tri[k]];
        const box64 c = {{p.x, p.y, p.z}, {p.x, p.y, p.z}};
        box_grow(&all, &c);
    }
    int qshift = 0;
    for (int i = 0; i < 3; i++) {
        if (all.hi[i] - all.lo[i] >= ((int64_t)1 << 30)) {
            fail(msg, msg_cap, "the mesh is larger than 16384 units");
            return NULL;
        }
        while (((all.hi[i] - all.lo[i]) >> qshift) + 1 > 65535)
            qshift++;
    }
    /* One block: the mesh, then its arrays (each 4-byte aligned). */
    const size_t nodes_max = 2u * n_tris;
    const size_t sz = sizeof(rt_mesh) + n_verts * sizeof(fx_vec3) +
                      (vn ? n_verts * sizeof(fx_dir3) : 0) +
                      nodes_max * sizeof(rt_mesh_node) +
                      ((3u * n_tris * sizeof(uint16_t) + 3) & ~(size_t)3);
    unsigned char *blk = calloc(1, sz);
    box64 *tbox = malloc(n_tris * sizeof *tbox);
    int64_t (*cen)[3] = malloc(n_tris * sizeof *cen);
    uint32_t *perm = malloc(n_tris * sizeof *perm);
    if (!blk || !tbox || !cen || !perm) {
        free(blk);
        free(tbox);
        free(cen);
        free(perm);
        fail(msg, msg_cap, "out of memory");
        return NULL;
    }
    rt_mesh *m = (rt_mesh *)blk;
    fx_vec3 *mv = (fx_vec3 *)(blk + sizeof(rt_mesh));
    fx_dir3 *mvn = vn ? (fx_dir3 *)(mv + n_verts) : NULL;
    rt_mesh_node *node =
        (rt_mesh_node *)(vn ? (unsigned char *)(mvn + n_verts)
                            : (unsigned char *)(mv + n_verts));
    uint16_t *mt = (uint16_t *)(node + nodes_max);
    memcpy(mv, v, n_verts * sizeof *mv);
    if (vn)
        memcpy(mvn, vn, n_verts * sizeof *mvn);
    for (unsigned t = 0; t < n_tris; t++) {
        box_empty(&tbox[t]);
        for (int i = 0; i < 3; i++)
            cen[t][i] = 0;
        for (int j = 0; j < 3; j++) {
            const fx_vec3 p = v[tri[3 * t + j]];
            const box64 c = {{p.x, p.y, p.z}, {p.x, p.y, p.z}};
            box_grow(&tbox[t], &c);
            cen[t][0] += p.x;
            cen[t][1] += p.y;
            cen[t][2] += p.z;
        }
        perm[t] = t;
    }
    builder b;
    memset(&b, 0, sizeof b);
    b.tri = tri;
    b.tbox = tbox;
    b.cen = (const int64_t (*)[3])cen;
    b.perm = perm;
    b.node = node;
    b.qshift = qshift;
    for (int i = 0; i < 3; i++)
        b.base[i] = all.lo[i];
    build(&b, 0, n_tris, 0, n_tris < MESH_MAX_LEAVES ? n_tris
                                                     : MESH_MAX_LEAVES);
    for (unsigned t = 0; t < n_tris; t++)
        for (int j = 0; j < 3; j++)
            mt[3 * t + j] = (uint16_t)tri[3 * perm[t] + j];
    free(tbox);
    free(cen);
    free(perm);
    if (b.n_nodes > RT_MESH_MAX) {
        free(blk);
        fail(msg, msg_cap, "the hierarchy needs more than 65535 nodes");
        return NULL;
    }
    m->v = mv;
    m->vn = mvn;
    m->tri = mt;
    m->node = node;
    m->n_verts = (uint16_t)n_verts;
    m->n_tris = (uint16_t)n_tris;
    m->n_nodes = (uint16_t)b.n_nodes;
    m->qshift = (uint8_t)qshift;
    m->depth = (uint8_t)b.depth;
    m->lo = fx_v3((fx_t)all.lo[0], (fx_t)all.lo[1], (fx_t)all.lo[2]);
    return m;
}

void mesh_free(rt_mesh *m)
{
    free(m);
}
