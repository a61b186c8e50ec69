/* SPDX-License-Identifier: MIT */
/* Builds a scene in C, without the parser or any scene text: the same
 * scene as
 *
 *   camera eye 0 2 -6 look 0 1 0 fov 50
 *   background 0.3 0.4 0.6
 *   light 5 10 -5
 *   material red color 0.9 0.2 0.2 shininess 30 reflect 0.2
 *   material floor color 0.8 0.8 0.8 checker 0.2 0.2 0.2 1
 *   quad corner -5 0 -5 edge1 0 0 10 edge2 10 0 0 material floor
 *   sphere center 0 1 0 radius 1 material red
 *
 * rendered to the same bytes. FX_CONST() turns a decimal into Q16.16 at
 * compile time; rt_material_defaults() gives a material the scene
 * language's defaults, so only what differs is written. */
#include <fixtrace/rt_render.h>

/* What your code calls (usually declared in a header of yours). Returns
 * RT_OK, or the status of the first material or object refused. */
rt_status build_scene(rt_scene *s);

rt_status build_scene(rt_scene *s)
{
    rt_material *red = &s->mat[0], *ground = &s->mat[1];
    rt_object *quad = &s->obj[0], *ball = &s->obj[1];
    rt_status st;

    rt_scene_init(s); /* camera, ambient light, 320x240, 1 spp, depth 5 */
    s->cam.eye = fx_v3(0, FX_CONST(2), FX_CONST(-6));
    s->cam.look = fx_v3(0, FX_CONST(1), 0);
    s->cam.fov = FX_CONST(50);
    s->background.r = FX_CONST(0.3);
    s->background.g = FX_CONST(0.4);
    s->background.b = FX_CONST(0.6);

    s->light[0].pos = fx_v3(FX_CONST(5), FX_CONST(10), FX_CONST(-5));
    s->light[0].color.r = s->light[0].color.g = s->light[0].color.b =
        FX_CONST(1);
    s->n_lights = 1;

    rt_material_defaults(red);
    red->color.r = FX_CONST(0.9);
    red->color.g = red->color.b = FX_CONST(0.2);
    red->shininess = 30;
    red->reflect = FX_CONST(0.2);
    rt_material_defaults(ground);
    ground->color.r = ground->color.g = ground->color.b = FX_CONST(0.8);
    ground->texture = RT_TEX_CHECKER;
    ground->color2.r = ground->color2.g = ground->color2.b = FX_CONST(0.2);
    ground->tex_scale = FX_CONST(1);
    s->n_materials = 2;
    if ((st = rt_material_prepare(red)) != RT_OK ||
        (st = rt_material_prepare(ground)) != RT_OK)
        return st;

    /* An object is its kind, its material and its kind's record in u
     * (rt_scene.h): u.sphere, u.quad, u.box, u.upright (cylinders and
     * cones) or u.mesh. */
    *quad = (rt_object){
        .kind = RT_QUAD,
        .material = 1,
        .u.quad = { .corner = { FX_CONST(-5), 0, FX_CONST(-5) },
                    .edge1 = { 0, 0, FX_CONST(10) },
                    .edge2 = { FX_CONST(10), 0, 0 } },
    };
    *ball = (rt_object){
        .kind = RT_SPHERE,
        .material = 0,
        .u.sphere = { .center = { 0, FX_CONST(1), 0 },
                      .radius = FX_CONST(1) },
    };
    s->n_objects = 2;
    if ((st = rt_object_prepare(quad)) != RT_OK ||
        (st = rt_object_prepare(ball)) != RT_OK)
        return st;
    return RT_OK;
}
