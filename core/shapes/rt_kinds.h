/* SPDX-License-Identifier: MIT */
/*
 * rt_kinds: what the shapes' files share, and the out-of-line parts of
 * some. Internal to core/shapes.
 *
 * A shape is one file: rt_sphere.c, rt_quad.c, rt_box.c, rt_upright.c
 * (cylinders and cones; their precise normals in rt_upright_normal.c) and
 * rt_mesh.c (with rt_mesh_check.c and rt_mesh_normal.c). Each provides
 *
 *   KIND_prepare  derives the kind's constants and its bounding sphere
 *                 (bc, br) from the fields the scene sets; RT_OK or
 *                 RT_ERR_DEGENERATE
 *   KIND_hit      the nearest t with tmin < t < tmax (rt_intersect's
 *                 contract)
 *   KIND_normal   the outward unit normal at a hit (rt_normal's contract)
 *
 * and rt_shape.c dispatches on the kind, one switch each. Row culling and
 * the direction grids need only the bounding sphere, the kind and, for a
 * quad, its plane (n, dist): fields prepare sets. Adding a kind is one
 * file and one case in each switch.
 */
#ifndef RT_KINDS_H
#define RT_KINDS_H

#include "rt_ray.h"

/* Raw ulps added to bounding-sphere radii, which must never cull a ray
 * that meets the shape. */
#define RT_BOUND_MARGIN 8

/* Cylinders (RT_CYLINDER) and cones (RT_CONE). */
fx_dir3 rt_upright_normal(const rt_object *o, const rt_ray *r, fx_t t,
                          fx_vec3 *p, unsigned part, int precise);

/* Where ray r meets the side of cylinder or cone o near its side root t,
 * from Newton steps at the unrounded o + t d (as rt_normal's for a
 * reflective side): 1 with *t30, the distance with 30 fraction bits; 0
 * where the steps decline (a ray within rounding of tangent). */
int rt_side_root(const rt_object *o, const rt_ray *r, fx_t t, int64_t *t30);

/* Distance along the unit component d (d != 0) from coordinate o to the
 * plane at coordinate p, (p - o) / d rounded to nearest: a flat quad's
 * distance, so that box faces and caps lying in such a quad's plane tie
 * with it exactly. 2^32 or more (beyond any tmax) comes back as INT64_MAX
 * or -INT64_MAX. */
int64_t rt_plane_t(int64_t p, fx_t o, int32_t d);

/* (corner - p).normal for quad o, exact, with 16 + FX_UBITS fraction
 * bits: negative when p lies on the side the normal points to, 0 on the
 * plane. small: p is fx_v3_small. A flat quad's dist is normal.corner
 * exactly; a small quad and point have corner - p within 32 bits. */
static inline int64_t rt_quad_num(const rt_object *o, fx_vec3 p, int small)
{
    const rt_quad *qd = &o->u.quad;
    if (qd->flat)
        return (int64_t)qd->dist * FX_UONE - fx_imul64(p.y, qd->normal.y);
    if (o->small && small)
        return fx_imul64(qd->corner.x - p.x, qd->normal.x) +
               fx_imul64(qd->corner.y - p.y, qd->normal.y) +
               fx_imul64(qd->corner.z - p.z, qd->normal.z);
    return fx_pd_dot_diff_raw(qd->corner, p, qd->normal);
}

#endif /* RT_KINDS_H */
