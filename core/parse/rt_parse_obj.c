/* SPDX-License-Identifier: MIT */
/*
 * rt_parse_obj: the 'material' statement and the five object statements
 * (rt_lex.h), which refer to materials by name. The names live in a table
 * on rt_parse()'s stack, so a scene carries only their indices.
 */
#include "rt_libc.h"
#include "rt_lex.h"

#if RT_CAP_BOTTOM != 1 || RT_CAP_TOP != 2
#error "the 'caps' words are listed in RT_CAP_* bit order"
#endif

/* Value limits (raw Q16.16); the defaults are rt_material_defaults()'s. */
#define IOR_MIN ((fx_t)655)  /* 0.01, as the parser rounds it */
#define IOR_MAX FX_INT(100)
#define BUMP_MAX FX_INT(4)
/* Texture and bump sizes: at least one ulp, the limit stated for a size
 * that rounds to 0 too. Cells are exact at any size (rt_texture.c). */
#define SIZE_RULE "at least 0.0000153 (2^-16, the smallest Q16.16 step)"

/* ---- Materials ---------------------------------------------------------- */

static int lookup(const rt_lex *p, const rt_lex_token *tk, const rt_scene *s,
                  const rt_parse_names names)
{
    for (int i = 0; i < s->n_materials; i++) {
        const char *n = names[i];
        size_t j = 0;
        while (j < tk->len && n[j] == p->t[tk->off + j])
            j++;
        if (j == tk->len && n[j] == '\0')
            return i;
    }
    return -1;
}

enum {
    M_COLOR, M_AMBIENT, M_DIFFUSE, M_SPECULAR, M_SHININESS, M_REFLECT,
    M_TRANSPARENCY, M_IOR, M_STRIPES, M_CHECKER, M_CHECKER3D, M_BUMP, M_COUNT
};
static const char *const mat_keys[] = {
    "color", "ambient", "diffuse", "specular", "shininess", "reflect",
    "transparency", "ior", "stripes", "checker", "checker3d", "bump", NULL};
#define M_TEXTURES ((1u << M_STRIPES) | (1u << M_CHECKER) | (1u << M_CHECKER3D))

static rt_status mat_field(rt_lex *p, int k, rt_material *m)
{
    const fx_t one = FX_ONE;
    const char *const k01 = "in [0, 1]";
    switch (k) {
    case M_COLOR:
        return rt_lex_get_rgb(p, "color", &m->color, one);
    case M_AMBIENT:
        return rt_lex_get_fxs(p, "ambient", NULL, 1, &m->ambient, 0, one,
                              k01);
    case M_DIFFUSE:
        return rt_lex_get_fxs(p, "diffuse", NULL, 1, &m->diffuse, 0, one,
                              k01);
    case M_SPECULAR:
        return rt_lex_get_fxs(p, "specular", NULL, 1, &m->specular, 0, one,
                              k01);
    case M_REFLECT:
        return rt_lex_get_fxs(p, "reflect", NULL, 1, &m->reflect, 0, one,
                              k01);
    case M_TRANSPARENCY:
        return rt_lex_get_fxs(p, "transparency", NULL, 1, &m->transparency,
                              0, one, k01);
    case M_IOR:
        return rt_lex_get_fxs(p, "ior", NULL, 1, &m->ior, IOR_MIN, IOR_MAX,
                              "in [0.01, 100]");
    case M_SHININESS: {
        uint32_t v;
        rt_lex_token tk;
        TRY(rt_lex_get_uint(p, "shininess", NULL, 1, 1024, "", &v, &tk));
        m->shininess = (uint16_t)v;
        return RT_OK;
    }
    case M_BUMP:
        TRY(rt_lex_get_fxs(p, "bump", "amplitude", 1, &m->bump, 0, BUMP_MAX,
                           "in [0, 4]"));
        return rt_lex_get_fxs(p, "bump", "size", 1, &m->bump_scale, 1,
                              FX_MAX, SIZE_RULE);
    case M_STRIPES: {
        static const char *const axes[] = {"x", "y", "z", NULL};
        rt_lex_token tk;
        int a;
        TRY(rt_lex_next(p, &tk));
        a = rt_lex_find(p, &tk, axes);
        if (a < 0) {
            rt_lex_fail(p, &tk, RT_ERR_PARSE,
                        "'stripes' needs an axis (x, y or z)");
            rt_lex_say_got(p, &tk);
            return RT_ERR_PARSE;
        }
        m->texture = RT_TEX_STRIPES;
        m->axis = (uint8_t)a;
        TRY(rt_lex_get_rgb(p, "stripes", &m->color2, one));
        return rt_lex_get_fxs(p, "stripes", "width", 1, &m->tex_scale, 1,
                              FX_MAX, SIZE_RULE);
    }
    default: { /* M_CHECKER, M_CHECKER3D */
        const char *w = k == M_CHECKER ? "checker" : "checker3d";
        m->texture = k == M_CHECKER ? RT_TEX_CHECKER : RT_TEX_CHECKER3D;
        TRY(rt_lex_get_rgb(p, w, &m->color2, one));
        return rt_lex_get_fxs(p, w, "size", 1, &m->tex_scale, 1, FX_MAX,
                              SIZE_RULE);
    }
    }
}

