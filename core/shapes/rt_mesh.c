/* SPDX-License-Identifier: MIT */
/*
 * rt_mesh: the watertight ray/triangle test and the hierarchy's traversal
 * (rt_mesh.h; the guarantees in docs/numerics.md; normals in
 * rt_mesh_normal.c).
 *
 * For one ray and one mesh the frame is fixed first: kz the axis along
 * which the direction d is largest, kx and ky the next two in cyclic
 * order, and a shift s that brings every vertex, taken relative to the
 * ray's origin, below 2^30 (s = 0 unless the mesh is thousands of units
 * away). A vertex a = (v - o) 2^-s then projects to
 *     X = a_kx d_kz - d_kx a_kz,  Y = a_ky d_kz - d_ky a_kz,
 * rounded once to Q16.16 units: the ray's own line projects to (0, 0),
 * and the projection of a vertex depends on the vertex and the ray alone,
 * so two triangles sharing an edge see the same two endpoints. The edge
 * functions of the origin (twice the signed areas it spans with each
 * edge) are exact 64-bit products of those integers: their signs, which
 * decide the hit, are exact too.
 */
#include "rt_mesh.h"

/* Half of a unit vector's last bit. */
#define UHALF ((int64_t)1 << (FX_UBITS - 1))

/* Node boxes are widened by this many (shifted) ulps, beyond the t
 * rounding of the slab test (2^-31 relative plus 1) and the projection's
 * (an ulp): a ray that meets a triangle always enters its boxes. */
#define BOX_SLACK 10

/* What a ray needs for one mesh. */
typedef struct {
    unsigned kx, ky, kz;
    int32_t dx, dy, dz; /* d along kx, ky, kz; |dz| >= 1/sqrt(3) */
    int s;              /* vertices are (v - o) 2^-s */
    int64_t o[3];       /* the origin, raw Q16.16 */
} shear;

static void shear_set(shear *sh, const rt_ray *r, int s)
{
    const int32_t d[3] = { r->d.x, r->d.y, r->d.z };
    const uint32_t ax = (uint32_t)(d[0] < 0 ? -(int64_t)d[0] : d[0]);
    const uint32_t ay = (uint32_t)(d[1] < 0 ? -(int64_t)d[1] : d[1]);
    const uint32_t az = (uint32_t)(d[2] < 0 ? -(int64_t)d[2] : d[2]);
    unsigned kz = 2;
    if (ax >= ay && ax >= az)
        kz = 0;
    else if (ay >= az)
        kz = 1;
    sh->kz = kz;
    sh->kx = kz == 2 ? 0 : kz + 1;
    sh->ky = sh->kx == 2 ? 0 : sh->kx + 1;
    sh->dx = d[sh->kx];
    sh->dy = d[sh->ky];
    sh->dz = d[kz];
    sh->s = s;
    sh->o[0] = r->o.x;
    sh->o[1] = r->o.y;
    sh->o[2] = r->o.z;
}

/* A vertex in the ray's frame: X, Y (below 2^30 + 4 in magnitude) and the
 * coordinate along kz (below 2^30). */
typedef struct {
    int32_t x, y, z;
} proj;

/* The projection of a vertex a (relative to the origin, shifted, each
 * component below 2^30). */
static proj shear_rel(const shear *sh, const int32_t a[3])
{
    const int32_t ax = a[sh->kx], ay = a[sh->ky], az = a[sh->kz];
    proj p;
    /* |(a_kx, a_kz)| |(d_kz, d_kx)| <= |a| |d|: each below 2^60. */
    p.x = (int32_t)((fx_imul64(ax, sh->dz) - fx_imul64(sh->dx, az) + UHALF) >>
                    FX_UBITS);
    p.y = (int32_t)((fx_imul64(ay, sh->dz) - fx_imul64(sh->dy, az) + UHALF) >>
                    FX_UBITS);
    p.z = az;
    return p;
}

static proj project(const shear *sh, fx_vec3 v)
{
    int64_t a[3] = { (int64_t)v.x - sh->o[0], (int64_t)v.y - sh->o[1],
                     (int64_t)v.z - sh->o[2] };
    int32_t a32[3];
    const int64_t half = sh->s > 0 ? (int64_t)1 << (sh->s - 1) : 0;
    for (int i = 0; i < 3; i++)
        a32[i] = (int32_t)((a[i] + half) >> sh->s);
    return shear_rel(sh, a32);
}

