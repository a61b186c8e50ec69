/* SPDX-License-Identifier: MIT */
/* rt_camera: the camera frame of a render (rt_camera.h). */
#include "rt_camera.h"

void rt_cam_setup(rt_cam_frame *cf, const rt_scene *s, unsigned height,
                  unsigned n)
{
    cf->w = fx_v3_normalize(fx_v3_sub(s->cam.look, s->cam.eye));
    cf->right = fx_v3_cross_unit(s->cam.up, cf->w);
    cf->up = fx_v3_cross_unit(cf->w, cf->right);
    cf->n = n;
    /* half < 2^31 in Q16.16, so half << 16 < 2^47. */
    int64_t half = fx_tan_half_deg(s->cam.fov);
    cf->step = (half * 65536) / (int64_t)(n * height);
}
