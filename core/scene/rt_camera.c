/* SPDX-License-Identifier: MIT */
/* rt_camera: the camera frame of a render (rt_camera.h). */
#include "rt_camera.h"

/* Once a render: compiled for size (RT_COLD), as it is not per pixel. */
RT_COLD void rt_cam_setup(rt_cam_frame *cf, const rt_scene *s, unsigned width,
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
    cf->step = (int64_t)fx_udiv64((uint64_t)half, n * height);
    /* The largest offset of a sample, |k| < n max(W, H), with 32 fraction
     * bits; keep 31 bits of it, but at most 30 fraction bits, so that
     * w 2^fbits + sy up + sx right stays below 2^60 + 2^62. */
    const unsigned side = width > height ? width : height;
    const uint64_t most = (uint64_t)(n * side) * (uint64_t)cf->step;
    int fb = most ? fx_clz64(most) - 1 : 30; /* 63 - bit length */
    cf->fbits = fb > 30 ? 30 : (fb < 2 ? 2 : fb);
}

/* 1 if v >> fb is an int32 above INT32_MIN (rt_cam_walk_dir). */
static int walk_fits(int64_t v, int fb)
{
    const int64_t lim = (int64_t)1 << (31 + fb);
    return v >= ((int64_t)1 << fb) - lim && v < lim;
}

/* Once a row: compiled for size (RT_COLD). */
RT_COLD void rt_cam_walk_init(rt_cam_walk *cw, const rt_cam_frame *cf,
                              const rt_cam_ray *b, unsigned width,
                              unsigned x0, unsigned x1)
{
    const int fb = cf->fbits, sh = 32 - fb;
    const int64_t h = (int64_t)1 << (fb - 1), up = (int64_t)1 << sh;
    const int32_t k0 = rt_cam_col_k(width, 1, x0, 0);
    const int32_t k1 = rt_cam_col_k(width, 1, x1, 0);
    const int32_t s0 = rt_cam_soff(cf, k0), s1 = rt_cam_soff(cf, k1);
    /* sx's step, dd or dd + 1, is below 2^31 for two columns or more
     * (every sx fits 31 bits); with one there is no step. */
    const int64_t dd = (2 * cf->step) >> sh;
    const int32_t d = (int32_t)(x1 > x0 ? dd : 0);
    const int64_t bv[3] = { b->x, b->y, b->z };
    const int32_t rv[3] = { cf->right.x, cf->right.y, cf->right.z };
    int64_t v[3], inc[2][3];
    int fits = 1;
    const uint32_t mask = ((uint32_t)1 << sh) - 1u;
    cw->frac = ((uint32_t)(2 * cf->step) & mask) << fb;
    cw->rem = ((uint32_t)((int64_t)k0 * cf->step + (up >> 1)) & mask) << fb;
    for (int c = 0; c < 3; c++) {
        /* sx is monotonic along the row: the ends bound every v. */
        const int64_t v1 = bv[c] + fx_imul64(rv[c], s1) + h;
        v[c] = bv[c] + fx_imul64(rv[c], s0) + h;
        inc[0][c] = fx_imul64(rv[c], d);
        inc[1][c] = inc[0][c] + rv[c];
        fits &= walk_fits(v[c], fb) & walk_fits(v1, fb) &
                walk_fits(inc[0][c], fb) & walk_fits(inc[1][c], fb);
    }
    cw->wide = !fits;
    cw->fbits = fb;
    for (int c = 0; c < 3; c++) {
        const int64_t m = fits ? up : 1;
        cw->v[c] = v[c] * m;
        cw->inc[0][c] = inc[0][c] * m;
        cw->inc[1][c] = inc[1][c] * m;
    }
}

RT_COLD fx_dir3 rt_cam_walk_dir_wide(const rt_cam_walk *cw)
{
    const int fb = cw->fbits;
    return fx_d3_normalize64(cw->v[0] >> fb, cw->v[1] >> fb, cw->v[2] >> fb);
}
