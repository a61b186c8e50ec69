/* SPDX-License-Identifier: MIT */
/*
 * mesh.h: the 'mesh' statement in the browser. The page has no files:
 * JavaScript hands over the OBJ files it serves (ft_file in api.h), and
 * the loader below finds a statement's file among them, by the path the
 * command line would open (relative to the scene's folder), and reads it
 * with the host's OBJ reader (port/posix/mesh_obj.c).
 */
#ifndef FT_WASM_MESH_H
#define FT_WASM_MESH_H

#include <stddef.h>
#include "rt_parse.h"

/* Appends a located error in the command line's layout (api.c). */
void wasm_message_parse_error(const char *file, const char *text,
                              size_t len, const rt_parse_error *e);

/* Keeps a file: its name (a path like "scenes/models/x.obj") and text,
 * copied. Returns 0, or -1 when memory runs out. */
int wasm_file_add(const char *name, size_t name_len, const char *text,
                  size_t len);

/* Forgets every file. */
void wasm_files_clear(void);

/* The rt_mesh_loader; ctx is the scene's name (NUL-terminated), whose
 * folder relative mesh paths start from. */
rt_status wasm_mesh_load(void *ctx, const char *path, size_t path_len,
                         const rt_mesh_place *pl, const struct rt_mesh **out,
                         char *msg, size_t msg_cap);

#endif /* FT_WASM_MESH_H */
