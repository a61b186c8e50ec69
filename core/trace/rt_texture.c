/* SPDX-License-Identifier: MIT */
/* rt_texture: procedural textures and bump noise, owned by materials. */
#include "rt_texture.h"
#include "fx_rsqrt.h" /* fx_umulhi32 */

/* floor((p - a) / d), d > 0, where p - a overflows int32 (p and a of
 * opposite signs, 2^31 < |p - a| < 2^32): its low word, with the
 * remainder, in [0, d), in the high word (a register pair, no memory).
 * The magnitude fits 32 bits, so one 32-bit divide gives it, not a
 * 64-bit library divide; below zero the floor is -q - 1 (~q in the low
 * word) unless the division is exact. */
static inline uint64_t floor_div_far(fx_t p, fx_t a, fx_t d)
{
    const uint32_t w = (uint32_t)p - (uint32_t)a; /* p - a mod 2^32 */
    const uint32_t ud = (uint32_t)d;
    if (p >= 0) { /* p - a in (2^31, 2^32): w itself */
        const uint32_t q = w / ud;
        return fx_pair64(w - q * ud, q);
    }
    const uint32_t m = 0u - w; /* a - p, in (2^31, 2^32) */
    const uint32_t q = m / ud, r = m - q * ud;
    return r ? fx_pair64(ud - r, ~q) : fx_pair64(0, 0u - q);
}

/* A word whose sign bit is set where p - a overflows int32: where p and
 * a differ in sign, and so do p and the wrapped difference. */
static inline uint32_t far_bit(fx_t p, fx_t a)
{
    const uint32_t d = (uint32_t)p - (uint32_t)a;
    return ((uint32_t)p ^ (uint32_t)a) & ((uint32_t)p ^ d);
}

/* 1 where p - a overflows int32. */
static inline int far_apart(fx_t p, fx_t a)
{
    return (int)(far_bit(p, a) >> 31);
}

/* The hit a texel is read for: ray r at t on an object, its outward unit
 * normal n_out. */
typedef struct {
    const rt_ray *r;
    fx_t t;
    fx_dir3 n_out;
} tex_hit;

/* How near a cell's edge, in Q16.16 ulps, the rounded point read must lie
 * for cell_edge to decide the cell: the point is o + t d rounded, moved
 * 2^-RT_EPS_LOG2 along the normal and rounded again, and t is rounded, so
 * it lies within 2 ulps of the hit of the ray's rounded t and the
 * rounded hit's exact one; twice that is the margin. */
#define TEX_NEAR 4

/* The exact hit is taken to 2^-(16 + TEX_FINE_BITS), about float32's
 * step at 2 to 4 units: finer, the rounding of the ray's own direction
 * (2^-FX_UBITS) would split a point the scene puts exactly on an edge,
 * which the reference keeps on it. Rounded to nearest; a point that
 * rounds onto the edge is in the cell above it. */
#define TEX_FINE_BITS 6

/* The hit's component i (x, y, z for 0, 1, 2). */
static inline int32_t comp(fx_vec3 v, unsigned i)
{
    return i == 0 ? v.x : (i == 1 ? v.y : v.z);
}

static inline int32_t dcomp(fx_dir3 v, unsigned i)
{
    return i == 0 ? v.x : (i == 1 ? v.y : v.z);
}

/* The cell along axis i of the hit h on object o, read at pi (the
 * rounded point's component) which lies rem from the start of cell k
 * (rem < TEX_NEAR) or s - rem from its end: the side of that edge B of
 * the exact hit, moved 2^-RT_EPS_LOG2 inside as the point is. A face in
 * an axis plane (a floor quad's, a box's) holds the hit exactly: the ray
 * meets plane x_j = P at x_i = o_i + d_i (P - o_j) / d_j, whose side of
 * B is that of (o_i - B) d_j + d_i (P - o_j) over d_j, from two exact
 * products; along j itself the point is P less the offset. Any other hit
 * takes o + t d with every bit of t d (16 + FX_UBITS fraction bits). The
 * point is then rounded to TEX_FINE_BITS more bits than Q16.16 and, on
 * the edge, is in the cell above it, as the floor of the division puts
 * an exact point. Out of these ranges, and where p is finer than o + t d
 * already, the rounded point stands. */
