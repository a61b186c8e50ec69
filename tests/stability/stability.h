/* SPDX-License-Identifier: MIT */
/*
 * The stability suite's shared part: the helpers every case file uses
 * (tests/stability/helpers.c) and the one list of cases, in the order the
 * runner (tests/test_stability.c) runs them.
 */
#ifndef STABILITY_H
#define STABILITY_H

#include <dirent.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "cli_util.h"
#include "compare.h"
#include "harness.h"
#include "ppm.h"
#include "ref_render.h"
#include "rt_shape.h"
#include "rt_texture.h"
#include "rt_parse.h"
#include "rt_render.h"
#include "rt_trace.h"

#define D2F(x) ((fx_t)lround((x) * 65536.0))

#define F2D(x) ((double)(x) / 65536.0)
/* A unit vector's component (FX_UBITS fraction bits) as a double. */
#define U2D(x) ((double)(x) / (double)FX_UONE)

/* A pixel differs when some channel is off by more than this (of 255). */
#define LEVEL 64

typedef struct {
    ppm_image *img;
} sink;

typedef struct {
    int w, h;  /* 0: the scene's own */
    int spp;   /* 0: the scene's own */
    int depth; /* -1: the scene's own */
    int band;  /* rows per rt_render_rows call; 0: all at once */
} view;

/* What a render comparison found. */
typedef struct {
    compare_result cmp;
    long speckles, speckles_loose, acne;
    rt_stats fx_stats, ref_stats;
} verdict;

/* Expects a hit within tol of t_want. */
#define HIT_AT(o, r, t_want, tol)                                             \
    do {                                                                      \
        double t_;                                                            \
        if (CHECK(cast(&(o), &(r), &t_, NULL)) &&                             \
            !CHECK(fabs(t_ - (t_want)) <= (tol)))                             \
            printf("    t = %.7f, want %.7f +- %g\n", t_, (double)(t_want),  \
                   (double)(tol));                                            \
    } while (0)

#define MISS(o, r)                                                            \
    do {                                                                      \
        double t_;                                                            \
        if (!CHECK(!cast(&(o), &(r), &t_, NULL)))                             \
            printf("    unexpected hit at t = %.7f\n", t_);                   \
    } while (0)

/* Background blue, which no surface in these scenes shows. */
#define BG_BLUE "background 0 0 1\n"

/* effects.c: a room seen from inside it, with %s for the fov. */
extern const char room[];

#define CAM "camera eye 0 0 -5 look 0 0 0\nmaterial m color 1 1 1\n"

/* Flat colours (ambient only) so a pixel says which quad it shows. */
#define BG_GREEN "background 0 1 0\n"

#define FLAT_MATS                                                             \
    "material red color 1 0 0 ambient 1 diffuse 0 specular 0\n"               \
    "material blue color 0 0 1 ambient 1 diffuse 0 specular 0\n"

extern int verbose;
extern const char *dump_dir;
extern const char *case_name;
extern rt_scene scene_a, scene_b;
extern int dump_seq;

int parse(const char *text, rt_scene *s);
void expect_reject(const char *text, rt_status want, const char *msg);
int to_image(void *ctx, int y, const uint8_t *row, size_t n);
rt_options options(const rt_scene *s, view v);
rt_status render(const rt_scene *s, view v, int ref, ppm_image *img,
                        rt_stats *stats);
int same_bytes(const ppm_image *a, const ppm_image *b);
const uint8_t *pix(const ppm_image *m, int x, int y);
int pdiff(const uint8_t *a, const uint8_t *b);
int at_edge(const ppm_image *m, int x, int y);
int agreeing(const ppm_image *m, int x, int y, int *nb);
long count_speckles2(const ppm_image *fx, const ppm_image *ref,
                            long *loose);
long count_speckles(const ppm_image *fx, const ppm_image *ref);
long count_acne(const ppm_image *fx, const ppm_image *ref);
long mirror_diffs(const ppm_image *m, int *max_err);
long count_colour(const ppm_image *m, uint8_t r, uint8_t g, uint8_t b);
void dump(const char *tag, const ppm_image *m);
void judge(const rt_scene *s, view vw, verdict *v, ppm_image *fx_out);
void expect_close(const rt_scene *s, view vw, double min_psnr);
void expect_clean(const rt_scene *s, view vw, double min_psnr,
                  const char *what);
