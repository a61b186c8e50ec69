/* SPDX-License-Identifier: MIT */
/*
 * mesh_build: the host's side of a mesh (core/shapes/rt_mesh.h): the bounding
 * volume hierarchy over a triangle list, built with the surface-area
 * heuristic, and the one allocation that holds the finished rt_mesh.
 */
#ifndef MESH_BUILD_H
#define MESH_BUILD_H

#include <stddef.h>

#include "rt_mesh.h"

/* Most triangles in one leaf (more only at RT_MESH_DEPTH, or in a mesh of
 * more than (RT_MESH_MAX + 1) / 2 triangles, whose leaves are shared out
 * so that the nodes fit 16-bit indices). */
#define MESH_LEAF_MAX 4

/* Builds a mesh over n_tris triangles (3 indices into v each, counter-
 * clockwise seen from outside) of the n_verts vertices; vn (may be NULL)
 * gives unit vertex normals. Copies what it needs; the triangles are
 * reordered into leaf order. Returns the mesh, which mesh_free releases,
 * or NULL with the reason in msg (more than RT_MESH_MAX triangles or
 * vertices; up to that many always fit the hierarchy), an
 * index out of range, a mesh larger than 16384 units, no memory). */
rt_mesh *mesh_build(const fx_vec3 *v, unsigned n_verts, const fx_dir3 *vn,
                    const uint32_t *tri, unsigned n_tris, char *msg,
                    size_t msg_cap);

/* Releases a mesh from mesh_build (NULL is allowed). */
void mesh_free(rt_mesh *m);

/* Generated closed meshes for tests and tools/mkmodel (Q16.16 vertices,
 * counter-clockwise outside, shared vertices, so watertight): an
 * icosphere of radius r about the origin, subdivided `level` times
 * (20 4^level triangles), and a torus about the y axis with radii R and
 * r, n_u segments around the axis and n_v around the tube (2 n_u n_v
 * triangles). Arrays come from malloc; *vn gets the exact normals.
 * Return 0, or -1 when out of memory. */
int mesh_icosphere(double r, unsigned level, fx_vec3 **v, fx_dir3 **vn,
                   unsigned *n_verts, uint32_t **tri, unsigned *n_tris);
int mesh_torus(double R, double r, unsigned n_u, unsigned n_v, fx_vec3 **v,
               fx_dir3 **vn, unsigned *n_verts, uint32_t **tri,
               unsigned *n_tris);

#endif /* MESH_BUILD_H */