/* project for a near mesh (s = 0): every difference from the origin is
 * below 2^30, so 32 bits hold it (the compiler's 32-bit subtraction). */
static proj project_near(const shear *sh, fx_vec3 v)
{
    const int32_t a[3] = { (int32_t)((int64_t)v.x - sh->o[0]),
                           (int32_t)((int64_t)v.y - sh->o[1]),
                           (int32_t)((int64_t)v.z - sh->o[2]) };
    return shear_rel(sh, a);
}

/* The sign of the edge function e of the origin for the edge p -> q; on
 * the edge (e = 0), the sign it takes at the origin moved by (eps, eps^2)
 * for an infinitesimal eps > 0: the same point for every triangle, so
 * the edge's two triangles, which see it with opposite signs, never both
 * claim it (a vertex likewise). 0 for an edge that projects to a point. */
static int edge_sign(int64_t e, proj p, proj q)
{
    if (e != 0)
        return e > 0 ? 1 : -1;
    if (p.y != q.y)
        return p.y > q.y ? 1 : -1;
    if (q.x != p.x)
        return q.x > p.x ? 1 : -1;
    return 0;
}

/* The test itself on projected vertices: 0 for a miss; else +1 or -1, the
 * sign of the projected area, and *t (raw Q16.16) with tmin < t < tmax. */
static int tri_core(const shear *sh, proj a, proj b, proj c, fx_t tmin,
                    fx_t tmax, fx_t *t)
{
    const int64_t u = fx_imul64(b.x, c.y) - fx_imul64(b.y, c.x);
    const int64_t v = fx_imul64(c.x, a.y) - fx_imul64(c.y, a.x);
    const int64_t w = fx_imul64(a.x, b.y) - fx_imul64(a.y, b.x);
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0))
        return 0; /* the common miss: strictly outside an edge */
    const int su = edge_sign(u, b, c);
    if (su == 0 || edge_sign(v, c, a) != su || edge_sign(w, a, b) != su)
        return 0;
    /* The weights of a, b and c, made positive; the sum is the projected
     * area, below 3 2^61 and not 0 (three zero weights would need a
     * triangle projected to a line, whose perturbed signs differ). */
    uint64_t wa = (uint64_t)(su > 0 ? u : -u);
    uint64_t wb = (uint64_t)(su > 0 ? v : -v);
    uint64_t wc = (uint64_t)(su > 0 ? w : -w);
    const uint64_t det = wa + wb + wc;
    const int k = 33 - fx_clz64(det); /* brings det below 2^31 */
    if (k > 0) {
        wa >>= k;
        wb >>= k;
        wc >>= k;
    }
    const uint32_t dw = (uint32_t)(wa + wb + wc); /* > 0 */
    if (dw == 0)
        return 0;
    /* The hit's coordinate along kz: the weighted mean of the vertices',
     * each product below 2^61. Then t = z / d_kz. */
    const int64_t num = fx_iumul64(a.z, (uint32_t)wa) +
                        fx_iumul64(b.z, (uint32_t)wb) +
                        fx_iumul64(c.z, (uint32_t)wc);
    if (num == 0 || (num < 0) != (sh->dz < 0))
        return 0; /* at or behind the origin */
    const uint64_t un = (uint64_t)(num < 0 ? -num : num);
    const uint32_t z = fx_udiv64_32(un + dw / 2, dw); /* below 2^30 */
    const uint32_t adz = (uint32_t)(sh->dz < 0 ? -(int64_t)sh->dz : sh->dz);
    /* z 2^FX_UBITS / |d_kz| < 2^30 sqrt(3) < 2^31. */
    const uint32_t ts =
        fx_udiv64_32(((uint64_t)z << FX_UBITS) + adz / 2, adz);
    if (ts >= ((uint32_t)1 << (31 - sh->s)))
        return 0; /* beyond the Q16.16 range */
    const fx_t tt = (fx_t)(ts << sh->s);
    if (tt <= tmin || tt >= tmax)
        return 0;
    *t = tt;
    return su;
}

/* The frame's shift for a mesh whose vertices are within bound (raw
 * Q16.16) of the ray's origin. */
static int shift_for(uint64_t bound)
{
    int s = 0;
    while (s < 30 && (bound >> s) >= ((uint64_t)1 << 30) - 4)
        s++;
    return s;
}

