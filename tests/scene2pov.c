/* SPDX-License-Identifier: MIT */
/*
 * scene2pov: translates a fixtrace scene into POV-Ray 3.7 scene language,
 * so that POV-Ray can check the double reference from outside.
 *
 *   scene2pov SCENE W H > scene.pov
 *   povray +Iscene.pov +Oout.ppm +FP +WW +HH -A -D File_Gamma=1.0
 *
 * The scene is read by the core's own parser (rt_parse), so POV-Ray sees
 * exactly the numbers fixtrace renders. The mapping of the two models
 * (docs/render-model.md, "POV-Ray") is:
 * - camera: POV-Ray's `angle` is the horizontal field of view, ours the
 *   vertical one; both sample pixel centres without anti-aliasing;
 * - light: linear (`assumed_gamma 1.0`, and File_Gamma=1.0 when writing);
 *   point lights without fading; `adc_bailout 0`, so POV-Ray traces every
 *   ray (the reference cuts none either);
 * - depth: POV-Ray counts the camera ray in `max_trace_level` (depth + 1);
 * - ambient and diffuse: POV-Ray scales them by (1 - transmit) only, ours
 *   by (1 - kr - kt), so they are given as k (1 - kr - kt) / (1 - kt);
 * - shadows: POV-Ray lets light through transparent objects; here each
 *   transparent object casts no shadow and an opaque twin that only casts
 *   shadows (no_image, no_reflection) stands in its place, as our model
 *   has transparent objects block light fully;
 * - textures: stripes are a gradient, checkers POV-Ray's checker pattern,
 *   scaled and moved to the object's first point; the 2-D checker's y is
 *   stretched so that one layer covers the scene. Bump noise has no
 *   POV-Ray counterpart and is left out (tests use scenes without it).
 * Total internal reflection is weighted differently in POV-Ray, so test
 * scenes keep glass away from it.
 *
 * Host-only test tool; it uses double, which the core never does.
 */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include "rt_parse.h"

static double d(fx_t v) { return (double)v / 65536.0; }

static void vec(const char *pre, fx_vec3 v)
{
    printf("%s<%.9g, %.9g, %.9g>", pre, d(v.x), d(v.y), d(v.z));
}

static void rgb(const char *pre, rt_rgb c)
{
    printf("%srgb <%.9g, %.9g, %.9g>", pre, d(c.r), d(c.g), d(c.b));
}

/* The pigment of material m on an object whose first point is a. */
static void pigment(const rt_material *m, fx_vec3 a)
{
    double s = d(m->tex_scale), t = d(m->transparency);
    printf("  pigment { ");
    switch (m->texture) {
    case RT_TEX_STRIPES: {
        const char *ax = m->axis == 0 ? "x" : (m->axis == 1 ? "y" : "z");
        /* gradient repeats over [0, 1): cells of s are halves of 2s. */
        printf("gradient %s color_map { [0 rgbt <%.9g, %.9g, %.9g, %.9g>] "
               "[0.5 rgbt <%.9g, %.9g, %.9g, %.9g>] [0.5 rgbt <%.9g, %.9g, "
               "%.9g, %.9g>] [1 rgbt <%.9g, %.9g, %.9g, %.9g>] } scale %.9g",
               ax, d(m->color.r), d(m->color.g), d(m->color.b), t,
               d(m->color.r), d(m->color.g), d(m->color.b), t, d(m->color2.r),
               d(m->color2.g), d(m->color2.b), t, d(m->color2.r),
               d(m->color2.g), d(m->color2.b), t, 2 * s);
        vec(" translate ", a);
        break;
    }
    case RT_TEX_CHECKER:
    case RT_TEX_CHECKER3D: {
        int flat = m->texture == RT_TEX_CHECKER;
        printf("checker rgbt <%.9g, %.9g, %.9g, %.9g> rgbt <%.9g, %.9g, "
               "%.9g, %.9g>",
               d(m->color.r), d(m->color.g), d(m->color.b), t, d(m->color2.r),
               d(m->color2.g), d(m->color2.b), t);
        if (flat)
            printf(" scale <%.9g, 1e6, %.9g> translate <%.9g, %.9g, %.9g>",
                   s, s, d(a.x), d(a.y) - 5e5, d(a.z));
        else
            printf(" scale %.9g translate <%.9g, %.9g, %.9g>", s, d(a.x),
                   d(a.y), d(a.z));
        break;
    }
    default:
        printf("rgbt <%.9g, %.9g, %.9g, %.9g>", d(m->color.r), d(m->color.g),
               d(m->color.b), t);
    }
    printf(" }\n");
}

