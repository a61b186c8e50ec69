/* SPDX-License-Identifier: MIT */
/* Stability cases: textures and bump maps at the smallest sizes. */
#include "stability.h"

/* The colour of a one-pixel image of the floor y = 0 seen straight down
 * from (x, 1, 0.5), x = 0.5 + k ulps (20,000.5 + k ulps if far): the
 * ray's x and z are exact, so both renderers read the texture at the same
 * point (the hit's y, 0, is exact too). The floor is a quad whose first
 * point is at x = 0.25, or if far a box whose min corner is 50,000 units
 * before the ray (the 64-bit path of the cell division). `mat` is the
 * material's fields after its colour. Returns 0 and the two pixels, or
 * -1. */
static int floor_pixel(int k, int far, const char *mat, uint8_t fx[3],
                       uint8_t ref[3])
{
    char text[1024], shape[256];
    const double x = (far ? 20000.5 : 0.5) + k / 65536.0;
    if (far)
        snprintf(shape, sizeof shape,
                 "box min -29999.5 -1 -10 max 30000 0 10 material m\n");
    else
        snprintf(shape, sizeof shape,
                 "quad corner 0.25 0 -10 edge1 0 0 20 edge2 20 0 0 "
                 "material m\n");
    snprintf(text, sizeof text,
             "image 1 1\n"
             "camera eye %.10f 1 0.5 look %.10f 0 0.5 up 0 0 1 fov 1\n"
             BG_BLUE "ambient 1 1 1\nlight %.10f 5 3\n"
             "material m color 1 1 1 %s\n%s",
             x, x, far ? 20000.5 : 0.5, mat, shape);
    if (!parse(text, &scene_a))
        return -1;
    ppm_image a, b;
    view vw = { 1, 1, 1, -1, 0 };
    if (!CHECK(render(&scene_a, vw, 0, &a, NULL) == RT_OK))
        return -1;
    if (!CHECK(render(&scene_a, vw, 1, &b, NULL) == RT_OK)) {
        ppm_free(&a);
        return -1;
    }
    memcpy(fx, a.data, 3);
    memcpy(ref, b.data, 3);
    ppm_free(&a);
    ppm_free(&b);
    return 0;
}

/* Texture cells of 1, 2 and 3 ulps (sizes 0.0000153 .. 0.0000458): a ray
 * stepped one ulp at a time across each texture, near its origin and
 * 50,000 units from it, sees exactly the reference's cell, and both
 * colours (not one flat colour, as when the reciprocal of the size
 * saturated). Flat white and black, ambient only, so a pixel is the cell.
 * The size is written out in decimals and rounds to the ulps meant. */
void case_texture_cells_1ulp(void)
{
    static const char *const kinds[] = { "stripes x", "checker",
                                         "checker3d" };
    for (int kind = 0; kind < 3; kind++) {
        for (int ulps = 1; ulps <= 3; ulps++) {
            for (int far = 0; far <= 1; far++) {
                char mat[128];
                snprintf(mat, sizeof mat,
                         "ambient 1 diffuse 0 specular 0 %s 0 0 0 %.10f",
                         kinds[kind], ulps / 65536.0);
                int seen[2] = { 0, 0 }, wrong = 0;
                for (int k = 0; k < 12; k++) {
                    uint8_t a[3], b[3];
                    if (floor_pixel(k, far, mat, a, b) != 0)
                        return;
                    wrong += pdiff(a, b) != 0;
                    seen[a[0] != 0] = 1;
                }
                if (!CHECK(wrong == 0 && seen[0] && seen[1]))
                    printf("    %s %d ulps%s: %d of 12 cells differ from "
                           "the reference; black %s, white %s\n",
                           kinds[kind], ulps, far ? ", far" : "", wrong,
                           seen[0] ? "seen" : "not seen",
                           seen[1] ? "seen" : "not seen");
            }
        }
    }
}

