/* SPDX-License-Identifier: MIT */
/*
 * rt_parse: the scene text format (docs/scene-format.md) into an rt_scene.
 *
 * One pass, line by line. Each statement reads its tokens left to right and
 * the first problem ends the parse with its position. Every byte is looked
 * at a bounded number of times, so the time is linear in the input. Nothing
 * is allocated and nothing recurses: the stack holds the material name
 * table and a few hundred bytes more.
 *
 * This file holds the scene-wide statements and the file; rt_parse_obj.c
 * the materials and objects; rt_lex.c and rt_lex_field.c the tokens,
 * numbers, values and messages they are read with (rt_lex.h).
 */
#include "rt_libc.h"
#include "rt_lex.h"

#define LIGHT_MAX FX_INT(16) /* light and ambient colours, raw Q16.16 */

/* ---- Scene-wide statements ---------------------------------------------- */

static const char *const image_keys[] = {"spp", "depth", NULL};

static rt_status st_image(rt_lex *p, rt_scene *s)
{
    rt_lex_token at[2], tk;
    uint32_t w, h, v, seen = 0;
    int k;
    TRY(rt_lex_get_uint(p, "image", "width", 1, RT_MAX_WIDTH,
                        " (RT_MAX_WIDTH)", &w, &tk));
    TRY(rt_lex_get_uint(p, "image", "height", 1, RT_MAX_HEIGHT,
                        " (RT_MAX_HEIGHT)", &h, &tk));
    s->width = (uint16_t)w;
    s->height = (uint16_t)h;
    for (;;) {
        TRY(rt_lex_next_key(p, "image", image_keys, at, &seen, &k));
        if (k < 0)
            return RT_OK;
        if (k == 1) {
            TRY(rt_lex_get_uint(p, "depth", NULL, 0, RT_MAX_DEPTH,
                                " (RT_MAX_DEPTH)", &v, &tk));
            s->depth = (uint8_t)v;
            continue;
        }
        TRY(rt_lex_get_uint(p, "spp", NULL, 1,
                            RT_MAX_SPP_SIDE * RT_MAX_SPP_SIDE,
                            " (RT_MAX_SPP_SIDE squared)", &v, &tk));
        uint32_t n = 1;
        while (n < RT_MAX_SPP_SIDE && n * n < v)
            n++;
        if (n * n != v) {
            rt_lex_fail(p, &tk, RT_ERR_PARSE, "spp must be a square n*n "
                                              "with n <= RT_MAX_SPP_SIDE: ");
            for (n = 1; n <= RT_MAX_SPP_SIDE; n++) {
                if (n > 1)
                    rt_lex_say(p, n == RT_MAX_SPP_SIDE ? " or " : ", ");
                rt_lex_say_u32(p, n * n);
            }
            return RT_ERR_PARSE;
        }
        s->spp = (uint8_t)v;
    }
}

static const char *const cam_keys[] = {"eye", "look", "up", "fov", NULL};

static rt_status st_camera(rt_lex *p, const rt_lex_token *kw, rt_scene *s)
{
    rt_lex_token at[4];
    uint32_t seen = 0;
    int k;
    rt_camera *c = &s->cam;
    for (;;) {
        TRY(rt_lex_next_key(p, "camera", cam_keys, at, &seen, &k));
        if (k < 0)
            break;
        if (k == 0)
            TRY(rt_lex_get_vec(p, "eye", &c->eye));
        else if (k == 1)
            TRY(rt_lex_get_vec(p, "look", &c->look));
        else if (k == 2)
            TRY(rt_lex_get_vec(p, "up", &c->up));
        else
            TRY(rt_lex_get_fxs(p, "fov", NULL, 1, &c->fov, 1,
                               FX_INT(180) - 1, "in (0, 180) degrees"));
    }
    TRY(rt_lex_require(p, kw, "camera", cam_keys, seen, 3u));
    /* Exact tests: |w| < 2^32 and |up| <= 2^31 raw, so each product below
     * fits int64 and the cross product is zero exactly when they match. */
    int64_t wx = (int64_t)c->look.x - c->eye.x;
    int64_t wy = (int64_t)c->look.y - c->eye.y;
    int64_t wz = (int64_t)c->look.z - c->eye.z;
    int64_t ux = c->up.x, uy = c->up.y, uz = c->up.z;
    if (wx == 0 && wy == 0 && wz == 0)
        return rt_lex_fail(p, &at[1], RT_ERR_PARSE,
                           "camera look must differ from eye");
    if (ux == 0 && uy == 0 && uz == 0)
        return rt_lex_fail(p, &at[2], RT_ERR_PARSE,
                           "camera up must not be zero");
    if (wy * uz == wz * uy && wz * ux == wx * uz && wx * uy == wy * ux) {
        if (seen & 4u)
            return rt_lex_fail(p, &at[2], RT_ERR_PARSE,
                               "camera up is parallel to the view direction "
                               "(look - eye)");
        return rt_lex_fail(p, kw, RT_ERR_PARSE,
                           "camera looks straight along the default up "
                           "(0 1 0); give another 'up'");
    }
    return RT_OK;
}

static const char *const light_keys[] = {"color", NULL};

