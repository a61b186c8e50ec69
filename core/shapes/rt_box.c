/* SPDX-License-Identifier: MIT */
/*
 * rt_box: axis-aligned boxes (corners min < max), by slabs after the
 * bounding sphere. The hit's part is the axis of the face; a face's
 * distance is taken as a flat quad's (rt_plane_t), so a face lying in a
 * floor's plane ties with it exactly.
 *
 * Part of the dispatch unit: rt_shape.c includes this file (its comment
 * says why); compiled alone it defines nothing.
 */
#include "rt_bsphere.h"
#include "rt_kinds.h"

static inline rt_status box_prepare(rt_object *o)
{
    const fx_vec3 lo = o->u.box.min, hi = o->u.box.max;
    if (hi.x <= lo.x || hi.y <= lo.y || hi.z <= lo.z)
        return RT_ERR_DEGENERATE;
    fx_vec3 half = fx_v3((fx_t)(((int64_t)hi.x - lo.x) / 2),
                         (fx_t)(((int64_t)hi.y - lo.y) / 2),
                         (fx_t)(((int64_t)hi.z - lo.z) / 2));
    o->bc = fx_v3_add(lo, half);
    o->br = fx_add(fx_v3_length(half), RT_BOUND_MARGIN);
    o->convex = 1;
    return RT_OK;
}


/* 1 / d for a unit component d != 0, to 32 bits whatever its size:
 * 1 / |d| = m 2^c / 2^63 for d normalised by c leading zeros. */
typedef struct {
    uint32_t m;
    int sh;  /* x / d in Q16.16 is (x m) >> sh, sh >= 2 */
    int neg; /* d < 0 */
} slab_inv;

static void slab_inv_set(slab_inv *v, int32_t d)
{
    uint32_t ud = (uint32_t)(d < 0 ? -(int64_t)d : d);
    int c = fx_clz32(ud);
    /* (2^63 - 1) / (ud 2^c) is below 2^32 as ud 2^c >= 2^31. */
    v->m = fx_udiv64_32(((uint64_t)1 << 63) - 1u, ud << c);
    v->sh = 63 - FX_UBITS - c;
    v->neg = d < 0;
}

/* x / d (Q16.16 x), within 2^-31 relative; saturates. |x m| < 2^63. */
static fx_t slab_t(const slab_inv *v, fx_t x)
{
    int64_t q = fx_iumul64(x, v->m) >> v->sh;
    return fx_sat64(v->neg ? -q : q);
}

static inline int box_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
               fx_t *t, uint16_t *part)
{
    {
        int64_t tca, h[3];
        uint64_t disc;
        if (!bsphere(&o->bc, o->br, o->small, r, tmin, tmax, &tca, &disc,
                     h))
            return 0;
    }
    /* Arrays, not pointers into the structs: indexing &v.x past x is
     * undefined behaviour. */
    const fx_vec3 bmin = o->u.box.min, bmax = o->u.box.max;
    const fx_t lo[3] = { bmin.x, bmin.y, bmin.z };
    const fx_t hi[3] = { bmax.x, bmax.y, bmax.z };
    const fx_t org[3] = { r->o.x, r->o.y, r->o.z };
    const int32_t dir[3] = { r->d.x, r->d.y, r->d.z };
    fx_t tn = FX_MIN, tf = FX_MAX;
    int an = 0, af = 0;
    for (int i = 0; i < 3; i++) {
        if (dir[i] == 0) {
            /* Parallel to this slab: outside it, a miss; inside it (both
             * faces inclusive) no constraint on t. */
            if (org[i] < lo[i] || org[i] > hi[i])
                return 0;
            continue;
        }
        slab_inv inv;
        slab_inv_set(&inv, dir[i]);
        fx_t t1 = slab_t(&inv, fx_sub(lo[i], org[i]));
        fx_t t2 = slab_t(&inv, fx_sub(hi[i], org[i]));
        if (t1 > t2) {
            fx_t tmp = t1;
            t1 = t2;
            t2 = tmp;
        }
        if (t1 > tn) {
            tn = t1;
            an = i;
        }
        if (t2 < tf) {
            tf = t2;
            af = i;
        }
    }
    if (tn > tf)
        return 0;
    /* part: the axis of the face, entry face first, else exit face. Its
     * distance is then taken as a quad takes it for an axis-aligned
     * plane, so a face lying in a floor quad's plane ties with it exactly
     * (the earlier object wins, without z-fighting). */
    if (tn > tmin && tn < tmax) {
        int64_t tw = dir[an] == 0 ? tn
                     : rt_plane_t(dir[an] > 0 ? lo[an] : hi[an], org[an],
                               dir[an]);
        if (tw > tmin && tw < tmax) {
            *t = (fx_t)tw;
            *part = (uint8_t)an;
            return 1;
        }
    }
    if (tf > tmin && tf < tmax) {
        int64_t tw = dir[af] == 0 ? tf
                     : rt_plane_t(dir[af] > 0 ? hi[af] : lo[af], org[af],
                               dir[af]);
        if (tw > tmin && tw < tmax) {
            *t = (fx_t)tw;
            *part = (uint8_t)af;
            return 1;
        }
    }
    return 0;
}

static inline fx_dir3 box_normal(const rt_object *o, fx_vec3 p, unsigned part)
{
    /* part is the axis of the face; its side is the one p lies on. */
    const fx_t pc[3] = { p.x, p.y, p.z };
    const fx_t cc[3] = { o->bc.x, o->bc.y, o->bc.z };
    int32_t v[3] = { 0, 0, 0 };
    v[part] = pc[part] > cc[part] ? FX_UONE : -FX_UONE;
    return fx_d3(v[0], v[1], v[2]);
}
