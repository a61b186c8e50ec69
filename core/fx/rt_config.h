/* SPDX-License-Identifier: MIT */
/*
 * fixtrace configuration: every build-time option and capacity limit, each
 * with its default. Override any of them in the configuration file (below)
 * or with -DNAME=value; nothing else in the tree defines these names.
 */
#ifndef RT_CONFIG_H
#define RT_CONFIG_H

/* ---- The user's configuration file (docs/embedding.md) -----------------
 * Found the way LVGL finds lv_conf.h: -DRT_CONFIG_FILE='"my_conf.h"' names
 * it; otherwise "fixtrace_conf.h" is included when it is on the include
 * path (__has_include, GCC 5+ and clang, any -std), or always with
 * -DRT_USE_CONF_FILE for a compiler without __has_include. It holds plain
 * `#define NAME value` lines for the options below; every file of the core
 * and of the application must see the same one (rt_scene.h checks the
 * capacities at link time). */
#if defined(RT_CONFIG_FILE)
#include RT_CONFIG_FILE
#elif defined(RT_USE_CONF_FILE)
#include "fixtrace_conf.h"
#elif defined(__has_include)
#if __has_include("fixtrace_conf.h")
#include "fixtrace_conf.h"
#endif
#endif

/* ---- Capacities (they size the caller's rt_scene) ---------------------- */

/* Objects in one scene. */
#ifndef RT_MAX_OBJECTS
#define RT_MAX_OBJECTS 128
#endif

/* Named materials in one scene. */
#ifndef RT_MAX_MATERIALS
#define RT_MAX_MATERIALS 32
#endif

/* Point lights in one scene; with RT_MAX_DEPTH, at most what the colour
 * bound (below) allows: 10 at the default depth of 5, 63 at depth 0. */
#ifndef RT_MAX_LIGHTS
#define RT_MAX_LIGHTS 4
#endif

/* Longest material name, in bytes, not counting the terminator. */
#ifndef RT_MAX_NAME
#define RT_MAX_NAME 23
#endif

/* Widest image the renderer accepts (the caller's row buffer holds one). */
#ifndef RT_MAX_WIDTH
#define RT_MAX_WIDTH 4096
#endif

/* Tallest image the renderer accepts. */
#ifndef RT_MAX_HEIGHT
#define RT_MAX_HEIGHT 4096
#endif

/* Compile-time cap on ray recursion (reflection + refraction bounces). The
 * stack grows by one trace frame per level, so this bounds stack use. It
 * also bounds the colours, with RT_MAX_LIGHTS (the colour bound, below):
 * (16 + 32 RT_MAX_LIGHTS) (RT_MAX_DEPTH + 1) must be below 2048, so the
 * depth is at most 13 with 4 lights, 17 with 3, 24 with 2 and 41 with 1;
 * lower RT_MAX_LIGHTS to go deeper. */
#ifndef RT_MAX_DEPTH
#define RT_MAX_DEPTH 5
#endif

/* Largest supersampling grid side: spp = n*n with n <= RT_MAX_SPP_SIDE. */
#ifndef RT_MAX_SPP_SIDE
#define RT_MAX_SPP_SIDE 4
#endif

/* ---- Behaviour ---------------------------------------------------------- */

/* 1: count rays and intersection tests in rt_stats. 0: no counting code. */
#ifndef RT_STATS
#define RT_STATS 1
#endif

/* RT_ACCURACY (0 fast, 1 default, 2 precise) was removed: neither setting
 * bought accuracy worth its cost (CHANGELOG.md). The math layer rounds as
 * fx_math.h states, as the default did; the accuracy setting is
 * RT_UNIT_BITS, below. */
#ifdef RT_ACCURACY
#error "RT_ACCURACY was removed: RT_UNIT_BITS (16..30) is the accuracy setting"
#endif

/* Fraction bits of unit vectors: ray directions, normals, directions to
 * lights and the camera frame (core/fx/fx_dir.h), 16..30. Positions,
 * distances and colours are Q16.16 whatever this says. 30 (Q2.30) is the
 * default: the image is then within rounding of float32 at a few percent
 * of the cost of 16; docs/accuracy.md measures each setting. */
#ifndef RT_UNIT_BITS
#define RT_UNIT_BITS 30
#endif

/* Levels of a draft render's lattice (rt_draft.h): it traces every
 * 2^RT_DRAFT_LEVELS-th pixel of every 2^RT_DRAFT_LEVELS-th row, then fills
 * in the pixels between them level by level, halving the spacing. 1..3;
 * each level keeps two rows of 14 bytes per lattice column. */
#ifndef RT_DRAFT_LEVELS
#define RT_DRAFT_LEVELS 2
#endif

/* 1: camera rays test only the objects their pixel row and column can
 * reach (rt_cull.c; costs RT_MAX_OBJECTS * 6 bytes of stack). 0: every
 * camera ray tests every object. The image is the same either way. */
#ifndef RT_CULL
#define RT_CULL 1
#endif

