/* SPDX-License-Identifier: MIT */
/*
 * rt_upright_normal: the outward unit normals of cylinders and cones.
 *
 * The hit point p = o + t d is rounded to Q16.16 and t itself to 2^-16;
 * either error, up to 2^-17 of a unit across the surface (more where the
 * ray grazes it), tilts a curved surface's normal by that over its
 * radius. A ray that bounces between the walls of a glass cylinder
 * multiplies the tilt at every bounce, so for a cylinder or cone side
 * that casts secondary rays the unrounded o + t d is formed with 30
 * fraction bits and moved along d by Newton steps onto the side, and the
 * normal and the hit point are taken there (docs/numerics.md).
 */
#include "rt_kinds.h"

/* v 2^-n, rounded to nearest, for n > 0. */
static int64_t shr_round(int64_t v, int n)
{
    return (v + ((int64_t)1 << (n - 1))) >> n;
}

/* Bounds beyond which side_step leaves the hit point as it is. */
#define FINE_V_MAX ((int32_t)1 << 30) /* |p - a| per component, raw */
#define FINE_E_MAX ((int32_t)1 << 17) /* o + t d - p: 8 Q16.16 ulps */
#define FINE_G_MAX ((int64_t)1 << 40) /* |v|^2 - r^2, Q32.32 */
/* The longest Newton step and the longest move, 2^-5 (2^25 with 30
 * fraction bits): a grazing ray's side root may be that far off. */
#define FINE_S_BITS 25
#define FINE_Q_MAX ((int32_t)1 << 25)

/* -g / den with 30 fraction bits, for g with 46 and den with
 * 16 + FX_UBITS, in *s; 0 if its magnitude would pass 2^FINE_S_BITS. */
static int newton_step(int64_t g, int64_t den, int32_t *s)
{
    if (den == 0)
        return 0;
    const int neg = (g < 0) == (den < 0); /* -g / den < 0 */
    uint64_t ug = (uint64_t)(g < 0 ? -g : g);
    uint64_t ud = (uint64_t)(den < 0 ? -den : den);
    /* |s| <= 2^FINE_S_BITS: |g| <= |den| 2^(FINE_S_BITS - FX_UBITS). (The
     * & 63 only keeps the shift of the branch not taken non-negative for
     * static analysis.) */
    if (FX_UBITS >= FINE_S_BITS ? ug > ud >> (FX_UBITS - FINE_S_BITS)
                                : ug > ud << ((FINE_S_BITS - FX_UBITS) & 63))
        return 0;
    const int k = ud >> 31 ? 33 - fx_clz64(ud) : 0;
    ud >>= k; /* below 2^31; the dividend below ud 2^FINE_S_BITS */
    ug = k <= FX_UBITS ? ug << (FX_UBITS - k) : ug >> (k - FX_UBITS);
    const int32_t su = (int32_t)fx_udiv64_32(ug, (uint32_t)ud);
    *s = neg ? -su : su;
    return 1;
}

/* What side_step and cone_step start from: q = o + t d - p with 30
 * fraction bits, and v = p - a across the axis (x and z, Q16.16, exact),
 * with |v|^2 added to *g0 (Q32.32) and v.d to *vd (16 + FX_UBITS).
 * Returns 0 where a value leaves its range. */
RT_ALWAYS_INLINE static inline int fine_start(const rt_ray *r, fx_t t,
                                              fx_vec3 p, fx_vec3 a,
                                              int32_t q[3], int32_t v[3],
                                              int64_t *g0, int64_t *vd)
{
    const int32_t pc[3] = { p.x, p.y, p.z }, ac[3] = { a.x, a.y, a.z };
    const int32_t oc[3] = { r->o.x, r->o.y, r->o.z };
    const int32_t dc[3] = { r->d.x, r->d.y, r->d.z };
    v[1] = 0;
    for (int i = 0; i < 3; i++) {
        /* t d has 16 + FX_UBITS fraction bits. */
        const int64_t e =
            shr_round(fx_imul64(t, dc[i]) - ((int64_t)pc[i] - oc[i]) *
                                                 ((int64_t)1 << FX_UBITS),
                      FX_UBITS - 14);
        if (e >= FINE_E_MAX || e <= -FINE_E_MAX)
            return 0;
        q[i] = (int32_t)e;
        if (i == 1)
            continue;
        const int64_t vi = (int64_t)pc[i] - ac[i];
        if (vi >= FINE_V_MAX || vi <= -FINE_V_MAX)
            return 0;
        v[i] = (int32_t)vi;
        *g0 += fx_imul64(v[i], v[i]);
        *vd += fx_imul64(v[i], dc[i]);
    }
    return *g0 < FINE_G_MAX && *g0 > -FINE_G_MAX;
}