rt_status rt_parse_material(rt_lex *p, const rt_lex_token *kw, rt_scene *s,
                            rt_parse_names names)
{
    rt_lex_token name, at[M_COUNT];
    uint32_t seen = 0;
    int k;
    rt_material *m;
    if (s->n_materials >= RT_MAX_MATERIALS) {
        return rt_lex_too_many(p, kw, "materials", "RT_MAX_MATERIALS",
                               RT_MAX_MATERIALS);
    }
    TRY(rt_lex_next(p, &name));
    const char *n = p->t + name.off;
    int ok = name.len > 0 &&
             (n[0] == '_' || ((n[0] | 0x20) >= 'a' && (n[0] | 0x20) <= 'z'));
    for (size_t i = 0; ok && i < name.len; i++)
        ok = n[i] == '_' || n[i] == '-' || rt_lex_is_digit(n[i]) ||
             ((n[i] | 0x20) >= 'a' && (n[i] | 0x20) <= 'z');
    if (!ok) {
        rt_lex_fail(p, &name, RT_ERR_PARSE,
                    "'material' needs a name (a letter or '_', then "
                    "letters, digits, '_', '-')");
        rt_lex_say_got(p, &name);
        return RT_ERR_PARSE;
    }
    if (name.len > RT_MAX_NAME) {
        rt_lex_fail(p, &name, RT_ERR_CAPACITY,
                    "material name longer than RT_MAX_NAME (");
        rt_lex_say_u32(p, RT_MAX_NAME);
        rt_lex_say(p, " bytes)");
        return RT_ERR_CAPACITY;
    }
    if (lookup(p, &name, s, names) >= 0) {
        rt_lex_fail(p, &name, RT_ERR_PARSE, "material ");
        rt_lex_say_tok(p, &name);
        rt_lex_say(p, " is already defined");
        return RT_ERR_PARSE;
    }
    m = &s->mat[s->n_materials];
    rt_material_defaults(m);
    for (;;) {
        TRY(rt_lex_next_key(p, "material", mat_keys, at, &seen, &k));
        if (k < 0)
            break;
        if ((1u << k) & M_TEXTURES && (seen & M_TEXTURES) != (1u << k)) {
            rt_lex_fail(p, &at[k], RT_ERR_PARSE,
                        "a material has at most one texture (stripes, "
                        "checker or checker3d)");
            return RT_ERR_PARSE;
        }
        TRY(mat_field(p, k, m));
    }
    TRY(rt_lex_require(p, kw, "material", mat_keys, seen, 1u << M_COLOR));
    if ((int64_t)m->reflect + m->transparency > FX_ONE) {
        int later = (seen & (1u << M_REFLECT)) &&
                    at[M_REFLECT].off > at[M_TRANSPARENCY].off;
        return rt_lex_fail(p, &at[later ? M_REFLECT : M_TRANSPARENCY],
                           RT_ERR_PARSE,
                           "reflect + transparency must be <= 1");
    }
    if (rt_material_prepare(m) != RT_OK)
        return rt_lex_fail(p, kw, RT_ERR_PARSE, "invalid material: a "
                           "texture or bump size is not > 0");
    memcpy(names[s->n_materials], n, name.len);
    names[s->n_materials][name.len] = '\0';
    s->n_materials++;
    return RT_OK;
}

