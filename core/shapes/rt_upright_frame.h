/* SPDX-License-Identifier: MIT */
/*
 * rt_upright_frame: the frame a cylinder or cone is solved in, and the
 * arithmetic on frame values (products, rounding, the side's quadratic).
 * Included by rt_upright.c only, which is part of the dispatch unit.
 */
#ifndef RT_UPRIGHT_FRAME_H
#define RT_UPRIGHT_FRAME_H

#include "rt_bsphere.h"
#include "rt_kinds.h"

/* Cylinders and cones are solved in a frame centred on the bounding
 * sphere and scaled by 2^-frame_shift (rt_upright), so that the sphere's
 * radius is between 1/2 and 1 there, with RT_FRAME_BITS (rt_scene.h)
 * fraction bits: a frame value is a world raw value times
 * 2^(RT_FRAME_BITS - 16 - frame_shift). 24 bits keep every product below
 * 2^63 for cone slopes up to 64. */

/* Frame ulps by which a cylinder's side reaches past its caps' planes,
 * and world ulps (at least frame ulps) by which the caps reach past the
 * side's radius: a cap's distance is a world value, so its point in the
 * frame is known only to a world ulp. No ray passes between the two. */
#define RT_RIM_SLACK 2

/* Below these (2^-8, as frame values with 16 fraction bits; see
 * RT_FRAME_BITS) a ray is within rounding of a cone's generator
 * direction: no linear root, and not treated as steep. */
#define RT_LINEAR_MIN_B ((int64_t)256 << (RT_FRAME_BITS - 16))
#define RT_STEEP_MIN_A 256

/* v 2^-n: rounded to nearest for n > 0, exact for n <= 0 (the callers
 * keep v 2^-n within 64 bits). */
static int64_t shift_round(int64_t v, int n)
{
    if (n <= 0)
        return v * ((int64_t)1 << -n);
    return (v + ((int64_t)1 << (n - 1))) >> n;
}

/* shift_round out of line, for the rare paths (thin_side, upright_thin),
 * where each inlined copy of its variable 64-bit shifts costs flash. */
RT_COLD static int64_t shift_round_cold(int64_t v, int n)
{
    return shift_round(v, n);
}

/* The low 32 bits of (t b + 2^(n - 1)) 2^-n, 0 < n < 32, for a unit
 * component b: fx_mul_round for a 32-bit t. */
static inline uint32_t frame_td(int64_t t, int32_t b, int n)
{
    if (t == (int32_t)t)
        return (uint32_t)fx_mul_round((int32_t)t, b, (unsigned)n);
    const uint64_t u = (uint64_t)(t * b) + ((uint32_t)1 << (n - 1));
    return ((uint32_t)u >> n) | ((uint32_t)(u >> 32) << (32 - n));
}

/* a b, exact, |a|, |b| <= 2^30. */
static inline int64_t frame_mul(int32_t a, int32_t b)
{
    return fx_imul64_30(a, b);
}

/* A product of two frame values back to RT_FRAME_BITS fraction bits,
 * rounded to nearest. */
static inline int64_t frame_round(int64_t v)
{
    return (v + ((int64_t)1 << (RT_FRAME_BITS - 1))) >> RT_FRAME_BITS;
}

/* n 2^RT_FRAME_BITS / d, truncated, for |n| < 2^31 and d != 0 (|d| <
 * 2^31); a quotient of 2^32 or more (256 frame units, far outside the
 * bounding sphere) comes back as +-2^32. */
static int64_t frame_div(int64_t n, int64_t d)
{
    const int neg = (n < 0) != (d < 0);
    const uint64_t un = (uint64_t)(n < 0 ? -n : n) << RT_FRAME_BITS;
    const uint32_t ud = (uint32_t)(d < 0 ? -d : d);
    int64_t q = (un >> 32) >= ud ? (int64_t)1 << 32
                                 : (int64_t)fx_udiv64_32(un, ud);
    return neg ? -q : q;
}

/* Roots of a t^2 + 2 b t + c = 0 (RT_FRAME_BITS fraction bits),
 * cancellation-free: q = -(b + sign(b) sqrt(b^2 - ac)), roots q / a and
 * c / q. Returns the count: one root when a = 0 (a ray along a cone's
 * generator). a, b and c are each rounded to half an ulp, so b^2 - ac is
 * known only to |b| + (|a| + |c|) / 2 (plus the rounding of the
 * products): a discriminant negative by less is a double root (a
 * tangent), not a miss; a wider tolerance would admit rays passing beside
 * a cone's apex. `real`: the roots are known to be real (a ray steeper
 * than a cone's side meets both nappes), so any negative discriminant is
 * rounding. */
