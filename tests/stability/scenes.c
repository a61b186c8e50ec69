/* SPDX-License-Identifier: MIT */
/* Stability cases: cameras inside objects, far and huge scenes,
 * degenerate shapes, coplanar quads. */
#include "stability.h"

/* ==== Cameras inside objects ============================================= */


/* Renders an enclosure scene: every pixel must show the inside of the
 * object (never the background), deterministically, with no speckles and
 * within min_psnr of the reference. */
static void inside_case(const char *text, double min_psnr)
{
    ppm_image fx;
    verdict v;
    if (!parse(text, &scene_a))
        return;
    view vw = { 48, 36, 1, -1, 0 };
    judge(&scene_a, vw, &v, &fx);
    long bg = count_colour(&fx, 0, 0, 255);
    if (!CHECK(bg == 0))
        printf("    %ld background pixels seen from inside\n", bg);
    CHECK_EQ(v.speckles, 0);
    if (!CHECK(v.cmp.psnr >= min_psnr))
        printf("    psnr %.2f dB, want >= %.1f\n", v.cmp.psnr, min_psnr);
    ppm_free(&fx);
}

/* Inside a sphere of radius 5 with a light inside: the whole view is the
 * sphere's inner surface, lit, plus a ball inside; no background speckle,
 * matching the reference. */
void case_camera_inside_sphere(void)
{
    inside_case("camera eye 0 0 0 look 0.3 -0.2 1 fov 100\n" BG_BLUE
                "light 0 2 -1\n"
                "material wall color 0.8 0.7 0.6 specular 0\n"
                "material ball color 0.2 0.8 0.3\n"
                "sphere center 0 0 0 radius 5 material wall\n"
                "sphere center 1 -1 3 radius 0.8 material ball\n", 40);
}

/* Inside a capped cylinder: side and both caps, lit from inside. */
void case_camera_inside_cylinder(void)
{
    inside_case("camera eye 0 0 0 look 1 0.6 2 fov 110\n" BG_BLUE
                "light 0.5 2 -1\n"
                "material wall color 0.8 0.7 0.6 specular 0\n"
                "cylinder base 0 -3 0 radius 4 height 6 material wall\n", 40);
}

/* Inside a capped cone, looking up towards its apex. */
void case_camera_inside_cone(void)
{
    inside_case("camera eye 0 0 0 look 0.2 2 1 fov 100\n" BG_BLUE
                "light 0 1 -0.5\n"
                "material wall color 0.8 0.7 0.6 specular 0\n"
                "cone base 0 -2 0 radius 4 height 6 material wall\n", 40);
}

/* Inside a box, looking into a corner. */
void case_camera_inside_box(void)
{
    inside_case("camera eye 0 0 0 look 1 0.5 2 fov 100\n" BG_BLUE
                "light -1 1.5 -2\n"
                "material wall color 0.8 0.7 0.6 specular 0.3\n"
                "material ball color 0.2 0.8 0.3\n"
                "box min -3 -2 -4 max 3 2 4 material wall\n"
                "sphere center 1 -1 2 radius 0.8 material ball\n", 40);
}

/* ==== Far and huge ======================================================= */

/* A small scene of every shape kind, moved by an offset on all three axes
 * (translated() fills it in). */
const char translated_fmt[] =
    "camera eye %.2f %.2f %.2f look %.2f %.2f %.2f fov 50\n"
    "background 0.2 0.3 0.4\n"
    "light %.2f %.2f %.2f\n"
    "material a color 0.9 0.3 0.2 specular 0.4\n"
    "material b color 0.3 0.8 0.3 stripes x 0.1 0.1 0.6 0.25\n"
    "material c color 0.8 0.8 0.8 checker 0.2 0.2 0.2 1\n"
    "quad corner %.2f %.2f %.2f edge1 0 0 12 edge2 12 0 0 material c\n"
    "sphere center %.2f %.2f %.2f radius 1 material a\n"
    "box min %.2f %.2f %.2f max %.2f %.2f %.2f material b\n"
    "cylinder base %.2f %.2f %.2f radius 0.7 height 2 material a\n"
    "cone base %.2f %.2f %.2f radius 0.8 height 1.6 material b\n";