static rt_status st_light(rt_lex *p, const rt_lex_token *kw, rt_scene *s)
{
    rt_lex_token at[1];
    uint32_t seen = 0;
    int k;
    rt_light *l;
    if (s->n_lights >= RT_MAX_LIGHTS) {
        return rt_lex_too_many(p, kw, "lights", "RT_MAX_LIGHTS",
                               RT_MAX_LIGHTS);
    }
    l = &s->light[s->n_lights];
    l->color.r = l->color.g = l->color.b = FX_ONE;
    TRY(rt_lex_get_vec(p, "light", &l->pos));
    for (;;) {
        TRY(rt_lex_next_key(p, "light", light_keys, at, &seen, &k));
        if (k < 0)
            break;
        TRY(rt_lex_get_rgb(p, "color", &l->color, LIGHT_MAX));
    }
    s->n_lights++;
    return RT_OK;
}

/* ---- The file ----------------------------------------------------------- */

enum {
    S_IMAGE, S_CAMERA, S_BACKGROUND, S_AMBIENT, S_SHADOWS, S_LIGHT,
    S_MATERIAL, S_SPHERE, S_QUAD, S_BOX, S_CYLINDER, S_CONE, S_MESH
};
static const char *const stmt_keys[] = {
    "image", "light", "camera", "background", "ambient", "shadows",
    "material", "sphere", "quad", "box", "cylinder", "cone", "mesh", NULL};
/* stmt_keys order, so the message lists them as a file usually has them. */
static const uint8_t stmt_ids[] = {S_IMAGE, S_LIGHT, S_CAMERA, S_BACKGROUND,
                                   S_AMBIENT, S_SHADOWS, S_MATERIAL,
                                   S_SPHERE, S_QUAD, S_BOX, S_CYLINDER,
                                   S_CONE, S_MESH};

static rt_status statement(rt_lex *p, const rt_lex_token *kw, rt_scene *s,
                           rt_parse_names names, uint32_t once[5])
{
    int i = rt_lex_find(p, kw, stmt_keys);
    if (i < 0) {
        rt_lex_fail(p, kw, RT_ERR_PARSE, "unknown keyword ");
        rt_lex_say_tok(p, kw);
        rt_lex_say(p, " (expected one of: ");
        rt_lex_say_list(p, stmt_keys);
        rt_lex_say(p, ")");
        return RT_ERR_PARSE;
    }
    int id = stmt_ids[i];
    if (id <= S_SHADOWS) {
        if (once[id]) {
            rt_lex_fail(p, kw, RT_ERR_PARSE, "second '");
            rt_lex_say(p, stmt_keys[i]);
            rt_lex_say(p, "' statement (the first is on line ");
            rt_lex_say_u32(p, once[id]);
            rt_lex_say(p, ")");
            return RT_ERR_PARSE;
        }
        once[id] = kw->line;
    }
    switch (id) {
    case S_IMAGE:
        return st_image(p, s);
    case S_CAMERA:
        return st_camera(p, kw, s);
    case S_BACKGROUND:
        TRY(rt_lex_get_rgb(p, "background", &s->background, FX_ONE));
        return rt_lex_end_stmt(p, "background");
    case S_AMBIENT:
        TRY(rt_lex_get_rgb(p, "ambient", &s->ambient, LIGHT_MAX));
        return rt_lex_end_stmt(p, "ambient");
    case S_SHADOWS: {
        static const char *const onoff[] = {"off", "on", NULL};
        rt_lex_token tk;
        TRY(rt_lex_next(p, &tk));
        int v = rt_lex_find(p, &tk, onoff);
        if (v < 0) {
            rt_lex_fail(p, &tk, RT_ERR_PARSE, "'shadows' needs 'on' or 'off'");
            rt_lex_say_got(p, &tk);
            return RT_ERR_PARSE;
        }
        s->shadows = (uint8_t)v;
        return rt_lex_end_stmt(p, "shadows");
    }
    case S_LIGHT:
        return st_light(p, kw, s);
    case S_MATERIAL:
        return rt_parse_material(p, kw, s, names);
    case S_MESH:
        return rt_parse_mesh(p, kw, s, names);
    default:
        return rt_parse_object(p, kw, RT_SPHERE + (id - S_SPHERE), s, names);
    }
}

rt_status rt_parse(const char *text, size_t len, rt_scene *s,
                   rt_parse_error *err)
{
    return rt_parse_with_meshes(text, len, s, err, NULL, NULL);
}

rt_status rt_parse_with_meshes(const char *text, size_t len, rt_scene *s,
                               rt_parse_error *err, rt_mesh_loader load,
                               void *ctx)
{
    rt_parse_names names;
    uint32_t once[5] = {0, 0, 0, 0, 0};
    rt_lex p;
    rt_lex_token kw;

    memset(&p, 0, sizeof p);
    memset(err, 0, sizeof *err);
    p.t = text;
    p.len = len;
    p.err = err;
    p.load = load;
    p.load_ctx = ctx;
    /* A UTF-8 byte order mark, as some editors write, is skipped. */
    if (len >= 3 && (unsigned char)text[0] == 0xEF &&
        (unsigned char)text[1] == 0xBB && (unsigned char)text[2] == 0xBF)
        p.next = p.line_off = p.line_end = 3;
    rt_scene_init(s);
    while (p.next < len) {
        rt_lex_start_line(&p);
        TRY(rt_lex_next(&p, &kw));
        if (kw.len)
            TRY(statement(&p, &kw, s, names, once));
    }
    if (!once[S_CAMERA]) {
        /* Point just past the last line's text. */
        kw.off = p.line_end;
        kw.len = 0;
        kw.line_off = p.line_off;
        kw.line = p.line ? p.line : 1;
        return rt_lex_fail(&p, &kw, RT_ERR_PARSE,
                           "no camera statement (every scene needs one)");
    }
    return RT_OK;
}