int rt_mesh_tri_hit(fx_vec3 a, fx_vec3 b, fx_vec3 c, const rt_ray *r,
                    fx_t tmin, fx_t tmax, fx_t *t, int *side)
{
    /* The frame without a shift, as rt_mesh_hit's for a near mesh. */
    const fx_vec3 v[3] = { a, b, c };
    for (int i = 0; i < 3; i++) {
        const int64_t dx = (int64_t)v[i].x - r->o.x;
        const int64_t dy = (int64_t)v[i].y - r->o.y;
        const int64_t dz = (int64_t)v[i].z - r->o.z;
        const uint64_t l1 = (uint64_t)(dx < 0 ? -dx : dx) +
                            (uint64_t)(dy < 0 ? -dy : dy) +
                            (uint64_t)(dz < 0 ? -dz : dz);
        if (shift_for(l1) != 0)
            return 0;
    }
    shear sh;
    shear_set(&sh, r, 0);
    int sg = tri_core(&sh, project(&sh, a), project(&sh, b),
                      project(&sh, c), tmin, tmax, t);
    /* Counter-clockwise in X, Y is the back of the triangle seen along d
     * for d_kz > 0 (the normal then points along d), the front for
     * d_kz < 0 (X and Y both change sign). */
    *side = sg == 0 ? 0 : ((sg > 0) == (sh.dz < 0) ? 1 : -1);
    return sg != 0;
}

/* ---- The hierarchy ------------------------------------------------------ */

/* 1 / d for a unit component d != 0, whatever its size: x / d with
 * FX_UBITS fraction bits in d is (x m) >> sh. */
typedef struct {
    uint32_t m;
    int sh;
} recip;

static recip recip_of(int32_t d)
{
    const uint32_t ud = (uint32_t)(d < 0 ? -(int64_t)d : d);
    const int c = fx_clz32(ud);
    recip q;
    q.m = fx_udiv64_32(((uint64_t)1 << 63) - 1u, ud << c);
    q.sh = 63 - FX_UBITS - c; /* >= 2 */
    return q;
}

/* The ray against the node boxes, in the shifted frame. */
typedef struct {
    int64_t base[3]; /* rt_mesh.lo - o, raw */
    int qshift, s;
    int32_t d[3];
    recip inv[3];
} box_ray;

/* Entry distance (shifted units) of the ray into the node's box when it
 * meets it before tmax and after tmin; else 0. */
static int box_hit(const box_ray *br, const rt_mesh_node *nd, int32_t tmin,
                   int32_t tmax, int32_t *tn_out)
{
    int32_t tn = tmin, tf = tmax;
    for (int i = 0; i < 3; i++) {
        int64_t lo = br->base[i] + ((int64_t)nd->box[i] << br->qshift);
        int64_t hi = br->base[i] + ((int64_t)nd->box[3 + i] << br->qshift);
        if (br->s > 0) {
            lo >>= br->s;                                  /* down */
            hi = -((-hi) >> br->s);                        /* up */
        }
        lo -= BOX_SLACK;
        hi += BOX_SLACK;
        const int32_t d = br->d[i];
        if (d == 0) {
            if (lo > 0 || hi < 0)
                return 0;
            continue;
        }
        /* |lo|, |hi| < 2^31: within the mesh's bound (rt_mesh_prepare). */
        int64_t t1 = fx_iumul64((int32_t)lo, br->inv[i].m) >> br->inv[i].sh;
        int64_t t2 = fx_iumul64((int32_t)hi, br->inv[i].m) >> br->inv[i].sh;
        if (d < 0) {
            const int64_t tmp = -t1;
            t1 = -t2;
            t2 = tmp;
        }
        if (t1 > tn)
            tn = fx_sat64(t1);
        if (t2 < tf)
            tf = fx_sat64(t2);
        if (tn > tf)
            return 0;
    }
    *tn_out = tn;
    return 1;
}

/* t 2^-s rounded up, at most FX_MAX - 1. */
static int32_t up_shift(fx_t t, int s)
{
    const int64_t v = ((int64_t)t + ((int64_t)1 << s) - 1) >> s;
    return v >= FX_MAX ? FX_MAX - 1 : (int32_t)v;
}

/* The ray against the node boxes when the mesh is near (s = 0): per axis
 * the distance to a face of coordinate index q is (c + (q << qshift)) m
 * >> sh, with m = 1 / d signed (|m| < 2^31), and c the offset of the
 * box's origin from the ray's, widened by BOX_SLACK outwards: c_near for
 * the face the ray enters through (lo for d > 0, hi for d < 0), c_far for
 * the other. All of it in 32 bits but the product. */
