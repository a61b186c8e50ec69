/* SPDX-License-Identifier: MIT */
/*
 * rt_mesh_normal: a mesh's normal at a hit (rt_mesh.h): the face's, from
 * the exact cross product of two edges, or with vertex normals their
 * blend by the barycentric weights of the hit point, found from the areas
 * it spans with each edge in the plane across the face normal's largest
 * component (exact 64-bit products after a shift to 30 bits).
 */
#include "rt_mesh.h"

fx_dir3 rt_mesh_normal(const rt_object *o, fx_vec3 p, unsigned tri)
{
    const rt_mesh *m = o->u.mesh.tables;
    const uint16_t *ix = &m->tri[3u * tri];
    const fx_vec3 a = m->v[ix[0]], b = m->v[ix[1]], c = m->v[ix[2]];
    const fx_dir3 n = fx_d3_cross_unit(fx_v3_sub(b, a), fx_v3_sub(c, a));
    if (!m->vn)
        return n;
    /* Barycentric weights of p from the areas it spans with each edge,
     * in the plane across the normal's largest component. */
    const int32_t ax = n.x < 0 ? -n.x : n.x, ay = n.y < 0 ? -n.y : n.y;
    const int32_t az = n.z < 0 ? -n.z : n.z;
    const unsigned ku = ax >= ay && ax >= az ? 1u : (ay >= az ? 2u : 0u);
    const unsigned kv = ku == 2 ? 0u : ku + 1;
    const fx_vec3 vv[3] = { a, b, c };
    const fx_t pc[3] = { p.x, p.y, p.z };
    int64_t q[3][2];
    uint64_t big = 0;
    for (int i = 0; i < 3; i++) {
        const fx_t vc[3] = { vv[i].x, vv[i].y, vv[i].z };
        q[i][0] = (int64_t)vc[ku] - pc[ku];
        q[i][1] = (int64_t)vc[kv] - pc[kv];
        for (int j = 0; j < 2; j++) {
            const uint64_t mag = (uint64_t)(q[i][j] < 0 ? -q[i][j] : q[i][j]);
            big |= mag;
        }
    }
    const int k = 34 - fx_clz64(big | 1u); /* below 2^30 after >> k */
    int32_t x[3], y[3];
    for (int i = 0; i < 3; i++) {
        x[i] = (int32_t)(k > 0 ? q[i][0] >> k : q[i][0]);
        y[i] = (int32_t)(k > 0 ? q[i][1] >> k : q[i][1]);
    }
    int64_t w[3] = {
        fx_imul64(x[1], y[2]) - fx_imul64(y[1], x[2]),
        fx_imul64(x[2], y[0]) - fx_imul64(y[2], x[0]),
        fx_imul64(x[0], y[1]) - fx_imul64(y[0], x[1]),
    };
    const int neg = w[0] + w[1] + w[2] < 0;
    uint64_t uw[3], sum = 0;
    for (int i = 0; i < 3; i++) {
        const int64_t wi = neg ? -w[i] : w[i];
        uw[i] = wi > 0 ? (uint64_t)wi : 0; /* rounding left p just outside */
        sum += uw[i];
    }
    if (sum == 0)
        return n;
    const int k2 = 33 - fx_clz64(sum); /* each weight below 2^31 */
    int64_t sx = 0, sy = 0, sz = 0;
    for (int i = 0; i < 3; i++) {
        const uint32_t wi = (uint32_t)(k2 > 0 ? uw[i] >> k2 : uw[i]);
        const fx_dir3 ni = m->vn[ix[i]];
        sx += fx_iumul64(ni.x, wi);
        sy += fx_iumul64(ni.y, wi);
        sz += fx_iumul64(ni.z, wi);
    }
    const fx_dir3 s = fx_d3_normalize64(sx, sy, sz);
    if (s.x == 0 && s.y == 0 && s.z == 0)
        return n;
    return s;
}
