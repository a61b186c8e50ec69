/* SPDX-License-Identifier: MIT */
/*
 * rt_upright: cylinders and cones (base centre a, radius r, height h:
 * rt_upright's base, radius and height; standing along +y), solved in a frame of their own (see
 * docs/numerics.md): after the bounding-sphere test, the side's quadratic
 * in a frame centred on that sphere and scaled by a power of two, so its
 * coefficients are near 1 whatever the object's size or distance, and the
 * caps as planes. Their normals are rt_upright_normal.c's.
 *
 * Part of the dispatch unit: rt_shape.c includes this file (its comment
 * says why); compiled alone it defines nothing.
 */
#include "rt_bsphere.h"
#include "rt_kinds.h"
#include "rt_upright_frame.h"

/* Largest cone slope r / h: flatter cones lose the unit-frame precision
 * (k^2 must stay well inside Q16.16). */
#define RT_MAX_CONE_SLOPE FX_INT(64)

/* Scales v by 2^-k, rounding to nearest; exact for k <= 0. */
static fx_t scale_pow2(fx_t v, int k)
{
    if (k <= 0)
        return fx_sat64((int64_t)v * ((int64_t)1 << -k));
    return (fx_t)(((int64_t)v + ((int64_t)1 << (k - 1))) >> k);
}

/* Bounding sphere and unit frame for an upright shape of radius r and
 * height h. */
static rt_status upright_bounds(rt_object *o)
{
    rt_upright *up = &o->u.upright;
    fx_t hh = up->height / 2;
    int k = 0;
    if (up->radius <= 0 || up->height <= 0)
        return RT_ERR_DEGENERATE;
    o->bc = fx_v3(up->base.x, fx_add(up->base.y, hh), up->base.z);
    o->br = fx_add(fx_v3_length(fx_v3(up->radius, hh, 0)), RT_BOUND_MARGIN);
    while (k < 15 && ((int64_t)o->br >> k) > FX_ONE)
        k++;
    while (k <= 0 && k > -15 && ((int64_t)o->br << -k) <= FX_HALF)
        k--;
    up->frame_shift = (int8_t)k;
    /* Radius and half height with 16 fraction bits in the frame: both
     * must be nonzero (rt_parse_obj.c states the limit). */
    if (scale_pow2(up->radius, k) == 0 || scale_pow2(hh, k) == 0)
        return RT_ERR_DEGENERATE;
    return RT_OK;
}

/* Open or capped, a cylinder is convex for the rays leaving it: a ray
 * leaving the outside of the side leaves the infinite solid cylinder,
 * which is convex, and one leaving a cap's outside leaves the half-space
 * that holds the whole shape; neither can meet the cylinder again. A cone
 * likewise, as one nappe's solid is convex. */
static inline rt_status upright_prepare(rt_object *o)
{
    rt_upright *up = &o->u.upright;
    o->convex = 1;
    if (o->kind == RT_CYLINDER)
        return upright_bounds(o);
    o->caps &= RT_CAP_BOTTOM;
    if (up->radius <= 0 || up->height <= 0)
        return RT_ERR_DEGENERATE;
    const fx_t k16 = fx_div(up->radius, up->height);
    if (k16 > RT_MAX_CONE_SLOPE || k16 == 0)
        return RT_ERR_DEGENERATE;
    /* The slope with RT_FRAME_BITS fraction bits, to nearest: r / h <= 64
     * keeps it below 2^30. */
    up->slope = (fx_t)fx_udiv64_32(
        ((uint64_t)(uint32_t)up->radius << RT_FRAME_BITS) +
            (uint32_t)up->height / 2,
        (uint32_t)up->height);
    /* Where the cone is thin (thin_side): 2^-6 of the frame over k, both
     * with RT_FRAME_BITS fraction bits. */
    const uint64_t th =
        ((uint64_t)1 << (2 * RT_FRAME_BITS - 6)) / (uint32_t)up->slope;
    up->thin = th > UINT32_MAX ? UINT32_MAX : (uint32_t)th;
    return upright_bounds(o);
}