/* The part across the axis of g = |v + q|^2 - ... (46 fraction bits) and
 * of den = (v + q).d (16 + FX_UBITS), added to *g and *den. */
RT_ALWAYS_INLINE static inline void fine_across(const rt_ray *r,
                                                const int32_t v[3],
                                                const int32_t q[3],
                                                int64_t *g, int64_t *den)
{
    const int32_t dc[3] = { r->d.x, r->d.y, r->d.z };
    for (int i = 0; i < 3; i += 2) {
        *g += 2 * fx_imul64(v[i], q[i]) + (fx_imul64(q[i], q[i]) >> 14);
        *den += fx_imul64(q[i], dc[i]) >> 14;
    }
}

/* One Newton step -g / (2 den) along d, added to q and to *moved_t: 1
 * while another is
 * due (the step was longer than a quarter of a Q16.16 ulp), 0 when done,
 * -1 where the step or the move leaves its range. */
RT_ALWAYS_INLINE static inline int fine_move(const rt_ray *r, int64_t g,
                                             int64_t den, int32_t q[3],
                                             int64_t *moved_t)
{
    const int32_t dc[3] = { r->d.x, r->d.y, r->d.z };
    int32_t s;
    if (!newton_step(g, 2 * den, &s))
        return -1;
    *moved_t += s;
    for (int i = 0; i < 3; i++) {
        q[i] += (int32_t)shr_round(fx_imul64(s, dc[i]), FX_UBITS);
        if (q[i] >= FINE_Q_MAX || q[i] <= -FINE_Q_MAX)
            return -1;
    }
    return s > (1 << 12) || s < -(1 << 12);
}

/* Where ray r meets the side of a cylinder (axis through a, along y,
 * radius rad) near its rounded hit p = o + t d: Newton steps along d from
 * the unrounded o + t d onto the side. A step moves the point by its
 * distance from the side divided by the cosine of the angle of
 * incidence and leaves an error of about its square over the radius
 * times that cosine: one step, or up to four while a step is longer than
 * a quarter of a Q16.16 ulp (a ray near tangent). Sets q to the move from
 * p, with 30 fraction bits, and returns 1; returns 0 where the move
 * would pass 2^-8 (a ray within rounding of tangent) or the values leave
 * their ranges, and the caller then takes p. Run only for hits that cast
 * secondary rays: compiled for size (RT_COLD), as cone_step. */
RT_COLD static int side_step(const rt_ray *r, fx_t t, fx_vec3 p, fx_vec3 a,
                             fx_t rad, int32_t q[3], int64_t *moved_t)
{
    int32_t v[3];
    int64_t g0 = -fx_imul64(rad, rad), vd = 0;
    if (!fine_start(r, t, p, a, q, v, &g0, &vd))
        return 0;
    for (int step = 0, more = 1; more && step < 4; step++) {
        /* At p + q: g = |v + q|^2 - r^2, den = (v + q).d. */
        int64_t g = g0 * ((int64_t)1 << 14), den = vd;
        fine_across(r, v, q, &g, &den);
        more = fine_move(r, g, den, q, moved_t);
        if (more < 0)
            return 0;
    }
    return 1;
}

/* n / h as a quotient (returned) and 2^-FINE_K_BITS of a unit of it in
 * *lo (|lo| < 2^FINE_K_BITS): n / h = q + lo 2^-FINE_K_BITS, to within
 * that. h > 0; |n| < 2^62. */
