/* SPDX-License-Identifier: MIT */
/*
 * rt_camera: the camera frame and where each sample of a pixel looks.
 * rt_render's samples and rt_cull's row planes both use these, so the
 * culling is conservative for exactly the rays that are traced. Internal.
 */
#ifndef RT_CAMERA_H
#define RT_CAMERA_H

#include "rt_scene.h"

/* The view of one render at n x n samples per pixel. */
typedef struct {
    fx_vec3 w, right, up; /* unit: forward, right and up */
    int64_t step; /* screen offset per unit of k: half / (n H), 32 frac bits */
    unsigned n;   /* grid side */
} rt_cam_frame;

/* Sets *cf for scene s's camera, an image height and grid side n. */
void rt_cam_setup(rt_cam_frame *cf, const rt_scene *s, unsigned height,
                  unsigned n);

/* Screen offset k * half / (n H) as Q16.16; |k| <= n * 2 * RT_MAX_WIDTH. */
static inline fx_t rt_cam_offset(const rt_cam_frame *cf, int32_t k)
{
    return fx_sat64(((int64_t)k * cf->step + 0x8000) >> 16);
}

/* k of sample row j of pixel row y (upwards from the image centre). */
static inline int32_t rt_cam_row_k(unsigned height, unsigned n, unsigned y,
                                   unsigned j)
{
    return (int32_t)(height * n) - (int32_t)(2 * y * n + 2 * j + 1);
}

/* k of sample column i of pixel column x (rightwards from the centre). */
static inline int32_t rt_cam_col_k(unsigned width, unsigned n, unsigned x,
                                   unsigned i)
{
    return (int32_t)(2 * x * n + 2 * i + 1) - (int32_t)(width * n);
}

/* Direction (not unit) of the sample at screen offset sx along a sample
 * row whose centre direction is base (w + sy up). */
static inline fx_vec3 rt_cam_dir(const rt_cam_frame *cf, fx_vec3 base,
                                 fx_t sx)
{
    const fx_t lim = (fx_t)1 << 30; /* fx_v3_madd_unit's range */
    /* right is a unit vector: the cheaper madd gives the same values. */
    return sx >= -lim && sx <= lim ? fx_v3_madd_unit(base, cf->right, sx)
                                   : fx_v3_madd(base, cf->right, sx);
}

#endif /* RT_CAMERA_H */