/* A side root this near tmax (2^-4, raw) is polished (rt_side_root)
 * before it counts as nearer. */
#define RT_ROOT_NEAR ((int64_t)1 << 12)

/* A cone's side root where its radius k (yt - y) is below this (2^-6 of
 * the frame, as a frame value), near the apex or anywhere on a needle, is
 * solved again in a finer frame (thin_side); rt_upright.thin holds the
 * height below the apex where that is. */
#define RT_THIN_SIDE ((int64_t)1 << (RT_FRAME_BITS - 6))

/* A ray steeper than a cone's side by more than rounding (its a < 0):
 * it meets each nappe once. */
static int cone_steep(int64_t a)
{
    return a < -((int64_t)RT_STEEP_MIN_A << (RT_FRAME_BITS - 16));
}

/* Where a cone is thin, near its apex or along a needle, the side's
 * quadratic formed at the ray's point nearest the bounding sphere's
 * centre is ill-conditioned: the roots there split as the square root of
 * the discriminant, whose rounding (an ulp of the frame, for coefficients
 * far larger than the radius there) moves them by about 2^-12 of the
 * frame, and decides whether a ray passing the apex, or grazing a needle,
 * meets the cone: a shadow ray towards a light at the apex or on a
 * needle's rim passes it at up to EPS. thin_side solves the side again
 * about the ray's point at frame distance s0 from tca (a root of the
 * first solve): from that point, exact in 64 bits (world units with 16 +
 * FX_UBITS fraction bits, from the ray's own integers), it takes x, z and
 * the radius w = k (yt - y) there, all small, in a frame 2^e times finer
 * than the cone's, e as large as keeps them within 2^23: the rounding then
 * moves the roots 2^-e as much. Returns 1 with *best set for a side hit, 0
 * for none, or -1 when that point is not thin after all or a root leaves
 * the fine frame's range (a ray within rounding of a generator's
 * direction): then the first solve's roots stand. */
