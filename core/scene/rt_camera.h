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
    fx_dir3 w, right, up; /* unit: forward, right and up */
    int64_t step; /* screen offset per unit of k: half / (n H), 32 frac bits */
    int fbits;    /* fraction bits of rt_cam_soff, 2..30 */
    unsigned n;   /* grid side */
} rt_cam_frame;

/* A sample's direction before normalisation: w + sy up + sx right, exact,
 * with FX_UBITS + cf->fbits fraction bits (each component below 2^63). */
typedef struct {
    int64_t x, y, z;
} rt_cam_ray;

/* Sets *cf for scene s's camera, an image of width x height and grid
 * side n. */
void rt_cam_setup(rt_cam_frame *cf, const rt_scene *s, unsigned width,
                  unsigned height, unsigned n);

/* Screen offset k * half / (n H) as Q16.16; |k| <= n * 2 * RT_MAX_WIDTH.
 * The culling works with these. */
static inline fx_t rt_cam_offset(const rt_cam_frame *cf, int32_t k)
{
    return fx_sat64(((int64_t)k * cf->step + 0x8000) >> 16);
}

/* The same offset with cf->fbits fraction bits, rounded to nearest: as
 * many as keep every sample of the image within 31 bits, so that a camera
 * ray is as precise as its unit vector, not limited to Q16.16. */
static inline int32_t rt_cam_soff(const rt_cam_frame *cf, int32_t k)
{
    const int sh = 32 - cf->fbits;
    return (int32_t)(((int64_t)k * cf->step + ((int64_t)1 << (sh - 1))) >> sh);
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

/* w + sy up for a sample row at offset sy (rt_cam_soff), exact. */
static inline rt_cam_ray rt_cam_row_base(const rt_cam_frame *cf, int32_t sy)
{
    const int64_t one = (int64_t)1 << cf->fbits; /* w 2^fbits, by a product:
                                                 w may be negative */
    rt_cam_ray b;
    b.x = cf->w.x * one + fx_imul64(cf->up.x, sy);
    b.y = cf->w.y * one + fx_imul64(cf->up.y, sy);
    b.z = cf->w.z * one + fx_imul64(cf->up.z, sy);
    return b;
}

/* Unit direction of the sample at offset sx (rt_cam_soff) along the
 * sample row whose base is b (rt_cam_row_base). The exact sum is rounded
 * to FX_UBITS fraction bits first (a relative 2^-31 at most), where it
 * fits 32 bits for any view narrower than about 120 degrees: then the
 * normalisation needs no 64-bit scaling. */
static inline fx_dir3 rt_cam_dir(const rt_cam_frame *cf, const rt_cam_ray *b,
                                 int32_t sx)
{
    const int fb = cf->fbits;
    const int64_t h = (int64_t)1 << (fb - 1);
    return fx_d3_normalize64((b->x + fx_imul64(cf->right.x, sx) + h) >> fb,
                             (b->y + fx_imul64(cf->right.y, sx) + h) >> fb,
                             (b->z + fx_imul64(cf->right.z, sx) + h) >> fb);
}

/* The directions of one sample row at one sample per pixel, column by
 * column, by additions: the same bits as rt_cam_dir(cf, b,
 * rt_cam_soff(cf, k)) for k = rt_cam_col_k(width, 1, x, 0). Why: that
 * costs a 64-bit multiply for the offset and, per component, a
 * multiply-add and a variable 64-bit shift, at every pixel. Along a row
 * k steps by 2, so the offset sx steps by d or d + 1 (the remainder of
 * its rounding says which), and each exact sum v = b + right sx + h by
 * right d or right (d + 1). v is kept times 2^(32 - fbits) where that
 * fits (views narrower than about 120 degrees): its high word is then
 * v >> fbits, an int32 above INT32_MIN, which fx_d3_normalize takes as
 * fx_d3_normalize64 would, without its range tests; else (wide) as it
 * is. The remainder is kept times 2^fbits, at the top of its word: the
 * carry is the word's own. */
typedef struct {
    int64_t v[3];      /* v, times 2^(32 - fbits) unless wide */
    int64_t inc[2][3]; /* its steps: right d and right (d + 1), the same */
    uint32_t rem;      /* (k step + 2^(sh-1)) mod 2^sh, times 2^fbits */
    uint32_t frac;     /* (2 step) mod 2^sh, times 2^fbits (sh = 32 - fb) */
    int wide;          /* v is not scaled: shift it by fbits */
    int fbits;
} rt_cam_walk;

/* Sets *cw at column x0 of the sample row whose base is b, for the
 * columns x0..x1 (x0 <= x1 < width) of an image width wide at cf->n = 1. */
void rt_cam_walk_init(rt_cam_walk *cw, const rt_cam_frame *cf,
                      const rt_cam_ray *b, unsigned width, unsigned x0,
                      unsigned x1);

/* Moves *cw one column right (never past the x1 it was set up for). */
static inline void rt_cam_walk_step(rt_cam_walk *cw)
{
    const uint32_t rem = cw->rem + cw->frac;
    const int64_t *inc = cw->inc[rem < cw->frac]; /* the carry */
    cw->rem = rem;
    cw->v[0] += inc[0];
    cw->v[1] += inc[1];
    cw->v[2] += inc[2];
}

/* rt_cam_walk_dir of a wide walk: out of line, as views that wide are
 * rare and its variable 64-bit shifts long. */
fx_dir3 rt_cam_walk_dir_wide(const rt_cam_walk *cw);

/* The unit direction at *cw's column: rt_cam_dir's. */
static inline fx_dir3 rt_cam_walk_dir(const rt_cam_walk *cw)
{
    if (!cw->wide)
        return fx_d3_normalize(fx_v3((fx_t)(cw->v[0] >> 32),
                                     (fx_t)(cw->v[1] >> 32),
                                     (fx_t)(cw->v[2] >> 32)));
    return rt_cam_walk_dir_wide(cw);
}

#endif /* RT_CAMERA_H */
