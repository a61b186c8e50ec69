/* SPDX-License-Identifier: MIT */
/*
 * rt_cull: conservative screen-space culling of camera rays.
 *
 * All camera rays of one sample row lie in the plane through the eye
 * spanned by f = norm(w + sy up) and right: D(s) = L f + s right with
 * L = |w + sy up|. That plane cuts an object's bounding sphere in a circle
 * (radius r' = sqrt(R^2 - h^2), h the centre's distance from the plane),
 * seen from the eye at angle phi (tan phi = p.right / p.f) with half-width
 * alpha (tan alpha = r' / sqrt(d'^2 - r'^2)); so the rays that can hit have
 * s = L tan(theta) with |theta - phi| <= alpha. Everything stays in world
 * units, where Q16.16 is precise, rather than in ratios like (R/d)^2 that
 * vanish for small far objects. A quad adds the half-plane of s where D(s)
 * points at its plane from the eye's side. The sphere is inflated and
 * the interval padded well beyond the arithmetic error, and any
 * ill-conditioned case falls back to "all columns", so culling only skips
 * tests that would have missed: images are bit-identical with or without
 * it (RT_CULL=0 in the tests).
 */
#include "rt_cull.h"

#define S_INF ((int64_t)1 << 40) /* beyond any screen offset */

/* An object's culling constants for this camera (cheap enough to derive
 * per row, which keeps them off the stack). */
typedef struct {
    fx_vec3 p;     /* bounding-sphere centre relative to the eye */
    fx_t r;        /* inflated bounding radius */
    fx_t pa, pb;   /* quads: den = pa + sy * pb + s * pc must have the sign */
    fx_t pc;       /* of num (the eye's side) for a hit in front */
    int8_t all;    /* 1: no sphere culling (eye inside or near, or beyond
                      the range where the row geometry is exact enough) */
    int8_t side;   /* quads: +1 / -1 the sign den needs; 0: not a quad */
    int8_t corners; /* quads: 1 if q holds its corners */
    fx_vec3 q[4];  /* quads: the corners relative to the eye */
} cull_obj;

/* The corners of quad o relative to the eye e into q; 0 if one is 2^14
 * units away or more (then no corner culling). */
static int quad_corners(fx_vec3 q[4], const rt_object *o, fx_vec3 e)
{
    const fx_vec3 a = o->u.quad.corner;
    const fx_vec3 e1 = o->u.quad.edge1, e2 = o->u.quad.edge2;
    int ok = 1;
    for (int i = 0; i < 4; i++) {
        /* The corner a + u e1 + v e2. */
        const int32_t u = i & 1, v = i >> 1;
        const int64_t x = (int64_t)a.x - e.x + (int64_t)u * e1.x +
                          (int64_t)v * e2.x;
        const int64_t y = (int64_t)a.y - e.y + (int64_t)u * e1.y +
                          (int64_t)v * e2.y;
        const int64_t z = (int64_t)a.z - e.z + (int64_t)u * e1.z +
                          (int64_t)v * e2.z;
        ok &= x > -FX_INT(16384) && x < FX_INT(16384) &&
              y > -FX_INT(16384) && y < FX_INT(16384) &&
              z > -FX_INT(16384) && z < FX_INT(16384);
        q[i] = ok ? fx_v3((fx_t)x, (fx_t)y, (fx_t)z) : fx_v3(0, 0, 0);
    }
    return ok;
}

static void cull_obj_set(cull_obj *k, const rt_object *o, const rt_scene *s,
                         const rt_cam_frame *cf)
{
    int64_t px = (int64_t)o->bc.x - s->cam.eye.x;
    int64_t py = (int64_t)o->bc.y - s->cam.eye.y;
    int64_t pz = (int64_t)o->bc.z - s->cam.eye.z;
    /* Inflate by 1/64 and 2^-6 units: far above the test's rounding. */
    int64_t r = (int64_t)o->br + o->br / 64 + 1024;
    k->all = 1;
    k->side = 0;
    k->p = fx_v3(0, 0, 0);
    k->r = 0;
    k->pa = k->pb = k->pc = 0;
    k->corners = 0;
    if (r < FX_INT(16384) && px > -FX_INT(16384) && px < FX_INT(16384) &&
        py > -FX_INT(16384) && py < FX_INT(16384) && pz > -FX_INT(16384) &&
        pz < FX_INT(16384)) {
        k->p = fx_v3((fx_t)px, (fx_t)py, (fx_t)pz);
        k->r = (fx_t)r;
        k->all = fx_v3_len2_q32(k->p) <= (uint64_t)(r * r);
    }
    if (o->kind == RT_QUAD) {
        /* The eye's side of the plane; a hit needs d.n of the other sign.
         * Too close to the plane to tell: no plane culling. */
        const fx_dir3 n = o->u.quad.normal;
        const int64_t raw =
            fx_pd_dot_diff_raw(o->u.quad.corner, s->cam.eye, n);
        fx_t num = fx_sat64((raw + ((int64_t)1 << (FX_UBITS - 1))) >>
                            FX_UBITS);
        k->corners = (int8_t)quad_corners(k->q, o, s->cam.eye);
        if (num > 256 || num < -256) {
            k->side = num > 0 ? 1 : -1;
            k->pa = fx_d3_dot(cf->w, n);
            k->pb = fx_d3_dot(cf->up, n);
            k->pc = fx_d3_dot(cf->right, n);
        }
    }
}