void translated(double o, char *buf, size_t n)
{
    snprintf(buf, n, translated_fmt, o, o + 3, o - 8, o, o + 0.5, o,
             o + 4, o + 8, o - 5, o - 6, o - 1, o - 6, o - 1, o + 1, o,
             o + 1.5, o, o + 2, o + 2.5, o + 2, o + 2.5, o - 3, o - 1, o,
             o + 1, o - 1, o + 2);
}

/* The same scene at the origin and moved to (30000, 30000, 30000), camera
 * and light too. Every difference of coordinates is exact, so the images
 * should agree to a few levels (the quad's plane distance n.a is the one
 * value that rounds differently); both match the reference. */
void case_translated_30000(void)
{
    char text[2048];
    ppm_image a, b;
    verdict v;
    view vw = { 80, 60, 1, -1, 0 };
    translated(0, text, sizeof text);
    if (!parse(text, &scene_a))
        return;
    translated(30000, text, sizeof text);
    if (!parse(text, &scene_b))
        return;
    judge(&scene_a, vw, &v, &a);
    CHECK_EQ(v.speckles, 0);
    judge(&scene_b, vw, &v, &b);
    CHECK_EQ(v.speckles, 0);
    compare_result c;
    compare_images(&a, &b, &c);
    if (!CHECK(c.max_err <= 2) || verbose)
        printf("    origin vs 30000: max %d, bad %.2f%%, psnr %.1f dB\n",
               c.max_err, c.bad_pct, c.psnr);
    ppm_free(&a);
    ppm_free(&b);
}

/* Tilted quads (a wall turned about y, a panel facing (1, 1, 1) and a
 * mirror facing (-1, 1, 0)) and a sphere, near the origin and moved by o
 * on every axis. */
static void tilted_quads(double o, char *buf, size_t n)
{
    snprintf(buf, n,
             "camera eye %.2f %.2f %.2f look %.2f %.2f %.2f fov 50\n"
             "background 0.2 0.3 0.4\n"
             "light %.2f %.2f %.2f\n"
             "material a color 0.9 0.3 0.2 specular 0.4\n"
             "material c color 0.8 0.8 0.8 checker 0.2 0.2 0.2 1\n"
             "material m color 0.8 0.8 0.9 diffuse 0.2 reflect 0.6\n"
             "quad corner %.2f %.2f %.2f edge1 0 6 0 edge2 8 0 6 "
             "material c\n"
             "quad corner %.2f %.2f %.2f edge1 2 -1 -1 edge2 0 2 -2 "
             "material a\n"
             "quad corner %.2f %.2f %.2f edge1 0 0 3 edge2 2 2 0 "
             "material m\n"
             "sphere center %.2f %.2f %.2f radius 1 material a\n",
             o + 1, o + 2, o - 9, o, o + 1, o,
             o + 3, o + 8, o - 6,
             o - 5, o - 2, o + 2,
             o - 1, o - 0.5, o - 3,
             o + 2, o - 1.5, o - 1,
             o - 0.5, o + 1, o - 1);
}

/* The tilted quads near the origin and moved to (30000, 30000, 30000):
 * there n.a, a quad's plane distance from the scene's origin, is up to
 * 52,000 (beyond Q16.16), so it saturated and the quads vanished or sat
 * elsewhere (a random scene lost a whole wall). Such a quad's plane is
 * tested as (a - o).n, exact at any distance: both images match the
 * reference without speckles, and agree with each other to 2 levels. */
