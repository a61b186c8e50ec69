/* SPDX-License-Identifier: MIT */
/*
 * rt_mesh: triangle meshes. A mesh is constant data the caller owns: its
 * vertices in world space (Q16.16), optional vertex normals, triangles as
 * vertex indices, and a bounding volume hierarchy over the triangles. The
 * host builds it (port/posix/mesh_*.c: the OBJ reader and the hierarchy
 * builder); a device gets the same tables in flash from `fixtrace
 * --emit-c`. The core only reads it: no allocation, no recursion.
 *
 * The ray/triangle test is watertight and exact (docs/numerics.md): the
 * vertices are moved to the ray's origin and sheared so that the ray runs
 * along an axis, each rounded once and the same way for every triangle
 * that shares it, and the three edge functions of the origin are exact
 * 64-bit integers. A point on an edge or a vertex is decided as if it
 * were moved an infinitesimal step in a fixed direction, so exactly one
 * of the triangles that meet there claims it.
 */
#ifndef RT_MESH_H
#define RT_MESH_H

#include "rt_ray.h"

/* Deepest hierarchy the traversal's fixed stack holds (the builder never
 * makes a deeper one; rt_mesh_check refuses one). */
#define RT_MESH_DEPTH 32

/* Most triangles and vertices of one mesh (16-bit indices). */
#define RT_MESH_MAX 65535u

/* A hierarchy node: its box, quantised to 16 bits per coordinate around
 * the mesh's origin (rt_mesh.lo + q 2^qshift, rounded outwards): box[0..2]
 * the low corner's x, y, z, box[3..5] the high corner's; and either two
 * children (n = 0: the left one follows this node, the right one is node
 * a) or a leaf of n triangles from tri[3 a]. */
typedef struct {
    uint16_t box[6];
    uint16_t a, n;
} rt_mesh_node;

typedef struct rt_mesh {
    const fx_vec3 *v;      /* vertices, world space */
    const fx_dir3 *vn;     /* unit vertex normals (smooth shading), or NULL:
                              flat faces */
    const uint16_t *tri;   /* 3 vertex indices per triangle, counter-
                              clockwise seen from outside, in leaf order */
    const rt_mesh_node *node; /* node[0] is the root */
    uint16_t n_verts, n_tris, n_nodes;
    uint8_t qshift;        /* node boxes are in units of 2^qshift raw */
    uint8_t depth;         /* levels below the root, <= RT_MESH_DEPTH */
    fx_vec3 lo;            /* origin of the node boxes */
} rt_mesh;

/* Nearest hit of r on mesh object o with tmin < t < tmax: returns 1 and
 * sets *t and *tri (the triangle's index), else 0. */
int rt_mesh_hit(const rt_object *o, const rt_ray *r, fx_t tmin, fx_t tmax,
                fx_t *t, uint16_t *tri);

/* Outward unit normal of triangle tri of mesh object o at p: the face's,
 * or with vertex normals their interpolation at p. */
fx_dir3 rt_mesh_normal(const rt_object *o, fx_vec3 p, unsigned tri);

/* One triangle (vertices a, b, c) against ray r, alone: 1 on a hit with
 * 0 <= tmin < t < tmax, with *t, and *side = +1 if it runs counter-
 * clockwise seen from the ray's origin (the ray meets its front), else -1.
 * For the tests: rt_mesh_hit applies the same test, and for a mesh within
 * about 8192 units of the origin (no frame shift) gives the same answers.
 * 0 for vertices farther than that. */
int rt_mesh_tri_hit(fx_vec3 a, fx_vec3 b, fx_vec3 c, const rt_ray *r,
                    fx_t tmin, fx_t tmax, fx_t *t, int *side);

/* rt_mesh_prepare (rt_scene.h) checks these tables once per object. */

#endif /* RT_MESH_H */
