/* SPDX-License-Identifier: MIT */
/*
 * randscene: writes one random scene, in the scene language, to stdout.
 *
 *   randscene SEED [--size | --jitter K]
 *
 * The same SEED gives the same scene on every host. Scenes cover the
 * parser's whole accepted range, as the randomized differential test
 * (tests/suite_random.sh) needs it: clusters anywhere up to +-30,000
 * units, scene scales from 1/100 to thousands of units, objects down to a
 * few ulp beside full-size ones, every primitive and cap variant, glass
 * up to ior 100, textures and bumps at odd and extreme scales (on
 * purpose textures down to 1 ulp, bumps to 64 ulps: docs/stability-cases.md
 * says why), lights anywhere including on surfaces (a sphere's skin, a
 * cone's apex, a quad, a box face), fields of view from 1 to 179.99
 * degrees and image shapes from 8:1 to 1:8. With --size it prints only
 * "W H", the image size the scene asks for, so a script can render it
 * small. With --jitter K (1 to 6) it writes the same scene with the eye
 * moved by 8 ulps along +x, -x, +y, -y, +z or -z: the documented
 * tolerance of a ray near a silhouette, which tools/random_test.sh allows
 * the core.
 *
 * Every object lies within 31,000 units of the eye: beyond the far plane
 * (32,767) the core shows the background by design
 * (docs/stability-cases.md, beyond_range_background), where the
 * reference, unbounded, shows the object. When eye and look are far
 * apart, the objects stand in front of the eye and the look point lies
 * near the other end of the range.
 *
 * Host-only test tool: it uses double, which the core never does.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng_state;

/* splitmix64: small, fast and the same everywhere. */
static uint64_t next_u64(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1). */
static double unit(void)
{
    return (double)(next_u64() >> 11) / 9007199254740992.0;
}

static double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }

static int below(int n) { return (int)(unit() * n); }

static int chance(double p) { return unit() < p; }

/* Log-uniform in [lo, hi], lo > 0. */
static double log_uniform(double lo, double hi)
{
    return lo * exp(unit() * log(hi / lo));
}

/* Clamps to the range the parser accepts, a little inside it. */
static double clamp_pos(double v)
{
    const double lim = 32000;
    return v < -lim ? -lim : (v > lim ? lim : v);
}

/* Prints a number as the parser reads it: decimal, no exponent. */
static void num(double v)
{
    if (v > -1e-9 && v < 1e-9)
        v = 0;
    printf(" %.8f", v);
}

/* An edge or extent, kept to 10,000 units: a cluster then reaches at most
 * about 29,000 units from its centre. */
static double clamp_len(double v)
{
    return v < -10000 ? -10000 : (v > 10000 ? 10000 : v);
}

static void vec(double x, double y, double z)
{
    num(x);
    num(y);
    num(z);
}

typedef struct {
    double x, y, z;
} v3;

static v3 rand_dir(void)
{
    for (;;) {
        v3 d = { uniform(-1, 1), uniform(-1, 1), uniform(-1, 1) };
        double l = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (l > 0.1 && l <= 1) {
            d.x /= l;
            d.y /= l;
            d.z /= l;
            return d;
        }
    }
}

/* How far from the cluster's centre the objects reach (as the
 * generator bounds them). */
static v3 centre;
static double reach;

static void extends(double x, double y, double z, double size)
{
    double dx = x - centre.x, dy = y - centre.y, dz = z - centre.z;
    double r = sqrt(dx * dx + dy * dy + dz * dz) + size;
    reach = r > reach ? r : reach;
}

/* A place a light may stand on: a point on some object's surface. */
static v3 surface[64];
static int n_surface;

static void on_surface(double x, double y, double z)
{
    if (n_surface < 64) {
        v3 p = { clamp_pos(x), clamp_pos(y), clamp_pos(z) };
        surface[n_surface++] = p;
    }
}

/* An object size: mostly a fraction of the scene's scale, sometimes a
 * few ulp or a thousandth of it. */
static double size_of(double scale)
{
    int r = below(10);
    if (r == 0)
        return (1 + below(8)) / 65536.0;
    double v = r == 1 ? scale * log_uniform(1e-4, 1e-2)
                      : scale * uniform(0.1, 1.2);
    return v < 2 / 65536.0 ? 2 / 65536.0 : v;
}

/* A texture or bump feature size: odd fractions of the scale, now and
 * then extreme (one or two ulp, or far larger than the object). */
static double feature_of(double scale, int bump)
{
    int r = below(12);
    if (r == 0)
        return (bump ? 64 + below(192) : 1 + below(2)) / 65536.0;
    double v = r == 1 ? scale * uniform(5, 50)
                      : scale * log_uniform(0.02, 0.7) * 1.0137;
    /* Bump lattices finer than 64 ulps are a documented limit
     * (docs/stability-cases.md), also in a scene a few hundred ulps wide. */
    const double least = (bump ? 64 : 1) / 65536.0;
    v = v < least ? least : v;
    return v > 30000 ? 30000 : v;
}

