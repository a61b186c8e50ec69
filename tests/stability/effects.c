/* SPDX-License-Identifier: MIT */
/* Stability cases: refraction, lights, recursion and sampling, image
 * sizes, properties, and the scenes in scenes/. */
#include "mesh_obj.h"
#include "stability.h"

/* ==== Refraction ========================================================= */

/* A camera inside a glass box (ior 2, so the critical angle is exactly 30
 * degrees) looking at the face z = 1 at angle deg from its normal; one
 * pixel, depth 1. Refraction shows the blue background; total internal
 * reflection meets the box again from inside, which is black (no ambient,
 * no diffuse) at the depth limit. Fills *st with the core's counters and
 * returns the pixel's blue channel (255 or 0), or -1. */
static int tir_pixel(double deg, rt_stats *st, rt_stats *ref_st, int *ref_b)
{
    char text[512];
    double a = deg * 3.14159265358979323846 / 180;
    snprintf(text, sizeof text,
             "image 1 1 depth 1\n"
             "camera eye 0 0 0 look %.10f 0 %.10f\n" BG_BLUE
             "material glass color 1 1 1 ambient 0 diffuse 0 specular 0 "
             "transparency 1 ior 2\n"
             "box min -5 -5 -5 max 5 5 1 material glass\n",
             10000 * sin(a), 10000 * cos(a));
    ppm_image fx, ref;
    memset(st, 0, sizeof *st);
    memset(ref_st, 0, sizeof *ref_st);
    if (!parse(text, &scene_a))
        return -1;
    view vw = { 0, 0, 0, -1, 0 };
    if (render(&scene_a, vw, 0, &fx, st) != RT_OK ||
        render(&scene_a, vw, 1, &ref, ref_st) != RT_OK)
        return -1;
    int b = fx.data[2];
    *ref_b = ref.data[2];
    ppm_free(&fx);
    ppm_free(&ref);
    return b;
}

/* Just below the critical angle (30 - 0.01 degrees, k = 1 - eta^2 sin^2 =
 * +6e-4, about 40 ulps) the ray refracts: one refraction ray, no
 * reflection ray, blue pixel. Just above (30 + 0.01) it is totally
 * reflected: one reflection ray (TIR counts as reflection), black. Same
 * as the reference, whose counters must match. Margins down to 0.002
 * degrees are reported. */
void case_tir_just_below_and_above(void)
{
    static const double margins[] = { 1, 0.1, 0.01, 0.005, 0.002 };
    for (int i = 0; i < 5; i++) {
        for (int side = -1; side <= 1; side += 2) {
            rt_stats st, rs;
            int rb, b = tir_pixel(30 + side * margins[i], &st, &rs, &rb);
            int tir = side > 0;
            int ok = b == (tir ? 0 : 255) && st.reflection == (unsigned)tir &&
                     st.refraction == (unsigned)!tir && rb == b &&
                     rs.reflection == st.reflection &&
                     rs.refraction == st.refraction;
            if (margins[i] >= 0.01) {
                if (!CHECK(ok))
                    printf("    30 %+g deg: blue %d (reference %d), "
                           "reflection %llu, refraction %llu\n",
                           side * margins[i], b, rb,
                           (unsigned long long)st.reflection,
                           (unsigned long long)st.refraction);
            } else if (!ok || verbose) {
                printf("    30 %+g deg: %s (core %s, reference %s)\n",
                       side * margins[i], ok ? "agrees" : "differs",
                       st.reflection ? "TIR" : "refracts",
                       rs.reflection ? "TIR" : "refracts");
            }
        }
    }
}

/* Exactly at the critical angle k is 0 up to rounding: either answer is
 * right, but exactly one secondary ray is cast, it is counted as what it
 * is, and the pixel agrees with it. The outcome is reported. */
void case_tir_at_critical(void)
{
    rt_stats st, rs;
    int rb, b = tir_pixel(30, &st, &rs, &rb);
    CHECK_EQ(st.reflection + st.refraction, 1);
    CHECK_EQ(b, st.reflection ? 0 : 255);
    printf("    at 30 degrees: core %s, reference %s\n",
           st.reflection ? "total internal reflection" : "refracts",
           rs.reflection ? "total internal reflection" : "refracts");
}

