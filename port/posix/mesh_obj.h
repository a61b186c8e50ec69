/* SPDX-License-Identifier: MIT */
/*
 * mesh_obj: Wavefront OBJ files for the 'mesh' statement, on the host.
 * Reads v, vn and f (triangles, and polygons split into fans); every other
 * statement is counted and ignored. The vertices are placed by the
 * statement's scale, rotation and translation in fixed point, and the
 * hierarchy is built (mesh_build.h). Errors are located file:line:col
 * like the scene's.
 */
#ifndef MESH_OBJ_H
#define MESH_OBJ_H

#include <stdio.h>

#include "mesh_build.h"
#include "rt_parse.h"

/* One mesh the loader made. */
struct mesh_obj_made {
    rt_mesh *m;
};

/* The loader's state (the ctx of rt_parse_with_meshes): where paths are
 * relative to, where messages go, and the meshes it made. */
typedef struct {
    char *base_dir;        /* the scene's directory ("" for the current) */
    FILE *diag;            /* errors and notes (NULL: none) */
    int quiet;             /* 1: no notes about ignored statements */
    struct mesh_obj_made *mesh; /* owned: mesh_obj_free */
    unsigned n_mesh;
    unsigned long ignored; /* statements ignored, over every file */
    unsigned long triangles; /* triangles made, over every file */
} mesh_obj_ctx;

/* An empty loader for the scene at scene_path (its directory is the base
 * of relative mesh paths). */
void mesh_obj_init(mesh_obj_ctx *c, const char *scene_path, FILE *diag,
                   int quiet);

/* Releases the meshes (the scenes that refer to them become invalid). */
void mesh_obj_free(mesh_obj_ctx *c);

/* The rt_mesh_loader: reads the file, relative to c->base_dir. */
rt_status mesh_obj_load(void *ctx, const char *path, size_t path_len,
                        const rt_mesh_place *pl, const struct rt_mesh **out,
                        char *msg, size_t msg_cap);

/* OBJ text to a placed mesh: NULL with *err filled in (line, column and
 * message, as rt_parse reports); *ignored counts the statements skipped. */
rt_mesh *mesh_obj_parse(const char *text, size_t len, const rt_mesh_place *pl,
                        rt_parse_error *err, unsigned long *ignored);

/* rt_parse_with_meshes with this loader for the scene at scene_path
 * (whose directory becomes the base of relative mesh paths). */
rt_status mesh_obj_parse_scene(const char *text, size_t len,
                               const char *scene_path, rt_scene *s,
                               rt_parse_error *err, mesh_obj_ctx *c);

#endif /* MESH_OBJ_H */
