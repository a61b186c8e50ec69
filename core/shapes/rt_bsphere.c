/* SPDX-License-Identifier: MIT */
/*
 * rt_bsphere: the bounding-sphere test's rare case, a ray within rounding
 * of the sphere's silhouette (rt_bsphere.h states the contract). Out of
 * line, so that the inlined common test stays small in every shape.
 */
#include "rt_bsphere.h"

int rt_bsphere_fine(const fx_vec3 *c, int64_t t, const rt_ray *ray, fx_t r,
                    uint64_t *disc)
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
        return 0;
    *disc = (r2 - h2) >> (2 * e);
    return 1;
}