/* A glass sphere with ior 1, transparency 1, reflect 0 and no ambient,
 * diffuse or specular, with shadows off, must render like the scene
 * without it. The transmitted rays start EPS inside and leave EPS outside
 * (two offsets of 1/512 along the normals), so features seen through the
 * sphere shift by up to 2 EPS: pixels away from edges of the glass-free
 * image agree within 2 levels; at edges a few may differ more (at most 2%
 * of the image). The reference does the same; the core's count of such
 * pixels is compared with the reference's. */
void case_glass_ior1_invisible(void)
{
    static const char base[] =
        "image 64 48\n"
        "camera eye 0 1.5 -6 look 0 0.8 0 fov 50\n"
        "background 0.3 0.5 0.8\n"
        "light 3 8 -5\n"
        "material floor color 0.9 0.9 0.9 specular 0 checker 0.1 0.1 0.1 "
        "0.7\n"
        "material red color 0.9 0.2 0.2\n"
        "material glass color 1 1 1 ambient 0 diffuse 0 specular 0 "
        "transparency 1 ior 1\n"
        "quad corner -10 0 -10 edge1 0 0 20 edge2 20 0 0 material floor\n"
        "sphere center 1.2 0.7 2 radius 0.7 material red\n";
    char with[1024];
    snprintf(with, sizeof with, "%s%s", base,
             "sphere center -0.4 1 0 radius 1 material glass\n");
    if (!parse(with, &scene_a) || !parse(base, &scene_b))
        return;
    scene_a.shadows = scene_b.shadows = 0;
    ppm_image g, n, rg, rn;
    view vw = { 0, 0, 0, -1, 0 };
    render(&scene_a, vw, 0, &g, NULL);
    render(&scene_b, vw, 0, &n, NULL);
    render(&scene_a, vw, 1, &rg, NULL);
    render(&scene_b, vw, 1, &rn, NULL);
    long inner = 0, edge = 0, ref_edge = 0;
    int inner_max = 0;
    for (int y = 0; y < g.height; y++)
        for (int x = 0; x < g.width; x++) {
            int e = pdiff(pix(&g, x, y), pix(&n, x, y));
            int er = pdiff(pix(&rg, x, y), pix(&rn, x, y));
            if (at_edge(&n, x, y)) {
                edge += e > 2;
                ref_edge += er > 2;
            } else if (e > 2) {
                inner++;
            }
            if (!at_edge(&n, x, y) && e > inner_max)
                inner_max = e;
        }
    if (!CHECK(inner == 0))
        printf("    %ld pixels away from edges differ (max %d)\n", inner,
               inner_max);
    if (!CHECK(edge <= g.width * g.height / 50))
        printf("    %ld edge pixels differ\n", edge);
    if (verbose || edge > ref_edge + 4)
        printf("    ior 1 glass: max %d levels away from edges; %ld edge "
               "pixels differ by more than 2 (reference: %ld)\n", inner_max,
               edge, ref_edge);
    ppm_free(&g);
    ppm_free(&n);
    ppm_free(&rg);
    ppm_free(&rn);
}

/* ==== Lights ============================================================= */

/* One light at the centre of a closed opaque sphere and one inside a
 * capped cylinder: every shadow ray towards them is blocked by the shell
 * and the shells' outsides face away, so the image is byte-identical to
 * the same scene with only the third, outside light. */
