/* SPDX-License-Identifier: MIT */
/* rt_camera: the camera frame of a render (rt_camera.h). */
#include "rt_camera.h"

void rt_cam_setup(rt_cam_frame *cf, const rt_scene *s, unsigned width,
                  unsigned height, unsigned n)
{
    /* look - eye in 64 bits: exact however far apart the two are. */
    cf->w = fx_d3_normalize64((int64_t)s->cam.look.x - s->cam.eye.x,
                              (int64_t)s->cam.look.y - s->cam.eye.y,
                              (int64_t)s->cam.look.z - s->cam.eye.z);
    cf->right = fx_d3_cross_unit(s->cam.up, fx_d3_raw(cf->w));
    cf->up = fx_d3_cross_unit(fx_d3_raw(cf->w), fx_d3_raw(cf->right));
    cf->n = n;
    /* tan(fov / 2) with 32 fraction bits, below 2^47. */
    int64_t half = fx_tan_half_deg_q32(s->cam.fov);
    cf->step = half / (int64_t)(n * height);
    /* The largest offset of a sample, |k| < n max(W, H), with 32 fraction
     * bits; keep 31 bits of it, but at most 30 fraction bits, so that
     * w 2^fbits + sy up + sx right stays below 2^60 + 2^62. */
    const unsigned side = width > height ? width : height;
    const uint64_t most = (uint64_t)(n * side) * (uint64_t)cf->step;
    int fb = most ? fx_clz64(most) - 1 : 30; /* 63 - bit length */
    cf->fbits = fb > 30 ? 30 : (fb < 2 ? 2 : fb);
}
