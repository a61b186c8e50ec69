/* SPDX-License-Identifier: MIT */
/*
 * rt_dirgrid: conservative culling of rays by direction (a light buffer,
 * after Haines and Greenberg, also used for rays leaving an object).
 *
 * A ray that starts within distance B of a centre L (a light: shadow rays
 * run from the surface towards it, so seen from L they start at L; an
 * object: its reflected and refracted rays start on it) and meets an
 * object's bounding sphere (c, R) has a parallel copy from L that passes
 * within R + B of c. So its direction u lies in the cone from L around
 * a = norm(c - L) with sin(theta) = (R + B) / |c - L|, and then
 * |u - a| <= 2 sin(theta / 2) (the chord). So |u.x - a.x| and |u.z - a.z|
 * are at most that chord, and u.y has a's sign unless the chord reaches
 * y = 0: a square per cone, marked on a grid over (u.x, u.z), one grid per
 * hemisphere of u.y.
 *
 * R is widened by every way the ray in the test differs from the ideal
 * one: its start is off the surface (rt_trace's offset, at most off_max),
 * a shadow ray's direction is rounded (well under 2^-14 of its length, at
 * most the largest distance from L to any object), and the
 * bounding-sphere test rounds; the chord gets 2^-12 more for the rounding
 * of a and u. So a cell leaves out only objects the intersection test
 * would miss: images are bit-identical with and without the grids
 * (RT_DIR_GRID=0 in the tests). Any case too large to bound in Q16.16
 * marks every cell.
 */
#include "rt_dirgrid.h"

#if RT_DIR_GRIDS

#include "rt_libc.h"

#define N RT_DIR_GRID

/* Components of c - L beyond this (and radii beyond it) are not culled. */
#define FAR_LIMIT FX_INT(8192)

/* Narrowest gridded range of u.x or u.z: keeps the cell scale in range. */
#define MIN_SPAN ((fx_t)1 << 8)

/* A cone box wider than this in u.x or u.z (a quarter of the square) does
 * not widen the gridded range: it is listed outside the range instead. */
#define WIDE FX_ONE

typedef struct {
    int all;        /* 1: every cell (the light is inside, or too far) */
    fx_t lo_x, hi_x, lo_z, hi_z;
    int lower, upper; /* hemispheres of u.y it reaches */
} cone_box;

static fx_t clamp1(int64_t v)
{
    return v < -FX_ONE ? -FX_ONE : (v > FX_ONE ? FX_ONE : (fx_t)v);
}

static void cone_of(cone_box *b, const rt_object *o, fx_vec3 lp, fx_t slack)
{
    int64_t vx = (int64_t)o->bc.x - lp.x, vy = (int64_t)o->bc.y - lp.y;
    int64_t vz = (int64_t)o->bc.z - lp.z;
    int64_t r = (int64_t)o->br + slack;
    b->all = 1;
    if (r >= FAR_LIMIT || vx <= -FAR_LIMIT || vx >= FAR_LIMIT ||
        vy <= -FAR_LIMIT || vy >= FAR_LIMIT || vz <= -FAR_LIMIT ||
        vz >= FAR_LIMIT)
        return;
    fx_vec3 v = fx_v3((fx_t)vx, (fx_t)vy, (fx_t)vz);
    fx_t d = fx_v3_length(v);
    /* Light inside the sphere or nearly: every direction. */
    if ((int64_t)d <= r + (r >> 4) + FX_ONE / 64)
        return;
    fx_vec3 a = fx_v3_normalize(v);
    /* 2 sin(theta / 2) = sin(theta) / cos(theta / 2), and
     * cos(theta / 2) = sqrt((1 + cos(theta)) / 2): no cancellation for
     * small cones. Widened by 2^-8 of itself and 2^-12 for the rounding
     * of a, u and these steps. */
    fx_t sn = fx_div((fx_t)r, d);
    fx_t cs = fx_sqrt(fx_sub(FX_ONE, fx_mul(sn, sn)));
    fx_t chord = fx_div(sn, fx_sqrt((FX_ONE + cs) / 2));
    chord = fx_add(chord, (chord >> 8) + ((fx_t)1 << 4));
    b->all = 0;
    b->lo_x = clamp1((int64_t)a.x - chord);
    b->hi_x = clamp1((int64_t)a.x + chord);
    b->lo_z = clamp1((int64_t)a.z - chord);
    b->hi_z = clamp1((int64_t)a.z + chord);
    b->lower = (int64_t)a.y - chord <= 0;
    b->upper = (int64_t)a.y + chord >= 0;
}

