/* SPDX-License-Identifier: MIT */
/* rt_dirgrid: which objects a ray leaving a known place can hit. Internal. */
#ifndef RT_DIRGRID_H
#define RT_DIRGRID_H

#include "rt_ray.h"

#define RT_DIR_NONE 0xFFu /* no grid: test every object */

/* RT_DIR_GRIDS (rt_config.h): the grids are built; else the stubs at the
 * end answer "no grid" and every ray tests every object. */
#if RT_DIR_GRIDS

/* Directions u from a ball (a light, or an object rays leave from), on a
 * grid over (u.x, u.z) per hemisphere of u.y: each cell lists the objects
 * a ray starting in the ball with a direction in the cell can hit. A
 * light's grid spans the directions of the objects that subtend a small
 * angle; those that subtend a wide one (a floor under the light) are also
 * listed for every direction outside it. */
typedef struct {
    fx_t x0, z0;             /* lower corner of the gridded (u.x, u.z) */
    uint32_t wx, wz;         /* its sides: the upper corner is x0 + wx,
                                z0 + wz */
    fx_t sx, sz;             /* cells per unit of u.x and u.z, times
                                2^RT_DIR_SBITS / 2^16 */
    const uint32_t *cell;    /* 2 RT_DIR_GRID^2 bit sets, hemisphere first */
    const uint32_t *outside; /* out, or NULL when nothing can be hit
                                outside the corners */
    uint32_t out[(RT_MAX_OBJECTS + 31) / 32]; /* the set outside them */
} rt_dir_grid;

/* Every grid of one render, in the caller's (the tracer's) memory. */
typedef struct {
    unsigned words;                 /* 32-bit words of one bit set */
    uint8_t light[RT_MAX_LIGHTS];   /* shadow rays to light i: grid */
    uint8_t from[RT_MAX_OBJECTS];   /* rays leaving object i: grid */
    uint8_t mirror[RT_MAX_OBJECTS]; /* eye rays mirrored off plane i */
    uint8_t near; /* every object small, bc and br within 2^22: the
                     narrow form of rt_passes_by (fx_cross_beyond) */
    fx_vec3 eye;                    /* the eye those grids are for */
    rt_dir_grid grid[RT_DIR_MAX_GRIDS];
    uint32_t pool[RT_DIR_POOL_WORDS];
} rt_dir_grids;

/* Builds grids for every light, then for the mirror images of the eye in
 * reflecting planes (rt_dir_mirror_of), then for every object whose
 * material reflects or refracts, while RT_DIR_MAX_GRIDS and the pool
 * last; the rest get RT_DIR_NONE. */
void rt_dir_grids_prepare(rt_dir_grids *gs, const rt_scene *s);

/* Fills g (its bit sets at cell, 2 RT_DIR_GRID^2 * words words) with the
 * objects of s but skip (RT_NO_OBJECT: none) a ray from within radius of
 * centre can hit. every_way: the rays leave the ball in every direction
 * (from an object's surface), so the grid spans every direction; else
 * (from a light or a point) only those of the objects that subtend a
 * small angle. */
void rt_dir_grid_prepare(rt_dir_grid *g, uint32_t *cell, unsigned words,
                         const rt_scene *s, fx_vec3 centre, fx_t radius,
                         int every_way, unsigned skip);

/* Fraction bits of the grids' scales: 24, so that a cell index is one
 * 32-bit product (rt_dir_index), where 64-bit products are built from
 * 16-bit ones no dearer than elsewhere. */
#define RT_DIR_SBITS 24

/* floor(d s / 2^RT_DIR_SBITS), a cell index, for 0 <= d <= span with
 * scale s = floor(RT_DIR_GRID 2^RT_DIR_SBITS / span) and span >= 2^8,
 * 2^17 at most: s is below 2^31, d s at most RT_DIR_GRID
 * 2^RT_DIR_SBITS, below 2^32 for 24 bits. */
static inline uint32_t rt_dir_index(fx_t d, fx_t s)
{
    return ((uint32_t)d * (uint32_t)s) >> RT_DIR_SBITS;
}

/* The bit set of objects a ray with unit direction u from g's ball may
 * hit, or NULL when it can hit none. */
