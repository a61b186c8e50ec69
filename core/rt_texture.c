/* SPDX-License-Identifier: MIT */
/* rt_texture: procedural textures and bump noise, owned by materials. */
#include "rt_texture.h"

/* Low word of the cell index of p - a along one axis for cells of size
 * m->tex_scale, floor((p - a) / size), exact at any distance from the
 * origin a: the texel needs only the parity of the sum. The difference
 * is formed in 64 bits only when it exceeds Q16.16, that is when p and
 * a differ in sign and so do p and the wrapped difference (#17: rt_texel
 * 61 -> 42 instructions a call on the M3, 129 -> 108 on the M0). */
static inline uint32_t cell(const rt_material *m, fx_t p, fx_t a)
{
    fx_t rem;
    uint32_t d = (uint32_t)p - (uint32_t)a;
    if ((((uint32_t)p ^ (uint32_t)a) & ((uint32_t)p ^ d)) >> 31)
        return (uint32_t)fx_floor_div((int64_t)p - a, m->tex_scale,
                                      m->tex_rcp, &rem);
    return (uint32_t)fx_floor_div((int32_t)((int64_t)p - a), m->tex_scale,
                                  m->tex_rcp, &rem);
}

/* Textures follow the object, not the world origin: cells count from the
 * object's first point o->a. The unsigned sums wrap by definition and
 * keep the parity. */
unsigned rt_texel(const rt_material *m, const rt_object *o, fx_vec3 p)
{
    uint32_t idx;
    switch (m->texture) {
    case RT_TEX_STRIPES:
        idx = m->axis == 0 ? cell(m, p.x, o->a.x)
                           : (m->axis == 1 ? cell(m, p.y, o->a.y)
                                           : cell(m, p.z, o->a.z));
        break;
    case RT_TEX_CHECKER:
        idx = cell(m, p.x, o->a.x) + cell(m, p.z, o->a.z);
        break;
    case RT_TEX_CHECKER3D:
        idx = cell(m, p.x, o->a.x) + cell(m, p.y, o->a.y) +
              cell(m, p.z, o->a.z);
        break;
    default:
        return 0;
    }
    return idx & 1u;
}

/* Lattice value in [-1, 1) with 30 fraction bits (17 significant): the
 * integer hash of docs/render-model.md, unsigned so every product wraps
 * by definition. */
static int32_t lattice(uint32_t seed, uint32_t ix, uint32_t iy, uint32_t iz)
{
    uint32_t h = (ix * 73856093u) ^ (iy * 19349663u) ^ (iz * 83492791u) ^
                 (seed * 2654435761u);
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return ((int32_t)(h >> 15) - FX_ONE) * (1 << 14);
}

/* The noise works with 30 fraction bits: in Q16.16 its rounding, and a
 * fraction from the rounded reciprocal of a large lattice, tilted a
 * strong bump's normal by up to 3e-4, which glass of an extreme index
 * turns into another path (docs/stability-cases.md). */
#define NOISE_BITS 30

/* lo + s (hi - lo), s in [0, 1): within [lo, hi], so the sum fits. */
static int32_t lerp(int32_t lo, int32_t hi, int32_t s)
{
    const int64_t half = (int64_t)1 << (NOISE_BITS - 1);
    /* hi - lo fits 32 bits: both are in [-1, 1). */
    return lo + (int32_t)((fx_imul64(s, hi - lo) + half) >> NOISE_BITS);
}

/* Smoothstep weight f^2 (3 - 2f) for f in [0, 1). */
static int32_t smooth(int32_t f)
{
    const int64_t half = (int64_t)1 << (NOISE_BITS - 1);
    const int64_t f2 = (fx_imul64(f, f) + half) >> NOISE_BITS;
    const uint32_t w = (uint32_t)(3u << NOISE_BITS) - 2u * (uint32_t)f;
    return (int32_t)((fx_iumul64((int32_t)f2, w) + half) >> NOISE_BITS);
}

/* Trilinear value noise in lattice cell i (coordinates modulo 2^32, as
 * the hash takes them) at fractions s, with NOISE_BITS fraction bits. */
static int32_t noise(uint32_t seed, const uint32_t i[3], const int32_t s[3])
{
    int32_t zv[2];
    for (int dz = 0; dz < 2; dz++) {
        int32_t yv[2];
        for (int dy = 0; dy < 2; dy++) {
            uint32_t y = i[1] + (uint32_t)dy, z = i[2] + (uint32_t)dz;
            int32_t v0 = lattice(seed, i[0], y, z);
            int32_t v1 = lattice(seed, i[0] + 1u, y, z);
            yv[dy] = lerp(v0, v1, s[0]);
        }
        zv[dz] = lerp(yv[0], yv[1], s[1]);
    }
    return lerp(zv[0], zv[1], s[2]);
}

fx_dir3 rt_bump(const rt_material *m, const rt_object *o, fx_vec3 p,
                fx_dir3 n)
{
    /* Lattice cell i = floor((p - a) / size), exact, and the fraction
     * within it, rem / size, with NOISE_BITS fraction bits, rounded down
     * (rem < size, so the quotient is below 2^NOISE_BITS). */
    const fx_t pk[3] = { p.x, p.y, p.z }, ak[3] = { o->a.x, o->a.y, o->a.z };
    uint32_t i[3];
    int32_t s[3];
    for (int k = 0; k < 3; k++) {
        fx_t rem;
        i[k] = (uint32_t)fx_floor_div((int64_t)pk[k] - ak[k],
                                      m->bump_scale, m->bump_rcp, &rem);
        s[k] = smooth((int32_t)fx_udiv64_32(
            (uint64_t)(uint32_t)rem << NOISE_BITS, (uint32_t)m->bump_scale));
    }
    /* norm(n + bump g), with FX_UBITS fraction bits: g bump has
     * 16 + NOISE_BITS (|g| <= 1, |bump| < 2^31: below 2^61). */
    const int32_t g[3] = { noise(1, i, s), noise(2, i, s), noise(3, i, s) };
    const int sh = 16 + NOISE_BITS - FX_UBITS;
    const int64_t half = (int64_t)1 << (sh - 1);
    return fx_d3_normalize64(
        (int64_t)n.x + ((fx_imul64(g[0], m->bump) + half) >> sh),
        (int64_t)n.y + ((fx_imul64(g[1], m->bump) + half) >> sh),
        (int64_t)n.z + ((fx_imul64(g[2], m->bump) + half) >> sh));
}