/* rt_dir_index's 24-bit scale needs RT_DIR_GRID 2^24 below 2^31. */
#if RT_DIR_GRID > 127
#error "RT_DIR_GRID must be at most 127"
#endif

/* The same map rt_dir_cell uses, so marking is conservative. */
static unsigned cell_of(fx_t v, fx_t v0, fx_t s)
{
    int64_t i = ((int64_t)(v - v0) * s) >> RT_DIR_SBITS;
    return i < 0 ? 0 : (i >= N ? N - 1 : (unsigned)i);
}

/* hi - lo is in [MIN_SPAN, 2^17 + MIN_SPAN] (lo within [-1, 1], hi
 * within [-1, 1] or MIN_SPAN above lo), so the quotient, below 2^35 /
 * 2^8, fits 32 bits: no 64-bit library divide. */
static fx_t cells_per_unit(fx_t lo, fx_t hi)
{
    return (fx_t)fx_udiv64_32((uint64_t)N << RT_DIR_SBITS,
                              (uint32_t)(hi - lo));
}

void rt_dir_grid_prepare(rt_dir_grid *g, uint32_t *cell, unsigned words,
                         const rt_scene *s, fx_vec3 lp, fx_t radius,
                         int every_way, unsigned skip)
{
    const unsigned n = s->n_objects;
    uint32_t *out = g->out;
    memset(cell, 0, (size_t)2 * N * N * words * sizeof *cell);
    memset(out, 0, sizeof g->out);
    g->cell = cell;
    g->outside = 0;
    /* The farthest any hit lies from the centre, and the largest origin
     * offset: they bound how far a ray strays from its ideal copy. */
    int64_t far = 0;
    fx_t off_max = RT_EPS;
    for (unsigned i = 0; i < n; i++) {
        const rt_object *o = &s->obj[i];
        fx_t off = rt_origin_offset(o);
        if (off > off_max)
            off_max = off;
        int64_t d = (int64_t)fx_v3_length(fx_v3_sub(o->bc, lp)) + o->br;
        if (d > far)
            far = d;
    }
    int64_t sl = (int64_t)radius + off_max +
                 ((far + radius + off_max) >> 12) + FX_ONE / 256;
    fx_t slack = sl > FAR_LIMIT ? FAR_LIMIT : (fx_t)sl;

    /* The range: the narrow cones' boxes, or every box if none is. Not
     * for rays leaving an object's ball: they go every way, and there the
     * wide cones outside the range would be tested for all of them. */
    fx_t x0 = FX_ONE, x1 = -FX_ONE, z0 = FX_ONE, z1 = -FX_ONE;
    for (int pass = every_way != 0; pass < 2 && x0 > x1; pass++)
        for (unsigned i = 0; i < n; i++) {
            cone_box b;
            if (i == skip)
                continue;
            cone_of(&b, &s->obj[i], lp, slack);
            if (pass == 0 && (b.all || b.hi_x - b.lo_x > WIDE ||
                              b.hi_z - b.lo_z > WIDE))
                continue;
            if (b.all) {
                x0 = z0 = -FX_ONE;
                x1 = z1 = FX_ONE;
            } else {
                x0 = b.lo_x < x0 ? b.lo_x : x0;
                x1 = b.hi_x > x1 ? b.hi_x : x1;
                z0 = b.lo_z < z0 ? b.lo_z : z0;
                z1 = b.hi_z > z1 ? b.hi_z : z1;
            }
        }
    if (n == 0) { /* nothing to hit: a range no unit vector reaches */
        g->x0 = g->z0 = 2 * FX_ONE;
        g->wx = g->wz = 0;
        g->sx = g->sz = 0;
        return;
    }
    if (x1 - x0 < MIN_SPAN)
        x1 = x0 + MIN_SPAN;
    if (z1 - z0 < MIN_SPAN)
        z1 = z0 + MIN_SPAN;
    g->x0 = x0;
    g->wx = (uint32_t)(x1 - x0);
    g->z0 = z0;
    g->wz = (uint32_t)(z1 - z0);
    g->sx = cells_per_unit(x0, x1);
    g->sz = cells_per_unit(z0, z1);

    for (unsigned i = 0; i < n; i++) {
        cone_box b;
        if (i == skip)
            continue;
        cone_of(&b, &s->obj[i], lp, slack);
        unsigned ix0 = 0, ix1 = N - 1, iz0 = 0, iz1 = N - 1;
        int lower = 1, upper = 1;
        if (!b.all) {
            ix0 = cell_of(b.lo_x, x0, g->sx);
            ix1 = cell_of(b.hi_x, x0, g->sx);
            iz0 = cell_of(b.lo_z, z0, g->sz);
            iz1 = cell_of(b.hi_z, z0, g->sz);
            lower = b.lower;
            upper = b.upper;
        }
        const uint32_t bit = (uint32_t)1 << (i % 32);
        if (b.all || b.lo_x < x0 || b.hi_x > x1 || b.lo_z < z0 ||
            b.hi_z > z1) {
            out[i / 32] |= bit; /* it reaches outside the range */
            g->outside = out;
        }
        for (unsigned iz = iz0; iz <= iz1; iz++)
            for (unsigned ix = ix0; ix <= ix1; ix++) {
                if (lower)
                    cell[(iz * N + ix) * words + i / 32] |= bit;
                if (upper)
                    cell[((N + iz) * N + ix) * words + i / 32] |= bit;
            }
    }
}