RT_NOINLINE static uint32_t cell_edge(const rt_material *m,
                                      const tex_hit *h, const rt_object *o,
                                      unsigned i, fx_t pi, uint32_t k,
                                      fx_t rem)
{
    const rt_ray *r = h->r;
    const fx_t s = m->tex_scale;
    const int up = rem >= TEX_NEAR; /* near the cell's far edge */
    const uint32_t above = up ? k + 1u : k; /* the cell from B up */
    const int64_t pb = up ? (int64_t)rem - s : rem; /* pi - B */
    const int64_t ob = (int64_t)comp(r->o, i) - pi + pb; /* o_i - B */
    const int32_t di = dcomp(r->d, i), ni = dcomp(h->n_out, i);
    int64_t w;
    unsigned j = 3; /* the axis of the face's plane, if any */
    fx_t plane = 0;
    if (o->kind == RT_QUAD && o->u.quad.flat &&
        (o->u.quad.normal.y == FX_UONE || o->u.quad.normal.y == -FX_UONE)) {
        j = 1;
        plane = o->u.quad.corner.y;
    } else if (o->kind == RT_BOX) {
        for (unsigned a = 0; a < 3; a++)
            if (dcomp(h->n_out, a) != 0) {
                j = a;
                plane = dcomp(h->n_out, a) > 0 ? comp(o->u.box.max, a)
                                                : comp(o->u.box.min, a);
            }
    }
    /* A reflective or transparent upright's p is its hit refined
     * already (rt_upright_normal), finer than o + t d. */
    if (ob < INT32_MIN || ob > INT32_MAX ||
        ((o->kind == RT_CYLINDER || o->kind == RT_CONE) &&
         (m->reflect > 0 || m->transparency > 0)))
        return k;
    if (j == i) {
        const int64_t q = (int64_t)plane - pi + pb; /* P - B */
        if (q < INT32_MIN || q > INT32_MAX)
            return k;
        w = q * FX_UONE - (int64_t)ni * ((int64_t)1 << RT_EPS_LOG2);
    } else if (j < 3 && dcomp(r->d, j) != 0) {
        const int32_t dj = dcomp(r->d, j);
        const int64_t pm = (int64_t)plane - comp(r->o, j); /* P - o_j */
        if (pm < INT32_MIN || pm > INT32_MAX)
            return k;
        const int64_t e = fx_imul64((int32_t)ob, dj) +
                          fx_imul64(di, (int32_t)pm); /* (x_i - B) d_j */
        const uint32_t adj = (uint32_t)(dj < 0 ? -dj : dj);
        return (dj < 0 ? -e : e) >= -(int64_t)(adj >> (TEX_FINE_BITS + 1))
                   ? above
                   : above - 1u;
    } else {
        w = ob * FX_UONE + fx_imul64(h->t, di) -
            (int64_t)ni * ((int64_t)1 << RT_EPS_LOG2);
    }
    /* w is x_i - B with 16 + FX_UBITS fraction bits. */
    return w >= -((int64_t)1 << (FX_UBITS - TEX_FINE_BITS - 1)) ? above
                                                                : above - 1u;
}

/* Low word of the cell index of p - a along axis i for cells of size
 * m->tex_scale, floor((p - a) / size), for a difference that fits int32
 * (not far_apart): the texel needs only the parity of the sum, so a
 * 32-bit word of it will do. Within TEX_NEAR of an edge, the hit h
 * decides (cell_edge). */
