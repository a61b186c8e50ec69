/* SPDX-License-Identifier: MIT */
/*
 * emit_c: a parsed scene as C source (`fixtrace --emit-c`). Firmware built
 * for one scene carries this constant instead of the scene text, so it
 * links neither the parser nor the text (mk/firmware.mk, PRUNE=1).
 *
 * Every field of rt_scene, rt_material, rt_object and rt_light is written
 * as a designated initialiser with an integer literal: Q16.16 values as
 * their raw int32 (65536 is 1.0). The derived fields are copied too: the
 * device runs the same integer code as the host, so they are exact, and
 * the device need not run rt_object_prepare() on data in flash.
 *
 * A field added to rt_scene.h must be added here as well:
 * tests/test_emit.c compiles what this file writes and compares it byte
 * for byte with the parsed scene, for every scene in scenes/.
 */
#include <stdarg.h>

#include "emit_c.h"
#include "rt_mesh.h"

/* The settings the parsed values depend on: the derived fields hold unit
 * vectors with RT_UNIT_BITS fraction bits, and a scene without a depth
 * gets RT_MAX_DEPTH. The generated file refuses to compile under
 * other values. A new setting that changes what rt_parse() produces
 * belongs here, and in FW_HOST_DEFS of mk/firmware.mk. */
static void put_settings_guard(FILE *f)
{
    fprintf(f, "/* The values below depend on these settings "
               "(rt_config.h). */\n");
    fprintf(f, "#if RT_UNIT_BITS != %d || RT_MAX_DEPTH != %d\n",
            (int)RT_UNIT_BITS, (int)RT_MAX_DEPTH);
    fprintf(f, "#error \"generated for RT_UNIT_BITS %d and RT_MAX_DEPTH %d: "
               "regenerate it with a fixtrace built with this build's "
               "values\"\n#endif\n",
            (int)RT_UNIT_BITS, (int)RT_MAX_DEPTH);
}

typedef struct {
    FILE *f;
    int indent; /* nesting level, 4 spaces each */
} emitter;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void put(emitter *e, const char *fmt, ...)
{
    va_list ap;
    fprintf(e->f, "%*s", 4 * e->indent, "");
    va_start(ap, fmt);
    vfprintf(e->f, fmt, ap);
    va_end(ap);
    fputc('\n', e->f);
}

/* Room for any int32 literal below. */
#define I32_CHARS 24

/* An int32 literal; INT32_MIN cannot be written as one. */
static const char *i32(char buf[I32_CHARS], int32_t v)
{
    if (v == INT32_MIN)
        snprintf(buf, I32_CHARS, "(-2147483647 - 1)");
    else
        snprintf(buf, I32_CHARS, "%ld", (long)v);
    return buf;
}

static void put_fx(emitter *e, const char *name, fx_t v)
{
    char b[I32_CHARS];
    put(e, ".%s = %s,", name, i32(b, v));
}

static void put_vec(emitter *e, const char *name, fx_vec3 v)
{
    char bx[I32_CHARS], by[I32_CHARS], bz[I32_CHARS];
    put(e, ".%s = {.x = %s, .y = %s, .z = %s},", name, i32(bx, v.x),
        i32(by, v.y), i32(bz, v.z));
}

static void put_rgb(emitter *e, const char *name, rt_rgb c)
{
    char br[I32_CHARS], bg[I32_CHARS], bb[I32_CHARS];
    put(e, ".%s = {.r = %s, .g = %s, .b = %s},", name, i32(br, c.r),
        i32(bg, c.g), i32(bb, c.b));
}

static void put_uint(emitter *e, const char *name, unsigned long v)
{
    put(e, ".%s = %lu,", name, v);
}

static const char *const kind_name[RT_KIND_COUNT] = {
    "RT_SPHERE", "RT_QUAD", "RT_BOX", "RT_CYLINDER", "RT_CONE", "RT_MESH"
};

static const char *const texture_name[] = {
    "RT_TEX_NONE", "RT_TEX_STRIPES", "RT_TEX_CHECKER", "RT_TEX_CHECKER3D"
};

