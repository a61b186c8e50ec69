/* SPDX-License-Identifier: MIT */
/* rt_shape: ray-shape intersection and surface normals, for every kind
 * through one dispatch (rt_shape.c; each kind's file is listed in
 * rt_kinds.h). Internal to the core. */
#ifndef RT_SHAPE_H
#define RT_SHAPE_H

#include "rt_kinds.h"

/* Ray-object intersection: the nearest t with tmin < t < tmax. Returns 1
 * and sets *t and *part (which face, cap or side; a mesh's triangle) on a
 * hit, else 0. A kind this build removed (RT_NO_SPHERE, ...) never
 * hits. */
int rt_intersect(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                 fx_t *t, uint16_t *part);

/* 1 if c = a p - b q (a component of oc x d: oc = c - o for a small
 * sphere (c, r) and ray, so |a|, |b| < 2^30, and unit components p and
 * q) is surely beyond +-(r + 4) 2^FX_UBITS. |oc x d| is |d| (within
 * 2^-28 of 1) times the centre's distance from the ray's line, so that
 * distance is then over r + 1 ulps, and bsphere's own tests (h within an
 * ulp of it) miss too: the same answers, without the closest approach.
 * fx_cross_hi gives c 2^-32 to within 2, taken against +-(k + 2), k
 * 2^32 >= (r + 5) 2^30 (r < 2^29): the ulps this gives away do not
 * matter. */
static inline int rt_miss_cross(int32_t a, int32_t p, int32_t b, int32_t q,
                                fx_t r)
{
    const uint32_t k1 = ((uint32_t)r >> 2) + 3u; /* k + 1 */
    /* ch >= k + 2 or ch <= -k - 2, in one unsigned compare. */
    return (uint32_t)fx_cross_hi(a, p, b, q) + k1 > 2u * k1;
}

/* rt_miss_cross for |a|, |b| < 2^23 and r < 2^22, from one 32-bit
 * product a term: c is taken as C 2^24, C = (a >> 8) (p >> 16) - (b >>
 * 8) (q >> 16). With a = A 2^8 + a0 and p = P 2^16 + p0 (a0, p0 >= 0),
 * a p - A P 2^24 = A p0 2^8 + a0 P 2^16 + a0 p0 is below (|A| + |P| +
 * 1) 2^24 <= (2^15 + 2^14 + 2) 2^24, so |c - C 2^24| < 98308 2^24, and
 * |C| >= k = (floor(r / 32) + 50) 2^11 > 64 r + 98563 makes |c| > (r +
 * 4) 2^30 as there. |C| <= 2^30 + 2^16: no overflow. */
static inline int rt_miss_cross_near(int32_t a, int32_t p, int32_t b,
                                     int32_t q, fx_t r)
{
    const int32_t c = (a >> 8) * (p >> 16) - (b >> 8) * (q >> 16);
    const uint32_t t = ((uint32_t)r >> 5) + 50u;
    /* C >= k or C <= -k - 1: C + k >= 2k, unsigned. */
    return ((uint32_t)c + (t << 11)) >> 12 >= t;
}

/* 1 if ray r surely misses object o: every shape but the quad is first
 * tested against its bounding sphere (bc, br; for a mesh when both are
 * small), so a ray passing it by misses. near: o is small and its bc
 * and br and r's origin are within 2^22 (64 units; rt_dir_grids.near),
 * so the 32-bit products of rt_miss_cross_near apply. */
static inline int rt_passes_by(const rt_object *o, const rt_ray *r,
                               int near)
{
    if (o->kind == RT_QUAD)
        return 0;
    /* The y and x components of oc x d: of the seed's tests, the first
     * rejects most, the two together more than three quarters; the z
     * one costs more than it saves. near implies both small. */
    if (near) {
        const int32_t oz = o->bc.z - r->o.z;
        return rt_miss_cross_near(oz, r->d.x, o->bc.x - r->o.x, r->d.z,
                                  o->br) ||
               rt_miss_cross_near(o->bc.y - r->o.y, r->d.z, oz, r->d.y,
                                  o->br);
    }
    if (!o->small || !r->small)
        return 0;
    const int32_t ox = o->bc.x - r->o.x, oy = o->bc.y - r->o.y;
    const int32_t oz = o->bc.z - r->o.z;
    return rt_miss_cross(oz, r->d.x, ox, r->d.z, o->br) ||
           rt_miss_cross(oy, r->d.z, oz, r->d.y, o->br);
}

/* Outward unit normal of o on the given part where ray r hits it at t.
 * *p is the hit point o + t d, rounded. With precise set (for a hit that
 * casts reflected or refracted rays, whose directions inherit the
 * normal's error), on a cylinder's side *p becomes the point of the side
 * where the ray meets it, rounded, and the normal is taken there: the
 * rounding of t and of p moves o + t d off the side
 * (rt_upright_normal.c). */
fx_dir3 rt_normal(const rt_object *o, const rt_ray *r, fx_t t, fx_vec3 *p,
                  uint16_t part, int precise);

#endif /* RT_SHAPE_H */