static void material(int i, double scale)
{
    printf("material m%d color", i);
    vec(unit(), unit(), unit());
    printf(" ambient");
    num(uniform(0, 0.3));
    printf(" diffuse");
    num(uniform(0, 1));
    printf(" specular");
    num(uniform(0, 1));
    printf(" shininess %d", 1 + below(chance(0.2) ? 1024 : 60));
    double kr = 0, kt = 0;
    if (chance(0.35))
        kr = uniform(0, 1);
    if (chance(0.35))
        kt = uniform(0, 1 - kr);
    if (kr > 0) {
        printf(" reflect");
        num(kr);
    }
    if (kt > 0) {
        static const double iors[] = { 1.001, 1.33, 1.5, 2.42, 5, 20, 100,
                                       0.5, 0.01, 0.9 };
        printf(" transparency");
        num(kt);
        printf(" ior");
        num(chance(0.2) ? uniform(0.01, 100) : iors[below(10)]);
    }
    int tex = below(5);
    if (tex == 1 || tex == 2 || tex == 3) {
        static const char *const kw[] = { "stripes", "checker", "checker3d" };
        printf(" %s", kw[tex - 1]);
        if (tex == 1)
            printf(" %c", "xyz"[below(3)]);
        vec(unit(), unit(), unit());
        num(feature_of(scale, 0));
    }
    if (chance(0.25)) {
        printf(" bump");
        num(uniform(0, 4));
        num(feature_of(scale, 1));
    }
    printf("\n");
}