/* An enum field by name when it has one, else as its number. */
static void put_enum(emitter *e, const char *name, unsigned v,
                     const char *const *names, unsigned count)
{
    if (v < count)
        put(e, ".%s = %s,", name, names[v]);
    else
        put_uint(e, name, v);
}

static void put_material(emitter *e, const rt_material *m)
{
    put_rgb(e, "color", m->color);
    put_fx(e, "ambient", m->ambient);
    put_fx(e, "diffuse", m->diffuse);
    put_fx(e, "specular", m->specular);
    put_uint(e, "shininess", m->shininess);
    put_fx(e, "reflect", m->reflect);
    put_fx(e, "transparency", m->transparency);
    put_fx(e, "ior", m->ior);
    put_enum(e, "texture", m->texture, texture_name,
             sizeof texture_name / sizeof texture_name[0]);
    put_uint(e, "axis", m->axis);
    put_rgb(e, "color2", m->color2);
    put_fx(e, "tex_scale", m->tex_scale);
    put_fx(e, "bump", m->bump);
    put_fx(e, "bump_scale", m->bump_scale);
    put(e, "/* Derived by rt_material_prepare(). */");
    put_uint(e, "tex_rcp", m->tex_rcp);
    put_fx(e, "ior_inv", m->ior_inv);
    put_uint(e, "bump_rcp", m->bump_rcp);
}

/* Opens the member `.u.name = {` of an object's initialiser. */
static void open_record(emitter *e, const char *name)
{
    put(e, ".u.%s = {", name);
    e->indent++;
}

static void close_record(emitter *e)
{
    e->indent--;
    put(e, "},");
}

/* Object i: the record of its kind only (the union's other members
 * overlay it). */
static void put_object(emitter *e, const rt_object *o, unsigned i)
{
    put_enum(e, "kind", o->kind, kind_name, RT_KIND_COUNT);
    put_uint(e, "material", o->material);
    put_uint(e, "caps", o->caps);
    put_uint(e, "convex", o->convex);
    put_uint(e, "small", o->small);
    switch (o->kind) {
    case RT_SPHERE:
        open_record(e, "sphere");
        put_vec(e, "center", o->u.sphere.center);
        put_fx(e, "radius", o->u.sphere.radius);
        put(e, "/* Derived by rt_object_prepare(). */");
        put_uint(e, "inv_radius", o->u.sphere.inv_radius);
        break;
    case RT_QUAD: {
        const rt_quad *q = &o->u.quad;
        open_record(e, "quad");
        put_vec(e, "corner", q->corner);
        put_vec(e, "edge1", q->edge1);
        put_vec(e, "edge2", q->edge2);
        put(e, "/* Derived by rt_object_prepare(). */");
        put_uint(e, "flat", q->flat);
        /* FX_UBITS fraction bits */
        put_vec(e, "normal", fx_d3_raw(q->normal));
        put_vec(e, "axis_u", fx_d3_raw(q->axis_u));
        put_vec(e, "axis_v", fx_d3_raw(q->axis_v));
        put_fx(e, "len_u", q->len_u);
        put_fx(e, "len_v", q->len_v);
        put_fx(e, "dist", q->dist);
        break;
    }
    case RT_BOX:
        open_record(e, "box");
        put_vec(e, "min", o->u.box.min);
        put_vec(e, "max", o->u.box.max);
        break;
    case RT_CYLINDER:
    case RT_CONE: {
        const rt_upright *up = &o->u.upright;
        open_record(e, "upright");
        put_vec(e, "base", up->base);
        put_fx(e, "radius", up->radius);
        put_fx(e, "height", up->height);
        put(e, "/* Derived by rt_object_prepare(). */");
        put(e, ".frame_shift = %d,", up->frame_shift);
        put_fx(e, "slope", up->slope);
        put_uint(e, "thin", up->thin);
        break;
    }
    default: /* RT_MESH */
        open_record(e, "mesh");
        put_vec(e, "origin", o->u.mesh.origin);
        if (o->u.mesh.tables)
            put(e, ".tables = &fw_mesh%u,", i);
        break;
    }
    close_record(e);
    put(e, "/* Derived by rt_object_prepare(). */");
    put_vec(e, "bc", o->bc);
    put_fx(e, "br", o->br);
}

