/* SPDX-License-Identifier: MIT */
/*
 * rt_sealed: which closed glass objects nothing else reaches into
 * (rt_sealed.h), decided once per render from bounding spheres.
 */
#include "rt_libc.h"
#include "rt_sealed.h"

#if RT_SEALED

/* 1 if the sphere (c, r) holds no point within d of p: |p - c| > r + d,
 * decided conservatively (distance rounded down, radii up). */
static int apart(fx_vec3 p, fx_vec3 c, fx_t r, fx_t d)
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

void rt_sealed_find(rt_sealed *sl, const rt_scene *s, int shadows)
{
    memset(sl->alone, 0, sizeof sl->alone);
    memset(sl->dark, 0, sizeof sl->dark);
    for (unsigned i = 0; i < s->n_objects; i++) {
        const rt_object *o = &s->obj[i];
        if (!closed(o) || s->mat[o->material].transparency == 0)
            continue;
        int alone = 1, dark = shadows != 0;
        for (unsigned j = 0; alone && j < s->n_objects; j++)
            if (j != i && !apart(s->obj[j].bc, o->bc, o->br, s->obj[j].br))
                alone = 0;
        for (unsigned li = 0; dark && li < s->n_lights; li++)
            if (!apart(s->light[li].pos, o->bc, o->br, 0))
                dark = 0;
        sl->alone[i / 32] |= (uint32_t)alone << (i % 32);
        sl->dark[i / 32] |= (uint32_t)dark << (i % 32);
    }
}
#endif