void case_light_inside_object(void)
{
    static const char lights_in[] =
        "camera eye 0 3 -8 look 0 0.5 0\n"
        "background 0.2 0.3 0.4\n"
        "light 0 1 0 color 2 2 2\n"
        "light 2.5 0.8 1.5 color 1 0.5 0.5\n"
        "light -6 6 -6 color 0.5 0.5 0.5\n";
    static const char objects[] =
        "material floor color 0.9 0.9 0.9 checker 0.2 0.2 0.2 1\n"
        "material shell color 0.8 0.5 0.3\n"
        "quad corner -6 0 -6 edge1 0 0 12 edge2 12 0 0 material floor\n"
        "sphere center 0 1 0 radius 0.75 material shell\n"
        "cylinder base 2.5 0 1.5 radius 0.6 height 1.6 material shell\n";
    static const char light_out[] =
        "camera eye 0 3 -8 look 0 0.5 0\n"
        "background 0.2 0.3 0.4\n"
        "light -6 6 -6 color 0.5 0.5 0.5\n";
    char a[1024], b[1024];
    snprintf(a, sizeof a, "%s%s", lights_in, objects);
    snprintf(b, sizeof b, "%s%s", light_out, objects);
    if (!parse(a, &scene_a) || !parse(b, &scene_b))
        return;
    ppm_image ia, ib;
    view vw = { 64, 48, 1, -1, 0 };
    render(&scene_a, vw, 0, &ia, NULL);
    render(&scene_b, vw, 0, &ib, NULL);
    if (!CHECK(same_bytes(&ia, &ib))) {
        compare_result c;
        compare_images(&ia, &ib, &c);
        printf("    enclosed lights change %ld pixels (max %d)\n", c.bad,
               c.max_err);
    }
    ppm_free(&ia);
    ppm_free(&ib);
    expect_close(&scene_a, vw, 40);
}

/* A light exactly on the floor's plane (it lights the floor at ndl = 0, so
 * not at all) and a second light exactly on a sphere's surface: the floor
 * before the sphere's tangent plane is lit, behind it shadowed. No
 * speckles, close to the reference. */
void case_light_on_surface(void)
{
    if (!parse("camera eye 0 4 -6 look 0 0.5 2\n"
               "background 0.2 0.3 0.4\n"
               "light 0 0 1\n"
               "light 0 1 2 color 0.8 0.8 0.8\n"
               "material floor color 0.9 0.9 0.9 checker 0.2 0.2 0.2 1\n"
               "material ball color 0.8 0.5 0.3\n"
               "quad corner -6 0 -4 edge1 0 0 12 edge2 12 0 0 "
               "material floor\n"
               "sphere center 0 1 3 radius 1 material ball\n", &scene_a))
        return;
    expect_close(&scene_a, (view){ 64, 48, 1, -1, 0 }, 35);
}

/* ==== Recursion and sampling ============================================= */

/* Two parallel mirrors facing each other with a ball between, at the
 * maximum depth (RT_MAX_DEPTH) and 16 samples per pixel: deterministic,
 * no speckles, close to the reference; each camera ray spawns at most
 * depth reflection rays, and the core casts the same number of reflection
 * rays as the reference to within 1%. */
void case_facing_mirrors_depth_max_spp16(void)
{
    if (!parse("camera eye 0.3 1.2 -3.5 look -0.2 1 4 fov 30\n"
               "background 0.1 0.1 0.15\n"
               "light 0 3.5 0\n"
               "material mirror color 0.9 0.9 0.9 ambient 0.02 diffuse 0.05 "
               "specular 0 reflect 0.9\n"
               "material ball color 0.9 0.3 0.2\n"
               "material floor color 0.8 0.8 0.8 checker 0.2 0.2 0.2 0.5\n"
               "quad corner -20 -20 -4 edge1 0 40 0 edge2 40 0 0 "
               "material mirror\n"
               "quad corner -20 -20 4 edge1 0 40 0 edge2 40 0 0 "
               "material mirror\n"
               "quad corner -3 -0.5 -3 edge1 0 0 6 edge2 6 0 0 material floor\n"
               "sphere center 0 1 0 radius 0.6 material ball\n", &scene_a))
        return;
    verdict v;
    view vw = { 32, 24, 16, RT_MAX_DEPTH, 0 };
    judge(&scene_a, vw, &v, NULL);
    CHECK_EQ(v.speckles, 0);
    if (!CHECK(v.cmp.psnr >= 35))
        printf("    psnr %.2f dB\n", v.cmp.psnr);
    CHECK_EQ(v.fx_stats.primary, 32 * 24 * 16);
    CHECK(v.fx_stats.reflection <= RT_MAX_DEPTH * v.fx_stats.primary);
    /* Most camera rays bounce between the mirrors to the depth limit. */
    CHECK(v.fx_stats.reflection >= 3 * v.fx_stats.primary);
    if (verbose)
        printf("    primary %llu, reflection %llu (reference %llu)\n",
               (unsigned long long)v.fx_stats.primary,
               (unsigned long long)v.fx_stats.reflection,
               (unsigned long long)v.ref_stats.reflection);
    double rel = fabs((double)v.fx_stats.reflection -
                      (double)v.ref_stats.reflection) /
                 (double)v.ref_stats.reflection;
    if (!CHECK(rel <= 0.01))
        printf("    reflection rays %llu, reference %llu\n",
               (unsigned long long)v.fx_stats.reflection,
               (unsigned long long)v.ref_stats.reflection);
}