/* A floor seen at a slant, its hit m/3 ulps from a checker edge at x =
 * 0.5: the eye's x and the look point's are Q16.16 and the look point
 * lies 2 units below the floor as the eye is 1 above it, so the hit, x =
 * 0.5 + m/3 ulps, lies between Q16.16 points (for m = 0 on the edge,
 * which is in the cell above it). Rounded to Q16.16 the hit of m = -1
 * lands on the edge and took the cell above it; the core decides an
 * edge within a few ulps from the exact hit, and must pick the
 * reference's cell for every m, on a quad floor and on a box's top face.
 * Returns 0 with both pixels, or -1. */
static int edge_pixel(int m, int box, uint8_t fx[3], uint8_t ref[3])
{
    char text[1024];
    snprintf(text, sizeof text,
             "image 1 1\n"
             "camera eye -0.5 1 0.6 look %.10f -2 0.6 up 0 0 1 fov 1\n"
             BG_BLUE "ambient 1 1 1\nlight 0 5 3\n"
             "material m color 1 1 1 ambient 1 diffuse 0 specular 0 "
             "checker 0 0 0 0.25\n%s",
             2.5 + m / 65536.0,
             box ? "box min -9.5 -1 -10 max 10 0 10 material m\n"
                 : "quad corner 0.25 0 -10 edge1 0 0 20 edge2 20 0 0 "
                   "material m\n");
    if (!parse(text, &scene_a))
        return -1;
    ppm_image a, b;
    view vw = { 1, 1, 1, -1, 0 };
    if (!CHECK(render(&scene_a, vw, 0, &a, NULL) == RT_OK))
        return -1;
    if (!CHECK(render(&scene_a, vw, 1, &b, NULL) == RT_OK)) {
        ppm_free(&a);
        return -1;
    }
    memcpy(fx, a.data, 3);
    memcpy(ref, b.data, 3);
    ppm_free(&a);
    ppm_free(&b);
    return 0;
}

void case_texture_edge_subulp(void)
{
    for (int box = 0; box <= 1; box++) {
        int wrong = 0, seen[2] = { 0, 0 };
        for (int m = -2; m <= 2; m++) {
            uint8_t a[3], b[3];
            if (edge_pixel(m, box, a, b) != 0)
                return;
            wrong += pdiff(a, b) != 0;
            seen[a[0] != 0] = 1;
        }
        if (!CHECK(wrong == 0 && seen[0] && seen[1]))
            printf("    %s: %d of 5 hits in another cell than the "
                   "reference's; black %s, white %s\n",
                   box ? "box" : "quad", wrong, seen[0] ? "seen" : "not seen",
                   seen[1] ? "seen" : "not seen");
    }
}

/* Bump lattices of 1, 2 and 3 ulps: stepped one ulp at a time as above,
 * each pixel (Lambert only, so it follows the perturbed normal) is within
 * 2 levels of the reference's, and the 12 pixels are not all alike (the
 * lattice changes every ulp or two, as the reference's does). */
void case_bump_lattice_1ulp(void)
{
    for (int ulps = 1; ulps <= 3; ulps++) {
        for (int far = 0; far <= 1; far++) {
            char mat[128];
            snprintf(mat, sizeof mat,
                     "ambient 0 diffuse 1 specular 0 bump 1 %.10f",
                     ulps / 65536.0);
            int worst = 0, lo = 255, hi = 0;
            for (int k = 0; k < 12; k++) {
                uint8_t a[3], b[3];
                if (floor_pixel(k, far, mat, a, b) != 0)
                    return;
                if (pdiff(a, b) > worst)
                    worst = pdiff(a, b);
                lo = a[0] < lo ? a[0] : lo;
                hi = a[0] > hi ? a[0] : hi;
            }
            if (!CHECK(worst <= 2 && hi - lo > 16))
                printf("    bump %d ulps%s: off by %d levels from the "
                       "reference; pixels %d .. %d\n",
                       ulps, far ? ", far" : "", worst, lo, hi);
        }
    }
}

/* Bump normals against the reference's noise at the same Q16.16 point:
 * lattices of 64 ulps to 100 units, amplitudes 0.5 to 4, 2,000 points
 * each, on a sphere 20,000 units from the origin. The core forms the
 * noise and the fraction in the cell with 30 fraction bits: its normal is
 * within 2^-22 of the reference's. In Q16.16, with the fraction from the
 * rounded reciprocal of the size, it was up to 3e-4 off on large
 * lattices (random scene 5040: refracted glass of a strong bump took
 * another path). */