static inline uint32_t cell(const rt_material *m, const tex_hit *h,
                            const rt_object *o, unsigned i, fx_t p, fx_t a)
{
    fx_t rem;
    const fx_t s = m->tex_scale;
    const uint32_t k = (uint32_t)fx_floor_div((int32_t)((int64_t)p - a), s,
                                              m->tex_rcp, &rem);
    /* rem < TEX_NEAR or rem >= s - TEX_NEAR, for s > 2 TEX_NEAR. */
    if ((uint32_t)(rem - TEX_NEAR) >= (uint32_t)(s - 2 * TEX_NEAR))
        return cell_edge(m, h, o, i, p, k, rem);
    return k;
}

/* The same at any distance from the origin a; far from it, the rounded
 * point decides. */
static inline uint32_t cell_any(const rt_material *m, const tex_hit *h,
                                const rt_object *o, unsigned i, fx_t p,
                                fx_t a)
{
    if (far_apart(p, a))
        return (uint32_t)floor_div_far(p, a, m->tex_scale);
    return cell(m, h, o, i, p, a);
}

/* rt_texel where some difference overflows int32 (points over 32,768
 * units from the object's origin). */
static unsigned texel_far(const rt_material *m, const tex_hit *h,
                          const rt_object *o, const fx_vec3 *p)
{
    uint32_t idx = cell_any(m, h, o, 0, p->x, o->u.origin.x) +
                   cell_any(m, h, o, 2, p->z, o->u.origin.z);
    if (m->texture == RT_TEX_STRIPES)
        idx = cell_any(m, h, o, m->axis, comp(*p, m->axis),
                       comp(o->u.origin, m->axis));
    else if (m->texture == RT_TEX_CHECKER3D)
        idx += cell_any(m, h, o, 1, p->y, o->u.origin.y);
    return idx & 1u;
}

/* Textures follow the object, not the world origin: cells count from the
 * object's first point o->u.origin. The unsigned sums wrap by definition and
 * keep the parity. */
unsigned rt_texel(const rt_material *m, const rt_object *o, const rt_ray *r,
                  fx_t t, fx_dir3 n_out, fx_vec3 p)
{
    const tex_hit h = { r, t, n_out };
    uint32_t idx;
    switch (m->texture) {
    case RT_TEX_STRIPES:
        if (m->axis == 0) {
            if (far_apart(p.x, o->u.origin.x))
                return texel_far(m, &h, o, &p);
            idx = cell(m, &h, o, 0, p.x, o->u.origin.x);
        } else if (m->axis == 1) {
            if (far_apart(p.y, o->u.origin.y))
                return texel_far(m, &h, o, &p);
            idx = cell(m, &h, o, 1, p.y, o->u.origin.y);
        } else {
            if (far_apart(p.z, o->u.origin.z))
                return texel_far(m, &h, o, &p);
            idx = cell(m, &h, o, 2, p.z, o->u.origin.z);
        }
        break;
    case RT_TEX_CHECKER:
        if ((far_bit(p.x, o->u.origin.x) | far_bit(p.z, o->u.origin.z)) >> 31)
            return texel_far(m, &h, o, &p);
        idx = cell(m, &h, o, 0, p.x, o->u.origin.x) + cell(m, &h, o, 2, p.z, o->u.origin.z);
        break;
    case RT_TEX_CHECKER3D:
        if ((far_bit(p.x, o->u.origin.x) | far_bit(p.y, o->u.origin.y) |
             far_bit(p.z, o->u.origin.z)) >> 31)
            return texel_far(m, &h, o, &p);
        idx = cell(m, &h, o, 0, p.x, o->u.origin.x) + cell(m, &h, o, 1, p.y, o->u.origin.y) +
              cell(m, &h, o, 2, p.z, o->u.origin.z);
        break;
    default:
        return 0;
    }
    return idx & 1u;
}

/* The hash of docs/render-model.md at lattice point (x, y, z) for noise
 * seed, its top 17 bits k in [0, 2^17); the lattice value is k - 2^16
 * over 2^16, in [-1, 1), held with 30 fraction bits as (k - 2^16) 2^14.
 * The point's terms x 73856093 ^ y 19349663 ^ z 83492791 (pt) are shared
 * by the three seeds. Unsigned, so every product wraps by definition. */