/* Shadow rays, and rays leaving a reflective or transparent object, test
 * only the objects listed for their direction on an N x N grid per
 * hemisphere (rt_dirgrid.c); rays inside closed glass that at most one
 * other shape reaches into test only the two (rt_sealed.h, RT_SEALED
 * below). 0: every such ray
 * tests every object. The image is the same either way. */
#ifndef RT_DIR_GRID
#define RT_DIR_GRID 8
#endif

/* Most direction grids of one render: lights first, then the eye's
 * mirror images in unbumped mirror quads, then the reflective or
 * transparent objects in scene order; the rest test every object. */
#ifndef RT_DIR_MAX_GRIDS
#define RT_DIR_MAX_GRIDS (RT_MAX_LIGHTS + 4)
#endif

/* Stack for the grids' bit sets, in 32-bit words: one grid takes
 * 2 N^2 ceil(objects / 32) words (128 for N = 8 and up to 32 objects).
 * Default: RT_DIR_MAX_GRIDS grids at full capacity, at most 4 KB. */
#ifndef RT_DIR_POOL_WORDS
#if RT_DIR_MAX_GRIDS * 2 * RT_DIR_GRID * RT_DIR_GRID * \
        ((RT_MAX_OBJECTS + 31) / 32) > 1024
#define RT_DIR_POOL_WORDS 1024
#else
#define RT_DIR_POOL_WORDS                                                     \
    (RT_DIR_MAX_GRIDS * 2 * RT_DIR_GRID * RT_DIR_GRID *                       \
     ((RT_MAX_OBJECTS + 31) / 32))
#endif
#endif

/* ---- Effect removal (default off; see docs/effects.md) ------------------
 * -DRT_NO_<NAME> removes the code for one effect or shape, for each NAME
 * of RT_FEATURE_LIST (rt_features.h): SHADOWS, REFLECTION, REFRACTION,
 * TEXTURES, BUMP, SPECULAR, MULTILIGHT, SUPERSAMPLING, SPHERE, QUAD, BOX,
 * CYLINDER, CONE, MESH. A scene that needs a removed effect is refused
 * (rt_render_rows returns RT_ERR_UNSUPPORTED), never rendered wrongly;
 * make firmware derives the flags from the scene (fixtrace --build-flags).
 *
 * The code reads each flag only as the 0/1 constant RT_HAS_<NAME> below,
 * in ordinary conditions (`if (RT_HAS_REFRACTION && m->transparency > 0)`):
 * the compiler drops the dead branch as #if would, and every branch still
 * compiles in every configuration. */

#ifdef RT_NO_SHADOWS
#define RT_HAS_SHADOWS 0
#else
#define RT_HAS_SHADOWS 1 /* shadow rays */
#endif

#ifdef RT_NO_REFLECTION
#define RT_HAS_REFLECTION 0
#else
#define RT_HAS_REFLECTION 1 /* mirror rays */
#endif

#ifdef RT_NO_REFRACTION
#define RT_HAS_REFRACTION 0
#else
#define RT_HAS_REFRACTION 1 /* transmitted rays */
#endif

#ifdef RT_NO_TEXTURES
#define RT_HAS_TEXTURES 0
#else
#define RT_HAS_TEXTURES 1 /* stripes and checkers */
#endif

#ifdef RT_NO_BUMP
#define RT_HAS_BUMP 0
#else
#define RT_HAS_BUMP 1 /* bump-mapped normals */
#endif

#ifdef RT_NO_SPECULAR
#define RT_HAS_SPECULAR 0
#else
#define RT_HAS_SPECULAR 1 /* Phong highlights */
#endif

#ifdef RT_NO_MULTILIGHT
#define RT_HAS_MULTILIGHT 0
#else
#define RT_HAS_MULTILIGHT 1 /* lights after the first */
#endif

#ifdef RT_NO_SUPERSAMPLING
#define RT_HAS_SUPERSAMPLING 0
#else
#define RT_HAS_SUPERSAMPLING 1 /* spp > 1 and adaptive anti-aliasing */
#endif

/* Draft renders (rt_draft.h, rt_options.draft): not a scene's effect but
 * a render option, so not in RT_FEATURE_LIST. -DRT_NO_DRAFT (make firmware
 * with DRAFT=0, which never asks for one) links nothing of rt_draft.c and
 * rt_thin.c; rt_render_rows then refuses o->draft with
 * RT_ERR_UNSUPPORTED. */
#ifdef RT_NO_DRAFT
#define RT_HAS_DRAFT 0
#else
#define RT_HAS_DRAFT 1 /* draft renders */
#endif

#ifdef RT_NO_SPHERE
#define RT_HAS_SPHERE 0
#else
#define RT_HAS_SPHERE 1 /* spheres */
#endif

#ifdef RT_NO_QUAD
#define RT_HAS_QUAD 0
#else
#define RT_HAS_QUAD 1 /* quads */
#endif

#ifdef RT_NO_BOX
#define RT_HAS_BOX 0
#else
#define RT_HAS_BOX 1 /* boxes */
#endif

#ifdef RT_NO_CYLINDER
#define RT_HAS_CYLINDER 0
#else
#define RT_HAS_CYLINDER 1 /* cylinders */
#endif