void case_bump_normal_precision(void)
{
    static const double sizes[] = { 64 / 65536.0, 1000 / 65536.0, 1,
                                    9.66028699, 100 };
    static const double amps[] = { 0.5, 1.5, 4 };
    uint64_t st = 0x5DEECE66Dull;
    double worst = 0;
    for (int si = 0; si < 5; si++)
        for (int ai = 0; ai < 3; ai++) {
            char text[512];
            snprintf(text, sizeof text,
                     "camera eye 0 0 -5 look 0 0 0\n"
                     "material m color 1 1 1 bump %.6f %.10f\n"
                     "sphere center 20000.3 -35.7 12.1 radius 3 "
                     "material m\n", amps[ai], sizes[si]);
            if (!parse(text, &scene_a))
                return;
            const rt_material *m = &scene_a.mat[0];
            const rt_object *o = &scene_a.obj[0];
            for (int k = 0; k < 2000; k++) {
                const fx_vec3 p = fx_v3(
                    o->u.origin.x + (fx_t)(th_rnd64(&st) % 400000) - 200000,
                    o->u.origin.y + (fx_t)(th_rnd64(&st) % 400000) - 200000,
                    o->u.origin.z + (fx_t)(th_rnd64(&st) % 400000) - 200000);
                const fx_dir3 n = fx_d3(0, FX_UONE, 0);
                const fx_dir3 c = rt_bump(m, o, p, n);
                const double z = F2D(m->bump_scale), amp = F2D(m->bump);
                const ref_vec3 u = { F2D(p.x - o->u.origin.x) / z,
                                     F2D(p.y - o->u.origin.y) / z,
                                     F2D(p.z - o->u.origin.z) / z };
                double b[3];
                for (int j = 0; j < 3; j++)
                    b[j] = amp * ref_noise((uint32_t)j + 1, u);
                b[1] += 1;
                const double l = sqrt(b[0] * b[0] + b[1] * b[1] +
                                      b[2] * b[2]);
                const double e = fmax(fabs(U2D(c.x) - b[0] / l),
                                      fmax(fabs(U2D(c.y) - b[1] / l),
                                           fabs(U2D(c.z) - b[2] / l)));
                worst = fmax(worst, e);
            }
        }
    if (!CHECK(worst < 1.0 / (1 << 22)) || verbose)
        printf("    bump normals within %.3g of the reference's\n", worst);
}

/* A texture or bump size below half an ulp rounds to 0: refused, at the
 * size, with the smallest size there is (2^-16, which 0.0000153 writes);
 * that size and 0.0000077 (which rounds up to it) are accepted. */
void case_texture_size_below_1ulp(void)
{
    static const struct {
        const char *field, *what;
    } f[] = {
        { "stripes x 0 0 0", "stripes width" },
        { "checker 0 0 0", "checker size" },
        { "checker3d 0 0 0", "checker3d size" },
        { "bump 0.5", "bump size" },
    };
    for (int i = 0; i < 4; i++) {
        static const char *const tiny[] = { "0.000007", "0.000001", "0",
                                            "-0.5" };
        static const char *const fine[] = { "0.0000153", "0.0000077" };
        char text[256], msg[128];
        snprintf(msg, sizeof msg, "%s must be at least 0.0000153 (2^-16, "
                 "the smallest Q16.16 step)", f[i].what);
        for (int k = 0; k < 4; k++) {
            snprintf(text, sizeof text, CAM "material t color 1 1 1 %s %s\n",
                     f[i].field, tiny[k]);
            expect_reject(text, RT_ERR_PARSE, msg);
        }
        for (int k = 0; k < 2; k++) {
            snprintf(text, sizeof text, CAM "material t color 1 1 1 %s %s\n",
                     f[i].field, fine[k]);
            if (parse(text, &scene_a)) {
                const rt_material *m = &scene_a.mat[1];
                CHECK_EQ(i == 3 ? m->bump_scale : m->tex_scale, 1);
            }
        }
    }
}
