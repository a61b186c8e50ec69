/* SPDX-License-Identifier: MIT */
/*
 * rt_scene: the scene description the renderer reads. The caller owns the
 * storage (fixed-capacity arrays sized in rt_config.h); the parser fills it
 * and rt_object_prepare() derives per-object constants.
 *
 * Geometry conventions: y is up. Cylinders and cones stand on their base
 * centre and extend along +y. Boxes are axis-aligned. A quad is a
 * parallelogram: corner + s*edge1 + t*edge2 for s, t in [0, 1]. A mesh
 * refers to triangles and their hierarchy in storage the caller owns
 * (constant tables in flash on a device, rt_mesh.h).
 */
#ifndef RT_SCENE_H
#define RT_SCENE_H

#include <stdint.h>
#include "rt_config.h"
#include "fx_dir.h"
#include "rt_features.h"

/* ---- Configuration check -------------------------------------------------
 * The capacities size rt_scene, so an application compiled with other
 * values than the core would hand it a scene of another layout. To make
 * that a link error instead of memory corruption, every entry point that
 * takes an rt_scene is linked under a name carrying them: with the default
 * capacities rt_render_rows is rt_render_rows_cfg_o128_m32_l4 (objects,
 * materials, lights). A mismatch reads, for example,
 *     undefined reference to `rt_render_rows_cfg_o16_m12_l2'
 * meaning: this file was compiled with RT_MAX_OBJECTS=16,
 * RT_MAX_MATERIALS=12 and RT_MAX_LIGHTS=2, the core with other values
 * (`nm` on the core lists its _cfg_ names). The capacities must be plain
 * decimal numbers. */
#define RT_CFG_NAME_(f, o, m, l) f##_cfg_o##o##_m##m##_l##l
#define RT_CFG_NAME(f, o, m, l) RT_CFG_NAME_(f, o, m, l)
#define RT_CFG(f) RT_CFG_NAME(f, RT_MAX_OBJECTS, RT_MAX_MATERIALS,      \
                              RT_MAX_LIGHTS)
#define rt_scene_init RT_CFG(rt_scene_init)
#define rt_parse RT_CFG(rt_parse)
#define rt_parse_with_meshes RT_CFG(rt_parse_with_meshes)
#define rt_render_rows RT_CFG(rt_render_rows)
#define rt_options_from_scene RT_CFG(rt_options_from_scene)
#define rt_scene_features RT_CFG(rt_scene_features)

/* Status codes: 0 is success, failures are negative. */
typedef enum {
    RT_OK = 0,
    RT_ERR_ARG = -1,      /* an argument is out of range */
    RT_ERR_PARSE = -2,    /* the scene text is malformed (see rt_parse_error) */
    RT_ERR_CAPACITY = -3, /* a compile-time capacity was exceeded */
    RT_ERR_ABORTED = -4,  /* the row callback asked to stop */
    RT_ERR_DEGENERATE = -5, /* a shape has zero size or no defined normal */
    RT_ERR_UNSUPPORTED = -6 /* the scene needs an effect this build removed */
} rt_status;

typedef struct {
    fx_t r, g, b; /* linear, nominally 0..1 */
} rt_rgb;

typedef enum {
    RT_TEX_NONE = 0,
    RT_TEX_STRIPES,  /* bands across one axis: axis, color2, scale */
    RT_TEX_CHECKER,  /* squares in x and z: color2, scale */
    RT_TEX_CHECKER3D /* cubes in x, y and z: color2, scale */
} rt_texture_kind;

typedef struct {
    rt_rgb color;       /* base colour */
    fx_t ambient;       /* ka */
    fx_t diffuse;       /* kd */
    fx_t specular;      /* ks */
    uint16_t shininess; /* Phong exponent, 1..1024 */
    fx_t reflect;       /* kr, 0..1 */
    fx_t transparency;  /* kt, 0..1 */
    fx_t ior;           /* index of refraction, > 0 (used when kt > 0) */
    uint8_t texture;    /* rt_texture_kind */
    uint8_t axis;       /* stripes: 0 = x, 1 = y, 2 = z */
    rt_rgb color2;      /* second texture colour */
    fx_t tex_scale;     /* size of one stripe or cell, > 0 */
    fx_t bump;          /* normal perturbation amplitude, 0 = none */
    fx_t bump_scale;    /* size of one bump feature, > 0 */
    /* Derived by rt_material_prepare(). */
    uint32_t tex_rcp;   /* fx_floor_rcp(tex_scale): exact texture cells */
    fx_t ior_inv;       /* 1 / ior */
    uint32_t bump_rcp;  /* fx_floor_rcp(bump_scale): exact lattice cells */
} rt_material;

typedef enum {
    RT_SPHERE = 0,
    RT_QUAD,
    RT_BOX,
    RT_CYLINDER,
    RT_CONE,
    /* Triangles with a bounding volume hierarchy (rt_mesh.h). */
    RT_MESH,
    RT_KIND_COUNT
} rt_kind;

/* Cap flags for cylinders (both) and cones (bottom only). */
#define RT_CAP_BOTTOM 1u
#define RT_CAP_TOP 2u