#define FINE_K_BITS 24
static int64_t div_frac(int64_t n, int32_t h, int64_t *lo)
{
    /* The truncated quotient and remainder from |n| by fx_udiv64, and the
     * fraction, below 2^FINE_K_BITS, by fx_udiv64_32: no signed 64-bit
     * library divide, which 32-bit cores would call. */
    const uint64_t un = n < 0 ? 0u - (uint64_t)n : (uint64_t)n;
    const uint64_t uq = fx_udiv64(un, (uint32_t)h);
    const uint32_t ur = (uint32_t)(un - uq * (uint32_t)h); /* < h */
    const int64_t f =
        (int64_t)fx_udiv64_32((uint64_t)ur << FINE_K_BITS, (uint32_t)h);
    *lo = n < 0 ? -f : f;
    return n < 0 ? -(int64_t)uq : (int64_t)uq;
}

/* The same for the side of a cone (axis through a, apex at height ya =
 * a.y + h, radius r at the base): Newton steps along d on g = |u|^2 -
 * (k W)^2, with u = p + q - a across the axis, W = ya - y the height below
 * the apex and k = r / h. k W is formed from the exact r and h, not the
 * rounded slope rt_upright.slope, whose 2^-24 is itself an ulp of a tall cone's
 * hit; each quotient carries FINE_K_BITS more fraction bits (its part
 * "lo"), so every product stays within 64 bits. Also sets n to the
 * normal (u, k^2 W) there, unnormalised, with 30 fraction bits. Returns 0,
 * and the caller takes p, as side_step does, or where a flat cone's
 * k^2 w leaves 2^32. Compiled for size (RT_COLD), as side_step. */
RT_COLD static int cone_step(const rt_ray *r, fx_t t, fx_vec3 p,
                             const rt_object *o, int32_t q[3], int64_t n[3],
                             int64_t *moved_t)
{
    const rt_upright *up = &o->u.upright;
    /* Q16.16, exact */
    const int64_t w = (int64_t)up->base.y + up->height - p.y;
    if (w <= 0 || w >= FINE_V_MAX || up->height <= 0)
        return 0; /* the apex, or past it */
    /* k w = R + e 2^-24, Q16.16 (r w < 2^61). */
    int64_t e;
    const int64_t rr = div_frac((int64_t)up->radius * w, up->height, &e);
    /* k^2 w, Q16.16, and its part below (|r R| < 2^62: R is about |u|). */
    if (rr >= FINE_V_MAX * (int64_t)2)
        return 0;
    int64_t kkw_lo;
    const int64_t kkw = div_frac((int64_t)up->radius * rr, up->height, &kkw_lo);
    if (kkw >= ((int64_t)1 << 32) || kkw <= -((int64_t)1 << 32))
        return 0;
    int32_t v[3];
    int64_t g0 = -rr * rr, vd = kkw * r->d.y;
    if (!fine_start(r, t, p, up->base, q, v, &g0, &vd))
        return 0;
    /* (k w)^2 = R^2 + 2 R e 2^-24 + e^2 2^-48: the last is below 2^-50. */
    const int64_t g1 = g0 * ((int64_t)1 << 14) -
                       shr_round(2 * rr * e, FINE_K_BITS - 14);
    int64_t kq, kq_lo;
    for (int step = 0, more = 1; more && step < 4; step++) {
        /* k qy = kq + kq_lo 2^-24, 30 fraction bits (r qy < 2^53). */
        kq = div_frac((int64_t)up->radius * q[1], up->height, &kq_lo);
        if (kq >= ((int64_t)1 << 30) || kq <= -((int64_t)1 << 30))
            return 0; /* a flat cone's k qy, kept to 32 bits */
        /* g at p + q with 46 fraction bits: (k W)^2 = (k w)^2 -
         * 2 (k w) (k qy) + (k qy)^2. */
        int64_t g = g1 + 2 * rr * kq +
                    shr_round(2 * (rr * kq_lo + e * kq), FINE_K_BITS) -
                    (fx_imul64((int32_t)kq, (int32_t)kq) >> 14);
        /* den = u.d + k^2 W dy (k^2 qy from 30 fraction bits to 16
         * first). */
        int64_t den =
            vd - shr_round(div_frac((int64_t)up->radius * kq, up->height,
                                    &kq_lo), 14) * r->d.y;
        fine_across(r, v, q, &g, &den);
        more = fine_move(r, g, den, q, moved_t);
        if (more < 0)
            return 0;
    }
    /* k^2 W with 30 fraction bits: k^2 w - k (k qy). */
    kq = div_frac((int64_t)up->radius * q[1], up->height, &kq_lo);
    int64_t lo;
    n[0] = (int64_t)v[0] * (1 << 14) + q[0];
    n[1] = kkw * (1 << 14) + shr_round(kkw_lo, FINE_K_BITS - 14) +
           shr_round(div_frac((int64_t)up->radius * e, up->height, &lo), 10) -
           div_frac((int64_t)up->radius * kq, up->height, &lo);
    n[2] = (int64_t)v[2] * (1 << 14) + q[2];
    return 1;
}