static int thin_side(const rt_object *o, const rt_ray *r, int64_t tca,
                     const upright_frame *fr, int64_t s0, fx_t tmin,
                     fx_t *best)
{
    const rt_upright *up = &o->u.upright;
    const upright_frame f = *fr;
    const int32_t *d = f.d;
    const int sf = f.sf;
    const int64_t ta = tca + shift_round_cold(s0, sf); /* world, Q16.16 */
    /* o - bc and ta d are each below 2^62 with FX_UBITS more fraction
     * bits (|o - bc| < 2^32, |ta| < 2^32 raw), and their sum is a point
     * within the bounding sphere: x and z from the axis, and y46 the
     * height below the apex. */
    const int64_t ay = (int64_t)up->base.y + up->height - o->bc.y;
    const int64_t x46 = ((int64_t)r->o.x - o->bc.x) * FX_UONE + ta * r->d.x;
    const int64_t z46 = ((int64_t)r->o.z - o->bc.z) * FX_UONE + ta * r->d.z;
    const int64_t y46 =
        ay * FX_UONE - (((int64_t)r->o.y - o->bc.y) * FX_UONE + ta * r->d.y);
    /* w46 = k y46, k with RT_FRAME_BITS fraction bits: y46 split so that
     * neither product overflows (k < 2^30). */
    const int64_t yh = y46 >> RT_FRAME_BITS;
    const int64_t yl = y46 - yh * ((int64_t)1 << RT_FRAME_BITS);
    if (yh > (INT64_MAX >> 31) || yh < -(INT64_MAX >> 31))
        return -1;
    const int64_t w46 = up->slope * yh + ((up->slope * yl) >> RT_FRAME_BITS);
    const uint64_t m = (uint64_t)(x46 < 0 ? -x46 : x46) |
                       (uint64_t)(z46 < 0 ? -z46 : z46) |
                       (uint64_t)(w46 < 0 ? -w46 : w46);
    /* A frame value is a 46-bit world value times 2^(sf - FX_UBITS); the
     * fine frame's 2^e more. Not thin after all: the first solve stands. */
    const int64_t fm = shift_round_cold((int64_t)m, FX_UBITS - sf);
    if (fm >= 2 * RT_THIN_SIDE)
        return -1;
    int e = 23 + FX_UBITS - sf - (m ? 64 - fx_clz64(m) : 0); /* bits */
    e = e < 0 ? 0 : (e > 24 ? 24 : e);
    const int n = FX_UBITS - sf - e;
    const int32_t qx = (int32_t)shift_round_cold(x46, n);
    const int32_t qz = (int32_t)shift_round_cold(z46, n);
    const int64_t qw = shift_round_cold(w46, n);
    const int64_t qy = shift_round_cold(y46, n); /* height below the apex */
    /* The cone's coefficients there, as in upright_hit; a is the same at
     * any scale. */
    const int32_t kdy = (int32_t)frame_round(fx_imul64(up->slope, d[1]));
    const int64_t a = frame_round(fx_imul64(d[0], d[0]) +
                                  fx_imul64(d[2], d[2])) -
                      frame_round(fx_imul64(kdy, kdy));
    const int64_t b = frame_round(fx_imul64(qx, d[0]) + fx_imul64(qz, d[2])) +
                      frame_round(qw * kdy);
    const int64_t c =
        frame_round(fx_imul64(qx, qx) + fx_imul64(qz, qz) - qw * qw);
    const int steep = cone_steep(a);
    int64_t root[2];
    int nr = quadratic(a, b, c, steep, root);
    if (steep && nr == 2) {
        if ((d[1] > 0) != (root[0] < root[1]))
            root[0] = root[1];
        nr = 1;
    }
    const int64_t lim = (int64_t)1 << 32; /* frame_div's saturation */
    for (int i = 0; i < nr; i++)
        if (root[i] >= lim || root[i] <= -lim)
            return -1;
    /* The base plane (with the rim slack) in fine units below the apex. */
    const int64_t base =
        ((int64_t)f.yt - f.yb + RT_RIM_SLACK) * ((int64_t)1 << e);
    for (int i = 0; i < nr; i++) {
        const int64_t y = qy - frame_round(root[i] * d[1]);
        if ((y < 0 && !steep) || y > base)
            continue; /* the mirrored nappe, or below the base */
        if (take(ta + shift_round_cold(root[i], sf + e), tmin, best))
            return 1;
    }
    return 0;
}

/* The caps of a cylinder or cone seen by the ray of frame f (discs at the
 * base, bottom, and at the top, a cylinder's only) nearer than *best: 1
 * with *best and *part (1 + cap) set for a hit. ur is the radius in the
 * frame. */
RT_ALWAYS_INLINE static inline int upright_caps(const rt_object *o,
                                                const rt_ray *r, int64_t tca,
                                                const upright_frame *f,
                                                int32_t ur, fx_t tmin,
                                                fx_t *best, uint16_t *part)
{
    const rt_upright *up = &o->u.upright;
    const int sf = f->sf;
    const int64_t rim = (int64_t)RT_RIM_SLACK << (sf > 0 ? sf : 0);
    int found = 0;
    if (r->d.y == 0)
        return 0;
    for (int cap = 0; cap < 2; cap++) {
        if (!(o->caps & (cap ? RT_CAP_TOP : RT_CAP_BOTTOM)))
            continue;
        /* t in world units, as a flat quad's for a plane y = const: a
         * cap in a floor quad's plane (a shape standing on the floor)
         * gives the very same t, so the tie goes to the earlier object
         * instead of flipping with rounding. */
        int64_t cy = cap ? (int64_t)up->base.y + up->height : up->base.y;
        int64_t tw = rt_plane_t(cy, r->o.y, r->d.y);
        if (tw <= tmin || tw >= *best)
            continue; /* take() would refuse it */
        if (tw - tca > o->br || tca - tw > o->br)
            continue; /* outside the bounding sphere; keeps tl small */
        const int64_t tl = shift_round(tw - tca, -sf);
        const int64_t x = f->p[0] + frame_round(tl * f->d[0]);
        const int64_t z = f->p[2] + frame_round(tl * f->d[2]);
        /* The caps reach RT_RIM_SLACK world ulps (at least as many frame
         * ulps) past the side's radius for a ray that meets them from
         * outside, which the side might let through at the rim. A ray
         * that meets a cap from inside the solid (up at the top, down at
         * the bottom) crossed the side first if it passed outside the
         * rim: no slack, or a ray passing just outside would see the
         * cap's inner face. */
        const int64_t slack = (cap ? r->d.y < 0 : r->d.y > 0) ? 2 * rim : 0;
        if (x * x + z * z > fx_imul64(ur, ur) + ur * slack)
            continue;
        if (take(tw, tmin, best)) {
            *part = (uint16_t)(1 + cap);
            found = 1;
        }
    }
    return found;
}