static void object(int n_mat, v3 c, double scale)
{
    v3 p = { clamp_pos(c.x + scale * uniform(-2, 2)),
             clamp_pos(c.y + scale * uniform(-1, 1)),
             clamp_pos(c.z + scale * uniform(-2, 2)) };
    int mat = below(n_mat);
    switch (below(5)) {
    case 0: {
        double r = size_of(scale);
        printf("sphere center");
        vec(p.x, p.y, p.z);
        printf(" radius");
        num(r);
        v3 d = rand_dir();
        on_surface(p.x + r * d.x, p.y + r * d.y, p.z + r * d.z);
        extends(p.x, p.y, p.z, r);
        break;
    }
    case 1: {
        double l = chance(0.3) ? scale * uniform(5, 20) : size_of(scale);
        if (l > 10000)
            l = 10000;
        v3 e1 = rand_dir(), e2 = rand_dir();
        double l2 = chance(0.5) ? l : size_of(scale);
        if (chance(0.4)) { /* a floor, edges along z and x */
            e1.x = 0, e1.y = 0, e1.z = 1;
            e2.x = 1, e2.y = 0, e2.z = 0;
            p.x = clamp_pos(p.x - l / 2);
            p.z = clamp_pos(p.z - l / 2);
            l2 = l;
        }
        printf("quad corner");
        vec(p.x, p.y, p.z);
        printf(" edge1");
        vec(clamp_len(l * e1.x), clamp_len(l * e1.y), clamp_len(l * e1.z));
        printf(" edge2");
        vec(clamp_len(l2 * e2.x), clamp_len(l2 * e2.y),
            clamp_len(l2 * e2.z));
        on_surface(p.x + 0.5 * (l * e1.x + l2 * e2.x),
                   p.y + 0.5 * (l * e1.y + l2 * e2.y),
                   p.z + 0.5 * (l * e1.z + l2 * e2.z));
        extends(p.x, p.y, p.z, l + (l2 < 17321 ? l2 : 17321));
        break;
    }
    case 2: {
        double sx = size_of(scale), sy = size_of(scale), sz = size_of(scale);
        printf("box min");
        vec(p.x, p.y, p.z);
        printf(" max");
        vec(clamp_pos(p.x + sx), clamp_pos(p.y + sy), clamp_pos(p.z + sz));
        on_surface(p.x + sx / 2, p.y + sy, p.z + sz / 2);
        extends(p.x, p.y, p.z, sx + sy + sz);
        break;
    }
    case 3: {
        double r = size_of(scale), h = size_of(scale);
        static const char *const caps[] = { "", " caps top", " caps bottom",
                                            " open", " caps both" };
        printf("cylinder base");
        vec(p.x, p.y, p.z);
        printf(" radius");
        num(r);
        printf(" height");
        num(h);
        printf("%s", caps[below(5)]);
        on_surface(p.x + r, p.y + h / 2, p.z);
        on_surface(p.x, p.y + h, p.z);
        extends(p.x, p.y, p.z, r + h);
        break;
    }
    default: {
        double h = size_of(scale), r = size_of(scale);
        if (chance(0.15)) /* flat: radius / height near the limit of 64 */
            r = h * uniform(40, 63.9);
        if (r > 63.9 * h)
            r = 63.9 * h;
        printf("cone base");
        vec(p.x, p.y, p.z);
        printf(" radius");
        num(r);
        printf(" height");
        num(h);
        if (chance(0.3))
            printf(" open");
        on_surface(p.x, p.y + h, p.z); /* the apex */
        on_surface(p.x + r, p.y, p.z);
        extends(p.x, p.y, p.z, r + h);
        break;
    }
    }
    printf(" material m%d\n", mat);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: randscene SEED [--size | --jitter K]\n");
        return 2;
    }
    rng_state = strtoull(argv[1], NULL, 10) * 0x2545F4914F6CDD1Dull + 1;
    static const int shapes[][2] = { { 48, 36 }, { 40, 40 }, { 64, 16 },
                                     { 16, 64 }, { 72, 9 },  { 9, 72 },
                                     { 56, 32 } };
    const int *wh = shapes[below(7)];
    if (argc > 2 && strcmp(argv[2], "--size") == 0) {
        printf("%d %d\n", wh[0], wh[1]);
        return 0;
    }
    int jitter = 0;
    if (argc > 3 && strcmp(argv[2], "--jitter") == 0)
        jitter = atoi(argv[3]);

    /* Where the cluster stands and how large it is. */
    v3 c = { 0, 0, 0 };
    double scale = log_uniform(0.01, 300);
    if (chance(0.3)) {
        c.x = uniform(-29000, 29000);
        c.y = uniform(-29000, 29000);
        c.z = uniform(-29000, 29000);
    }
    if (chance(0.1))
        scale = log_uniform(300, 2500);

    printf("# randscene %s\n", argv[1]);
    printf("image %d %d depth %d\n", wh[0], wh[1], below(6));

    /* The camera: usually a few scales away; sometimes eye and look far
     * apart (across the whole range), the objects then a few scales in
     * front of the eye; fov from 1 to 179.99 degrees. It is written after
     * the objects, when their reach is known. */
    v3 d = rand_dir();
    double dist = scale * uniform(2, 8);
    v3 eye = { clamp_pos(c.x + dist * d.x), clamp_pos(c.y + dist * d.y),
               clamp_pos(c.z + dist * d.z) };
    v3 look = c;
    if (chance(0.08)) {
        eye.x = -30000 + uniform(0, 500);
        look.x = 30000 - uniform(0, 500);
        double wx = look.x - eye.x, wy = look.y - eye.y, wz = look.z - eye.z;
        double wl = sqrt(wx * wx + wy * wy + wz * wz);
        c.x = eye.x + dist * wx / wl;
        c.y = eye.y + dist * wy / wl;
        c.z = eye.z + dist * wz / wl;
    }
    double fov;
    int f = below(10);
    fov = f == 0 ? uniform(1, 5) : (f == 1 ? uniform(170, 179.99)
                                           : uniform(20, 100));
    centre = c;
    printf("background");
    vec(unit(), unit(), unit());
    printf("\n");
    if (chance(0.5)) {
        printf("ambient");
        vec(uniform(0, 2), uniform(0, 2), uniform(0, 2));
        printf("\n");
    }
    if (chance(0.1))
        printf("shadows off\n");

    int n_mat = 1 + below(5);
    for (int i = 0; i < n_mat; i++)
        material(i, scale);
    int n_obj = 1 + below(8);
    for (int i = 0; i < n_obj; i++)
        object(n_mat, c, scale);

    /* Within the far plane: an eye too far for the objects' reach moves
     * towards the cluster's centre. */
    double ex = eye.x - c.x, ey = eye.y - c.y, ez = eye.z - c.z;
    double el = sqrt(ex * ex + ey * ey + ez * ez);
    if (el + reach > 31000 && el > 0) {
        double k = (31000 - reach > 0 ? 31000 - reach : 0) / el;
        eye.x = c.x + k * ex;
        eye.y = c.y + k * ey;
        eye.z = c.z + k * ez;
    }
    if (jitter >= 1 && jitter <= 6) {
        double j = (jitter % 2 ? 8.0 : -8.0) / 65536;
        if (jitter <= 2)
            eye.x += j;
        else if (jitter <= 4)
            eye.y += j;
        else
            eye.z += j;
    }
    printf("camera eye");
    vec(eye.x, eye.y, eye.z);
    printf(" look");
    vec(look.x, look.y, look.z);
    /* Keep up away from the view direction. */
    double vx = look.x - eye.x, vy = look.y - eye.y, vz = look.z - eye.z;
    double vl2 = vx * vx + vy * vy + vz * vz;
    if (vy * vy > 0.8 * vl2)
        printf(" up 1 0 0");
    printf(" fov");
    num(fov);
    printf("\n");

    int n_light = below(5);
    for (int i = 0; i < n_light; i++) {
        v3 l;
        if (n_surface > 0 && chance(0.4)) {
            l = surface[below(n_surface)];
        } else {
            v3 ld = rand_dir();
            double r = scale * uniform(1, 10);
            l.x = clamp_pos(c.x + r * ld.x);
            l.y = clamp_pos(c.y + r * ld.y);
            l.z = clamp_pos(c.z + r * ld.z);
        }
        printf("light");
        vec(l.x, l.y, l.z);
        if (chance(0.3)) {
            printf(" color");
            vec(uniform(0, 3), uniform(0, 3), uniform(0, 3));
        }
        printf("\n");
    }
    return 0;
}