/* ==== Image sizes and fields of view ===================================== */

/* A 1x1 image is the centre ray: the same pixel as the reference within 2
 * levels, at 1 and at 16 samples. */
void case_image_1x1(void)
{
    char text[2048];
    translated(0, text, sizeof text);
    if (!parse(text, &scene_a))
        return;
    for (int spp = 1; spp <= 16; spp += 15) {
        ppm_image fx, ref;
        view vw = { 1, 1, spp, -1, 0 };
        CHECK_EQ(render(&scene_a, vw, 0, &fx, NULL), RT_OK);
        CHECK_EQ(render(&scene_a, vw, 1, &ref, NULL), RT_OK);
        if (!CHECK(pdiff(fx.data, ref.data) <= 2))
            printf("    spp %d: %d %d %d, reference %d %d %d\n", spp,
                   fx.data[0], fx.data[1], fx.data[2], ref.data[0],
                   ref.data[1], ref.data[2]);
        ppm_free(&fx);
        ppm_free(&ref);
    }
}

/* The room scene of the wide views (fov_near_180 and views.c's
 * fov_near_180_wide); %s is the field of view. */
const char room[] =
    "camera eye 0 0 0 look 0.2 -0.1 1 fov %s\n" BG_BLUE
    "light -1 1.5 -2\n"
    "material wall color 0.8 0.7 0.6 specular 0.3 checker 0.3 0.3 0.4 0.75\n"
    "material ball color 0.2 0.8 0.3\n"
    "box min -3 -2 -4 max 3 2 4 material wall\n"
    "sphere center 1 -1 2 radius 0.8 material ball\n"
    "cylinder base -1.5 -2 1.5 radius 0.4 height 3 material ball\n";

static int parse_room(const char *fov, rt_scene *s)
{
    char text[1024];
    snprintf(text, sizeof text, room, fov);
    return parse(text, s);
}

/* A 4096 x 1 image (the widest; a 176-degree panorama at fov 1): 
 * deterministic, no speckles, close to the reference. */
void case_image_4096x1(void)
{
    if (parse_room("1", &scene_a))
        expect_close(&scene_a, (view){ 4096, 1, 1, -1, 0 }, 35);
}

/* A field of view of 0.001 degrees (half-height 8.7e-6, below one ulp of a
 * direction): every camera ray is the view direction to within an ulp, so
 * the image is one flat colour, the reference's centre pixel (within 2
 * levels). The smallest fov the parser takes (2^-16 degrees) too. */
void case_fov_near_0(void)
{
    static const char *const fovs[] = { "0.001", "0.0000153" };
    for (int i = 0; i < 2; i++) {
        ppm_image fx, ref;
        if (!parse_room(fovs[i], &scene_a))
            continue;
        view vw = { 33, 25, 1, -1, 0 };
        render(&scene_a, vw, 0, &fx, NULL);
        render(&scene_a, vw, 1, &ref, NULL);
        long same = count_colour(&fx, fx.data[0], fx.data[1], fx.data[2]);
        CHECK_EQ(same, 33 * 25);
        CHECK(pdiff(fx.data, pix(&ref, 16, 12)) <= 2);
        ppm_free(&fx);
        ppm_free(&ref);
    }
}

/* Small fields of view against the reference, on a checker 2000 units
 * away. A unit direction is quantised to about 2^-16 rad, which at 0.5
 * degrees is 8% of a pixel of a 48-row image and at 0.05 degrees 80%: the
 * checker's edges may move by that much (a PSNR of hard edges means
 * little), but no pixel away from an edge may be wrong (no interior
 * outliers) and there are no speckles. */
