/* SPDX-License-Identifier: MIT */
/*
 * api.h: the WebAssembly module's exports, which port/wasm/web/app.js
 * calls. The module has no C library and imports nothing. JavaScript
 * hands over the OBJ files (ft_file), writes the scene text at ft_text()
 * and its name at ft_name(), calls
 * ft_parse(), then ft_begin() and ft_rows() for bands of rows, and reads
 * the RGB888 image at ft_image(). Statuses are rt_status: 0 is success,
 * failures are negative.
 */
#ifndef FT_WASM_API_H
#define FT_WASM_API_H

#include <stdint.h>

#define FT_EXPORT(name) __attribute__((export_name(#name)))

/* Where JavaScript writes the scene text, ft_text_capacity() bytes. */
FT_EXPORT(ft_text) char *ft_text(void);
FT_EXPORT(ft_text_capacity) uint32_t ft_text_capacity(void);

/* Where JavaScript writes the scene's name for messages: NUL-terminated,
 * at most 255 bytes. */
FT_EXPORT(ft_name) char *ft_name(void);

/* The last error, NUL-terminated, worded as the command line words it. */
FT_EXPORT(ft_message) const char *ft_message(void);

/* Forgets the scene and every file given with ft_file(). */
FT_EXPORT(ft_reset) void ft_reset(void);

/* Keeps a copy of a file a scene may name (an OBJ mesh): its path as the
 * command line would open it (e.g. "scenes/models/torus.obj") at
 * ft_name(), its len bytes at ft_text(). Give every file before parsing:
 * the files stay until ft_reset(). Returns 0, or RT_ERR_CAPACITY. */
FT_EXPORT(ft_file) int ft_file(uint32_t len);

/* Parses len bytes at ft_text(), loading the meshes it names from the
 * files given with ft_file(). Returns 0, or a negative status with the
 * message in ft_message(): "NAME:LINE:COL: error: MESSAGE", the line, and
 * a caret under the column, as `fixtrace NAME` prints it. */
FT_EXPORT(ft_parse) int ft_parse(uint32_t len);

/* The parsed scene's own size, samples per pixel and depth. */
FT_EXPORT(ft_scene_width) int ft_scene_width(void);
FT_EXPORT(ft_scene_height) int ft_scene_height(void);
FT_EXPORT(ft_scene_spp) int ft_scene_spp(void);
FT_EXPORT(ft_scene_depth) int ft_scene_depth(void);

/* Sets up a render of the parsed scene by `which` (0: the fixed-point
 * core, 1: the double reference), as the command line's -W -H -s -d
 * --adaptive --draft do: a width, height or spp of 0 and a depth below 0
 * keep the scene's; adaptive and draft 0 are off, and the reference takes
 * neither. Zeroes the counters. Returns 0, or RT_ERR_ARG with the command
 * line's message for a value out of its range (the page's own for a size
 * above 1024 x 768). */
FT_EXPORT(ft_begin) int ft_begin(int which, int width, int height, int spp,
                                 int depth, int adaptive, int draft);

/* Renders rows y0 <= y < y1 of the render ft_begin(which, ...) set up
 * into ft_image(which). Rows are independent: bands give the bytes of one
 * call. Returns 0 or a negative status. */
FT_EXPORT(ft_rows) int ft_rows(int which, int y0, int y1);

/* The image of `which`: ft_width() * ft_height() RGB888 pixels, the top
 * row first. */
FT_EXPORT(ft_image) uint8_t *ft_image(int which);
FT_EXPORT(ft_width) int ft_width(int which);
FT_EXPORT(ft_height) int ft_height(int which);

/* A counter of the render of `which`, as --stats names them: 0
 * primary_rays, 1 shadow_rays, 2 reflection_rays, 3 refraction_rays, 4
 * intersection_tests, 5 rays_cut, 6 interpolated_pixels; -1 for another
 * k. A double holds every count exactly up to 2^53. */
FT_EXPORT(ft_stat) double ft_stat(int which, int k);

#endif /* FT_WASM_API_H */