/* The plane of one sample row. */
typedef struct {
    fx_t sy;
    fx_dir3 f;  /* unit, along w + sy up */
    fx_dir3 nr; /* unit normal of the row's plane */
    fx_t len;   /* |w + sy up| */
} row_plane;

/* The plane through the eye that holds every ray of sample row k: built
 * from the very base the rays are (rt_cam_row_base), so it holds them to
 * the precision of unit vectors. Its length and sy only scale and bound
 * the intervals, whose padding covers their Q16.16 rounding. */
static void row_plane_set(row_plane *rp, const rt_cam_frame *cf, int32_t k)
{
    const fx_t sy = rt_cam_offset(cf, k);
    const rt_cam_ray b = rt_cam_row_base(cf, rt_cam_soff(cf, k));
    fx_vec3 fu = fx_v3_madd(fx_d3_to_v3(cf->w), fx_d3_to_v3(cf->up), sy);
    rp->sy = sy;
    rp->len = fx_v3_length(fu);
    rp->f = fx_d3_normalize64(b.x, b.y, b.z);
    rp->nr = fx_d3_cross_unit(fx_d3_raw(rp->f), fx_d3_raw(cf->right));
}

/* 1 if the four corners q lie on one side of the plane through the eye
 * with unit normal nr, by a margin far beyond the rounding of h and of
 * the rays. */
static int corners_off(const fx_vec3 q[4], fx_dir3 nr)
{
    int above = 0, below = 0;
    for (int i = 0; i < 4; i++) {
        const fx_t m = 1024 + fx_abs(q[i].x) / 64 + fx_abs(q[i].y) / 64 +
                       fx_abs(q[i].z) / 64; /* each below 2^30 */
        const fx_t h = fx_pd_dot(q[i], nr);
        above += h > m;
        below += h < -m;
    }
    return above == 4 || below == 4;
}

/* tan(phi + sg * alpha) from the two tangents; +-S_INF past 90 degrees. */
static int64_t tan_sum(fx_t tp, fx_t ta, int sg)
{
    fx_t ta_s = sg > 0 ? ta : fx_neg(ta);
    fx_t den = fx_sub(FX_ONE, fx_mul(tp, ta_s));
    if (den <= 1024) /* the edge reaches 90 degrees: unbounded */
        return sg > 0 ? S_INF : -S_INF;
    return fx_div(fx_add(tp, ta_s), den);
}

/* Interval [*lo, *hi] of s for one sample row; returns 0 if empty. */
static int row_interval(const cull_obj *k, const rt_cam_frame *cf,
                        const row_plane *rp, int64_t *lo, int64_t *hi)
{
    const fx_t sy = rp->sy;
    *lo = -S_INF;
    *hi = S_INF;
    if (k->corners && sy < FX_INT(64) && sy > -FX_INT(64)) {
        /* All four corners of a quad on one side of the row's plane
         * (corners_off): no ray of the row reaches it (a floor seen
         * from above, in the rows between its far edge and the
         * horizon). Cheaper than the quad's tests it saves at each of
         * the row's pixels. */
        if (corners_off(k->q, rp->nr))
            return 0;
    }
    if (!k->all && sy < FX_INT(64) && sy > -FX_INT(64)) {
        fx_t h = fx_pd_dot(k->p, rp->nr);
        if (h >= k->r || h <= -k->r)
            return 0; /* the row's plane misses the sphere */
        uint64_t r2 = (uint64_t)((int64_t)k->r * k->r - (int64_t)h * h);
        fx_t pf = fx_pd_dot(k->p, rp->f), pr = fx_pd_dot(k->p, cf->right);
        uint64_t d2 = (uint64_t)((int64_t)pf * pf) +
                      (uint64_t)((int64_t)pr * pr);
        if (pf < 0 && (uint64_t)((int64_t)pf * pf) > r2)
            return 0; /* the circle lies wholly behind the eye */
        if (pf > 0 && d2 > r2) {
            fx_t rr = (fx_t)fx_sqrt_q32(r2);
            fx_t tang = (fx_t)fx_sqrt_q32(d2 - r2);
            if (tang > 64) {
                fx_t tp = fx_div(pr, pf), ta = fx_div(rr, tang);
                int64_t t0 = tan_sum(tp, ta, -1), t1 = tan_sum(tp, ta, 1);
                if (t0 > -S_INF) {
                    int64_t s0 = ((int64_t)t0 * rp->len) >> 16;
                    *lo = s0 - 256 - (s0 < 0 ? -s0 : s0) / 128;
                }
                if (t1 < S_INF) {
                    int64_t s1 = ((int64_t)t1 * rp->len) >> 16;
                    *hi = s1 + 256 + (s1 < 0 ? -s1 : s1) / 128;
                }
            }
        }
    }
    if (k->side != 0 && sy < FX_INT(64) && sy > -FX_INT(64)) {
        /* side * (pa + sy pb + s pc) > 0 */
        fx_t al = fx_add(k->pa, fx_mul(sy, k->pb));
        fx_t be = k->pc;
        if (k->side < 0) {
            al = fx_neg(al);
            be = fx_neg(be);
        }
        if (be > 64 || be < -64) {
            int64_t s0 = fx_div(fx_neg(al), be);
            int64_t pad = 256 + (s0 < 0 ? -s0 : s0) / 128;
            if (be > 0 && s0 - pad > *lo)
                *lo = s0 - pad;
            if (be < 0 && s0 + pad < *hi)
                *hi = s0 + pad;
        } else if (al < -256) {
            return 0; /* the whole row points away from the plane */
        }
    }
    return *lo <= *hi;
}

