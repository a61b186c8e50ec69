/* SPDX-License-Identifier: MIT */
/*
 * rt_parse: the text scene format (docs/scene-format.md) into an rt_scene.
 * No allocation: the caller provides the scene; names live on the parser's
 * stack while it runs. Works on a device as on a host.
 */
#ifndef RT_PARSE_H
#define RT_PARSE_H

#include <stddef.h>
#include "rt_scene.h"

/* Where and what the first problem in the text is. The message names the
 * limit or rule that was broken; it is plain ASCII without a position, so a
 * caller can print "file:line:col: msg", then the line, then a marker. */
typedef struct {
    uint32_t line;   /* 1-based line of the problem */
    uint32_t col;    /* 1-based column (bytes) */
    size_t line_off; /* offset of that line's first byte in the input */
    size_t line_len; /* its length, without the newline (or "\r\n") */
    size_t tok_len;  /* bytes of the offending token from col; 0 when
                        something is missing at the end of a line */
    char msg[192];   /* what is wrong, NUL-terminated, no position */
} rt_parse_error;

/* Parses len bytes of scene text into *s (which it initialises first).
 * Never reads outside text[0..len); time is linear in len; no recursion,
 * no allocation. Returns RT_OK; or RT_ERR_PARSE, RT_ERR_CAPACITY,
 * RT_ERR_DEGENERATE, or RT_ERR_UNSUPPORTED for a 'mesh' statement (see
 * rt_parse_with_meshes), with *err filled in (err must not be NULL).
 * After an error *s holds a partial scene: do not render it. */
rt_status rt_parse(const char *text, size_t len, rt_scene *s,
                   rt_parse_error *err);

/* Where a 'mesh' statement places its model: scaled about the model's
 * origin, then rotated about x, then y, then z, then moved. */
typedef struct {
    fx_t scale;        /* uniform, > 0 (default 1) */
    fx_t rotate[3];    /* degrees about x, y and z (default 0) */
    fx_vec3 translate; /* default 0 */
    uint8_t smooth;    /* 1: interpolated vertex normals; 0: flat faces */
} rt_mesh_place;

/* Reads the mesh file path[0 .. path_len) (as written in the scene, not
 * NUL-terminated) and places it by *pl. Returns RT_OK with *out, a mesh
 * that stays valid as long as the scene (the loader owns it); or a
 * failure status with a short reason in msg (msg_cap bytes, NUL-
 * terminated), having reported any position inside the file itself. */
typedef rt_status (*rt_mesh_loader)(void *ctx, const char *path,
                                    size_t path_len, const rt_mesh_place *pl,
                                    const struct rt_mesh **out, char *msg,
                                    size_t msg_cap);

/* rt_parse with 'mesh' statements, whose files load(ctx, ...) reads. A
 * NULL load refuses them, as rt_parse does: a scene parsed on a device
 * cannot name a file (firmware built with PRUNE=1 carries its meshes as
 * tables instead, mk/firmware.mk). */
rt_status rt_parse_with_meshes(const char *text, size_t len, rt_scene *s,
                               rt_parse_error *err, rt_mesh_loader load,
                               void *ctx);

/* Parses one decimal number [+-]digits[.digits] at text[0..len) straight
 * to Q16.16, correctly rounded to nearest (ties away from zero). Either
 * side of the point may be empty ("1.", ".5"), not both. Stores the count
 * of bytes used in *used (if used is not NULL; 0 when there is no number)
 * and stops at the first byte that cannot continue the number, which the
 * caller checks. Returns RT_OK, or RT_ERR_PARSE for no number, a value
 * that rounds outside the Q16.16 range, or more than 40 digits in all;
 * *out is written only on success. */
rt_status rt_parse_fx(const char *text, size_t len, fx_t *out, size_t *used);

#endif /* RT_PARSE_H */
