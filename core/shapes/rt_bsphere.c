/* SPDX-License-Identifier: MIT */
/*
 * rt_bsphere: what the hit tests share out of line: the bounding-sphere
 * test's rare case, a ray within rounding of the sphere's silhouette
 * (rt_bsphere.h states the contract), kept out of line so that the
 * inlined common test stays small in every shape; and the distance to an
 * axis-aligned plane (rt_kinds.h).
 */
#include "rt_bsphere.h"
#include "rt_kinds.h"

uint64_t rt_bsphere_fine(const fx_vec3 *c, int64_t t, const rt_ray *ray,
                         fx_t r)
{
    const int64_t ox = (int64_t)c->x - ray->o.x;
    const int64_t oy = (int64_t)c->y - ray->o.y;
    const int64_t oz = (int64_t)c->z - ray->o.z;
    int e = fx_clz32((uint32_t)r) - 2; /* >= 1, as r < 2^29 */
    if (e > FX_USHIFT)
        e = FX_USHIFT;
    const int sh = FX_UBITS - e; /* >= 16 */
    const int64_t sc = (int64_t)1 << e, half = (int64_t)1 << (sh - 1);
    /* |h| is near r, so each fine component is below 2^30 + 2^e. */
    const int64_t hx = ox * sc - ((t * ray->d.x + half) >> sh);
    const int64_t hy = oy * sc - ((t * ray->d.y + half) >> sh);
    const int64_t hz = oz * sc - ((t * ray->d.z + half) >> sh);
    const uint64_t h2 = (uint64_t)(hx * hx) + (uint64_t)(hy * hy) +
                        (uint64_t)(hz * hz);
    const uint64_t re = (uint64_t)r << e;
    const uint64_t r2 = re * re;
    if (h2 > r2)
        return RT_BSPHERE_MISS;
    return (r2 - h2) >> (2 * e);
}

int64_t rt_plane_t(int64_t p, fx_t o, int32_t d)
{
    int64_t dp = p - o; /* |p - o| < 2^33 */
    int neg = (dp < 0) != (d < 0);
    uint64_t adp = (uint64_t)(dp < 0 ? -dp : dp);
    uint32_t ud = (uint32_t)(d < 0 ? -(int64_t)d : d); /* <= 2^FX_UBITS */
    /* t = |p - o| 2^FX_UBITS / |d| in Q16.16; at |p - o| >= 2^32 it is
     * 2^32 or more, as |d| <= 2^FX_UBITS. */
    if ((adp >> 32) != 0 || ((adp << FX_UBITS) >> 32) >= ud)
        return neg ? -INT64_MAX : INT64_MAX;
    /* Rounded: floor((n + floor(d / 2)) / d), as a quad's. */
    uint64_t un = (adp << FX_UBITS) + (ud >> 1);
    if ((un >> 32) >= ud)
        return neg ? -INT64_MAX : INT64_MAX;
    int64_t q = fx_udiv64_32(un, ud);
    return neg ? -q : q;
}