rt_status rt_parse_material_ref(rt_lex *p, const rt_scene *s,
                                const rt_parse_names names, int *m)
{
    rt_lex_token tk;
    *m = 0;
    TRY(rt_lex_next(p, &tk));
    if (tk.len == 0)
        return rt_lex_need(p, &tk, "material", NULL, 1, "name");
    *m = lookup(p, &tk, s, names);
    if (*m < 0) {
        rt_lex_fail(p, &tk, RT_ERR_PARSE, "material ");
        rt_lex_say_tok(p, &tk);
        rt_lex_say(p, " is not defined (materials must be defined "
                      "before use)");
        return RT_ERR_PARSE;
    }
    return RT_OK;
}

/* ---- Objects ------------------------------------------------------------ */

/* What each object field sets: F_A the first point (center, corner, min
 * or base), F_B and F_C the second and third vectors (edge1 and edge2, or
 * max), F_R the radius, F_H the height. */
enum { F_A, F_B, F_C, F_R, F_H, F_MAT, F_OPEN, F_CAPS };

typedef struct {
    const char *name;
    const char *const *keys;
    uint8_t field[6];
    uint8_t n_required; /* the first n keys are required */
} shape_spec;

static const char *const sphere_keys[] = {"center", "radius", "material",
                                          NULL};
static const char *const quad_keys[] = {"corner", "edge1", "edge2",
                                        "material", NULL};
static const char *const box_keys[] = {"min", "max", "material", NULL};
static const char *const cyl_keys[] = {"base", "radius", "height", "material",
                                       "open", "caps", NULL};
static const char *const cone_keys[] = {"base", "radius", "height",
                                        "material", "open", NULL};

/* Indexed by rt_kind. */
static const shape_spec shapes[RT_KIND_COUNT] = {
    {"sphere", sphere_keys, {F_A, F_R, F_MAT}, 3},
    {"quad", quad_keys, {F_A, F_B, F_C, F_MAT}, 4},
    {"box", box_keys, {F_A, F_B, F_MAT}, 3},
    {"cylinder", cyl_keys, {F_A, F_R, F_H, F_MAT, F_OPEN, F_CAPS}, 4},
    {"cone", cone_keys, {F_A, F_R, F_H, F_MAT, F_OPEN}, 4},
};

static int key_of(const shape_spec *sp, int field)
{
    int i = 0;
    while (sp->field[i] != field)
        i++;
    return i;
}

/* Where vector field f (F_A, F_B, F_C) of o's kind goes. */
static fx_vec3 *vec_field(rt_object *o, int f)
{
    if (f == F_A)
        return &o->u.origin; /* every record's first point (rt_scene.h) */
    if (o->kind == RT_QUAD)
        return f == F_B ? &o->u.quad.edge1 : &o->u.quad.edge2;
    return &o->u.box.max;
}

/* Where scalar field f (F_R, F_H) of o's kind goes. */
static fx_t *fx_field(rt_object *o, int f)
{
    if (o->kind == RT_SPHERE)
        return &o->u.sphere.radius;
    return f == F_R ? &o->u.upright.radius : &o->u.upright.height;
}

static rt_status degenerate(rt_lex *p, const rt_lex_token *at,
                            const char *shape, const char *why)
{
    rt_lex_fail(p, at, RT_ERR_DEGENERATE, "degenerate ");
    rt_lex_say(p, shape);
    rt_lex_say(p, ": ");
    rt_lex_say(p, why);
    return RT_ERR_DEGENERATE;
}

/* Shape checks with specific messages; rt_object_prepare() has the last
 * word. */