typedef struct {
    int32_t cn[3], cf[3]; /* offsets of the near and far faces */
    int32_t m[3];         /* 1 / d, 0 for d = 0 */
    uint8_t sh[3];
    uint8_t in[3], jf[3]; /* box[] index of the near and far face */
    uint8_t qshift;
} near_box;

static void near_box_set(near_box *nb, const rt_mesh *m, const rt_ray *r)
{
    const int32_t d[3] = { r->d.x, r->d.y, r->d.z };
    const fx_t lo[3] = { m->lo.x, m->lo.y, m->lo.z };
    const fx_t org[3] = { r->o.x, r->o.y, r->o.z };
    nb->qshift = m->qshift;
    for (int i = 0; i < 3; i++) {
        /* Within the mesh's bound (below 2^30): the difference fits. */
        const int32_t b = (int32_t)((int64_t)lo[i] - org[i]);
        const int neg = d[i] < 0;
        nb->in[i] = (uint8_t)(neg ? 3 + i : i);
        nb->jf[i] = (uint8_t)(neg ? i : 3 + i);
        nb->cn[i] = neg ? b + BOX_SLACK : b - BOX_SLACK;
        nb->cf[i] = neg ? b - BOX_SLACK : b + BOX_SLACK;
        if (d[i] == 0) {
            nb->m[i] = 0;
            nb->sh[i] = 0;
            continue;
        }
        const uint32_t ud = (uint32_t)(neg ? -(int64_t)d[i] : d[i]);
        const int c = fx_clz32(ud);
        /* (2^62 - 1) / (ud 2^c) < 2^31 as ud 2^c >= 2^31. */
        const int32_t q =
            (int32_t)fx_udiv64_32(((uint64_t)1 << 62) - 1u, ud << c);
        nb->m[i] = neg ? -q : q;
        nb->sh[i] = (uint8_t)(62 - FX_UBITS - c);
    }
}

/* As box_hit, for a near mesh. */
static int near_box_hit(const near_box *nb, const rt_mesh_node *nd,
                        int32_t tmin, int32_t tmax, int32_t *tn_out)
{
    int64_t tn = tmin, tf = tmax;
    const int qs = nb->qshift;
    for (int i = 0; i < 3; i++) {
        const int32_t pn = nb->cn[i] + ((int32_t)nd->box[nb->in[i]] << qs);
        const int32_t pf = nb->cf[i] + ((int32_t)nd->box[nb->jf[i]] << qs);
        if (nb->m[i] == 0) {
            /* Parallel: inside the slab or a miss (pn is lo's, pf hi's). */
            if (pn > 0 || pf < 0)
                return 0;
            continue;
        }
        const int64_t t1 = fx_imul64(pn, nb->m[i]) >> nb->sh[i];
        const int64_t t2 = fx_imul64(pf, nb->m[i]) >> nb->sh[i];
        if (t1 > tn)
            tn = t1;
        if (t2 < tf)
            tf = t2;
        if (tn > tf)
            return 0;
    }
    *tn_out = (int32_t)tn; /* within [tmin, tmax] */
    return 1;
}

/* Either frame for the node boxes, as near says. */
typedef struct {
    int near;
    union {
        near_box nb;
        box_ray br;
    } u;
} box_frame;

static inline int node_hit(const box_frame *bf, const rt_mesh_node *nd,
                           int32_t tmin, int32_t tmax, int32_t *tn)
{
    return bf->near ? near_box_hit(&bf->u.nb, nd, tmin, tmax, tn)
                    : box_hit(&bf->u.br, nd, tmin, tmax, tn);
}

/* The node boxes' frame for ray r and shift s: 32-bit offsets for a near
 * mesh (s = 0), else 64-bit ones shifted like the vertices. */
static inline void box_frame_set(box_frame *bf, const rt_mesh *m,
                                 const rt_ray *r, int s)
{
    bf->near = s == 0;
    if (bf->near) {
        near_box_set(&bf->u.nb, m, r);
        return;
    }
    const int32_t dd[3] = { r->d.x, r->d.y, r->d.z };
    bf->u.br.base[0] = (int64_t)m->lo.x - r->o.x;
    bf->u.br.base[1] = (int64_t)m->lo.y - r->o.y;
    bf->u.br.base[2] = (int64_t)m->lo.z - r->o.z;
    bf->u.br.qshift = m->qshift;
    bf->u.br.s = s;
    for (int i = 0; i < 3; i++) {
        bf->u.br.d[i] = dd[i];
        if (dd[i] != 0)
            bf->u.br.inv[i] = recip_of(dd[i]);
    }
}

