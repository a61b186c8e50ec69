/* SPDX-License-Identifier: MIT */
/*
 * ref_render: the double-precision reference renderer. It implements
 * docs/render-model.md with textbook formulas in plain double and libm, so
 * the difference between its image and the fixed-point core's is the cost
 * of the arithmetic alone. Host only: it never goes into core/.
 *
 * It reads the same rt_scene the parser fills, converting every Q16.16
 * field to double (value / 65536), and recomputes everything else (quad
 * normals, cone slopes, convexity) from the primary fields; the derived
 * fields of rt_object and rt_material are never read.
 */
#ifndef REF_RENDER_H
#define REF_RENDER_H

#include <stddef.h>
#include <stdint.h>
#include "rt_render.h"

/* Offset of secondary-ray origins, and the smallest accepted hit distance. */
#define REF_EPS (1.0 / 512.0)

/* A ray is parallel to a plane when |d . n| < REF_PAR. */
#define REF_PAR (1.0 / 65536.0)

typedef struct {
    double x, y, z;
} ref_vec3;

/* One shape in double, as rt_object's primary fields describe it. */
typedef struct {
    int kind;      /* rt_kind */
    unsigned caps; /* RT_CAP_* (a cone keeps only RT_CAP_BOTTOM) */
    int convex;    /* a ray leaving its outside cannot meet it again */
    ref_vec3 a;    /* sphere: centre; quad: corner; box: min; cylinder,
                      cone: base centre; mesh: its texture's origin (the
                      first point of each, rt_object.u.origin) */
    ref_vec3 b;    /* quad: edge1; box: max */
    ref_vec3 c;    /* quad: edge2 */
    double r, h;   /* radius, height */
    const struct rt_mesh *mesh; /* mesh: its triangles (the scene's) */
    struct ref_mesh_boxes *boxes; /* mesh: the reference's own boxes
                      (ref_mesh_setup), or NULL to test every triangle */
} ref_shape;

/* The nearest hit of a ray on one shape. */
typedef struct {
    double t;       /* distance along the unit direction */
    ref_vec3 n_out; /* unit outward normal (a quad: norm(edge1 x edge2),
                       not yet turned to face the ray) */
} ref_hit;

/* Converts an object's primary fields to double and derives its convexity
 * (sphere, quad, box, a cylinder with both caps, a cone with its cap). */
void ref_shape_from_object(const rt_object *obj, ref_shape *sh);

/* Intersects the ray o + t*d (d a unit vector) with one shape, accepting
 * REF_EPS < t < tmax (HUGE_VAL for no bound). Returns 1 and fills
 * *hit with the nearest such hit, or returns 0. */
int ref_intersect(const ref_shape *sh, ref_vec3 o, ref_vec3 d, double tmax,
                  ref_hit *hit);

/* The bump lattice value at an integer point, exactly as the spec's hash
 * defines it: a multiple of 2^-16 in [-1, 1). */
/* A mesh shape's own bounding boxes (port/posix/ref_mesh.c): a speed-up
 * only, the hits are the same without. Returns 0, or -1 out of memory. */
int ref_mesh_setup(ref_shape *sh);

/* Releases what ref_mesh_setup made. */
void ref_mesh_release(ref_shape *sh);

/* The mesh's nearest hit, as ref_intersect. */
int ref_mesh_hit(const ref_shape *sh, ref_vec3 o, ref_vec3 d, double tmax,
                 ref_hit *hit);

double ref_lattice(uint32_t seed, int32_t ix, int32_t iy, int32_t iz);

/* Value noise at u: smoothstep-weighted trilinear interpolation of the
 * eight surrounding lattice values, in the order x, y, z. */
double ref_noise(uint32_t seed, ref_vec3 u);

/* Renders rows y0 <= y < y1 exactly as rt_render_rows() does (same
 * options, row layout, callback and counters; rows are independent), in
 * double precision. stats may be NULL; like the core, this call's rays and
 * ray-object tests are added to it (the caller zeroes it). Returns RT_OK,
 * RT_ERR_ARG for bad options, rows, pointers or scene indices,
 * RT_ERR_DEGENERATE for a shape with no size, or RT_ERR_ABORTED when fn
 * returned non-zero. */
rt_status ref_render_rows(const rt_scene *s, const rt_options *o, int y0,
                          int y1, uint8_t *row_buf, rt_row_fn fn, void *ctx,
                          rt_stats *stats);

/* ref_render_rows() compiled in float32 instead of double (port/posix/
 * ref32.h): the same formulas, arguments and results, a float-class
 * yardstick for the fixed-point core (fixtrace --reference-float). */
rt_status ref32_render_rows(const rt_scene *s, const rt_options *o, int y0,
                            int y1, uint8_t *row_buf, rt_row_fn fn,
                            void *ctx, rt_stats *stats);

#endif /* REF_RENDER_H */
