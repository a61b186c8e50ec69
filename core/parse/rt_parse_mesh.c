/* SPDX-License-Identifier: MIT */
/*
 * rt_parse_mesh: the 'mesh' statement,
 *     mesh file "models/x.obj" material NAME [scale S] [rotate X Y Z]
 *          [translate X Y Z] [smooth]
 * The parser reads the statement; the file itself is the loader's
 * (rt_parse_with_meshes): the host reads Wavefront OBJ and builds the
 * hierarchy (port/posix/mesh_obj.c). Without a loader, as on a device
 * that parses its scene text, the statement is refused.
 */
#include "rt_libc.h"
#include "rt_lex.h"

enum { K_FILE, K_MATERIAL, K_SCALE, K_ROTATE, K_TRANSLATE, K_SMOOTH };
static const char *const mesh_keys[] = {"file", "material", "scale",
                                        "rotate", "translate", "smooth",
                                        NULL};

/* Smallest and largest scale (raw Q16.16): 1/1024 and 4096. */
#define SCALE_MIN ((fx_t)64)
#define SCALE_MAX FX_INT(4096)

rt_status rt_parse_mesh(rt_lex *p, const rt_lex_token *kw, rt_scene *s,
                        const rt_parse_names names)
{
    rt_lex_token at[6], file = {0, 0, 0, 0};
    uint32_t seen = 0;
    int k, mat = 0;
    rt_mesh_place pl;
    if (s->n_objects >= RT_MAX_OBJECTS)
        return rt_lex_too_many(p, kw, "objects", "RT_MAX_OBJECTS",
                               RT_MAX_OBJECTS);
    memset(&pl, 0, sizeof pl);
    pl.scale = FX_ONE;
    for (;;) {
        TRY(rt_lex_next_key(p, "mesh", mesh_keys, at, &seen, &k));
        if (k < 0)
            break;
        switch (k) {
        case K_FILE:
            TRY(rt_lex_next(p, &file));
            if (file.len == 0)
                return rt_lex_need(p, &file, "file", NULL, 1, "path");
            /* Quotes are optional; a quoted path may hold spaces. */
            if (file.len >= 2 && p->t[file.off] == '"' &&
                p->t[file.off + file.len - 1] == '"') {
                file.off++;
                file.len -= 2;
            }
            if (file.len == 0)
                return rt_lex_fail(p, &at[K_FILE], RT_ERR_PARSE,
                                   "'file' needs a path");
            break;
        case K_MATERIAL:
            TRY(rt_parse_material_ref(p, s, names, &mat));
            break;
        case K_SCALE:
            TRY(rt_lex_get_fxs(p, "scale", NULL, 1, &pl.scale, SCALE_MIN,
                               SCALE_MAX, "in [0.001, 4096]"));
            break;
        case K_ROTATE:
            TRY(rt_lex_get_fxs(p, "rotate", "x y z", 3, pl.rotate,
                               -FX_INT(360), FX_INT(360),
                               "in [-360, 360] degrees"));
            break;
        case K_TRANSLATE:
            TRY(rt_lex_get_vec(p, "translate", &pl.translate));
            break;
        default: /* K_SMOOTH */
            pl.smooth = 1;
            break;
        }
    }
    TRY(rt_lex_require(p, kw, "mesh", mesh_keys, seen, 3u));
    if (!p->load)
        return rt_lex_fail(p, kw, RT_ERR_UNSUPPORTED,
                           "'mesh' reads a file, which a scene parsed on "
                           "the device cannot: build the firmware with "
                           "PRUNE=1, which carries meshes as tables");
    const struct rt_mesh *m = 0;
    char why[120];
    why[0] = '\0';
    rt_status st = p->load(p->load_ctx, p->t + file.off, file.len, &pl, &m,
                           why, sizeof why);
    if (st != RT_OK || !m) {
        rt_lex_fail(p, &file, st != RT_OK ? st : RT_ERR_ARG,
                    "cannot load mesh file: ");
        rt_lex_say(p, why);
        return st != RT_OK ? st : RT_ERR_ARG;
    }
    rt_object *o = &s->obj[s->n_objects];
    memset(o, 0, sizeof *o);
    o->kind = RT_MESH;
    o->material = (uint8_t)mat;
    o->u.mesh.tables = m;
    if (rt_object_prepare(o) != RT_OK)
        return rt_lex_fail(p, &file, RT_ERR_DEGENERATE,
                           "the mesh's tables are inconsistent (a loader "
                           "bug: rt_mesh.h states what they must hold)");
    s->n_objects++;
    return RT_OK;
}
