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
 * (core/shapes/rt_upright.c), and of a cone's slope rt_upright.slope. */
#define RT_FRAME_BITS 24

/* Each kind's record: the fields the scene gives, then those
 * rt_object_prepare() derives. Coordinates are world units in Q16.16; a
 * unit vector (fx_dir3) has RT_UNIT_BITS fraction bits. Every record
 * starts with a point, the one its texture cells count from (rt_object's
 * u.origin reads it for any kind). A record's byte field follows that
 * point, within the first 32 bytes of rt_object, where a Cortex-M0 loads
 * a byte with one instruction. */

/* A sphere. */
typedef struct {
    fx_vec3 center;
    fx_t radius;         /* > 0 */
    /* Derived. */
    uint32_t inv_radius; /* (2^(31 + b) - 1) / radius, b the bit length of
                            radius (below 2^32): the normal is
                            (p - center) inv_radius / 2^(b + 1) */
} rt_sphere;

/* A quad: the parallelogram corner + s edge1 + t edge2, s and t in
 * [0, 1]. */
typedef struct {
    fx_vec3 corner;
    uint8_t flat;   /* derived: 1 if normal is along y, axis_u along z and
                       axis_v along x; 2 if normal along y, axis_u along x,
                       axis_v along z (the intersection skips the zero
                       terms); else 0 */
    fx_vec3 edge1;  /* nonzero */
    fx_vec3 edge2;  /* nonzero, not parallel to edge1 */
    /* Derived. */
    fx_dir3 normal; /* unit normal, norm(edge1 x edge2) */
    fx_dir3 axis_u; /* unit in-plane axis, norm(edge2 x normal) */
    fx_dir3 axis_v; /* unit in-plane axis, norm(normal x edge1) */
    fx_t len_u;     /* > 0: a point p of the quad has
                       0 <= (p - corner).axis_u <= len_u */
    fx_t len_v;     /* > 0: likewise 0 <= (p - corner).axis_v <= len_v */
    fx_t dist;      /* normal . corner, rounded and saturated: only a flat
                       quad, whose dist is exact, uses it */
} rt_quad;

/* An axis-aligned box. */
typedef struct {
    fx_vec3 min; /* the low corner */
    fx_vec3 max; /* the high corner, above min on every axis */
} rt_box;

/* A cylinder or a cone (rt_object.kind tells which), standing on its
 * base along +y; a cone's apex is at base + (0, height, 0). */
typedef struct {
    fx_vec3 base;       /* centre of the base */
    int8_t frame_shift; /* derived: the shape is solved in the frame
                           centred on rt_object.bc and scaled by
                           2^-frame_shift (exact), which brings
                           rt_object.br into (1/2, 1] */
    fx_t radius;        /* > 0; a cone's at its base */
    fx_t height;        /* > 0 */
    /* Derived, cones only. */
    fx_t slope;         /* radius / height with RT_FRAME_BITS fraction bits
                           (not Q16.16), in (0, 2^30] */
    uint32_t thin;      /* the height below the apex within which the
                           radius is below 2^-6 of the frame, with
                           RT_FRAME_BITS fraction bits (2^42 / slope, at
                           most 2^32 - 1) */
} rt_upright;

/* A triangle mesh. */
typedef struct {
    fx_vec3 origin;               /* where its texture cells count from;
                                     the parser sets (0, 0, 0), as the
                                     vertices are in world space */
    const struct rt_mesh *tables; /* its triangles, in world space, and
                                     their hierarchy (rt_mesh.h; caller-
                                     owned, not copied) */
} rt_mesh_ref;

/* An object: its kind and material, its kind's record in u (a named
 * member: C99 has no anonymous unions), and its bounding sphere. */
typedef struct {
    uint8_t kind;     /* rt_kind; selects the member of u */
    uint8_t material; /* index into rt_scene.mat */
    uint8_t caps;     /* RT_CAP_*: cylinders (both), cones (bottom only) */
    uint8_t convex;   /* derived: a ray leaving the surface cannot re-hit it */
    uint8_t small;    /* derived: bounding sphere within 8192 units (the
                         32-bit intersection path applies) */
    union {
        fx_vec3 origin;       /* any kind's first point (see above) */
        rt_sphere sphere;     /* RT_SPHERE */
        rt_quad quad;         /* RT_QUAD */
        rt_box box;           /* RT_BOX */
        rt_upright upright;   /* RT_CYLINDER, RT_CONE */
        rt_mesh_ref mesh;     /* RT_MESH */
        uint32_t size_[26];   /* makes rt_object 128 bytes, a power of two
                                 to index (rt_scene.c checks it) */
    } u;
    fx_vec3 bc;       /* derived: bounding sphere centre */
    fx_t br;          /* derived: bounding sphere radius */
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
