/* SPDX-License-Identifier: MIT */
/*
 * randscene: writes one random scene, in the scene language, to stdout.
 *
 *   randscene SEED [--size]
 *
 * The same SEED gives the same scene on every host. Scenes cover the
 * parser's whole accepted range, as the randomized differential test
 * (tests/suite_random.sh) needs it: clusters anywhere up to +-30,000
 * units, scene scales from 1/100 to thousands of units, objects down to a
 * few ulp beside full-size ones, every primitive and cap variant, glass
 * up to ior 100, textures and bumps at odd and extreme scales down to a
 * few ulp, lights anywhere including on surfaces (a sphere's skin, a cone's
 * apex, a quad, a box face), fields of view from 1 to 179.99 degrees and
 * image shapes from 8:1 to 1:8. With --size it prints only "W H", the
 * image size the scene asks for, so a script can render it small.
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

/* An edge or extent, kept inside the Q16.16 range. */
static double clamp_len(double v)
{
    return v < -16000 ? -16000 : (v > 16000 ? 16000 : v);
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
static double feature_of(double scale)
{
    int r = below(12);
    if (r == 0)
        return (1 + below(2)) / 65536.0;
    double v = r == 1 ? scale * uniform(5, 50)
                      : scale * log_uniform(0.02, 0.7) * 1.0137;
    v = v < 1 / 65536.0 ? 1 / 65536.0 : v;
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
        num(feature_of(scale));
    }
    if (chance(0.25)) {
        printf(" bump");
        num(uniform(0, 4));
        num(feature_of(scale));
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
        break;
    }
    case 1: {
        double l = chance(0.3) ? scale * uniform(5, 20) : size_of(scale);
        if (l > 16000)
            l = 16000;
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
        break;
    }
    case 2: {
        double sx = size_of(scale), sy = size_of(scale), sz = size_of(scale);
        printf("box min");
        vec(p.x, p.y, p.z);
        printf(" max");
        vec(clamp_pos(p.x + sx), clamp_pos(p.y + sy), clamp_pos(p.z + sz));
        on_surface(p.x + sx / 2, p.y + sy, p.z + sz / 2);
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
        break;
    }
    }
    printf(" material m%d\n", mat);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: randscene SEED [--size]\n");
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
     * apart (across the whole range); fov from 1 to 179.99 degrees. */
    v3 d = rand_dir();
    double dist = scale * uniform(2, 8);
    v3 eye = { clamp_pos(c.x + dist * d.x), clamp_pos(c.y + dist * d.y),
               clamp_pos(c.z + dist * d.z) };
    v3 look = c;
    if (chance(0.08)) {
        eye.x = -30000 + uniform(0, 500);
        look.x = 30000 - uniform(0, 500);
    }
    double fov;
    int f = below(10);
    fov = f == 0 ? uniform(1, 5) : (f == 1 ? uniform(170, 179.99)
                                           : uniform(20, 100));
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
