/* SPDX-License-Identifier: MIT */
/* Stability cases of issue 18's second round: glass of an extreme index
 * of refraction. */
#include "stability.h"

/* ==== Extreme index of refraction (class 5) ============================= */

/* A glass sphere before a striped wall on a checker floor. */
static const char glass_ball[] =
    "camera eye 0 1.2 -5 look 0 1 0 fov 35\n"
    "background 0.3 0.5 0.8\n"
    "light 3 6 -4\n"
    "material floor color 0.9 0.9 0.9 specular 0 checker 0.1 0.1 0.1 0.5\n"
    "material wall color 0.9 0.3 0.2 specular 0 stripes y 0.2 0.8 0.3 0.3\n"
    "material glass color 1 1 1 ambient 0 diffuse 0 specular 0.3 "
    "reflect 0.1 transparency 0.9 ior %s\n"
    "quad corner -10 0 -10 edge1 0 0 20 edge2 20 0 0 material floor\n"
    "quad corner -10 0 4 edge1 0 10 0 edge2 20 0 0 material wall\n"
    "sphere center 0 1 0 radius 1 material glass\n";

/* The glass sphere at ior 100 (the largest the parser takes), 50 and
 * 0.01 (the smallest: eta 100 on the way in). Inside a sphere of ior 100
 * a ray meets the far side at an angle whose sine is at most 1/100, the
 * sine of the critical angle: in the outer ring every decision is close
 * to it. k = 1 - eta^2 (1 - cos^2) multiplies the rounding of cos^2 by
 * eta^2 = 10^4, which made those decisions noise (30 outliers at 96x72,
 * 90 at 160x120, with Q16.16 directions). No speckles, and within 30 dB
 * of the reference (the image inside the ball is chaotic in both). */
void case_glass_ior_100_outer_ring(void)
{
    static const char *const iors[] = { "100", "50", "0.01" };
    for (int i = 0; i < 3; i++) {
        char text[1024], what[64];
        snprintf(text, sizeof text, glass_ball, iors[i]);
        if (!parse(text, &scene_a))
            return;
        static const int sizes[2][2] = { { 96, 72 }, { 160, 120 } };
        for (int k = 0; k < 2; k++) {
            snprintf(what, sizeof what, "ior %s at %dx%d", iors[i],
                     sizes[k][0], sizes[k][1]);
            expect_clean(&scene_a,
                         (view){ sizes[k][0], sizes[k][1], 1, -1, 0 }, 30,
                         what);
        }
    }
}
