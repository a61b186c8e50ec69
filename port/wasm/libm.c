/* SPDX-License-Identifier: MIT */
/*
 * libm.c: the maths of the host files the page reuses, where there is no
 * libm: the double reference renderer (port/posix/ref_render.c,
 * ref_shapes.c) and the OBJ reader's placement (port/posix/mesh_obj.c).
 * tan, pow, floor, fabs, copysign and fmax are bench/softref/libm.c's,
 * the small libm of the reference's bare-metal build, compiled here
 * unchanged. sqrt is WebAssembly's f64.sqrt, IEEE 754's correctly rounded
 * square root: the value the host's libm and softref's digit loop give, in
 * one instruction.
 */
#define sqrt softref_sqrt
#include "../../bench/softref/libm.c"
#undef sqrt

double sqrt(double x); /* math.h's was renamed with the rest above */

double sqrt(double x)
{
    return __builtin_sqrt(x);
}

double fmin(double x, double y)
{
    if (x != x)
        return y;
    if (y != y)
        return x;
    return x < y ? x : y;
}

/* pi / 2 in two parts (Cody and Waite): the first has 33 bits, so k times
 * it is exact for the small k of a rotation in degrees. */
#define PIO2_HI 1.57079632673412561417e+00
#define PIO2_LO 6.07710050650619224932e-11

/* sin(r) - r and cos(r) - 1 for r in [-pi/4, pi/4]: the Taylor series by
 * Horner's rule from its smallest term (the 13th is below 2^-60), the
 * leading term added last, so that the small rest keeps its bits. */
static double sin_rest(double r)
{
    double z = r * r, u = 0;
    for (int n = 13; n >= 1; n--)
        u = -z / ((2 * n) * (2 * n + 1)) * (1 + u);
    return r * u;
}

static double cos_rest(double r)
{
    double z = r * r, u = 0;
    for (int n = 13; n >= 1; n--)
        u = -z / ((2 * n - 1) * (2 * n)) * (1 + u);
    return u;
}

/* x = k pi/2 + r with |r| <= pi/4; returns r and the quadrant k mod 4. */
static double reduce(double x, int *quadrant)
{
    double k = floor(x / PI * 2 + 0.5);
    *quadrant = (int)((long long)k & 3);
    return (x - k * PIO2_HI) - k * PIO2_LO;
}

double sin(double x)
{
    int q;
    double r = reduce(x, &q);
    switch (q) {
    case 0: return r + sin_rest(r);
    case 1: return 1 + cos_rest(r);
    case 2: return -(r + sin_rest(r));
    default: return -(1 + cos_rest(r));
    }
}

double cos(double x)
{
    int q;
    double r = reduce(x, &q);
    switch (q) {
    case 0: return 1 + cos_rest(r);
    case 1: return -(r + sin_rest(r));
    case 2: return -(1 + cos_rest(r));
    default: return r + sin_rest(r);
    }
}

long long llround(double x)
{
    if (x < 0)
        return -llround(-x);
    double t = floor(x);
    return (long long)t + (x - t >= 0.5); /* x - t is exact */
}

long lround(double x)
{
    return (long)llround(x);
}