/* upright_hit's answer again for a cone whose side had a root s0 where
 * the cone is thin: the side's hit is thin_side's, and the caps are
 * tested again against it; or, if thin_side declines, the answer found
 * (with *t and *part) stands. f is upright_hit's frame for the ray. */
RT_COLD static int upright_thin(const rt_object *o, const rt_ray *r,
                                int64_t tca, const upright_frame *f,
                                int64_t s0, fx_t tmin, fx_t tmax, int found,
                                fx_t *t, uint16_t *part)
{
    const rt_upright *up = &o->u.upright;
    fx_t best = tmax;
    uint16_t pt = 0;
    int side = thin_side(o, r, tca, f, s0, tmin, &best);
    if (side < 0)
        return found;
    if (side > 0) {
        /* Once more about that root, which is nearer the apex or the
         * needle than s0, so the frame there is finer still: a ray
         * within rounding of tangent there (a shadow ray to a light on
         * the apex along a generator) had its roots split by the first
         * fine frame's rounding, up to a few EPS apart. */
        fx_t again = tmax;
        const int64_t s1 = shift_round_cold((int64_t)best - tca, -f->sf);
        const int side1 = thin_side(o, r, tca, f, s1, tmin, &again);
        if (side1 >= 0) {
            side = side1;
            best = again;
        }
    }
    const int32_t ur = (int32_t)shift_round_cold(up->radius, -f->sf);
    found = upright_caps(o, r, tca, f, ur, tmin, &best, &pt) | side;
    if (found) {
        *t = best;
        *part = pt;
    }
    return found;
}

/* The side's roots for the ray of frame f (ur the radius in the frame),
 * as frame distances from tca, in root: returns their count. *steep: a
 * cone's side the ray is clearly steeper than (not within rounding of a
 * generator's direction, where one root is far and saturates), whose one
 * root is then the lower nappe's. */
static inline int side_roots(const rt_object *o, const upright_frame *f,
                             int32_t ur, int cone, int *steep,
                             int64_t root[2])
{
    const rt_upright *up = &o->u.upright;
    const int32_t px = f->p[0], py = f->p[1], pz = f->p[2];
    const int32_t dx = f->d[0], dy = f->d[1], dz = f->d[2];
    /* Side: x^2 + z^2 = R(y)^2, R = ur (cylinder) or k (yt - y) (cone). */
    const int64_t pp = frame_mul(px, px) + frame_mul(pz, pz);
    int64_t a = frame_round(frame_mul(dx, dx) + frame_mul(dz, dz));
    int64_t b = frame_round(frame_mul(px, dx) + frame_mul(pz, dz));
    int64_t c = frame_round(pp - frame_mul(ur, ur));
    if (cone) {
        /* The slope has RT_FRAME_BITS fraction bits, below 2^30;
         * ky below 2^31 (|yt - py| < 2^25). */
        const int32_t kdy = (int32_t)frame_round(fx_imul64(up->slope, dy));
        const int64_t ky = frame_round(fx_imul64(up->slope, f->yt - py));
        a -= frame_round(frame_mul(kdy, kdy));
        b += frame_round(mul_q(ky, kdy));
        c = frame_round(pp - (ky == (int32_t)ky
                                  ? fx_imul64((int32_t)ky, (int32_t)ky)
                                  : ky * ky));
    }
    *steep = cone && cone_steep(a);
    int n = quadratic(a, b, c, *steep, root);
    if (*steep && n == 2) {
        /* A ray steeper than the side meets each nappe once: the root
         * with the lower y is on the cone, however near the apex rounding
         * puts it (a y <= top threshold there lets rays through). */
        if ((dy > 0) != (root[0] < root[1]))
            root[0] = root[1];
        n = 1;
    }
    return n;
}