RT_ALWAYS_INLINE static inline int quadratic(int64_t a, int64_t b,
                                             int64_t c, int real,
                                             int64_t root[2])
{
    /* A common scale brings the coefficients within 30 bits (only a
     * flat cone's need it); the roots do not change. A range test first,
     * as that is rare. */
    const uint64_t lim = ((uint64_t)1 << 30) - 1; /* |v| < 2^30 */
    int sh = 0;
    if ((uint64_t)a + lim > 2 * lim || (uint64_t)b + lim > 2 * lim ||
        (uint64_t)c + lim > 2 * lim)
        sh = 34 - fx_clz64((uint64_t)(a < 0 ? -a : a) |
                           (uint64_t)(b < 0 ? -b : b) |
                           (uint64_t)(c < 0 ? -c : c));
    int64_t lin_min = RT_LINEAR_MIN_B;
    if (sh > 0) {
        a = shift_round(a, sh);
        b = shift_round(b, sh);
        c = shift_round(c, sh);
        lin_min >>= sh;
    }
    if (a == 0) {
        /* One root, -c / 2b; b and c both shrink as the ray nears the
         * generator itself, and their ratio becomes noise: none then. */
        if (b > -lin_min && b < lin_min)
            return 0;
        root[0] = root[1] = frame_div(-c, 2 * b);
        return 1;
    }
    /* a, b and c are now within 30 bits: 32-bit products. */
    int64_t disc = frame_mul((int32_t)b, (int32_t)b) -
                   frame_mul((int32_t)a, (int32_t)c);
    if (disc < 0) {
        int64_t aa = a < 0 ? -a : a, ab = b < 0 ? -b : b;
        int64_t ac = c < 0 ? -c : c;
        if (!real && disc < -(ab + (aa + ac) / 2 + 1))
            return 0;
        disc = 0;
    }
    const int64_t sq = (int64_t)fx_isqrt64((uint64_t)disc);
    const int64_t q = b >= 0 ? -(b + sq) : sq - b; /* |q| < 2^31 */
    if (q == 0) {
        root[0] = root[1] = 0;
        return 1;
    }
    int64_t r0 = frame_div(q, a), r1 = frame_div(c, q);
    root[0] = r0 < r1 ? r0 : r1;
    root[1] = r0 < r1 ? r1 : r0;
    return 2;
}

/* A cylinder's or cone's frame for one ray (upright_hit): the frame is
 * centred on the bounding sphere and scaled by 2^-frame_shift, with
 * RT_FRAME_BITS fraction bits; a frame value is a world raw value times
 * 2^sf. */
typedef struct {
    int sf;
    int32_t p[3];   /* the ray's point at tca, o + tca d - bc */
    int32_t d[3];   /* its direction */
    int32_t yb, yt; /* the base's and the top's (apex's) height */
} upright_frame;

/* frame_set's p, yb and yt (frame_set's f->sf is sf) for an object
 * beyond 2^8 in radius (or a build with few unit bits), in 64-bit
 * values. */
static void frame_set_wide(upright_frame *f, const rt_object *o,
                           const rt_ray *r, int64_t tca, int sf)
{
    const rt_upright *up = &o->u.upright;
    int64_t (*const sr)(int64_t, int) = shift_round_cold;
    const int dsh = FX_UBITS - sf;
    f->p[0] = (int32_t)(sr(tca * r->d.x, dsh) -
                        sr((int64_t)o->bc.x - r->o.x, -sf));
    f->p[1] = (int32_t)(sr(tca * r->d.y, dsh) -
                        sr((int64_t)o->bc.y - r->o.y, -sf));
    f->p[2] = (int32_t)(sr(tca * r->d.z, dsh) -
                        sr((int64_t)o->bc.z - r->o.z, -sf));
    f->yb = (int32_t)sr((int64_t)up->base.y - o->bc.y, -sf);
    f->yt = (int32_t)sr((int64_t)up->base.y + up->height - o->bc.y, -sf);
}

/* Sets *f for object o and ray r, whose bounding-sphere tca is given. */
RT_ALWAYS_INLINE static inline void frame_set(upright_frame *f,
                                              const rt_object *o,
                                              const rt_ray *r, int64_t tca)
{
    const rt_upright *up = &o->u.upright;
    const int sf = RT_FRAME_BITS - 16 - up->frame_shift;
    f->sf = sf;
    /* The closest point p = o + tca d - bc in the frame, from the exact
     * o - bc and tca d (not bsphere's rounded h). Frame values near the
     * sphere are below 2^25: 32-bit operands. */
    const int dsh = FX_UBITS - sf;
    if (sf >= 0 && (FX_UBITS > 23 || dsh > 0)) { /* sf <= 23 */
        /* Up to 2^8 in radius: 32-bit shifts of a product's two words and
         * a difference's low word. */
        f->p[0] = (int32_t)(frame_td(tca, r->d.x, dsh) -
                            (((uint32_t)o->bc.x - r->o.x) << sf));
        f->p[1] = (int32_t)(frame_td(tca, r->d.y, dsh) -
                            (((uint32_t)o->bc.y - r->o.y) << sf));
        f->p[2] = (int32_t)(frame_td(tca, r->d.z, dsh) -
                            (((uint32_t)o->bc.z - r->o.z) << sf));
        /* Base and top, exact from the object's fields (the centre bc.y
         * is a.y + h/2 rounded down). */
        f->yb = (int32_t)(((uint32_t)up->base.y - (uint32_t)o->bc.y) << sf);
        f->yt = (int32_t)(((uint32_t)up->base.y + (uint32_t)up->height -
                           (uint32_t)o->bc.y) << sf);
    } else {
        frame_set_wide(f, o, r, tca, sf);
    }
    /* The direction with RT_FRAME_BITS fraction bits, as shift_round
     * gives it, in 32-bit shifts. */
    const int rs = FX_UBITS > RT_FRAME_BITS ? FX_UBITS - RT_FRAME_BITS : 0;
    const int ls = rs - (FX_UBITS - RT_FRAME_BITS);
    const int32_t dh = (int32_t)(((int64_t)1 << rs) >> 1);
    f->d[0] = ((r->d.x + dh) >> rs) * ((int32_t)1 << ls);
    f->d[1] = ((r->d.y + dh) >> rs) * ((int32_t)1 << ls);
    f->d[2] = ((r->d.z + dh) >> rs) * ((int32_t)1 << ls);
}

#endif /* RT_UPRIGHT_FRAME_H */