/* Pixel column of screen offset s (Q16.16), rounded down, exact from -2
 * to W + 1; below, -3, and above, some column past W + 1, which
 * rt_cull_row's clamps treat as the true one (x1 below 0, or x0 past
 * W - 1: the span is empty; else x0 at 0, or x1 at W - 1). */
static int64_t column(const rt_cam_frame *cf, int64_t s, unsigned width)
{
    if (s <= -S_INF)
        return -1;
    if (s >= S_INF)
        return (int64_t)width;
    if (cf->step == 0) /* fov so small every ray is w: no column to tell */
        return s < 0 ? -1 : (int64_t)width;
    /* s = k step / 2^16 with k = 2 x n + 2 i + 1 - W n, so the column is
     * floor((k + W n) / 2n), k = floor(s 2^16 / step), and -2 or more
     * exactly when k + (W + 4) n >= 0, with (W + 4) n < 2^20. Below zero
     * k = -floor((-s 2^16 - 1) / step) - 1, so k is q = floor(m / step),
     * or ~q, for m = s 2^16 or ~(s 2^16), below 2^56. With step < 2^47
     * shifted right by e to 32 bits (its top bit set where e > 0), a
     * quotient below 2^21 of the shifted values is never below q and at
     * most 1 above it (the two differ by less than 2^22 / 2^31), and its
     * product with step tells which: no 64-bit library divide. */
    const uint64_t step = (uint64_t)cf->step;
    const uint32_t neg = s < 0 ? 0xFFFFFFFFu : 0;
    const uint64_t m = ((uint64_t)s << 16) ^ fx_pair64(neg, neg);
    const uint32_t bh = (uint32_t)(step >> 32);
    uint64_t a = m;
    uint32_t b = (uint32_t)step;
    if (bh) { /* e in [1, 15], by words */
        const int e = 32 - fx_clz32(bh);
        const uint32_t mh = (uint32_t)(m >> 32);
        a = fx_pair64(mh >> e, ((uint32_t)m >> e) | (mh << (32 - e)));
        b = (b >> e) | (bh << (32 - e));
    }
    /* Where q >= 2^21 - 1, 2^22 stands for it: either way the column is
     * past W + 1 (2^22 / 2n > 2^16), or y below zero. */
    uint32_t q = 1u << 22;
    if ((a >> 21) < b) {
        q = fx_udiv64_32(a, b);
        q -= q * step > m;
    }
    /* k + (W + 4) n mod 2^32, below 2^23 in magnitude: its sign bit. */
    const uint32_t y = (width + 4u) * cf->n + (q ^ neg);
    if (y >> 31)
        return -3;
    /* A shift for one sample a pixel: no divide, which is a library
     * call on a core without one. */
    if (cf->n == 1)
        return (int64_t)(y >> 1) - 2;
    return (int64_t)(y / (2u * cf->n)) - 2;
}

void rt_cull_row(const rt_scene *s, const rt_cam_frame *cf, unsigned width,
                 unsigned height, unsigned y, rt_row_spans *rs)
{
    rt_span *spans = rs->span;
    unsigned count = 0;
    const unsigned n = cf->n;
    row_plane rp[RT_MAX_SPP_SIDE];
    for (unsigned j = 0; j < n; j++) {
        row_plane_set(&rp[j], cf, rt_cam_row_k(height, n, y, j));
    }
    for (unsigned i = 0; i < s->n_objects; i++) {
        int64_t lo = S_INF, hi = -S_INF;
        cull_obj k;
        cull_obj_set(&k, &s->obj[i], s, cf);
        for (unsigned j = 0; j < n; j++) {
            int64_t l, h;
            if (row_interval(&k, cf, &rp[j], &l, &h)) {
                lo = l < lo ? l : lo;
                hi = h > hi ? h : hi;
            }
        }
        if (lo > hi)
            continue;
        int64_t x0 = column(cf, lo, width) - 1;
        int64_t x1 = column(cf, hi, width) + 1;
        if (x0 < 0)
            x0 = 0;
        if (x1 > (int64_t)width - 1)
            x1 = (int64_t)width - 1;
        if (x0 > x1)
            continue;
        spans[count].obj = (uint16_t)i;
        spans[count].x0 = (int16_t)x0;
        spans[count].x1 = (int16_t)x1;
        count++;
    }
    rs->count = count;
}
