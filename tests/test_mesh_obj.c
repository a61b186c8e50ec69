/* SPDX-License-Identifier: MIT */
/*
 * The 'mesh' statement and the host's OBJ reader: placement (scale, then
 * rotations about x, y, z, then translation) in exact fixed point,
 * polygons split into fans, statements other than v, vn and f counted,
 * errors located at line and column, and rt_parse (a device's parser)
 * refusing meshes with a clear message.
 */
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "mesh_obj.h"
#include "rt_render.h"
#include "cli_util.h"

static rt_mesh_place plain(void)
{
    rt_mesh_place pl;
    memset(&pl, 0, sizeof pl);
    pl.scale = FX_ONE;
    return pl;
}

static rt_mesh *parse(const char *obj, const rt_mesh_place *pl,
                      rt_parse_error *e, unsigned long *ign)
{
    *ign = 0;
    return mesh_obj_parse(obj, strlen(obj), pl, e, ign);
}

/* The OBJ text must fail at line:col with msg in the message. */
static void bad(const char *obj, unsigned line, unsigned col, const char *msg)
{
    rt_parse_error e;
    unsigned long ign;
    rt_mesh_place pl = plain();
    rt_mesh *m = parse(obj, &pl, &e, &ign);
    CHECK(m == NULL);
    mesh_free(m);
    CHECK_EQ(e.line, line);
    CHECK_EQ(e.col, col);
    if (!CHECK(strstr(e.msg, msg) != NULL))
        printf("    message: %s\n", e.msg);
}

static const char quad_obj[] =
    "# a unit square in z = 0, as one polygon\n"
    "mtllib x.mtl\n"
    "o square\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\n"
    "vn 0 0 1\n"
    "usemtl red\n"
    "f 1//1 2//1 3//1 4//1\n";

static void test_obj(void)
{
    rt_parse_error e;
    unsigned long ign;
    rt_mesh_place pl = plain();
    rt_mesh *m = parse(quad_obj, &pl, &e, &ign);
    if (!CHECK(m != NULL)) {
        printf("    %u:%u: %s\n", (unsigned)e.line, (unsigned)e.col, e.msg);
        return;
    }
    CHECK_EQ(m->n_tris, 2);     /* the polygon as a fan */
    CHECK_EQ(m->n_verts, 4);
    CHECK_EQ(ign, 4);           /* mtllib, o, vt, usemtl */
    CHECK(m->vn == NULL);       /* flat unless 'smooth' */
    mesh_free(m);

    /* scale 2, rotate 90 about z, translate (10 0 0): (1 0 0) goes to
     * (10 2 0) exactly. */
    pl.scale = FX_INT(2);
    pl.rotate[2] = FX_INT(90);
    pl.translate = fx_v3(FX_INT(10), 0, 0);
    pl.smooth = 1;
    m = parse("v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n", &pl, &e, &ign);
    if (CHECK(m != NULL)) {
        int found = 0;
        for (unsigned i = 0; i < m->n_verts; i++)
            found += m->v[i].x == FX_INT(10) && m->v[i].y == FX_INT(2) &&
                     m->v[i].z == 0;
        CHECK_EQ(found, 1);
        CHECK(m->vn != NULL); /* made from the faces */
        mesh_free(m);
    }
    m = parse("v 0 0 0\nv 1e0 0 0\nv 0 1.5E-1 0\nf -3 -2 -1\n", &pl, &e,
              &ign);
    CHECK(m != NULL);
    mesh_free(m);

    bad("v 0 0\n", 1, 6, "'v' needs 3 numbers");
    bad("v 0 0 0\nv 1 x 0\n", 2, 5, "numbers");
    bad("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, 7, "has 3 so far");
    bad("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", 4, 6, "at least 3");
    bad("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 0 2\n", 4, 5, "vertex");
    bad("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", 4, 3, "normal");
    bad("v 0 0 0\n", 1, 1, "no faces");
}

static void test_statement(void)
{
    static rt_scene s;
    rt_parse_error e;
    const char *scene = "camera eye 0 0 -5 look 0 0 0\n"
                        "material m color 1 1 1\n"
                        "mesh file \"tri.obj\" material m smooth\n";
    CHECK_EQ(rt_parse(scene, strlen(scene), &s, &e), RT_ERR_UNSUPPORTED);
    CHECK_EQ(e.line, 3);
    CHECK_EQ(e.col, 1);
    CHECK(strstr(e.msg, "PRUNE=1") != NULL);

    const char *bad_mat = "camera eye 0 0 -5 look 0 0 0\n"
                          "mesh file x.obj material nope\n";
    CHECK_EQ(rt_parse(bad_mat, strlen(bad_mat), &s, &e), RT_ERR_PARSE);
    CHECK(strstr(e.msg, "not defined") != NULL);

    const char *no_file = "camera eye 0 0 -5 look 0 0 0\n"
                          "material m color 1 1 1\nmesh material m\n";
    CHECK_EQ(rt_parse(no_file, strlen(no_file), &s, &e), RT_ERR_PARSE);
    CHECK(strstr(e.msg, "file") != NULL);

    /* With the host's loader: a missing file is an error at its token. */
    mesh_obj_ctx c;
    mesh_obj_init(&c, "/nonexistent/scene.scene", NULL, 1);
    CHECK_EQ(mesh_obj_parse_scene(scene, strlen(scene), NULL, &s, &e, &c),
             RT_ERR_ARG);
    CHECK_EQ(e.line, 3);
    CHECK_EQ(e.col, 12);
    CHECK(strstr(e.msg, "cannot load mesh file") != NULL);
    mesh_obj_free(&c);

    /* The gallery's scene, with its models. */
    size_t len;
    char err[256];
    char *text = cli_read_file("scenes/meshes.scene", &len, err, sizeof err);
    if (CHECK(text != NULL)) {
        mesh_obj_init(&c, NULL, NULL, 1);
        CHECK_EQ(mesh_obj_parse_scene(text, len, "scenes/meshes.scene", &s,
                                      &e, &c), RT_OK);
        CHECK_EQ(c.n_mesh, 2);
        CHECK_EQ(c.triangles, 1280 + 1024);
        CHECK_EQ(rt_scene_features(&s, 1) & RT_FEAT_MESH, RT_FEAT_MESH);
        mesh_obj_free(&c);
        free(text);
    }
}

int main(void)
{
    test_obj();
    test_statement();
    return th_summary();
}