/* The tables of mesh object i, as constants named fw_mesh<i>_*, and the
 * rt_mesh fw_mesh<i> that points at them. */
static void put_mesh(emitter *e, const rt_mesh *m, unsigned i)
{
    char bx[I32_CHARS], by[I32_CHARS], bz[I32_CHARS];
    put(e, "/* Object %u: a mesh of %u triangles, %u vertices, %u nodes. */",
        i, m->n_tris, m->n_verts, m->n_nodes);
    put(e, "static const fx_vec3 fw_mesh%u_v[%u] = {", i, m->n_verts);
    for (unsigned k = 0; k < m->n_verts; k++)
        put(e, "    {%s, %s, %s},", i32(bx, m->v[k].x), i32(by, m->v[k].y),
            i32(bz, m->v[k].z));
    put(e, "};");
    if (m->vn) {
        put(e, "static const fx_dir3 fw_mesh%u_vn[%u] = {", i, m->n_verts);
        for (unsigned k = 0; k < m->n_verts; k++)
            put(e, "    {%s, %s, %s},", i32(bx, m->vn[k].x),
                i32(by, m->vn[k].y), i32(bz, m->vn[k].z));
        put(e, "};");
    }
    put(e, "static const uint16_t fw_mesh%u_tri[%u] = {", i, 3u * m->n_tris);
    for (unsigned k = 0; k < m->n_tris; k++)
        put(e, "    %u, %u, %u,", m->tri[3 * k], m->tri[3 * k + 1],
            m->tri[3 * k + 2]);
    put(e, "};");
    put(e, "static const rt_mesh_node fw_mesh%u_node[%u] = {", i, m->n_nodes);
    for (unsigned k = 0; k < m->n_nodes; k++) {
        const rt_mesh_node *n = &m->node[k];
        put(e, "    {{%u, %u, %u, %u, %u, %u}, %u, %u},", n->box[0], n->box[1],
            n->box[2], n->box[3], n->box[4], n->box[5], n->a, n->n);
    }
    put(e, "};");
    put(e, "static const rt_mesh fw_mesh%u = {", i);
    e->indent++;
    put(e, ".v = fw_mesh%u_v,", i);
    if (m->vn)
        put(e, ".vn = fw_mesh%u_vn,", i);
    put(e, ".tri = fw_mesh%u_tri,", i);
    put(e, ".node = fw_mesh%u_node,", i);
    put_uint(e, "n_verts", m->n_verts);
    put_uint(e, "n_tris", m->n_tris);
    put_uint(e, "n_nodes", m->n_nodes);
    put_uint(e, "qshift", m->qshift);
    put_uint(e, "depth", m->depth);
    put_vec(e, "lo", m->lo);
    e->indent--;
    put(e, "};");
    fputc('\n', e->f);
}

static void put_light(emitter *e, const rt_light *l)
{
    put_vec(e, "pos", l->pos);
    put_rgb(e, "color", l->color);
}

/* Entry i of one of the scene's arrays. */
typedef void (*put_entry_fn)(emitter *e, const rt_scene *s, unsigned i);

static void put_mat_i(emitter *e, const rt_scene *s, unsigned i)
{
    put_material(e, &s->mat[i]);
}

static void put_light_i(emitter *e, const rt_scene *s, unsigned i)
{
    put_light(e, &s->light[i]);
}

static void put_obj_i(emitter *e, const rt_scene *s, unsigned i)
{
    put_object(e, &s->obj[i], i);
}

/* The used entries of an array member; none at all when it is empty
 * (C99 has no empty braces, and the rest is zero anyway). */
static void put_array(emitter *e, const char *name, unsigned n,
                      const rt_scene *s, put_entry_fn fn)
{
    if (n == 0)
        return;
    put(e, ".%s = {", name);
    e->indent++;
    for (unsigned i = 0; i < n; i++) {
        put(e, "[%u] = {", i);
        e->indent++;
        fn(e, s, i);
        e->indent--;
        put(e, "},");
    }
    e->indent--;
    put(e, "},");
}