void case_fov_small_scale(void)
{
    static const char *const fovs[] = { "0.5", "0.05" };
    static const char *const cells[] = { "1.3", "0.13" };
    for (int i = 0; i < 2; i++) {
        char text[512];
        snprintf(text, sizeof text,
                 "camera eye 0 0 -2000 look 0 0 0 fov %s\n"
                 "material c color 0.9 0.9 0.9 ambient 1 diffuse 0 "
                 "specular 0 checker3d 0.1 0.1 0.1 %s\n"
                 "quad corner -50 -50 0 edge1 0 100 0 edge2 100 0 0 "
                 "material c\n", fovs[i], cells[i]);
        if (!parse(text, &scene_a))
            continue;
        verdict v;
        judge(&scene_a, (view){ 64, 48, 1, -1, 0 }, &v, NULL);
        CHECK_EQ(v.speckles, 0);
        if (!CHECK(v.cmp.interior_outliers == 0) || verbose)
            printf("    fov %s: psnr %.1f dB, %ld outliers, %ld interior\n",
                   fovs[i], v.cmp.psnr, v.cmp.outliers,
                   v.cmp.interior_outliers);
    }
}

/* Fields of view of 179.99 and 179.99998 degrees (the largest the parser
 * takes; the tangent saturates at 32767) on a square image, inside a room:
 * no speckles, close to the reference. */
void case_fov_near_180(void)
{
    static const char *const fovs[] = { "179.99", "179.99998" };
    for (int i = 0; i < 2; i++)
        if (parse_room(fovs[i], &scene_a))
            expect_close(&scene_a, (view){ 48, 48, 1, -1, 0 }, 30);
}

/* ==== Properties ========================================================= */

/* Light colours from 0.25 up to 16 (the maximum) on a white sphere with a
 * strong highlight: every channel of every pixel is non-decreasing as the
 * light brightens (saturation, never wrap-around to dark), the brightest
 * image is white wherever the light reaches, and each image matches the
 * reference. */
void case_colour_saturates_monotone(void)
{
    static const char *const lc[] = { "0.25", "0.5", "1", "2", "4", "8",
                                      "16" };
    ppm_image prev = { 0, 0, NULL };
    long drops = 0;
    for (int i = 0; i < 7; i++) {
        char text[1024];
        snprintf(text, sizeof text,
                 "camera eye 0 1 -5 look 0 0.5 0\n"
                 "background 0.1 0.1 0.1\n"
                 "ambient 16 16 16\n"
                 "light 2 3 -3 color %s %s %s\n"
                 "light -2 1 -3 color %s %s %s\n"
                 "material w color 1 1 1 ambient 0.01 specular 1 "
                 "shininess 3\n"
                 "material f color 0.5 0.6 0.7 ambient 0.01 reflect 0.5\n"
                 "sphere center 0 1 0 radius 1 material w\n"
                 "quad corner -5 0 -5 edge1 0 0 10 edge2 10 0 0 material f\n",
                 lc[i], lc[i], lc[i], lc[i], lc[i], lc[i]);
        if (!parse(text, &scene_a))
            break;
        ppm_image img;
        view vw = { 48, 36, 1, -1, 0 };
        CHECK_EQ(render(&scene_a, vw, 0, &img, NULL), RT_OK);
        if (prev.data)
            for (size_t k = 0; k < (size_t)img.width * img.height * 3; k++)
                drops += img.data[k] < prev.data[k];
        ppm_free(&prev);
        prev = img;
        expect_close(&scene_a, vw, 40);
    }
    if (!CHECK(drops == 0))
        printf("    %ld channel values went down as the light brightened\n",
               drops);
    /* At colour 16 the lit sphere is white: its centre pixel saturates. */
    if (prev.data)
        CHECK(pdiff(pix(&prev, 24, 13), (const uint8_t *)"\xff\xff\xff") ==
              0);
    ppm_free(&prev);
}

/* A white image in RGB565 with dithering stays 0xFFFF: adding the Bayer
 * threshold to 255 clamps, never wraps to 0. */