/* Fraction bits of the frame cylinders and cones are solved in
 * (core/shapes/rt_upright.c), and of a cone's slope rt_object.k. */
#define RT_FRAME_BITS 24

typedef struct {
    uint8_t kind;     /* rt_kind */
    uint8_t material; /* index into rt_scene.mat */
    uint8_t caps;     /* RT_CAP_* */
    uint8_t convex;   /* derived: a ray leaving the surface cannot re-hit it */
    uint8_t small;    /* derived: bounding sphere within 8192 units (the
                         32-bit intersection path applies) */
    uint8_t flat;     /* derived, quads: 1 if n is along y, pu along z and
                         pv along x; 2 if n along y, pu along x, pv along z
                         (the intersection skips the zero terms); else 0 */
    int8_t ushift;    /* derived: cylinders and cones are solved in the
                         frame centred on bc and scaled by 2^-ushift
                         (exact), which brings br into (1/2, 1] */
    fx_vec3 a;        /* sphere: centre; quad: corner; box: min;
                         cylinder, cone: base centre */
    fx_vec3 b;        /* quad: edge1; box: max */
    fx_vec3 c;        /* quad: edge2 */
    fx_t r;           /* sphere, cylinder, cone: radius */
    fx_t h;           /* cylinder, cone: height */
    /* Derived by rt_object_prepare(). */
    fx_dir3 n;        /* quad: unit normal, norm(edge1 x edge2) */
    fx_dir3 pu, pv;   /* quad: unit in-plane axes across edge2 and edge1 */
    fx_t lu, lv;      /* quad: 0 <= (p - a).pu <= lu, 0 <= (p - a).pv <= lv */
    fx_t dist;        /* quad: n . a, rounded and saturated: only a flat
                         quad, whose dist is exact, uses it */
    fx_vec3 bc;       /* bounding sphere centre */
    fx_t br;          /* bounding sphere radius */
    const struct rt_mesh *mesh; /* mesh: its triangles, in world space, and
                         their hierarchy (caller-owned, not copied); here,
                         in ushift's place, rt_object stays 128 bytes on
                         32-bit targets (a power of two to index) */
    uint32_t rinv;    /* sphere: (2^(31 + b) - 1) / r, b the bit length of
                         r: the normal is (p - a) rinv / 2^(b + 1); cone:
                         the height below its apex within which its radius
                         is below 2^-6 of its frame, with RT_FRAME_BITS
                         fraction bits (2^42 / k, at most 2^32 - 1) */
    fx_t k;           /* cone: slope r / h with RT_FRAME_BITS fraction bits
                         (not Q16.16) */
} rt_object;

typedef struct {
    fx_vec3 pos;
    rt_rgb color;
} rt_light;

typedef struct {
    fx_vec3 eye, look, up;
    fx_t fov; /* vertical field of view in degrees, 0 < fov < 180 */
} rt_camera;

typedef struct {
    rt_camera cam;
    rt_rgb background;
    rt_rgb ambient;     /* ambient light colour, multiplies material ka */
    uint16_t width;     /* default image size; the caller may override */
    uint16_t height;
    uint8_t spp;        /* default samples per pixel: 1, 4, 9 or 16 */
    uint8_t depth;      /* default recursion depth, <= RT_MAX_DEPTH */
    uint8_t shadows;    /* 1: lights cast shadows (default), 0: none */
    uint8_t n_materials;
    uint8_t n_lights;
    uint16_t n_objects;
    rt_material mat[RT_MAX_MATERIALS];
    rt_light light[RT_MAX_LIGHTS];
    rt_object obj[RT_MAX_OBJECTS];
} rt_scene;

/* Sets defaults: empty scene, camera at (0,0,-10) looking at the origin,
 * fov 60, black background, white ambient, 320x240, 1 spp, depth 5. */
void rt_scene_init(rt_scene *s);

/* Derives an object's constants and checks its shape (each shape's file in
 * core/shapes, through core/shapes/rt_shape.c). Returns RT_OK, or
 * RT_ERR_DEGENERATE for a zero radius, height, edge or extent, or for
 * parallel quad edges, or RT_ERR_ARG for a mesh without one (rt_mesh.h
 * states what a mesh must hold). */
rt_status rt_object_prepare(rt_object *o);

/* A mesh object's part of rt_object_prepare (core/shapes/rt_mesh_check.c):
 * checks its tables (indices in range, a hierarchy that covers every
 * triangle once within RT_MESH_DEPTH levels, boxes that hold what lies
 * below them) and derives its bounding sphere. Returns RT_OK, or
 * RT_ERR_ARG. Costs a pass over the mesh. */
rt_status rt_mesh_prepare(rt_object *o);

/* Fills a material with the scene language's defaults (docs/scene-format.md):
 * black, ambient 0.1, diffuse 0.9, specular 0.5, shininess 10, ior 1, no
 * reflection, transparency, texture or bump. The parser starts every
 * material from it; set the colour and what else differs, then call
 * rt_material_prepare(). */
void rt_material_defaults(rt_material *m);

/* Derives a material's constants (reciprocal scales). Returns RT_OK, or
 * RT_ERR_ARG for a zero texture or bump scale. */
rt_status rt_material_prepare(rt_material *m);

#endif /* RT_SCENE_H */
