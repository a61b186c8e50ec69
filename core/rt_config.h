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

/* Point lights in one scene. */
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
 * stack grows by one trace frame per level, so this bounds stack use. */
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

/* Accuracy of the math layer (core/fx_*): 0 = fast (rounds down; roots,
 * divide and normalize within 1-2 ulps without correction steps),
 * 1 = default (correctly rounded; the reference checksums), 2 = precise
 * (ties to even, normalize correctly rounded). fx_math.h states each
 * operation's bound; docs/accuracy.md measures cost against image error. */
#ifndef RT_ACCURACY
#define RT_ACCURACY 1
#endif

/* 1: camera rays test only the objects their pixel row and column can
 * reach (rt_cull.c; costs RT_MAX_OBJECTS * 6 bytes of stack). 0: every
 * camera ray tests every object. The image is the same either way. */
#ifndef RT_CULL
#define RT_CULL 1
#endif

/* Shadow rays, and rays leaving a reflective or transparent object, test
 * only the objects listed for their direction on an N x N grid per
 * hemisphere (rt_dirgrid.c); rays inside closed glass that nothing else
 * reaches into test only it (rt_trace.h RT_SEALED). 0: every such ray
 * tests every object. The image is the same either way. */
#ifndef RT_DIR_GRID
#define RT_DIR_GRID 8
#endif

/* Most direction grids of one render: lights first, then the reflective
 * or transparent objects in scene order; the rest test every object. */
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
 * Each flag removes the code for one effect. A scene that needs a removed
 * effect is refused (rt_render_rows returns RT_ERR_UNSUPPORTED), never
 * rendered wrongly; make firmware derives the flags from the scene.
 * RT_NO_REFLECTION, RT_NO_REFRACTION, RT_NO_TEXTURES, RT_NO_BUMP,
 * RT_NO_SHADOWS, RT_NO_SPECULAR, RT_NO_SUPERSAMPLING, RT_NO_MULTILIGHT,
 * RT_NO_SPHERE, RT_NO_QUAD, RT_NO_BOX, RT_NO_CYLINDER, RT_NO_CONE. */

#endif /* RT_CONFIG_H */