void case_dither_white_no_wrap(void)
{
    if (!parse("camera eye 0 0 -5 look 0 0 0\nbackground 1 1 1\n",
               &scene_a))
        return;
    rt_options o;
    rt_options_from_scene(&o, &scene_a);
    o.width = 8;
    o.height = 4;
    o.format = RT_RGB565_LE;
    o.dither = 1;
    uint8_t row[64];
    ppm_image img;
    ppm_alloc(&img, 8, 4);
    for (int y = 0; y < 4; y++) {
        sink k = { &img };
        CHECK_EQ(rt_render_rows(&scene_a, &o, y, y + 1, row, to_image, &k,
                                NULL), RT_OK);
        for (int i = 0; i < 16; i++)
            CHECK_EQ(img.data[(size_t)y * 24 + (size_t)i], 0xFF);
    }
    ppm_free(&img);
}

/* A scene mirror-symmetric about x = 0 (every object, the checker cells,
 * the light) with the camera on the axis and an even width: column x and
 * column W-1-x see mirrored rays. The reference is exactly symmetric. The
 * core is not quite: fx_mul and the other rounding steps break ties toward
 * +infinity, so -v and v round differently at exact ties (about 1 product
 * in 8000), which moves a value by one ulp and, rarely, a pixel by one
 * level; and a sample that lands within an ulp of a discontinuity (a
 * checker cell's edge, a silhouette) may fall on different sides in the
 * two halves. Asserted at 320x240: at most 1 pixel in 2000 differs from
 * its mirror, and every difference beyond 2 levels is at an edge of the
 * image (a discontinuity), never inside a smooth region. */
void case_symmetric_scene_mirrors(void)
{
    if (!parse("camera eye 0 2.5 -8 look 0 1 0 fov 50\n"
               "background 0.2 0.3 0.4\n"
               "light 0 6 -4\n"
               "material red color 0.9 0.2 0.2 specular 0.6\n"
               "material blue color 0.2 0.3 0.9\n"
               "material glass color 1 1 1 ambient 0 diffuse 0 specular 0.5 "
               "reflect 0.1 transparency 0.8 ior 1.5\n"
               "material mirror color 0.9 0.9 0.9 diffuse 0.1 reflect 0.8\n"
               "material floor color 0.9 0.9 0.9 checker 0.2 0.2 0.2 1\n"
               "quad corner -5.5 0 -5.5 edge1 0 0 11 edge2 11 0 0 "
               "material floor\n"
               "sphere center -1.5 1 0 radius 1 material red\n"
               "sphere center 1.5 1 0 radius 1 material red\n"
               "sphere center 0 0.7 -2.5 radius 0.7 material glass\n"
               "box min -0.5 0 2 max 0.5 3 3 material mirror\n"
               "cylinder base -3 0 3 radius 0.5 height 2 material blue\n"
               "cylinder base 3 0 3 radius 0.5 height 2 material blue\n"
               "cone base -3.5 0 0 radius 0.6 height 1.5 material blue\n"
               "cone base 3.5 0 0 radius 0.6 height 1.5 material blue\n",
               &scene_a))
        return;
    ppm_image fx, ref;
    view vw = { 320, 240, 1, -1, 0 };
    render(&scene_a, vw, 0, &fx, NULL);
    render(&scene_a, vw, 1, &ref, NULL);
    int max_fx, max_ref;
    long n_fx = mirror_diffs(&fx, &max_fx), n_ref = mirror_diffs(&ref, &max_ref);
    long big = 0, big_smooth = 0;
    for (int y = 0; y < fx.height; y++)
        for (int x = 0; x < fx.width / 2; x++) {
            int xm = fx.width - 1 - x;
            if (pdiff(pix(&fx, x, y), pix(&fx, xm, y)) <= 2)
                continue;
            big++;
            if (!at_edge(&fx, x, y) || !at_edge(&fx, xm, y)) {
                big_smooth++;
                printf("    (%d, %d) and (%d, %d) differ by %d levels away "
                       "from any edge\n", x, y, xm, y,
                       pdiff(pix(&fx, x, y), pix(&fx, xm, y)));
            }
        }
    printf("    mirror differences: core %ld of %d pixel pairs (max %d "
           "levels, %ld beyond 2 levels, all at edges: %s), reference %ld\n",
           n_fx, 160 * 240, max_fx, big, big_smooth ? "no" : "yes", n_ref);
    CHECK(n_fx <= 320 * 240 / 2000);
    CHECK_EQ(big_smooth, 0);
    CHECK_EQ(n_ref, 0);
    ppm_free(&fx);
    ppm_free(&ref);
}

