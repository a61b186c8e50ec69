/* SPDX-License-Identifier: MIT */
/*
 * mkmodel: closed meshes of our own making as Wavefront OBJ, for the
 * gallery and the mesh benchmarks (port/posix/mesh_shapes.c makes them):
 *     mkmodel icosphere LEVEL [RADIUS]        20 4^LEVEL triangles
 *     mkmodel torus NU NV [R r]               2 NU NV triangles
 * Coordinates are the Q16.16 values the tracer will read back exactly
 * (6 decimals round-trip a Q16.16 value); every face has its vertex
 * normals (v//vn), counter-clockwise seen from outside.
 * Built by `make models`, which regenerates scenes/models/.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_build.h"

static int usage(void)
{
    fprintf(stderr, "usage: mkmodel icosphere LEVEL [RADIUS]\n"
                    "       mkmodel torus NU NV [R r]\n");
    return 2;
}

int main(int argc, char **argv)
{
    fx_vec3 *v;
    fx_dir3 *vn;
    uint32_t *tri;
    unsigned nv, nt;
    int rc;
    if (argc >= 3 && strcmp(argv[1], "icosphere") == 0) {
        const unsigned level = (unsigned)atoi(argv[2]);
        if (level > 6)
            return usage();
        rc = mesh_icosphere(argc > 3 ? atof(argv[3]) : 1.0, level, &v, &vn,
                            &nv, &tri, &nt);
        printf("# icosphere, %u subdivisions: %u vertices, %u triangles\n",
               level, nv, nt);
    } else if (argc >= 4 && strcmp(argv[1], "torus") == 0) {
        const unsigned nu = (unsigned)atoi(argv[2]);
        const unsigned nvv = (unsigned)atoi(argv[3]);
        if (nu < 3 || nvv < 3 || nu * nvv > 40000)
            return usage();
        rc = mesh_torus(argc > 4 ? atof(argv[4]) : 1.0,
                        argc > 5 ? atof(argv[5]) : 0.4, nu, nvv, &v, &vn,
                        &nv, &tri, &nt);
        printf("# torus, %u x %u segments: %u vertices, %u triangles\n", nu,
               nvv, nv, nt);
    } else {
        return usage();
    }
    if (rc != 0) {
        fprintf(stderr, "mkmodel: out of memory\n");
        return 1;
    }
    printf("# made by tools/mkmodel.c (fixtrace); MIT licence\n");
    for (unsigned i = 0; i < nv; i++)
        printf("v %.6f %.6f %.6f\n", v[i].x / 65536.0, v[i].y / 65536.0,
               v[i].z / 65536.0);
    for (unsigned i = 0; i < nv; i++)
        printf("vn %.6f %.6f %.6f\n", (double)vn[i].x / FX_UONE,
               (double)vn[i].y / FX_UONE, (double)vn[i].z / FX_UONE);
    for (unsigned k = 0; k < nt; k++)
        printf("f %u//%u %u//%u %u//%u\n", tri[3 * k] + 1, tri[3 * k] + 1,
               tri[3 * k + 1] + 1, tri[3 * k + 1] + 1, tri[3 * k + 2] + 1,
               tri[3 * k + 2] + 1);
    free(v);
    free(vn);
    free(tri);
    return ferror(stdout) ? 1 : 0;
}