static rt_status check_shape(rt_lex *p, const rt_lex_token *kw,
                             const shape_spec *sp, const rt_lex_token *at,
                             rt_object *o)
{
    const char *nm = sp->name;
    if (o->kind == RT_QUAD) {
        const fx_vec3 a = o->u.quad.edge1, b = o->u.quad.edge2;
        if (a.x == 0 && a.y == 0 && a.z == 0)
            return degenerate(p, &at[1], nm, "edge1 must not be zero");
        if (b.x == 0 && b.y == 0 && b.z == 0)
            return degenerate(p, &at[2], nm, "edge2 must not be zero");
        /* Exact: each product is below 2^62. */
        if ((int64_t)a.y * b.z == (int64_t)a.z * b.y &&
            (int64_t)a.z * b.x == (int64_t)a.x * b.z &&
            (int64_t)a.x * b.y == (int64_t)a.y * b.x)
            return degenerate(p, &at[2], nm,
                              "edge1 and edge2 are parallel");
    } else if (o->kind == RT_BOX) {
        const fx_vec3 lo = o->u.box.min, hi = o->u.box.max;
        if (hi.x <= lo.x)
            return degenerate(p, &at[1], nm, "max x must be > min x");
        if (hi.y <= lo.y)
            return degenerate(p, &at[1], nm, "max y must be > min y");
        if (hi.z <= lo.z)
            return degenerate(p, &at[1], nm, "max z must be > min z");
    } else if (o->kind == RT_SPHERE) {
        if (o->u.sphere.radius <= 0)
            return degenerate(p, &at[key_of(sp, F_R)], nm,
                              "radius must be > 0");
    } else {
        const fx_t r = o->u.upright.radius, h = o->u.upright.height;
        if (r <= 0)
            return degenerate(p, &at[key_of(sp, F_R)], nm,
                              "radius must be > 0");
        if (h <= 0)
            return degenerate(p, &at[key_of(sp, F_H)], nm,
                              "height must be > 0");
        /* rt_upright.c's RT_MAX_CONE_SLOPE, as docs/numerics.md states. */
        if (o->kind == RT_CONE && fx_div(r, h) > FX_INT(64))
            return degenerate(p, &at[key_of(sp, F_R)], nm,
                              "radius / height must be at most 64");
    }
    if (rt_object_prepare(o) != RT_OK)
        return degenerate(p, o->kind == RT_QUAD ? &at[1]
                             : o->kind == RT_BOX ? kw
                                                 : &at[key_of(sp, F_R)],
                          nm, o->kind == RT_QUAD
                                  ? "edges too short for Q16.16"
                                  : "too thin or too flat for Q16.16 "
                                    "(the radius and half the height must "
                                    "each be at least 1/65536 of the "
                                    "other)");
    return RT_OK;
}

rt_status rt_parse_object(rt_lex *p, const rt_lex_token *kw, int kind,
                          rt_scene *s, const rt_parse_names names)
{
    static const char *const caps[] = {"none", "bottom", "top", "both", NULL};
    const shape_spec *sp = &shapes[kind];
    const char *const *keys = sp->keys;
    rt_lex_token at[6];
    uint32_t seen = 0;
    int k, caps_given = 0;
    rt_object *o;
    if (s->n_objects >= RT_MAX_OBJECTS) {
        return rt_lex_too_many(p, kw, "objects", "RT_MAX_OBJECTS",
                               RT_MAX_OBJECTS);
    }
    o = &s->obj[s->n_objects];
    memset(o, 0, sizeof *o);
    o->kind = (uint8_t)kind;
    o->caps = kind == RT_CYLINDER ? (RT_CAP_BOTTOM | RT_CAP_TOP)
              : kind == RT_CONE   ? RT_CAP_BOTTOM
                                  : 0;
    for (;;) {
        TRY(rt_lex_next_key(p, sp->name, keys, at, &seen, &k));
        if (k < 0)
            break;
        const char *key = keys[k];
        switch (sp->field[k]) {
        case F_A:
        case F_B:
        case F_C:
            TRY(rt_lex_get_vec(p, key, vec_field(o, sp->field[k])));
            break;
        case F_R:
        case F_H:
            TRY(rt_lex_get_fxs(p, key, NULL, 1, fx_field(o, sp->field[k]),
                               FX_MIN, FX_MAX, ""));
            break;
        case F_MAT: {
            int m;
            TRY(rt_parse_material_ref(p, s, names, &m));
            o->material = (uint8_t)m;
            break;
        }
        case F_OPEN:
            o->caps = 0;
            break;
        default: { /* F_CAPS */
            rt_lex_token tk;
            TRY(rt_lex_next(p, &tk));
            int c = rt_lex_find(p, &tk, caps);
            if (c < 0) {
                rt_lex_fail(p, &tk, RT_ERR_PARSE,
                            "'caps' needs one of: both top bottom none");
                rt_lex_say_got(p, &tk);
                return RT_ERR_PARSE;
            }
            o->caps = (uint8_t)c; /* the list is in RT_CAP_* bit order */
            break;
        }
        }
        if (sp->field[k] >= F_OPEN && caps_given++ > 0)
            return rt_lex_fail(p, &at[k], RT_ERR_PARSE,
                               "give either 'open' or 'caps', not both");
    }
    TRY(rt_lex_require(p, kw, sp->name, keys, seen,
                       (1u << sp->n_required) - 1u));
    TRY(check_shape(p, kw, sp, at, o));
    s->n_objects++;
    return RT_OK;
}