void case_far_tilted_quads(void)
{
    static char text[2048];
    ppm_image a, b;
    view vw = { 80, 60, 1, -1, 0 };
    tilted_quads(0, text, sizeof text);
    if (!parse(text, &scene_a))
        return;
    tilted_quads(30000, text, sizeof text);
    if (!parse(text, &scene_b))
        return;
    expect_clean(&scene_a, vw, 40, "at the origin");
    expect_clean(&scene_b, vw, 40, "at 30000");
    CHECK_EQ(render(&scene_a, vw, 0, &a, NULL), RT_OK);
    CHECK_EQ(render(&scene_b, vw, 0, &b, NULL), RT_OK);
    compare_result c;
    compare_images(&a, &b, &c);
    if (!CHECK(c.max_err <= 2) || verbose)
        printf("    origin vs 30000: max %d, bad %.2f%%, psnr %.1f dB\n",
               c.max_err, c.bad_pct, c.psnr);
    ppm_free(&a);
    ppm_free(&b);
}

/* Objects 20000 units away under a 3-degree view: the hit error grows as
 * 2^-15 t (0.6 units at 20000, against objects of radius 300 and more), so
 * the image still matches the reference with no speckles. */
void case_far_objects_20000(void)
{
    if (!parse("camera eye 0 200 -15000 look 0 0 5000 fov 3\n"
               "background 0.2 0.3 0.4\n"
               "light -3000 9000 -9000\n"
               "material a color 0.9 0.3 0.2 specular 0.4\n"
               "material b color 0.3 0.8 0.3\n"
               "material c color 0.8 0.8 0.8 checker 0.2 0.2 0.2 100\n"
               "quad corner -2000 -500 3000 edge1 0 0 4000 edge2 4000 0 0 "
               "material c\n"
               "sphere center -300 0 5000 radius 500 material a\n"
               "box min 300 -500 4600 max 800 200 5200 material b\n"
               "cylinder base -700 -500 4400 radius 150 height 600 material b\n",
               &scene_a))
        return;
    expect_close(&scene_a, (view){ 64, 48, 1, -1, 0 }, 28);
}

/* A camera 60000 units from a large sphere: beyond the far plane (32767),
 * so the core shows only background, where the reference (unbounded)
 * shows the sphere. A documented limit; the point is that nothing wraps:
 * no pixel shows anything but the background. */
void case_beyond_range_background(void)
{
    ppm_image fx;
    if (!parse("camera eye -30000 0 0 look 30000 0 0 fov 10\n"
               "background 0.2 0.3 0.4\n"
               "light -30000 1000 0\n"
               "material a color 0.9 0.3 0.2\n"
               "sphere center 30000 0 0 radius 2000 material a\n",
               &scene_a))
        return;
    CHECK_EQ(render(&scene_a, (view){ 32, 24, 1, -1, 0 }, 0, &fx, NULL),
             RT_OK);
    long bg = count_colour(&fx, 51, 77, 102);
    if (!CHECK(bg == 32 * 24))
        printf("    %ld of %d pixels show background\n", bg, 32 * 24);
    ppm_free(&fx);
}

/* The ground as a sphere of radius 30000 (centre 30000 below) and as a box
 * 32000 wide reaching down to -32768, seen from 2 units above towards the
 * horizon: both render like the reference, without speckles. (Texture
 * coordinates are measured from the object's first point and saturate
 * 32767 units from it, so the box is kept narrower than the full range.) */
void case_huge_ground_shapes(void)
{
    static const char *const texts[] = {
        "camera eye 0 2 -10 look 0 1 0 fov 60\n"
        "background 0.2 0.3 0.4\nlight 5 20 -10\n"
        "material g color 0.8 0.8 0.8 checker 0.2 0.2 0.2 2\n"
        "material a color 0.9 0.3 0.2\n"
        "sphere center 0 -30000 0 radius 30000 material g\n"
        "sphere center 0 1 0 radius 1 material a\n",
        "camera eye 0 2 -10 look 0 1 0 fov 60\n"
        "background 0.2 0.3 0.4\nlight 5 20 -10\n"
        "material g color 0.8 0.8 0.8 checker 0.2 0.2 0.2 2\n"
        "material a color 0.9 0.3 0.2\n"
        "box min -16000 -32768 -16000 max 16000 0 16000 material g\n"
        "sphere center 0 1 0 radius 1 material a\n",
    };
    for (int i = 0; i < 2; i++)
        if (parse(texts[i], &scene_a))
            expect_close(&scene_a, (view){ 64, 48, 1, -1, 0 }, 30);
}