/* p moved by q (30 fraction bits), rounded to Q16.16. */
static fx_vec3 moved(fx_vec3 p, const int32_t q[3])
{
    return fx_v3(p.x + (fx_t)shr_round(q[0], 14),
                 p.y + (fx_t)shr_round(q[1], 14),
                 p.z + (fx_t)shr_round(q[2], 14));
}

/* A cylinder's or cone's side normal at the ray's own hit (side_step,
 * cone_step), with *pp moved there; the zero vector where the steps
 * decline. Out of line, so that rt_normal's frame, paid by every hit,
 * does not grow by theirs. */
RT_NOINLINE static fx_dir3 fine_normal(const rt_object *o, const rt_ray *r,
                                       fx_t t, fx_vec3 *pp)
{
    const rt_upright *up = &o->u.upright;
    const fx_vec3 p = *pp;
    int32_t q[3];
    int64_t moved_t = 0;
    if (o->kind == RT_CONE) {
        int64_t n[3];
        if (!cone_step(r, t, p, o, q, n, &moved_t))
            return fx_d3(0, 0, 0);
        *pp = moved(p, q);
        return fx_d3_normalize64(n[0], n[1], n[2]);
    }
    if (!side_step(r, t, p, up->base, up->radius, q, &moved_t))
        return fx_d3(0, 0, 0);
    *pp = moved(p, q);
    /* |p - a| across the axis is below 2^30 here (side_step). */
    return fx_d3_normalize64(((int64_t)p.x - up->base.x) * (1 << 14) + q[0], 0,
                             ((int64_t)p.z - up->base.z) * (1 << 14) + q[2]);
}

int rt_side_root(const rt_object *o, const rt_ray *r, fx_t t, int64_t *t30)
{
    const rt_upright *up = &o->u.upright;
    const fx_vec3 p = fx_v3_madd_d(r->o, r->d, t);
    int32_t q[3];
    int64_t n[3], moved_t = 0;
    if (!(o->kind == RT_CONE ? cone_step(r, t, p, o, q, n, &moved_t)
                             : side_step(r, t, p, up->base, up->radius, q,
                                         &moved_t)))
        return 0;
    *t30 = (int64_t)t * (1 << 14) + moved_t;
    return 1;
}

fx_dir3 rt_upright_normal(const rt_object *o, const rt_ray *r, fx_t t,
                          fx_vec3 *pp, unsigned part, int precise)
{
    const rt_upright *up = &o->u.upright;
    if (part == 1)
        return fx_d3(0, -FX_UONE, 0);
    if (part == 2)
        return fx_d3(0, FX_UONE, 0);
    if (precise) {
        const fx_dir3 n = fine_normal(o, r, t, pp);
        if (n.x != 0 || n.y != 0 || n.z != 0)
            return n;
    }
    const fx_vec3 p = *pp;
    fx_t x = fx_sub(p.x, up->base.x), z = fx_sub(p.z, up->base.z);
    if (o->kind == RT_CONE) {
        fx_t rho = (fx_t)fx_sqrt_q32((uint64_t)(fx_imul64(x, x)) +
                                     (uint64_t)(fx_imul64(z, z)));
        if (rho == 0)
            return fx_d3(0, FX_UONE, 0); /* apex */
        /* y = k rho, the slope with RT_FRAME_BITS fraction bits. */
        return fx_d3_normalize64(
            x, shr_round(fx_imul64(up->slope, rho), RT_FRAME_BITS), z);
    }
    return fx_d3_normalize(fx_v3(x, 0, z));
}