/* The triangles of leaf nd nearer than *best: 1 with *best and *tri set
 * for a hit. */
static inline int leaf_hit(const rt_mesh *m, const rt_mesh_node *nd,
                           const shear *sh, int near, fx_t tmin, fx_t *best,
                           uint16_t *tri)
{
    const uint16_t *ix = &m->tri[3u * nd->a];
    int found = 0;
    for (unsigned k = 0; k < nd->n; k++, ix += 3) {
        fx_t tk;
        const proj pa = near ? project_near(sh, m->v[ix[0]])
                             : project(sh, m->v[ix[0]]);
        const proj pb = near ? project_near(sh, m->v[ix[1]])
                             : project(sh, m->v[ix[1]]);
        const proj pc = near ? project_near(sh, m->v[ix[2]])
                             : project(sh, m->v[ix[2]]);
        if (tri_core(sh, pa, pb, pc, tmin, *best, &tk)) {
            *best = tk;
            *tri = (uint16_t)(nd->a + k);
            found = 1;
        }
    }
    return found;
}

int rt_mesh_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                fx_t *t, uint16_t *tri)
{
    const rt_mesh *m = o->u.mesh.tables;
    /* Every vertex and box lies within br of bc (rt_mesh_prepare), and
     * the L1 distance bounds the Euclidean one. */
    const int64_t cx = (int64_t)o->bc.x - r->o.x;
    const int64_t cy = (int64_t)o->bc.y - r->o.y;
    const int64_t cz = (int64_t)o->bc.z - r->o.z;
    const uint64_t bound = (uint64_t)(cx < 0 ? -cx : cx) +
                           (uint64_t)(cy < 0 ? -cy : cy) +
                           (uint64_t)(cz < 0 ? -cz : cz) + (uint64_t)o->br +
                           2 * BOX_SLACK;
    shear sh;
    shear_set(&sh, r, shift_for(bound));
    const int s = sh.s;
    box_frame bf;
    box_frame_set(&bf, m, r, s);
    /* Distances in the shifted frame, rounded outwards (and one below
     * FX_MAX, so that best_s + 1 is one too). */
    const int32_t tmin_s = tmin >> s;
    int32_t best_s = up_shift(tmax, s);
    fx_t best = tmax;
    int found = 0;

    uint16_t stack_node[RT_MESH_DEPTH];
    int32_t stack_t[RT_MESH_DEPTH];
    unsigned sp = 0, ni = 0;
    int32_t tn;
    if (!node_hit(&bf, &m->node[0], tmin_s - 1, best_s + 1, &tn))
        return 0;
    for (;;) {
        const rt_mesh_node *nd = &m->node[ni];
        if (nd->n) {
            found |= leaf_hit(m, nd, &sh, bf.near, tmin, &best, tri);
            best_s = up_shift(best, s);
        } else {
            unsigned l = ni + 1, rr = nd->a;
            int32_t tl, tr;
            const int hl = node_hit(&bf, &m->node[l], tmin_s - 1, best_s + 1,
                                   &tl);
            const int hr = node_hit(&bf, &m->node[rr], tmin_s - 1, best_s + 1,
                                   &tr);
            if (hl && hr) {
                if (tr < tl) { /* the nearer first */
                    const unsigned ti = l;
                    const int32_t tt = tl;
                    l = rr;
                    rr = ti;
                    tl = tr;
                    tr = tt;
                }
                if (sp < RT_MESH_DEPTH) { /* always: depth is checked */
                    stack_node[sp] = (uint16_t)rr;
                    stack_t[sp] = tr;
                    sp++;
                }
                ni = l;
                continue;
            }
            if (hl || hr) {
                ni = hl ? l : rr;
                continue;
            }
        }
        /* The next pending node the best hit does not already hide. */
        for (;;) {
            if (sp == 0) {
                if (found)
                    *t = best;
                return found;
            }
            sp--;
            if (stack_t[sp] <= best_s + 1) {
                ni = stack_node[sp];
                break;
            }
        }
    }
}