rt_object obj(int kind, double ax, double ay, double az);
rt_object sphere(double cx, double cy, double cz, double r);
rt_object upright(int kind, double ax, double ay, double az, double r,
                         double h);
rt_object box(double x0, double y0, double z0, double x1, double y1,
                     double z1);
rt_object quad(fx_vec3 a, fx_vec3 e1, fx_vec3 e2);
fx_vec3 V(double x, double y, double z);
rt_ray ray_raw(fx_vec3 o, fx_vec3 d);
fx_dir3 dir16(fx_vec3 d);
rt_ray ray(double ox, double oy, double oz, double dx, double dy,
                  double dz);
int cast(const rt_object *o, const rt_ray *r, double *t, uint16_t *part);
int cast_ref(const rt_object *o, const rt_ray *r, double *t,
                    ref_vec3 *n);
fx_dir3 normal_at(const rt_object *o, const rt_ray *r, double t,
                         uint16_t part);
double nerr(fx_dir3 n, double x, double y, double z);
int sweep(const rt_object *ob, fx_vec3 o, fx_vec3 step, fx_vec3 d,
                 int n, int k_sure, double tol);

/* scenes.c: a small scene moved o units away along each axis. */
extern const char translated_fmt[];
void translated(double o, char *buf, size_t n);

/* geometry.c: a fixed-seed uniform generator in [0, 1). */
extern uint32_t rng_state;
double rnd(void);

#define STAB_CASES(X) \
    X(tangent_sphere_exact) \
    X(tangent_cylinder_side) \
    X(tangent_cone_side) \
    X(grazing_quad_dn_1ulp) \
    X(plane_parallel_few_ulps) \
    X(grazing_box_face) \
    X(grazing_cylinder_side) \
    X(grazing_cone_generator) \
    X(origin_on_sphere) \
    X(origin_on_quad) \
    X(origin_on_box_face) \
    X(origin_on_cylinder_rim) \
    X(tiny_sphere_3ulp) \
    X(tiny_upright_4ulp) \
    X(tiny_quad_box_1ulp) \
    X(huge_coords_saturate) \
    X(cylinder_cap_rim_watertight) \
    X(cone_apex_and_rim) \
    X(cone_apex_centre_pixel) \
    X(box_edges_watertight) \
    X(quad_seam_no_crack) \
    X(camera_inside_sphere) \
    X(camera_inside_cylinder) \
    X(camera_inside_cone) \
    X(camera_inside_box) \
    X(translated_30000) \
    X(far_objects_20000) \
    X(beyond_range_background) \
    X(huge_ground_shapes) \
    X(degenerate_sphere) \
    X(degenerate_box) \
    X(degenerate_quad) \
    X(degenerate_upright) \
    X(coplanar_quads_axis) \
    X(coplanar_quads_tilted) \
    X(coplanar_bottom_on_floor) \
    X(coplanar_glass_on_floor) \
    X(tir_just_below_and_above) \
    X(tir_at_critical) \
    X(glass_ior1_invisible) \
    X(light_inside_object) \
    X(light_on_surface) \
    X(facing_mirrors_depth_max_spp16) \
    X(image_1x1) \
    X(image_4096x1) \
    X(fov_near_0) \
    X(fov_small_scale) \
    X(fov_near_180) \
    X(colour_saturates_monotone) \
    X(dither_white_no_wrap) \
    X(symmetric_scene_mirrors) \
    X(apex_and_rim_render) \
    X(acne_open_shapes) \
    X(adaptive_bands_deterministic) \
    X(scenes_no_speckles) \
    X(seed_no_acne_320) \
    X(texture_cells_1ulp) \
    X(texture_edge_subulp) \
    X(bump_lattice_1ulp) \
    X(bump_normal_precision) \
    X(texture_size_below_1ulp) \
    X(eye_look_60000_apart) \
    X(fov_near_180_wide) \
    X(flat_cone_grazing_rim) \
    X(glass_ior_100_outer_ring) \
    X(light_at_cone_apex) \
    X(apex_light_along_generator) \
    X(light_on_flat_cone_rim) \
    X(bumped_mirror_under_flat_cone) \
    X(lights_on_surfaces) \
    X(far_tilted_quads) \
    X(bumped_glass_and_mirror) \
    X(rim_caps_from_outside) \
    X(needle_cone_grazing)

#define STAB_DECLARE(n) void case_##n(void);
STAB_CASES(STAB_DECLARE)
#undef STAB_DECLARE

#endif /* STABILITY_H */