/* The source path inside a comment: printable ASCII, and no comment end. */
static void put_path(FILE *f, const char *path)
{
    char prev = 0;
    for (const char *p = path; *p; p++) {
        char c = (*p >= ' ' && *p <= '~') ? *p : '?';
        if (prev == '*' && c == '/')
            fputc(' ', f);
        fputc(c, f);
        prev = c;
    }
}

static unsigned at_least_1(unsigned n)
{
    return n > 0 ? n : 1;
}

int emit_c_scene(FILE *f, const rt_scene *s, const char *source)
{
    emitter e = {f, 0};
    unsigned n_mat = s->n_materials, n_light = s->n_lights;
    unsigned n_obj = s->n_objects;

    fputs("/*\n * Generated by `fixtrace --emit-c` from ", f);
    put_path(f, source ? source : "(unnamed)");
    fputs(".\n * Do not edit: change the scene and regenerate.\n"
          " *\n"
          " * The parsed scene as a constant, so that firmware needs neither"
          " the\n"
          " * text nor the parser. Q16.16 values are raw int32 (65536 is"
          " 1.0); the\n"
          " * derived fields are the host's, which are exact on the device"
          " too.\n */\n", f);
    /* The core's own tree has its folders on the include path; a package
     * user has include/fixtrace/ only. */
    put(&e, "#if defined(__has_include)");
    put(&e, "#if !__has_include(\"rt_mesh.h\") && "
            "__has_include(<fixtrace/rt_mesh.h>)");
    put(&e, "#define FW_SCENE_PACKAGE 1");
    put(&e, "#endif");
    put(&e, "#endif");
    put(&e, "#ifdef FW_SCENE_PACKAGE");
    put(&e, "#include <fixtrace/rt_mesh.h>");
    put(&e, "#else");
    put(&e, "#include \"rt_mesh.h\"");
    put(&e, "#endif");
    fputc('\n', f);
    put(&e, "/* The scene's counts, at least 1 (they size arrays). */");
    put(&e, "#define FW_SCENE_OBJECTS %u", at_least_1(n_obj));
    put(&e, "#define FW_SCENE_MATERIALS %u", at_least_1(n_mat));
    put(&e, "#define FW_SCENE_LIGHTS %u", at_least_1(n_light));
    fputc('\n', f);
    put(&e, "#if RT_MAX_OBJECTS < FW_SCENE_OBJECTS || \\");
    put(&e, "    RT_MAX_MATERIALS < FW_SCENE_MATERIALS || \\");
    put(&e, "    RT_MAX_LIGHTS < FW_SCENE_LIGHTS");
    put(&e, "#error \"the scene has more objects, materials or lights than "
            "RT_MAX_OBJECTS, RT_MAX_MATERIALS or RT_MAX_LIGHTS allow\"");
    put(&e, "#endif");
    fputc('\n', f);
    put_settings_guard(f);
    fputc('\n', f);
    for (unsigned i = 0; i < n_obj; i++)
        if (s->obj[i].kind == RT_MESH && s->obj[i].u.mesh.tables)
            put_mesh(&e, s->obj[i].u.mesh.tables, i);
    put(&e, "const rt_scene fw_scene = {");
    e.indent++;
    put(&e, ".cam = {");
    e.indent++;
    put_vec(&e, "eye", s->cam.eye);
    put_vec(&e, "look", s->cam.look);
    put_vec(&e, "up", s->cam.up);
    put_fx(&e, "fov", s->cam.fov);
    e.indent--;
    put(&e, "},");
    put_rgb(&e, "background", s->background);
    put_rgb(&e, "ambient", s->ambient);
    put_uint(&e, "width", s->width);
    put_uint(&e, "height", s->height);
    put_uint(&e, "spp", s->spp);
    put_uint(&e, "depth", s->depth);
    put_uint(&e, "shadows", s->shadows);
    put_uint(&e, "n_materials", s->n_materials);
    put_uint(&e, "n_lights", s->n_lights);
    put_uint(&e, "n_objects", s->n_objects);

    put_array(&e, "mat", n_mat, s, put_mat_i);
    put_array(&e, "light", n_light, s, put_light_i);
    put_array(&e, "obj", n_obj, s, put_obj_i);
    e.indent--;
    put(&e, "};");
    fflush(f);
    return ferror(f) ? -1 : 0;
}