/* Takes the next grid from the pool, or returns RT_DIR_NONE. */
static uint8_t add_grid(rt_dir_grids *gs, unsigned *used, unsigned *next,
                        const rt_scene *s, fx_vec3 centre, fx_t radius,
                        int every_way, unsigned skip)
{
    const unsigned size = 2u * N * N * gs->words;
    if (*used >= RT_DIR_MAX_GRIDS || *next + size > RT_DIR_POOL_WORDS)
        return RT_DIR_NONE;
    rt_dir_grid_prepare(&gs->grid[*used], gs->pool + *next, gs->words, s,
                        centre, radius, every_way, skip);
    *next += size;
    return (uint8_t)(*used)++;
}

/* The eye e mirrored in quad o's plane (through a, the corner, with the
 * unit normal n; lu and lv are its len_u and len_v: rt_quad)
 * into *m, with in *radius how far a reflected camera ray's line may pass
 * from it; 0 when that is out of range (no grid).
 *
 * A camera ray from e hits the quad at p; its mirror direction r, traced
 * back from p by |p - e|, ends at e's image in the plane through p
 * parallel to n: *m, if p lies on that plane. So the reflected ray
 * starts, seen from *m, within the sum of: twice p's distance from the
 * plane of a and n (p is on the quad's own plane, whose normal n
 * is within a few 2^-FX_UBITS: at most (lu + lv) 2^-(FX_UBITS - 2)),
 * p's own rounding, and that of *m (each a few ulps). The radius takes
 * 2^-10 of |e - a| + lu + lv and 1/64 unit, far above both at any
 * FX_UBITS >= 16; rt_dir_grid_prepare adds the origin offset and the
 * rounding of r over the scene's extent. */
