/* SPDX-License-Identifier: MIT */
/*
 * no_mesh: the reference renderer's mesh entry points for the soft-float
 * firmware, which renders the analytic scenes only (it has no allocator,
 * which port/posix/ref_mesh.c needs for its boxes). A mesh object is
 * refused at set-up, so the renderer returns RT_ERR_CAPACITY for it.
 */
#include "ref_render.h"

int ref_mesh_setup(ref_shape *sh)
{
    (void)sh;
    return -1;
}

void ref_mesh_release(ref_shape *sh)
{
    (void)sh;
}

int ref_mesh_hit(const ref_shape *sh, ref_vec3 o, ref_vec3 d, double tmax,
                 ref_hit *hit)
{
    (void)sh;
    (void)o;
    (void)d;
    (void)tmax;
    (void)hit;
    return 0;
}