static inline const uint32_t *rt_dir_cell(const rt_dir_grid *g, fx_t ux,
                                          fx_t uy, fx_t uz, unsigned words)
{
    /* Within the corners: 0 <= u - x0 <= wx, one unsigned compare (u
     * and x0 within 2^17: no overflow). */
    const uint32_t dx = (uint32_t)(ux - g->x0), dz = (uint32_t)(uz - g->z0);
    if (dx > g->wx || dz > g->wz)
        return g->outside;
    /* sx = RT_DIR_GRID 2^RT_DIR_SBITS / wx, rounded down: the cell is at
     * most RT_DIR_GRID. */
    uint32_t ix = rt_dir_index((fx_t)dx, g->sx);
    uint32_t iz = rt_dir_index((fx_t)dz, g->sz);
    if (ix >= RT_DIR_GRID)
        ix = RT_DIR_GRID - 1;
    if (iz >= RT_DIR_GRID)
        iz = RT_DIR_GRID - 1;
    unsigned c = ((uy > 0) * RT_DIR_GRID + iz) * RT_DIR_GRID + ix;
    return g->cell + c * words;
}

/* The grid of rays leaving object i, or RT_DIR_NONE (also for i >=
 * n_objects: no known origin). */
static inline unsigned rt_dir_from_object(const rt_dir_grids *gs,
                                          unsigned i, unsigned n_objects)
{
    return i < n_objects ? gs->from[i] : RT_DIR_NONE;
}

/* The grid of the reflections off object i, a plane, of rays from o, if
 * o is the eye; else RT_DIR_NONE. Such a ray runs on the line from the
 * eye's mirror image in the plane through its hit: seen from that image
 * it is a ray from a point, culled as tightly as a shadow ray. A floor's
 * own grid, centred on a ball that holds the whole scene, culls
 * nothing. */
static inline unsigned rt_dir_mirror_of(const rt_dir_grids *gs, unsigned i,
                                        fx_vec3 o)
{
    if (o.x != gs->eye.x || o.y != gs->eye.y || o.z != gs->eye.z)
        return RT_DIR_NONE; /* the reflected ray's parent is no eye ray */
    return gs->mirror[i];
}

/* What a ray in direction d may hit, by grid g (not RT_DIR_NONE): a bit
 * set (rt_dir_cell), or NULL for nothing. */
static inline const uint32_t *rt_dir_candidates(const rt_dir_grids *gs,
                                                unsigned g, fx_dir3 d)
{
    /* The grids are laid out in Q16.16: d rounded to it (within half an
     * ulp of the truth, inside the grids' margins). */
    return rt_dir_cell(&gs->grid[g], fx_u_to_fx(d.x), fx_u_to_fx(d.y),
                       fx_u_to_fx(d.z), gs->words);
}

/* Shadow rays towards light li along unit direction ld: 1 with *cand set
 * to what may block them if the light has a grid, else 0. */
static inline int rt_dir_to_light(const rt_dir_grids *gs, unsigned li,
                                  fx_dir3 ld, const uint32_t **cand)
{
    if (gs->light[li] == RT_DIR_NONE)
        return 0;
    /* Seen from the light, the ray runs along -ld (rounded as above). */
    *cand = rt_dir_cell(&gs->grid[gs->light[li]], fx_u_to_fx(-ld.x),
                        fx_u_to_fx(-ld.y), fx_u_to_fx(-ld.z), gs->words);
    return 1;
}

#else /* the stubs: no grid anywhere */

typedef struct {
    unsigned words;
    uint8_t near;
} rt_dir_grids;

static inline void rt_dir_grids_prepare(rt_dir_grids *gs, const rt_scene *s)
{
    (void)s;
    gs->words = 0;
    gs->near = 0;
}

static inline unsigned rt_dir_from_object(const rt_dir_grids *gs,
                                          unsigned i, unsigned n_objects)
{
    (void)gs, (void)i, (void)n_objects;
    return RT_DIR_NONE;
}

static inline unsigned rt_dir_mirror_of(const rt_dir_grids *gs, unsigned i,
                                        fx_vec3 o)
{
    (void)gs, (void)i, (void)o;
    return RT_DIR_NONE;
}

static inline const uint32_t *rt_dir_candidates(const rt_dir_grids *gs,
                                                unsigned g, fx_dir3 d)
{
    (void)gs, (void)g, (void)d;
    return 0; /* never asked: there is no grid */
}

static inline int rt_dir_to_light(const rt_dir_grids *gs, unsigned li,
                                  fx_dir3 ld, const uint32_t **cand)
{
    (void)gs, (void)li, (void)ld, (void)cand;
    return 0;
}

#endif
#endif /* RT_DIRGRID_H */
