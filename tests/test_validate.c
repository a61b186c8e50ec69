/* SPDX-License-Identifier: MIT */
/*
 * rt_render_rows on scenes built in C with out-of-range indices and
 * values: it must answer RT_ERR_ARG without reading through a bad index
 * (make SANITIZE=1 test runs this under ASan and UBSan), and render the
 * same scene once it is repaired.
 */
#include <string.h>

#include "harness.h"
#include "rt_render.h"

static int count_rows(void *ctx, int y, const uint8_t *row, size_t n)
{
    (void)y, (void)row, (void)n;
    ++*(int *)ctx;
    return 0;
}

/* One sphere under one light, 8x6 at 1 spp. */
static void small_scene(rt_scene *s, rt_options *o)
{
    rt_scene_init(s);
    s->n_materials = 1;
    s->mat[0].color = (rt_rgb){ FX_ONE / 2, FX_ONE / 2, FX_ONE / 2 };
    s->mat[0].ambient = FX_ONE / 10;
    s->mat[0].diffuse = FX_ONE / 2;
    s->mat[0].shininess = 1;
    s->mat[0].ior = FX_ONE;
    s->mat[0].tex_scale = FX_ONE;
    s->mat[0].bump_scale = FX_ONE;
    rt_material_prepare(&s->mat[0]);
    s->n_lights = 1;
    s->light[0].pos = fx_v3(FX_INT(5), FX_INT(5), FX_INT(-5));
    s->light[0].color = (rt_rgb){ FX_ONE, FX_ONE, FX_ONE };
    s->n_objects = 1;
    s->obj[0].kind = RT_SPHERE;
    s->obj[0].u.sphere.center = fx_v3(0, 0, 0);
    s->obj[0].u.sphere.radius = FX_ONE;
    CHECK_EQ(rt_object_prepare(&s->obj[0]), RT_OK);
    rt_options_from_scene(o, s);
    o->width = 8;
    o->height = 6;
    o->spp = 1;
}

static rt_status render(const rt_scene *s, const rt_options *o, int *rows)
{
    static uint8_t buf[8 * 3 + 9 * 8];
    *rows = 0;
    return rt_render_rows(s, o, 0, o->height, buf, count_rows, rows, NULL);
}

int main(void)
{
    static rt_scene s;
    rt_options o;
    int rows;

    small_scene(&s, &o);
    CHECK_EQ(render(&s, &o, &rows), RT_OK);
    CHECK_EQ(rows, 6);

    /* A material index past the materials, and past the array. */
    s.obj[0].material = 1;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    s.obj[0].material = 200;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    CHECK_EQ(rows, 0);
    s.obj[0].material = 0;

    /* An object kind past the shapes. */
    s.obj[0].kind = 200;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    s.obj[0].kind = RT_KIND_COUNT;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    /* A mesh without its tables. */
    s.obj[0].kind = RT_MESH;
    s.obj[0].u.mesh.tables = NULL;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    s.obj[0].kind = RT_SPHERE;

    /* Counts past the arrays. */
    s.n_objects = RT_MAX_OBJECTS + 1;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    s.n_objects = 1;
    s.n_materials = RT_MAX_MATERIALS + 1;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    s.n_materials = 1;
    s.n_lights = RT_MAX_LIGHTS + 1;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    s.n_lights = 1;

    /* A texture kind past the textures, and a colour over 1. */
    s.mat[0].texture = 200;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    s.mat[0].texture = RT_TEX_NONE;
    s.mat[0].color.g = FX_ONE + 1;
    CHECK_EQ(render(&s, &o, &rows), RT_ERR_ARG);
    s.mat[0].color.g = FX_ONE / 2;

    /* No scene, no options. */
    CHECK_EQ(rt_render_rows(NULL, &o, 0, 1, (uint8_t[32]){ 0 }, count_rows,
                            &rows, NULL), RT_ERR_ARG);
    CHECK_EQ(rt_render_rows(&s, NULL, 0, 1, (uint8_t[32]){ 0 }, count_rows,
                            &rows, NULL), RT_ERR_ARG);

    /* Repaired, it renders again. */
    CHECK_EQ(render(&s, &o, &rows), RT_OK);
    CHECK_EQ(rows, 6);
    return th_summary();
}