/* A cone seen from above its apex and a capped cylinder seen across its
 * top rim, large in the frame: no speckles at the apex or along the rims,
 * close to the reference. */
void case_apex_and_rim_render(void)
{
    if (!parse("camera eye 0.3 4 -2.5 look 0 1.4 0.2 fov 40\n"
               "background 0.2 0.3 0.4\n"
               "light -3 6 -4\n"
               "material a color 0.8 0.5 0.3 specular 0.5\n"
               "material b color 0.3 0.6 0.8 stripes y 0.9 0.9 0.9 0.3\n"
               "cone base -0.8 0 0.5 radius 0.9 height 2 material a\n"
               "cylinder base 0.9 0 0.4 radius 0.7 height 1.5 material b\n",
               &scene_a))
        return;
    expect_close(&scene_a, (view){ 96, 72, 4, -1, 0 }, 35);
}

/* Self-shadowing on open cylinders and cones: an open cylinder (a tube)
 * and an open cone lit at a grazing angle, small and at radius 60 (where a
 * hit point in the shape's frame is rounded to 2^7 ulps, one EPS), from
 * outside; and a tube of radius 60 seen from above, lit inside near its
 * wall. No acne (and no speckles) against the reference. */
void case_acne_open_shapes(void)
{
    static const char *const texts[] = {
        "camera eye 0.5 3 -6 look 0 0.8 0 fov 45\n"
        "background 0.2 0.3 0.4\n"
        "light 4 1.2 -1\n"
        "material a color 0.8 0.8 0.8 specular 0\n"
        "cylinder base -1.2 0 0 radius 1 height 2 material a open\n"
        "cone base 1.3 0 0 radius 1 height 2 material a open\n",
        "camera eye 30 180 -360 look 0 48 0 fov 45\n"
        "background 0.2 0.3 0.4\n"
        "light 240 72 -60\n"
        "material a color 0.8 0.8 0.8 specular 0\n"
        "cylinder base -72 0 0 radius 60 height 120 material a open\n"
        "cone base 78 0 0 radius 60 height 120 material a open\n",
        /* Looking down into a tube of radius 60 lit from inside, near its
         * wall: the inner wall is lit at grazing angles. */
        "camera eye 20 260 -30 look 0 0 0 up 0 0 1 fov 50\n"
        "background 0.2 0.3 0.4\n"
        "light -50 100 10\n"
        "material a color 0.8 0.8 0.8 specular 0\n"
        "material f color 0.6 0.6 0.6 specular 0\n"
        "quad corner -100 0 -100 edge1 0 0 200 edge2 200 0 0 material f\n"
        "cylinder base 0 0 0 radius 60 height 120 material a open\n",
    };
    for (int i = 0; i < 3; i++) {
        verdict v;
        if (!parse(texts[i], &scene_a))
            continue;
        judge(&scene_a, (view){ 96, 72, 1, -1, 0 }, &v, NULL);
        if (!CHECK(v.acne == 0 && v.speckles == 0))
            printf("    scene %d: acne %ld, speckles %ld (psnr %.1f dB)\n",
                   i, v.acne, v.speckles, v.cmp.psnr);
    }
}

/* Adaptive anti-aliasing (rt_options.adaptive) keeps the centre samples of
 * neighbouring rows in scratch, and promises the same bytes for any split
 * into bands: seed.scene at 96x72, 16 samples, threshold 8, rendered whole,
 * in bands of 7 rows and one row at a time, gives the same bytes three
 * times. */
