/* rt_texture: procedural textures and bump noise, owned by materials. */
#include "rt_texture.h"

/* Local point: textures follow the object, not the world origin. */
static fx_vec3 local_point(const rt_object *o, fx_vec3 p)
{
    return fx_v3_sub(p, o->a);
}

unsigned rt_texel(const rt_material *m, const rt_object *o, fx_vec3 p)
{
    fx_vec3 q = local_point(o, p);
    int32_t idx;
    switch (m->texture) {
    case RT_TEX_STRIPES: {
        fx_t c = m->axis == 0 ? q.x : (m->axis == 1 ? q.y : q.z);
        idx = fx_floor_int(fx_mul(c, m->tex_inv));
        break;
    }
    case RT_TEX_CHECKER:
        idx = fx_floor_int(fx_mul(q.x, m->tex_inv)) +
              fx_floor_int(fx_mul(q.z, m->tex_inv));
        break;
    case RT_TEX_CHECKER3D:
        idx = fx_floor_int(fx_mul(q.x, m->tex_inv)) +
              fx_floor_int(fx_mul(q.y, m->tex_inv)) +
              fx_floor_int(fx_mul(q.z, m->tex_inv));
        break;
    default:
        return 0;
    }
    return (unsigned)idx & 1u;
}

/* Lattice value in [-1, 1): the integer hash of docs/render-model.md,
 * unsigned so every product wraps by definition. */
static fx_t lattice(uint32_t seed, int32_t ix, int32_t iy, int32_t iz)
{
    uint32_t h = ((uint32_t)ix * 73856093u) ^ ((uint32_t)iy * 19349663u) ^
                 ((uint32_t)iz * 83492791u) ^ (seed * 2654435761u);
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return (fx_t)(h >> 15) - FX_ONE;
}

static fx_t lerp(fx_t lo, fx_t hi, fx_t s)
{
    return fx_add(lo, fx_mul(s, fx_sub(hi, lo)));
}

/* Smoothstep weight f^2 (3 - 2f) for f in [0, 1). */
static fx_t smooth(fx_t f)
{
    return fx_mul(fx_mul(f, f), FX_INT(3) - 2 * f);
}

/* Trilinear value noise at u (Q16.16 lattice units). */
static fx_t noise(uint32_t seed, const int32_t i[3], const fx_t s[3])
{
    fx_t zv[2];
    for (int dz = 0; dz < 2; dz++) {
        fx_t yv[2];
        for (int dy = 0; dy < 2; dy++) {
            fx_t v0 = lattice(seed, i[0], i[1] + dy, i[2] + dz);
            fx_t v1 = lattice(seed, i[0] + 1, i[1] + dy, i[2] + dz);
            yv[dy] = lerp(v0, v1, s[0]);
        }
        zv[dz] = lerp(yv[0], yv[1], s[1]);
    }
    return lerp(zv[0], zv[1], s[2]);
}

fx_vec3 rt_bump(const rt_material *m, const rt_object *o, fx_vec3 p,
                fx_vec3 n)
{
    fx_vec3 q = local_point(o, p);
    fx_t u[3] = { fx_mul(q.x, m->bump_inv), fx_mul(q.y, m->bump_inv),
                  fx_mul(q.z, m->bump_inv) };
    int32_t i[3];
    fx_t s[3];
    for (int k = 0; k < 3; k++) {
        i[k] = fx_floor_int(u[k]);
        s[k] = smooth(u[k] & 0xFFFF);
    }
    fx_vec3 g = fx_v3(noise(1, i, s), noise(2, i, s), noise(3, i, s));
    return fx_v3_normalize(fx_v3_madd(n, g, m->bump));
}