/* Cylinder (kind RT_CYLINDER) or cone, in the object's frame. */
static inline int upright_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                   fx_t *t, uint16_t *part)
{
    const rt_upright *up = &o->u.upright;
    int64_t tca, h[3];
    uint64_t disc;
    fx_t best = tmax;
    int64_t root[2];
    int found = 0, steep;
    const int cone = RT_HAS_CONE && o->kind == RT_CONE;
    if (!bsphere(&o->bc, o->br, o->small, r, tmin, tmax, &tca, &disc, h))
        return 0;
    upright_frame f;
    frame_set(&f, o, r, tca);
    const int32_t py = f.p[1], dy = f.d[1];
    const int32_t yb = f.yb, yt = f.yt;
    /* The radius in the frame, exact. */
    const int32_t ur = (int32_t)shift_round(up->radius, -f.sf);
    const int64_t one = (int64_t)1 << RT_FRAME_BITS;
    const int n = side_roots(o, &f, ur, cone, &steep, root);
    for (int i = 0; i < n; i++) {
        /* Roots of a real hit lie within the bounding sphere's chord. */
        if (root[i] > 4 * one || root[i] < -4 * one)
            continue;
        /* |root| <= 2^(RT_FRAME_BITS + 2): 32-bit operands. */
        int64_t y = py + frame_round(frame_mul((int32_t)root[i], dy));
        /* The side reaches RT_RIM_SLACK frame ulps past each cap's
         * plane, as the caps reach past the side's radius below: the
         * two are rounded separately, and no ray may pass between. A
         * cone's apex meets no cap, so it gets no slack: past it lies
         * the mirrored nappe. */
        if (y < yb - RT_RIM_SLACK ||
            (y > yt + (cone ? 0 : RT_RIM_SLACK) && !steep))
            continue;
        /* World distance: tca + root 2^(frame_shift - (F - 16)). */
        if (take(tca + shift_round(root[i], f.sf), tmin, &best)) {
            *part = 0;
            found = 1;
            break;
        }
    }
    /* A side root just short of tmax (a shadow ray to a light on the
     * rim, say, or a hit as near as another object's) is decided at the
     * ray's own hit: the roots' rounding moves them by up to about an
     * ulp of the frame over the cosine of incidence, which a grazing ray
     * makes hundreds of ulps. */
    int64_t t30;
    if (found && tmax < FX_MAX && (int64_t)tmax - best < RT_ROOT_NEAR &&
        rt_side_root(o, r, best, &t30) && t30 >= (int64_t)tmax * (1 << 14)) {
        found = 0;
        best = tmax;
    }
    found |= upright_caps(o, r, tca, &f, ur, tmin, &best, part);
    if (found)
        *t = best;
    /* A side root where a cone is thin (near its apex, or on a needle) is
     * as much rounding's as the ray's: the answer is then upright_thin's.
     * (A ray within rounding of the cone there has a root: quadratic()
     * takes a discriminant within its rounding for a tangent's.) */
    for (int i = 0; cone && i < n; i++)
        if (root[i] <= 4 * one && root[i] >= -4 * one &&
            py + frame_round(frame_mul((int32_t)root[i], dy)) >
                yt - (int64_t)up->thin) {
            /* The frame again from f, not frame_set, which is large; a
             * copy, so that f itself need not be kept in memory on the
             * common path. */
            const upright_frame fc = f;
            return upright_thin(o, r, tca, &fc, root[i], tmin, tmax, found,
                                t, part);
        }
    return found;
}