static int mirror_eye(const rt_object *o, fx_vec3 e, fx_vec3 *m,
                      fx_t *radius)
{
    const rt_quad *q = &o->u.quad;
    const int64_t v[3] = { (int64_t)e.x - q->corner.x,
                           (int64_t)e.y - q->corner.y,
                           (int64_t)e.z - q->corner.z };
    const int32_t n[3] = { q->normal.x, q->normal.y, q->normal.z };
    int64_t dot = 0, size = (int64_t)q->len_u + q->len_v;
    for (unsigned k = 0; k < 3; k++) {
        if (v[k] <= -FAR_LIMIT || v[k] >= FAR_LIMIT)
            return 0;
        dot += v[k] * n[k]; /* below 3 2^29 2^30 */
        size += v[k] < 0 ? -v[k] : v[k];
    }
    /* (e - a).n, Q16.16 */
    const int64_t h = (dot + ((int64_t)1 << (FX_UBITS - 1))) >> FX_UBITS;
    int64_t mk[3];
    for (unsigned k = 0; k < 3; k++) {
        /* 2 h n_k: |h| < 2^31, |n_k| <= 2^FX_UBITS */
        const int64_t shift = (2 * h * n[k] + ((int64_t)1 << (FX_UBITS - 1)))
                              >> FX_UBITS;
        mk[k] = (int64_t)(k == 0 ? e.x : k == 1 ? e.y : e.z) - shift;
        if (mk[k] <= -FAR_LIMIT || mk[k] >= FAR_LIMIT)
            return 0;
    }
    *m = fx_v3((fx_t)mk[0], (fx_t)mk[1], (fx_t)mk[2]);
    const int64_t r = (size >> 10) + FX_ONE / 64;
    if (r >= FAR_LIMIT)
        return 0;
    *radius = (fx_t)r;
    return 1;
}

void rt_dir_grids_prepare(rt_dir_grids *gs, const rt_scene *s)
{
    unsigned used = 0, next = 0;
    gs->words = (s->n_objects + 31u) / 32u;
    gs->near = 0;
    for (unsigned i = 0; i < RT_MAX_LIGHTS; i++)
        gs->light[i] = RT_DIR_NONE;
    for (unsigned i = 0; i < RT_MAX_OBJECTS; i++)
        gs->from[i] = gs->mirror[i] = RT_DIR_NONE;
    gs->eye = s->cam.eye;
    if (gs->words == 0)
        return;
    /* Shadow rays are the most numerous: lights first. */
    for (unsigned i = 0; RT_HAS_SHADOWS && s->shadows && i < s->n_lights &&
                         i < RT_MAX_LIGHTS;
         i++)
        gs->light[i] =
            add_grid(gs, &used, &next, s, s->light[i].pos, 0, 0,
                     RT_NO_OBJECT);
    /* Then camera rays' reflections in unbumped mirror quads (a floor):
     * as many as the camera rays that hit them. The quad is left out:
     * its rays skip it (a quad is convex, rt_nearest's skip). */
    for (unsigned i = 0; RT_HAS_REFLECTION && i < s->n_objects; i++) {
        const rt_object *o = &s->obj[i];
        const rt_material *m = &s->mat[o->material];
        fx_vec3 c;
        fx_t radius;
        if (o->kind == RT_QUAD && m->reflect > 0 && m->bump == 0 &&
            mirror_eye(o, s->cam.eye, &c, &radius))
            gs->mirror[i] = add_grid(gs, &used, &next, s, c, radius, 0, i);
    }
    /* And whether rt_passes_by may take its 16-bit path: offset by
     * 2^22, each of bc's components and br is below 2^23 if their OR
     * is. */
    uint32_t span = 0;
    for (unsigned i = 0; RT_HAS_SECONDARY && i < s->n_objects; i++) {
        const rt_object *o = &s->obj[i];
        const rt_material *m = &s->mat[o->material];
        const uint32_t lim = (uint32_t)1 << 22;
        span |= ((uint32_t)o->bc.x + lim) | ((uint32_t)o->bc.y + lim) |
                ((uint32_t)o->bc.z + lim) | (uint32_t)o->br |
                (o->small ? 0u : ~0u);
        if (m->reflect > 0 || m->transparency > 0)
            gs->from[i] =
                add_grid(gs, &used, &next, s, o->bc, o->br, 1, RT_NO_OBJECT);
    }
    gs->near = RT_HAS_SECONDARY && span < (uint32_t)1 << 23;
}

#endif
