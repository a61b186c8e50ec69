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

/* The OBJ text of len bytes, placed by pl, must fail at line:col with msg
 * in the message. */
static void bad_n(const char *obj, size_t len, const rt_mesh_place *pl,
                  unsigned line, unsigned col, const char *msg)
{
    rt_parse_error e;
    unsigned long ign = 0;
    rt_mesh *m = mesh_obj_parse(obj, len, pl, &e, &ign);
    CHECK(m == NULL);
    mesh_free(m);
    CHECK_EQ(e.line, line);
    CHECK_EQ(e.col, col);
    if (!CHECK(strstr(e.msg, msg) != NULL))
        printf("    message: %s\n", e.msg);
}

/* The OBJ text must fail at line:col with msg in the message. */
static void bad(const char *obj, unsigned line, unsigned col, const char *msg)
{
    rt_mesh_place pl = plain();
    bad_n(obj, strlen(obj), &pl, line, col, msg);
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

/* Appends printf-style text to a growing buffer (the tests' big OBJs). */
typedef struct {
    char *p;
    size_t n, cap;
} text_buf;

static void put(text_buf *b, const char *fmt, unsigned a, unsigned c)
{
    if (b->cap - b->n < 64) {
        b->cap = b->cap ? 2 * b->cap : 1 << 16;
        b->p = realloc(b->p, b->cap);
        if (!b->p)
            abort();
    }
    b->n += (size_t)snprintf(b->p + b->n, b->cap - b->n, fmt, a, c);
}

/* Errors found once the whole file is read point at the statement at
 * fault, not at the file's last line: a vertex placed out of range, the
 * vertex that makes the mesh span too far, the face that brings it to
 * one triangle or one vertex too many. */
static void test_located(void)
{
    rt_mesh_place pl = plain();
    const char *far = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 20000 0 0\n"
                      "f 1 2 3\nf 1 2 4\n# the end\n";
    pl.scale = FX_INT(2);
    bad_n(far, strlen(far), &pl, 4, 1, "scaled, leaves the Q16.16 range");
    pl = plain();
    pl.translate = fx_v3(FX_INT(15000), 0, 0);
    bad_n(far, strlen(far), &pl, 4, 1, "rotated and moved, leaves the");
    pl = plain();
    bad("v -9000 0 0\nv 0 1 0\nv 9000 0 0\nv 0 0 1\nf 2 4 1\nf 2 4 3\n"
        "f 1 2 4\n", 3, 1, "span more than 16384 units");

    /* A grid of 183 x 183 vertices has 66,248 triangles, one a line. */
    text_buf b = {NULL, 0, 0};
    const unsigned side = 183;
    for (unsigned z = 0; z < side; z++)
        for (unsigned x = 0; x < side; x++)
            put(&b, "v %u 0 %u\n", x, z);
    for (unsigned z = 0; z + 1 < side; z++)
        for (unsigned x = 0; x + 1 < side; x++) {
            const unsigned a = z * side + x + 1, c = a + side;
            put(&b, "f %u %u", a, c);
            put(&b, " %u\nf %u", a + 1, a + 1);
            put(&b, " %u %u\n", c, c + 1);
        }
    bad_n(b.p, b.n, &pl, side * side + RT_MESH_MAX + 1, 1,
          "this face brings the mesh to 65536 triangles");

    /* 21,846 triangles of their own 3 vertices each: the 21,846th face
     * brings the vertices to 65,536. */
    b.n = 0;
    const unsigned nt = 21846;
    for (unsigned i = 0; i < 3 * nt; i++)
        put(&b, "v %u %u 1\n", i % 256, i / 256);
    for (unsigned i = 0; i < nt; i++) {
        put(&b, "f %u %u", 3 * i + 1, 3 * i + 2);
        put(&b, " %u\n", 3 * i + 3, 0);
    }
    pl = plain();
    bad_n(b.p, b.n, &pl, 3 * nt + nt, 1,
          "this face brings the mesh to 65536 vertices");
    free(b.p);
}

/* Malformed, out-of-range and non-ASCII input each get their own message;
 * an exponent too small for a double is still a number (0). */
static void test_bytes(void)
{
    rt_parse_error e;
    unsigned long ign;
    rt_mesh_place pl = plain();
    rt_mesh *m = parse("v 1e-400 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &pl,
                       &e, &ign);
    if (CHECK(m != NULL)) {
        int zero = 0;
        for (unsigned i = 0; i < m->n_verts; i++)
            zero += m->v[i].x == 0 && m->v[i].y == 0;
        CHECK_EQ(zero, 1);
        mesh_free(m);
    } else {
        printf("    %u:%u: %s\n", (unsigned)e.line, (unsigned)e.col, e.msg);
    }
    bad("v 1e400 0 0\n", 1, 3, "1e400 is out of range");
    bad("v 0 0 0\nv 40000 0 0\n", 2, 3, "40000 is out of range");
    bad("v 0 0 0\nv 1 x2 0\n", 2, 5, "'x2' is not one");
    bad("v 0 0 0\nv 1 nan 0\n", 2, 5, "'nan' is not one");
    bad("v 0 0 0\nv 1 0\xc3\xa9 0\n", 2, 6, "not ASCII (0xC3)");
    bad("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\xe2\n", 4, 8,
        "not ASCII (0xE2)");
    static const char nul[] = "v 0 0 0\nv 1 \0 0\nv 0 1 0\nf 1 2 3\n";
    bad_n(nul, sizeof nul - 1, &pl, 2, 5, "a NUL byte");
    /* Outside the statements read, any byte goes (a UTF-8 group name). */
    m = parse("g caf\xc3\xa9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &pl, &e,
              &ign);
    CHECK(m != NULL);
    mesh_free(m);
}

int main(void)
{
    test_obj();
    test_located();
    test_bytes();
    test_statement();
    return th_summary();
}
