/* SPDX-License-Identifier: MIT */
/*
 * rt_mesh_check: what the traversal relies on, checked once when a mesh
 * object is prepared (rt_mesh_prepare, rt_mesh.h), and the object's
 * bounding sphere. The traversal then needs no checks of its own: every
 * index is in range, the hierarchy is a tree no deeper than its stack,
 * its leaves hold each triangle once, and every box holds what lies
 * below it.
 */
#include "rt_mesh.h"

/* Largest extent of a mesh and of its boxes, raw: 2^30 (16384 units), so
 * that differences of its points fit 31 bits. */
#define MESH_SPAN ((int64_t)1 << 30)

/* The bounding sphere's margin (raw) beyond the farthest vertex or box
 * corner: the rounding of its own test, and of the triangle test's
 * projection for a ray within 8192 units (rt_shape.c tests the sphere
 * only then). */
#define MESH_MARGIN 32

/* A node's box, raw. */
static void node_box(const rt_mesh *m, const rt_mesh_node *nd, int64_t lo[3],
                     int64_t hi[3])
{
    const int64_t base[3] = { m->lo.x, m->lo.y, m->lo.z };
    for (int i = 0; i < 3; i++) {
        lo[i] = base[i] + ((int64_t)nd->box[i] << m->qshift);
        hi[i] = base[i] + ((int64_t)nd->box[3 + i] << m->qshift);
    }
}

static int vertex_in(fx_vec3 v, const int64_t lo[3], const int64_t hi[3])
{
    return v.x >= lo[0] && v.x <= hi[0] && v.y >= lo[1] && v.y <= hi[1] &&
           v.z >= lo[2] && v.z <= hi[2];
}

/* The tree in depth-first order, left before right: children after their
 * parent, leaves in triangle order, each box within its parent's. */
static rt_status check_tree(const rt_mesh *m)
{
    uint16_t stack[RT_MESH_DEPTH + 1];
    uint8_t level[RT_MESH_DEPTH + 1];
    unsigned sp = 0, next_tri = 0;
    stack[sp] = 0;
    level[sp++] = 0;
    while (sp > 0) {
        sp--;
        const unsigned ni = stack[sp], lv = level[sp];
        const rt_mesh_node *nd = &m->node[ni];
        int64_t lo[3], hi[3];
        node_box(m, nd, lo, hi);
        for (int i = 0; i < 3; i++)
            if (nd->box[i] > nd->box[3 + i] || hi[i] - lo[i] > MESH_SPAN)
                return RT_ERR_ARG;
        if (nd->n) {
            if (nd->a != next_tri || (unsigned)nd->a + nd->n > m->n_tris)
                return RT_ERR_ARG;
            next_tri += nd->n;
            for (unsigned k = 3u * nd->a; k < 3u * next_tri; k++) {
                if (m->tri[k] >= m->n_verts ||
                    !vertex_in(m->v[m->tri[k]], lo, hi))
                    return RT_ERR_ARG;
            }
            continue;
        }
        const unsigned kids[2] = { ni + 1, nd->a };
        if (lv >= m->depth || nd->a <= ni + 1 || nd->a >= m->n_nodes ||
            ni + 1 >= m->n_nodes)
            return RT_ERR_ARG;
        for (int c = 0; c < 2; c++) {
            const rt_mesh_node *ch = &m->node[kids[c]];
            for (int i = 0; i < 3; i++)
                if (ch->box[i] < nd->box[i] || ch->box[3 + i] > nd->box[3 + i])
                    return RT_ERR_ARG;
        }
        /* Right below left: the left one is taken first. */
        stack[sp] = (uint16_t)kids[1];
        level[sp++] = (uint8_t)(lv + 1);
        stack[sp] = (uint16_t)kids[0];
        level[sp++] = (uint8_t)(lv + 1);
    }
    return next_tri == m->n_tris ? RT_OK : RT_ERR_ARG;
}

/* |p - c| for points within MESH_SPAN of each other, rounded up. */
static fx_t dist_up(int64_t dx, int64_t dy, int64_t dz)
{
    const uint64_t d2 = (uint64_t)(dx * dx) + (uint64_t)(dy * dy) +
                        (uint64_t)(dz * dz);
    uint64_t r = fx_isqrt64(d2);
    if (r * r < d2)
        r++;
    return (fx_t)r;
}

rt_status rt_mesh_prepare(rt_object *o)
{
    const rt_mesh *m = o->u.mesh.tables;
    if (!m || !m->v || !m->tri || !m->node || m->n_tris == 0 ||
        m->n_verts == 0 || m->n_nodes == 0 || m->depth > RT_MESH_DEPTH ||
        m->qshift > 16)
        return RT_ERR_ARG;
    rt_status st = check_tree(m);
    if (st != RT_OK)
        return st;
    /* The root box holds every vertex (check_tree): its centre and its
     * half diagonal bound them all, and the node boxes too. */
    int64_t lo[3], hi[3];
    node_box(m, &m->node[0], lo, hi);
    const int64_t c[3] = { (lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2,
                           (lo[2] + hi[2]) / 2 };
    if (c[0] < FX_MIN || c[0] > FX_MAX || c[1] < FX_MIN || c[1] > FX_MAX ||
        c[2] < FX_MIN || c[2] > FX_MAX)
        return RT_ERR_ARG;
    o->bc = fx_v3((fx_t)c[0], (fx_t)c[1], (fx_t)c[2]);
    int64_t e[3];
    for (int i = 0; i < 3; i++)
        e[i] = hi[i] - c[i] > c[i] - lo[i] ? hi[i] - c[i] : c[i] - lo[i];
    o->br = dist_up(e[0], e[1], e[2]) + MESH_MARGIN;
    o->convex = 0;
    o->caps = 0;
    return RT_OK;
}