/* ==== Degenerate shapes: the parser refuses them ========================= */


/* Zero or negative radius: "degenerate sphere: radius must be > 0",
 * status RT_ERR_DEGENERATE. A radius of one ulp is accepted. */
void case_degenerate_sphere(void)
{
    expect_reject(CAM "sphere center 0 0 0 radius 0 material m\n",
                  RT_ERR_DEGENERATE, "degenerate sphere: radius must be > 0");
    expect_reject(CAM "sphere center 0 0 0 radius -1 material m\n",
                  RT_ERR_DEGENERATE, "degenerate sphere: radius must be > 0");
    parse(CAM "sphere center 0 0 0 radius 0.0000153 material m\n", &scene_a);
}

/* A box with max <= min on an axis: "degenerate box: max y must be > min
 * y". A box one ulp thick is accepted. */
void case_degenerate_box(void)
{
    expect_reject(CAM "box min 0 1 0 max 1 1 1 material m\n",
                  RT_ERR_DEGENERATE, "degenerate box: max y must be > min y");
    expect_reject(CAM "box min 0 0 0 max -1 1 1 material m\n",
                  RT_ERR_DEGENERATE, "degenerate box: max x must be > min x");
    parse(CAM "box min 0 0 0 max 1 0.0000153 1 material m\n", &scene_a);
}

/* A quad with a zero edge or parallel edges (checked exactly on the
 * Q16.16 values: 0.0000153 rounds to 1 ulp, 0.0000306 to 2). Edges that
 * are not parallel but so close that the in-plane extent rounds to 0 are
 * refused by rt_object_prepare() ("degenerate quad: edges too short for
 * Q16.16"). Edges of one ulp at right angles are accepted. */
void case_degenerate_quad(void)
{
    expect_reject(CAM "quad corner 0 0 0 edge1 0 0 0 edge2 1 0 0 material m\n",
                  RT_ERR_DEGENERATE, "degenerate quad: edge1 must not be zero");
    expect_reject(CAM "quad corner 0 0 0 edge1 1 2 3 edge2 -2 -4 -6 "
                      "material m\n",
                  RT_ERR_DEGENERATE,
                  "degenerate quad: edge1 and edge2 are parallel");
    expect_reject(CAM "quad corner 0 0 0 edge1 3 0.0000153 0 "
                      "edge2 6 0.0000306 0 material m\n",
                  RT_ERR_DEGENERATE,
                  "degenerate quad: edge1 and edge2 are parallel");
    expect_reject(CAM "quad corner 0 0 0 edge1 3 0.0000153 0 "
                      "edge2 6 0.0000153 0 material m\n",
                  RT_ERR_DEGENERATE, "degenerate quad: ");
    parse(CAM "quad corner 0 0 0 edge1 0.0000153 0 0 edge2 0 0.0000153 0 "
              "material m\n", &scene_a);
}

/* Cylinders and cones with zero radius or height, and cones flatter than
 * radius / height = 64: "degenerate cone: radius / height must be at most
 * 64". The steepest accepted slope is exactly 64. A height of one ulp
 * is refused the same way (its half height, the frame's unit, rounds to
 * 0); two ulps are accepted. */
void case_degenerate_upright(void)
{
    expect_reject(CAM "cylinder base 0 0 0 radius 1 height 0 material m\n",
                  RT_ERR_DEGENERATE,
                  "degenerate cylinder: height must be > 0");
    expect_reject(CAM "cylinder base 0 0 0 radius 0 height 1 material m\n",
                  RT_ERR_DEGENERATE,
                  "degenerate cylinder: radius must be > 0");
    expect_reject(CAM "cone base 0 0 0 radius 0 height 1 material m\n",
                  RT_ERR_DEGENERATE, "degenerate cone: radius must be > 0");
    expect_reject(CAM "cone base 0 0 0 radius 65 height 1 material m\n",
                  RT_ERR_DEGENERATE,
                  "degenerate cone: radius / height must be at most 64");
    parse(CAM "cone base 0 0 0 radius 64 height 1 material m\n", &scene_a);
    expect_reject(CAM "cylinder base 0 0 0 radius 0.0000153 "
                      "height 0.0000153 material m\n",
                  RT_ERR_DEGENERATE, "degenerate cylinder: too thin");
    parse(CAM "cylinder base 0 0 0 radius 0.0000153 height 0.0000306 "
              "material m\n", &scene_a);
    parse(CAM "cone base 0 0 0 radius 0.0000153 height 0.0000306 "
              "material m\n", &scene_a);
}