static inline uint32_t lattice_k(uint32_t pt, uint32_t seed)
{
    uint32_t h = pt ^ (seed * 2654435761u);
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return h >> 15;
}

/* The noise works with 30 fraction bits: in Q16.16 its rounding, and a
 * fraction from the rounded reciprocal of a large lattice, tilted a
 * strong bump's normal by up to 3e-4, which glass of an extreme index
 * turns into another path (docs/stability-cases.md). */
#define NOISE_BITS 30

/* lo + s (hi - lo), s in [0, 1]: within [lo, hi], so the sum fits; s
 * is taken unsigned, as it is. */
static int32_t lerp(int32_t lo, int32_t hi, int32_t s)
{
    const int64_t half = (int64_t)1 << (NOISE_BITS - 1);
    /* hi - lo fits 32 bits: both are in [-1, 1). */
    const int64_t p = fx_iumul64(hi - lo, (uint32_t)s);
    return lo + (int32_t)((p + half) >> NOISE_BITS);
}

/* lerp of the lattice values of k0 and k1: with hi - lo = dk 2^14, the
 * step is floor((s dk + 2^15) / 2^16), |s dk| < 2^47: with s = sh 2^16 +
 * sl and dk = dh 2^16 + dl (dl and sl unsigned, dh in [-2, 1]), sh dk +
 * sl dh + floor((sl dl + 2^15) / 2^16) from three 32-bit products; the
 * sum is formed unsigned, which wraps by definition, and the step fits
 * int32. */
static inline int32_t lerp_k(uint32_t k0, uint32_t k1, int32_t s)
{
    const int32_t lo = ((int32_t)k0 - FX_ONE) * (1 << 14);
    const int32_t dk = (int32_t)k1 - (int32_t)k0;
    const uint32_t sl = (uint32_t)s & 0xFFFFu, dl = (uint32_t)dk & 0xFFFFu;
    const uint32_t step = (uint32_t)((s >> 16) * dk) +
                          (uint32_t)((int32_t)sl * (dk >> 16)) +
                          ((sl * dl + 0x8000u) >> 16);
    return lo + (int32_t)step;
}

/* Smoothstep weight f^2 (3 - 2f) for f in [0, 1). */
static int32_t smooth(int32_t f)
{
    const int64_t half = (int64_t)1 << (NOISE_BITS - 1);
    const int64_t f2 = (fx_imul64(f, f) + half) >> NOISE_BITS;
    const uint32_t w = (uint32_t)(3u << NOISE_BITS) - 2u * (uint32_t)f;
    return (int32_t)((fx_iumul64((int32_t)f2, w) + half) >> NOISE_BITS);
}

/* The lerp along x of seed's values at the corners x0 ^ yz and x1 ^ yz
 * (the hash terms of two corners that differ in x only). noise3 writes
 * its four out rather than loop over them: the hash terms stay in
 * registers. */
static inline int32_t edge(uint32_t x0, uint32_t x1, uint32_t yz,
                           uint32_t seed, int32_t s)
{
    return lerp_k(lattice_k(x0 ^ yz, seed), lattice_k(x1 ^ yz, seed), s);
}

/* Trilinear value noise of seeds 1, 2 and 3 in lattice cell i
 * (coordinates modulo 2^32, as the hash takes them) at fractions s, with
 * NOISE_BITS fraction bits; the corners' terms of the hash are formed
 * once for the three. */
