/* SPDX-License-Identifier: MIT */
/*
 * rt_sealed: which closed glass objects nothing else reaches into, or
 * only one other object (rt_sealed.h), decided once per render from the
 * shapes themselves: their axis-aligned boxes (a floor's is flat) and
 * their bounding spheres.
 *
 * Why dropping the others is exact. A ray inside closed glass i starts
 * within its origin offset of i's shape (shading moves it off i's
 * surface, rt_origin_offset); where it leaves i, at the t of i's own
 * hit, it is on i's surface to within the rounding of that test. i is
 * convex, so every point of the ray between the two lies within their
 * sum of i. An object j whose shape keeps farther than that sum, plus
 * the rounding of j's own test, from i's shape has no hit on the ray up
 * to i's: it cannot be the nearest when i's hit is. The margin (margin())
 * takes the origin offset, 1/256 unit and 2^-12 of the largest
 * coordinate involved, far above the tests' rounding (a few ulps, and
 * 2^-24 of a cylinder's or cone's size in the frame it is solved in).
 * The tracer checks that the nearest hit is i's and otherwise searches
 * again among every object (rt_nearest.h).
 */
#include "rt_libc.h"
#include "rt_ray.h"
#include "rt_sealed.h"

#if RT_SEALED

/* 1 if the sphere (c, r) holds no point within d of p: |p - c| > r + d,
 * decided conservatively (distance rounded down, radii up). */
static int apart(fx_vec3 p, fx_vec3 c, fx_t r, int64_t d)
{
    int64_t lim = (int64_t)r + d; /* < 2^32 */
    int64_t dx = (int64_t)p.x - c.x, dy = (int64_t)p.y - c.y;
    int64_t dz = (int64_t)p.z - c.z;
    dx = dx < 0 ? -dx : dx;
    dy = dy < 0 ? -dy : dy;
    dz = dz < 0 ? -dz : dz;
    if (dx > lim || dy > lim || dz > lim)
        return 1;
    /* Every term is now below 2^32; 2 bits less keep the sum in 64. */
    uint64_t ux = (uint64_t)dx >> 2, uy = (uint64_t)dy >> 2;
    uint64_t uz = (uint64_t)dz >> 2, ul = ((uint64_t)lim + 3) >> 2;
    return ux * ux + uy * uy + uz * uz > ul * ul;
}

static int closed(const rt_object *o)
{
    return o->kind == RT_SPHERE || o->kind == RT_BOX ||
           (o->kind == RT_CYLINDER &&
            o->caps == (RT_CAP_BOTTOM | RT_CAP_TOP)) ||
           (o->kind == RT_CONE && (o->caps & RT_CAP_BOTTOM));
}

/* An axis-aligned box; for small objects (rt_object.small) every
 * coordinate is within 2^30. */
typedef struct {
    fx_t lo[3], hi[3];
} span3;

static fx_t comp(fx_vec3 v, unsigned k)
{
    return k == 0 ? v.x : (k == 1 ? v.y : v.z);
}

/* The axis-aligned box that holds small object o's shape (a mesh's
 * bounding sphere's), and the largest coordinate magnitude in it. */
static fx_t extent(const rt_object *o, span3 *b)
{
    fx_t mag = 0;
    for (unsigned k = 0; k < 3; k++) {
        const fx_t c = comp(o->bc, k);
        fx_t lo = c - o->br, hi = c + o->br; /* a sphere's is exact */
        if (o->kind == RT_BOX) {
            lo = comp(o->u.box.min, k);
            hi = comp(o->u.box.max, k);
        } else if (o->kind == RT_CYLINDER || o->kind == RT_CONE) {
            const rt_upright *up = &o->u.upright;
            const fx_t a = comp(up->base, k);
            lo = k == 1 ? a : a - up->radius;
            hi = k == 1 ? a + up->height : a + up->radius;
        } else if (o->kind == RT_QUAD) { /* the four corners */
            const fx_t a = comp(o->u.quad.corner, k);
            const fx_t e1 = comp(o->u.quad.edge1, k);
            const fx_t e2 = comp(o->u.quad.edge2, k);
            lo = a + (e1 < 0 ? e1 : 0) + (e2 < 0 ? e2 : 0);
            hi = a + (e1 > 0 ? e1 : 0) + (e2 > 0 ? e2 : 0);
        }
        b->lo[k] = lo;
        b->hi[k] = hi;
        mag = -lo > mag ? -lo : mag;
        mag = hi > mag ? hi : mag;
    }
    return mag;
}

/* 1 if a ray inside closed object i cannot hit object j before it
 * leaves i (this file's comment): j's shape keeps farther than the
 * margin from i's, along an axis or between the bounding spheres.
 * Objects beyond 8192 units are never apart. */
static int keeps_out(const rt_object *i, const rt_object *j)
{
    span3 bi, bj;
    if (!i->small || !j->small)
        return 0;
    fx_t mag = extent(i, &bi), mj = extent(j, &bj);
    mag = mj > mag ? mj : mag;
    /* Below 2^20, as mag is below 2^30. */
    const int64_t d = rt_origin_offset(i) + FX_ONE / 256 + (mag >> 12);
    for (unsigned k = 0; k < 3; k++)
        if ((int64_t)bi.lo[k] - bj.hi[k] > d ||
            (int64_t)bj.lo[k] - bi.hi[k] > d)
            return 1;
    return apart(j->bc, i->bc, i->br, (int64_t)j->br + d);
}

void rt_sealed_find(rt_sealed *sl, const rt_scene *s, int shadows)
{
    memset(sl->dark, 0, sizeof sl->dark);
    for (unsigned i = 0; i < RT_MAX_OBJECTS; i++)
        sl->with[i] = RT_SEALED_NONE;
    for (unsigned i = 0; i < s->n_objects; i++) {
        const rt_object *o = &s->obj[i];
        if (!closed(o) || s->mat[o->material].transparency == 0)
            continue;
        unsigned with = i, near = 0;
        for (unsigned j = 0; near < 2 && j < s->n_objects; j++)
            if (j != i && !keeps_out(o, &s->obj[j])) {
                with = j;
                near++;
            }
        if (near < 2)
            sl->with[i] = (uint16_t)with;
        int dark = shadows != 0;
        for (unsigned li = 0; dark && li < s->n_lights; li++)
            if (!apart(s->light[li].pos, o->bc, o->br, 0))
                dark = 0;
        sl->dark[i / 32] |= (uint32_t)dark << (i % 32);
    }
}
#endif
