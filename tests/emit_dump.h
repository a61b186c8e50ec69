/* SPDX-License-Identifier: MIT */
/*
 * emit_dump: a scene as bytes for tests/test_emit.c, which compiles it
 * into the program that checks the generated tables too: the rt_scene
 * with its mesh pointers cleared, then each mesh's counts and arrays in
 * object order. Equal dumps mean equal scenes, meshes included.
 */
#ifndef EMIT_DUMP_H
#define EMIT_DUMP_H

#include <stdio.h>
#include <string.h>

#include "rt_mesh.h"

static void emit_dump(FILE *f, const rt_scene *s)
{
    static rt_scene c;
    memcpy(&c, s, sizeof c);
    for (unsigned k = 0; k < RT_MAX_OBJECTS; k++)
        if (c.obj[k].kind == RT_MESH)
            c.obj[k].u.mesh.tables = NULL;
    fwrite(&c, sizeof c, 1, f);
    for (unsigned k = 0; k < s->n_objects; k++) {
        if (s->obj[k].kind != RT_MESH || !s->obj[k].u.mesh.tables)
            continue;
        const rt_mesh *m = s->obj[k].u.mesh.tables;
        rt_mesh h;
        memset(&h, 0, sizeof h);
        h.n_verts = m->n_verts;
        h.n_tris = m->n_tris;
        h.n_nodes = m->n_nodes;
        h.qshift = m->qshift;
        h.depth = m->depth;
        h.lo = m->lo;
        const unsigned char has_vn = m->vn != NULL;
        fwrite(&h, sizeof h, 1, f);
        fwrite(&has_vn, 1, 1, f);
        fwrite(m->v, sizeof *m->v, m->n_verts, f);
        if (has_vn)
            fwrite(m->vn, sizeof *m->vn, m->n_verts, f);
        fwrite(m->tri, sizeof *m->tri, 3u * m->n_tris, f);
        fwrite(m->node, sizeof *m->node, m->n_nodes, f);
    }
}

#endif /* EMIT_DUMP_H */