static void noise3(const uint32_t i[3], const int32_t s[3], int32_t g[3])
{
    const uint32_t x0 = i[0] * 73856093u, y0 = i[1] * 19349663u,
                   z0 = i[2] * 83492791u;
    const uint32_t x1 = x0 + 73856093u, y1 = y0 + 19349663u,
                   z1 = z0 + 83492791u;
    const uint32_t yz[4] = { y0 ^ z0, y1 ^ z0, y0 ^ z1, y1 ^ z1 };
    for (uint32_t seed = 1; seed <= 3; seed++) {
        const int32_t v0 = edge(x0, x1, yz[0], seed, s[0]),
                      v1 = edge(x0, x1, yz[1], seed, s[0]),
                      v2 = edge(x0, x1, yz[2], seed, s[0]),
                      v3 = edge(x0, x1, yz[3], seed, s[0]);
        g[seed - 1] = lerp(lerp(v0, v1, s[1]), lerp(v2, v3, s[1]), s[2]);
    }
}

/* One 15-bit digit of a quotient by d <= 2^17: q = floor(x / d) for x
 * < 2^32, its remainder to *r, with no divide (a library call on a core
 * without one): floor(x rcp / 2^32) with rcp = fx_floor_rcp(d) is never
 * above q and at most 2 below it (rcp > (2^32 - 1) / d - 1), and the
 * remainder, below 3d, corrects it. */
static inline uint32_t frac_digit(uint32_t x, uint32_t d, uint32_t rcp,
                                  uint32_t *r)
{
    uint32_t q = fx_umulhi32(x, rcp), rr = x - q * d;
    while (rr >= d) {
        q++;
        rr -= d;
    }
    *r = rr;
    return q;
}

/* Lattice cell i = floor((p - a) / size) of one axis, exact, and the
 * fraction within it, rem / size, with NOISE_BITS fraction bits, rounded
 * down (rem < size, so the quotient is below 2^NOISE_BITS), smoothed.
 * For a size up to 2 units (2^17) the fraction is two 15-bit digits,
 * each r 2^15 < size 2^15 <= 2^32, not a 64-bit divide. The cell is
 * formed as in cell. */
static inline void lattice_axis(const rt_material *m, fx_t p, fx_t a,
                                uint32_t *i, int32_t *s)
{
    const uint32_t d = (uint32_t)m->bump_scale;
    fx_t rem;
    uint32_t f, r;
    if (far_apart(p, a)) {
        const uint64_t qr = floor_div_far(p, a, m->bump_scale);
        *i = (uint32_t)qr;
        rem = (fx_t)(qr >> 32);
    } else {
        *i = (uint32_t)fx_floor_div((int32_t)((int64_t)p - a),
                                    m->bump_scale, m->bump_rcp, &rem);
    }
    if (d <= 1u << 17) {
        f = frac_digit((uint32_t)rem << 15, d, m->bump_rcp, &r) << 15;
        f |= frac_digit(r << 15, d, m->bump_rcp, &r);
    } else {
        f = fx_udiv64_32((uint64_t)(uint32_t)rem << NOISE_BITS, d);
    }
    *s = smooth((int32_t)f);
}

fx_dir3 rt_bump(const rt_material *m, const rt_object *o, fx_vec3 p,
                fx_dir3 n)
{
    uint32_t i[3];
    int32_t s[3];
    lattice_axis(m, p.x, o->u.origin.x, &i[0], &s[0]);
    lattice_axis(m, p.y, o->u.origin.y, &i[1], &s[1]);
    lattice_axis(m, p.z, o->u.origin.z, &i[2], &s[2]);
    /* norm(n + bump g), with FX_UBITS fraction bits: g bump has
     * 16 + NOISE_BITS (|g| <= 1, |bump| < 2^31: below 2^61). */
    int32_t g[3];
    noise3(i, s, g);
    const int sh = 16 + NOISE_BITS - FX_UBITS;
    const int64_t half = (int64_t)1 << (sh - 1);
    return fx_d3_normalize64(
        (int64_t)n.x + ((fx_imul64(g[0], m->bump) + half) >> sh),
        (int64_t)n.y + ((fx_imul64(g[1], m->bump) + half) >> sh),
        (int64_t)n.z + ((fx_imul64(g[2], m->bump) + half) >> sh));
}