#ifdef RT_NO_CONE
#define RT_HAS_CONE 0
#else
#define RT_HAS_CONE 1 /* cones */
#endif

#ifdef RT_NO_MESH
#define RT_HAS_MESH 0
#else
#define RT_HAS_MESH 1 /* triangle meshes */
#endif

/* ---- Derived switches (0/1) --------------------------------------------- */

/* Rays that leave a surface: reflected or refracted. */
#define RT_HAS_SECONDARY (RT_HAS_REFLECTION || RT_HAS_REFRACTION)

/* Any ray besides camera rays (shadow, reflected, refracted). */
#define RT_HAS_RAYS (RT_HAS_SHADOWS || RT_HAS_SECONDARY)

/* Cylinders or cones: the shapes solved in their own frame. */
#define RT_HAS_UPRIGHT (RT_HAS_CYLINDER || RT_HAS_CONE)

/* Any shape at all (0: a firmware for a scene with no objects). */
#define RT_HAS_SHAPES                                                         \
    (RT_HAS_SPHERE || RT_HAS_QUAD || RT_HAS_BOX || RT_HAS_UPRIGHT ||       \
     RT_HAS_MESH)

/* The cut-off of faint rays (rt_cutoff.h): with secondary rays only. */
#define RT_CUTOFF RT_HAS_SECONDARY

/* The direction grids are built (rt_dirgrid.h): RT_DIR_GRID > 0 and some
 * ray kind they cull is in the build. */
#define RT_DIR_GRIDS (RT_DIR_GRID > 0 && RT_HAS_RAYS)

/* Culling for closed glass (rt_sealed.h), off with the direction grids
 * (RT_DIR_GRID 0) so that suite_cull compares it too. */
#define RT_SEALED (RT_DIR_GRIDS && RT_HAS_REFRACTION)

/* ---- Compiler hints ----------------------------------------------------- */

/* Inlining decisions that measurably matter for cost or stack (GCC and
 * Clang; other compilers decide for themselves). */
#if defined(__GNUC__)
#define RT_ALWAYS_INLINE __attribute__((always_inline))
#define RT_NOINLINE __attribute__((noinline))
/* A rare path: out of line, and compiled for size rather than speed. */
#define RT_COLD __attribute__((noinline, cold))
#else
#define RT_ALWAYS_INLINE
#define RT_NOINLINE
#define RT_COLD
#endif

/* ---- Checks -------------------------------------------------------------- */

/* The scene's field types bound the capacities. */
#if RT_DRAFT_LEVELS < 1 || RT_DRAFT_LEVELS > 3
#error "RT_DRAFT_LEVELS must be 1..3"
#endif
#if RT_MAX_LIGHTS < 1 || RT_MAX_LIGHTS > 255
#error "RT_MAX_LIGHTS must be 1..255: rt_scene.n_lights is a uint8_t"
#endif
#if RT_MAX_WIDTH < 1 || RT_MAX_WIDTH > 65535 || RT_MAX_HEIGHT < 1 || \
    RT_MAX_HEIGHT > 65535
#error "RT_MAX_WIDTH and RT_MAX_HEIGHT must be 1..65535 (uint16_t sizes)"
#endif
#if RT_MAX_SPP_SIDE < 1 || RT_MAX_SPP_SIDE > 15
#error "RT_MAX_SPP_SIDE must be 1..15: rt_scene.spp is a uint8_t"
#endif
#if RT_MAX_DEPTH < 0 || RT_MAX_DEPTH > 255
#error "RT_MAX_DEPTH must be 0..255: rt_scene.depth is a uint8_t"
#endif
#if RT_MAX_MATERIALS < 1 || RT_MAX_MATERIALS > 255
#error "RT_MAX_MATERIALS must be 1..255: rt_object.material is a uint8_t"
#endif
#if RT_MAX_OBJECTS < 1 || RT_MAX_OBJECTS > 65535
#error "RT_MAX_OBJECTS must be 1..65535: rt_scene.n_objects is a uint16_t"
#endif
#if RT_MAX_NAME < 1
#error "RT_MAX_NAME must be at least 1"
#endif

/* The colour bound. Colour arithmetic needs no saturation (rt_colour.h): a
 * channel stays below 16 (ambient) plus 32 per light (Lambert and Phong,
 * lights up to 16), summed over every level of recursion, and that sum is
 * kept below 2048, a sixteenth of the Q16.16 range. With L lights the
 * deepest recursion is 2047 / (16 + 32 L) - 1. */
#define RT_COLOUR_BOUND ((16 + 32 * RT_MAX_LIGHTS) * (RT_MAX_DEPTH + 1))
#if RT_COLOUR_BOUND >= 2048
#error "RT_MAX_DEPTH and RT_MAX_LIGHTS exceed the colour bound: (16 + 32 lights) x (depth + 1) must be below 2048, so depth <= 13 with 4 lights, 17 with 3, 24 with 2, 41 with 1, and lights <= 10 at depth 5 (rt_config.h)"
#endif

#endif /* RT_CONFIG_H */