/* ==== Coplanar quads ===================================================== */


/* Two quads in the plane y = 0, the big red one first, a small blue one
 * inside it second. Both give the same t bit for bit (the plane distance
 * is exact for an axis normal), and the nearest-hit loop keeps the first
 * object on a tie (it needs t < best), so no blue pixel shows. In the
 * other order the blue quad shows wherever it is hit alone. Deterministic
 * both ways. */
void case_coplanar_quads_axis(void)
{
    static const char red_first[] =
        "camera eye 0.3 6 -4 look 0 0 0\n" BG_GREEN FLAT_MATS
        "quad corner -3 0 -3 edge1 0 0 6 edge2 6 0 0 material red\n"
        "quad corner -1 0 -1 edge1 0 0 2 edge2 2 0 0 material blue\n";
    static const char blue_first[] =
        "camera eye 0.3 6 -4 look 0 0 0\n" BG_GREEN FLAT_MATS
        "quad corner -1 0 -1 edge1 0 0 2 edge2 2 0 0 material blue\n"
        "quad corner -3 0 -3 edge1 0 0 6 edge2 6 0 0 material red\n";
    static const char blue_alone[] =
        "camera eye 0.3 6 -4 look 0 0 0\n" BG_GREEN FLAT_MATS
        "quad corner -1 0 -1 edge1 0 0 2 edge2 2 0 0 material blue\n";
    ppm_image a, a2, b, c;
    view vw = { 64, 48, 1, -1, 0 };
    if (!parse(red_first, &scene_a))
        return;
    render(&scene_a, vw, 0, &a, NULL);
    render(&scene_a, vw, 0, &a2, NULL);
    CHECK(same_bytes(&a, &a2));
    CHECK_EQ(count_colour(&a, 0, 0, 255), 0);
    if (parse(blue_first, &scene_a) && parse(blue_alone, &scene_b)) {
        render(&scene_a, vw, 0, &b, NULL);
        render(&scene_b, vw, 0, &c, NULL);
        /* The blue quad exactly as alone: the same blue pixels. */
        long both = 0, blue_b = count_colour(&b, 0, 0, 255);
        for (int y = 0; y < c.height; y++)
            for (int x = 0; x < c.width; x++)
                both += pix(&c, x, y)[2] == 255 && pix(&b, x, y)[2] == 255;
        CHECK_EQ(blue_b, count_colour(&c, 0, 0, 255));
        CHECK_EQ(both, blue_b);
        CHECK(blue_b > 100);
        ppm_free(&b);
        ppm_free(&c);
    }
    ppm_free(&a);
    ppm_free(&a2);
}

/* The same on a tilted plane (normal along (1, 2, 2) / 3): the small quad's
 * corner is the big one's plus whole edges, exactly in the plane, but the
 * two plane distances n.a round separately, so the two t values may differ
 * by an ulp. Whatever the core picks must be deterministic (same bytes
 * twice and in bands); the count of blue pixels is reported. */