void case_adaptive_bands_deterministic(void)
{
    char err[256];
    size_t len;
    rt_parse_error pe;
    char *text = cli_read_file("scenes/seed.scene", &len, err, sizeof err);
    if (!CHECK(text != NULL))
        return;
    rt_status st = rt_parse(text, len, &scene_a, &pe);
    free(text);
    if (!CHECK(st == RT_OK))
        return;
    rt_options o = options(&scene_a, (view){ 96, 72, 16, -1, 0 });
    o.adaptive = 8;
    uint8_t *row = malloc(rt_buffer_bytes(&o));
    ppm_image img[3];
    static const int bands[3] = { 72, 7, 1 };
    for (int k = 0; k < 3; k++) {
        sink snk = { &img[k] };
        ppm_alloc(&img[k], 96, 72);
        for (int y = 0; y < 72; y += bands[k]) {
            int y1 = y + bands[k] > 72 ? 72 : y + bands[k];
            CHECK_EQ(rt_render_rows(&scene_a, &o, y, y1, row, to_image, &snk,
                                    NULL), RT_OK);
        }
    }
    CHECK(same_bytes(&img[0], &img[1]));
    CHECK(same_bytes(&img[0], &img[2]));
    for (int k = 0; k < 3; k++)
        ppm_free(&img[k]);
    free(row);
}

/* ==== The scenes in scenes/ ============================================== */

/* The meshes of the scene last read from scenes/. */
static mesh_obj_ctx meshes;

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Every scenes/ *.scene at 160x120 (its own spp and depth): deterministic
 * (same bytes twice and in bands) and no speckles against the reference.
 * seed.scene also has no shadow acne. The PSNR of each is printed. */
void case_scenes_no_speckles(void)
{
    char *names[64];
    int count = 0, seen_seed = 0;
    DIR *d = opendir("scenes");
    if (!CHECK(d != NULL))
        return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL && count < 64) {
        size_t n = strlen(e->d_name);
        if (n > 6 && strcmp(e->d_name + n - 6, ".scene") == 0)
            names[count++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)count, sizeof names[0], cmp_names);
    CHECK(count > 0);
    for (int i = 0; i < count; i++) {
        char path[512], err[256];
        size_t len;
        rt_parse_error pe;
        snprintf(path, sizeof path, "scenes/%s", names[i]);
        char *text = cli_read_file(path, &len, err, sizeof err);
        if (!CHECK(text != NULL)) {
            printf("    %s\n", err);
            free(names[i]);
            continue;
        }
        /* Meshes of the scene before are released; this one's are kept
         * until the next (or the end). */
        mesh_obj_free(&meshes);
        mesh_obj_init(&meshes, path, stdout, 1);
        rt_status st = mesh_obj_parse_scene(text, len, path, &scene_a, &pe,
                                            &meshes);
        free(text);
        if (!CHECK(st == RT_OK)) {
            printf("    %s:%u:%u: %s\n", path, (unsigned)pe.line,
                   (unsigned)pe.col, pe.msg);
            free(names[i]);
            continue;
        }
        verdict v;
        judge(&scene_a, (view){ 160, 120, 0, -1, 0 }, &v, NULL);
        int seed = strcmp(names[i], "seed.scene") == 0;
        seen_seed |= seed;
        printf("    %-17s psnr %5.1f dB, max %3d, outliers %3ld, speckles "
               "%ld (%ld at sub-pixel features), acne %ld\n", names[i],
               v.cmp.psnr, v.cmp.max_err, v.cmp.outliers, v.speckles,
               v.speckles_loose - v.speckles, v.acne);
        CHECK_EQ(v.speckles, 0);
        if (seed)
            CHECK_EQ(v.acne, 0);
        free(names[i]);
    }
    mesh_obj_free(&meshes);
    if (!CHECK(seen_seed))
        printf("    scenes/seed.scene is missing\n");
}

/* seed.scene at 320x240: no shadow acne (see count_acne) and no
 * speckles. */
void case_seed_no_acne_320(void)
{
    char err[256];
    size_t len;
    rt_parse_error pe;
    char *text = cli_read_file("scenes/seed.scene", &len, err, sizeof err);
    if (!CHECK(text != NULL)) {
        printf("    %s\n", err);
        return;
    }
    rt_status st = rt_parse(text, len, &scene_a, &pe);
    free(text);
    if (!CHECK(st == RT_OK))
        return;
    verdict v;
    judge(&scene_a, (view){ 320, 240, 1, -1, 0 }, &v, NULL);
    if (!CHECK(v.acne == 0 && v.speckles == 0) || verbose)
        printf("    seed 320x240: acne %ld, speckles %ld, psnr %.1f dB\n",
               v.acne, v.speckles, v.cmp.psnr);
}