static void finish(const rt_material *m)
{
    double kr = d(m->reflect), kt = d(m->transparency);
    double wl = 1 - kr - kt;
    double f = kt < 1 ? (wl > 0 ? wl : 0) / (1 - kt) : 0;
    printf("  finish { ambient %.9g diffuse %.9g phong %.9g phong_size %u "
           "reflection { %.9g } }\n",
           d(m->ambient) * f, d(m->diffuse) * f, d(m->specular),
           (unsigned)m->shininess, kr);
    if (kt > 0)
        printf("  interior { ior %.9g }\n", d(m->ior));
}

/* The shape of o alone, without closing brace, then its modifiers. */
static void shape(const rt_object *o)
{
    const rt_upright *up = &o->u.upright;
    fx_vec3 top = up->base;
    top.y += up->height;
    switch (o->kind) {
    case RT_SPHERE:
        vec("sphere { ", o->u.sphere.center);
        printf(", %.9g\n", d(o->u.sphere.radius));
        break;
    case RT_QUAD: {
        const rt_quad *q = &o->u.quad;
        double ax = d(q->corner.x), ay = d(q->corner.y), az = d(q->corner.z);
        double bx = d(q->edge1.x), by = d(q->edge1.y), bz = d(q->edge1.z);
        double cx = d(q->edge2.x), cy = d(q->edge2.y), cz = d(q->edge2.z);
        printf("polygon { 5, <%.9g, %.9g, %.9g>, <%.9g, %.9g, %.9g>, "
               "<%.9g, %.9g, %.9g>, <%.9g, %.9g, %.9g>, <%.9g, %.9g, %.9g>\n",
               ax, ay, az, ax + bx, ay + by, az + bz, ax + bx + cx,
               ay + by + cy, az + bz + cz, ax + cx, ay + cy, az + cz, ax, ay,
               az);
        break;
    }
    case RT_BOX:
        vec("box { ", o->u.box.min);
        vec(", ", o->u.box.max);
        printf("\n");
        break;
    case RT_CYLINDER:
        if (o->caps == (RT_CAP_BOTTOM | RT_CAP_TOP) || o->caps == 0) {
            vec("cylinder { ", up->base);
            vec(", ", top);
            printf(", %.9g%s\n", d(up->radius), o->caps ? "" : " open");
        } else {
            vec("union { cylinder { ", up->base);
            vec(", ", top);
            printf(", %.9g open }\n", d(up->radius));
            vec("  disc { ", o->caps == RT_CAP_TOP ? top : up->base);
            printf(", <0, 1, 0>, %.9g }\n", d(up->radius));
        }
        break;
    default: /* RT_CONE */
        vec("cone { ", up->base);
        printf(", %.9g", d(up->radius));
        vec(", ", top);
        printf(", 0%s\n", (o->caps & RT_CAP_BOTTOM) ? "" : " open");
        break;
    }
}

int main(int argc, char **argv)
{
    static rt_scene s;
    static char text[1 << 20];
    rt_parse_error err;
    if (argc != 4) {
        fprintf(stderr, "usage: scene2pov SCENE W H\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "rb");
    if (!f) {
        perror(argv[1]);
        return 2;
    }
    size_t len = fread(text, 1, sizeof text, f);
    fclose(f);
    if (rt_parse(text, len, &s, &err) != RT_OK) {
        fprintf(stderr, "%s:%u:%u: error: %s\n", argv[1], (unsigned)err.line,
                (unsigned)err.col, err.msg);
        return 1;
    }
    double w = atof(argv[2]), h = atof(argv[3]);
    const double pi = 3.14159265358979323846;
    double vt = tan(d(s.cam.fov) * pi / 360);
    double hfov = 360 / pi * atan(vt * w / h);

    printf("// Generated by scene2pov from %s for %gx%g.\n", argv[1], w, h);
    printf("global_settings { assumed_gamma 1.0 max_trace_level %u "
           "adc_bailout 0", (unsigned)s.depth + 1);
    rgb(" ambient_light ", s.ambient);
    printf(" }\n");
    vec("camera { location ", s.cam.eye);
    vec(" look_at ", s.cam.look);
    vec(" sky ", s.cam.up);
    printf(" right x * %.9g up y angle %.12g }\n", w / h, hfov);
    rgb("background { ", s.background);
    printf(" }\n");
    for (unsigned i = 0; i < s.n_lights; i++) {
        vec("light_source { ", s.light[i].pos);
        rgb(" color ", s.light[i].color);
        printf(" }\n");
    }
    for (unsigned i = 0; i < s.n_objects; i++) {
        const rt_object *o = &s.obj[i];
        const rt_material *m = &s.mat[o->material];
        shape(o);
        pigment(m, o->u.origin);
        finish(m);
        if (m->transparency > 0 || !s.shadows)
            printf("  no_shadow\n");
        printf("}\n");
        if (m->transparency > 0 && s.shadows) {
            shape(o);
            printf("  pigment { rgb 0 } no_image no_reflection\n}\n");
        }
    }
    return 0;
}