void case_coplanar_quads_tilted(void)
{
    static const char text[] =
        "camera eye 4 7 -3 look 0 0 0\n" BG_GREEN FLAT_MATS
        "quad corner -3 1.5 0 edge1 4 -2 0 edge2 2 4 -5 material red\n"
        "quad corner -0.5 1.5 -1.25 edge1 1 -0.5 0 edge2 1 2 -2.5 "
        "material blue\n";
    ppm_image a, a2, banded;
    view vw = { 64, 48, 1, -1, 0 }, vb = { 64, 48, 1, -1, 5 };
    if (!parse(text, &scene_a))
        return;
    render(&scene_a, vw, 0, &a, NULL);
    render(&scene_a, vw, 0, &a2, NULL);
    render(&scene_a, vb, 0, &banded, NULL);
    CHECK(same_bytes(&a, &a2));
    CHECK(same_bytes(&a, &banded));
    long blue = count_colour(&a, 0, 0, 255), red = count_colour(&a, 255, 0, 0);
    printf("    tilted coplanar: %ld red, %ld blue pixels\n", red, blue);
    ppm_free(&a);
    ppm_free(&a2);
    ppm_free(&banded);
}

/* Objects standing on a floor quad (y = 0): a capped cylinder, a cone and a
 * box, whose bottoms lie exactly in the floor's plane. Seen from inside
 * (through glass, say) a ray meets the floor and the bottom at the same
 * distance; for the earlier object to win that tie, as in the reference,
 * both must give the same t bit for bit, not two values a rounding apart
 * (which would make the choice flip from pixel to pixel: z-fighting).
 * 3000 rays from inside each shape, downwards. */
void case_coplanar_bottom_on_floor(void)
{
    rt_object floor = quad(V(-20, 0, -20), V(0, 0, 40), V(40, 0, 0));
    rt_object shapes[3];
    shapes[0] = upright(RT_CYLINDER, 1.3, 0, -0.7, 0.9, 1.7);
    shapes[1] = upright(RT_CONE, -1.1, 0, 0.4, 1.1, 2.3);
    shapes[2] = box(-0.6, 0, 2.1, 1.3, 1.1, 3.4);
    static const double cx[3] = { 1.3, -1.1, 0.35 }, cz[3] = { -0.7, 0.4, 2.75 };
    static const char *const names[3] = { "cylinder", "cone", "box" };
    for (int k = 0; k < 3; k++) {
        int differ = 0, n = 0;
        for (int i = 0; i < 3000; i++) {
            double ox = cx[k] + (rnd() - 0.5) * 0.6;
            double oz = cz[k] + (rnd() - 0.5) * 0.6;
            double oy = 0.05 + rnd() * 0.4;
            rt_ray r = ray(ox, oy, oz, rnd() - 0.5, -0.3 - rnd(), rnd() - 0.5);
            fx_t tf, ts;
            uint16_t pf, ps;
            if (!rt_intersect(&floor, &r, RT_EPS, FX_MAX, &tf, &pf) ||
                !rt_intersect(&shapes[k], &r, RT_EPS, FX_MAX, &ts, &ps))
                continue;
            if (ps != (k == 2 ? 1 : 1))
                continue; /* left through the side, not the bottom */
            n++;
            differ += tf != ts;
        }
        if (!CHECK(differ == 0) || verbose)
            printf("    %s: %d of %d rays through the bottom see a "
                   "different t on the floor\n", names[k], differ, n);
    }
}

/* The same seen in a render: glass shapes standing on a checker floor,
 * looked at from above so the floor is seen through their bottoms. No
 * speckles against the reference. */
void case_coplanar_glass_on_floor(void)
{
    if (!parse("camera eye 1 6 -5 look 0 0.3 0.5 fov 45\n"
               "background 0.2 0.3 0.4\n"
               "light 3 8 -4\n"
               "material floor color 0.9 0.9 0.9 checker 0.15 0.15 0.15 0.5\n"
               "material glass color 1 1 1 ambient 0 diffuse 0 specular 0.5 "
               "transparency 0.9 ior 1.5\n"
               "quad corner -20 0 -20 edge1 0 0 40 edge2 40 0 0 "
               "material floor\n"
               "cylinder base 1.3 0 -0.7 radius 0.9 height 1.7 material glass\n"
               "cone base -1.4 0 0.4 radius 1.1 height 2.3 material glass\n"
               "box min -0.6 0 2.1 max 1.3 1.1 3.4 material glass\n",
               &scene_a))
        return;
    expect_close(&scene_a, (view){ 128, 96, 1, -1, 0 }, 30);
}

