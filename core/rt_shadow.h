/* rt_shadow: which objects can block a shadow ray to a light. Internal. */
#ifndef RT_SHADOW_H
#define RT_SHADOW_H

#include "rt_internal.h"

#if !defined(RT_NO_SHADOWS) && RT_SHADOW_GRID > 0

/* Words of one object bit set. */
#define RT_SHADOW_WORDS ((RT_MAX_OBJECTS + 31) / 32)

/* Directions u from one light, on a grid over (u.x, u.z) per hemisphere of
 * u.y: each cell lists the objects whose bounding sphere, widened for every
 * rounding of the shadow ray, some direction in the cell can reach. */
typedef struct {
    fx_t x0, z0;   /* lower corner of the gridded square of (u.x, u.z) */
    fx_t x1, z1;   /* upper corner; outside it no object can block */
    fx_t sx, sz;   /* cells per unit of u.x and u.z (Q16.16) */
    uint32_t cell[2][RT_SHADOW_GRID * RT_SHADOW_GRID][RT_SHADOW_WORDS];
} rt_shadow_grid;

/* Fills g for light position lp in scene s. */
void rt_shadow_prepare(rt_shadow_grid *g, const rt_scene *s, fx_vec3 lp);

/* The objects that may block a shadow ray whose unit direction towards the
 * light is ld (from any hit point of s), or NULL when none can. */
static inline const uint32_t *rt_shadow_cell(const rt_shadow_grid *g,
                                             fx_vec3 ld)
{
    /* u = -ld points from the light to the surface. */
    const fx_t ux = -ld.x, uz = -ld.z;
    if (ux < g->x0 || ux > g->x1 || uz < g->z0 || uz > g->z1)
        return 0;
    /* (u - x0) * sx is below 2^18 * 2^27: the cell is the high word. */
    uint32_t ix = (uint32_t)(((int64_t)(ux - g->x0) * g->sx) >> 32);
    uint32_t iz = (uint32_t)(((int64_t)(uz - g->z0) * g->sz) >> 32);
    if (ix >= RT_SHADOW_GRID)
        ix = RT_SHADOW_GRID - 1;
    if (iz >= RT_SHADOW_GRID)
        iz = RT_SHADOW_GRID - 1;
    return g->cell[ld.y < 0][iz * RT_SHADOW_GRID + ix];
}

#endif
#endif /* RT_SHADOW_H */
