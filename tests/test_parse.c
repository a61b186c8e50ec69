/* SPDX-License-Identifier: MIT */
/*
 * Tests for rt_parse: the number reader against exact rational rounding,
 * every statement of the scene format, every error with its position, the
 * limits, and robustness (prefixes, mutations, large inputs), with every
 * input in a heap block of exactly its length so ASan catches any read
 * past the end.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "harness.h"
#include "rt_parse.h"

typedef unsigned __int128 u128;

static uint64_t rng = 0x9E3779B97F4A7C15u;
static uint64_t rnd(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}
static unsigned rnd_below(unsigned n)
{
    return (unsigned)(rnd() % n);
}

/* Copies text into a block of exactly its length (ASan bounds). */
static char *exact_copy(const char *text, size_t len)
{
    char *b = malloc(len ? len : 1);
    memcpy(b, text, len);
    return b;
}

static rt_status fx_of(const char *str, fx_t *v, size_t *used)
{
    size_t n = strlen(str);
    char *b = exact_copy(str, n);
    rt_status st = rt_parse_fx(b, n, v, used);
    free(b);
    return st;
}

/* ---- Numbers: fixed cases ---------------------------------------------- */

typedef struct {
    const char *s;
    int ok;
    int64_t raw;
    size_t used;
} fx_case;

static const fx_case fx_cases[] = {
    {"0", 1, 0, 1},
    {"1", 1, 65536, 1},
    {"-1", 1, -65536, 2},
    {"+2", 1, 131072, 2},
    {"-0", 1, 0, 2},
    {"1.5", 1, 98304, 3},
    {".5", 1, 32768, 2},
    {"-.5", 1, -32768, 3},
    {"1.", 1, 65536, 2},
    {"0.1", 1, 6554, 3},  /* 6553.6 */
    {"0.9", 1, 58982, 3}, /* 58982.4 */
    {"-0.1", 1, -6554, 4},
    {"3.14159", 1, 205887, 7}, /* 205887.4 */
    {"000001.000", 1, 65536, 10},
    {"32767", 1, 2147418112, 5},
    {"-32768", 1, -2147483648LL, 6},
    {"32767.9999847412109375", 1, 2147483647, 22}, /* FX_MAX exactly */
    {"32767.99999", 1, 2147483647, 11},            /* 2^31 - 0.655 */
    {"32767.99999237060546874", 1, 2147483647, 23}, /* just below tie */
    {"32767.99999237060546875", 0, 0, 23},          /* tie: rounds out */
    {"32767.999995", 0, 0, 12},
    {"32768", 0, 0, 5},
    {"-32768.000001", 1, -2147483648LL, 13}, /* 0.066 ulp past */
    {"-32768.00000762939453124", 1, -2147483648LL, 24},
    {"-32768.00000762939453125", 0, 0, 24}, /* tie away: out of range */
    {"-32769", 0, 0, 6},
    {"99999999999", 0, 0, 11},
    /* Ties at half an ulp, 2^-17 = 0.00000762939453125: away from zero. */
    {"0.00000762939453125", 1, 1, 19},
    {"-0.00000762939453125", 1, -1, 20},
    {"0.00000762939453124999999999", 1, 0, 28},
    {"0.00000762939453125000000001", 1, 1, 28},
    {"0.00002288818359375", 1, 2, 19}, /* 1.5 ulp */
    {"-0.00002288818359375", 1, -2, 20},
    {"0.00003814697265625", 1, 3, 19}, /* 2.5 ulp */
    {"1.00000762939453125", 1, 65537, 19},
    /* The grammar stops at the first byte that cannot continue. */
    {"1e5", 1, 65536, 1},
    {"0x10", 1, 0, 1},
    {"1.5.3", 1, 98304, 3},
    {"2 3", 1, 131072, 1},
    {"7#c", 1, 458752, 1},
    /* No number. */
    {"", 0, 0, 0},
    {".", 0, 0, 0},
    {"+", 0, 0, 0},
    {"-.", 0, 0, 0},
    {"+-1", 0, 0, 0},
    {"nan", 0, 0, 0},
    {"inf", 0, 0, 0},
    {" 1", 0, 0, 0},
    /* 40 digits are fine, 41 are not. */
    {"1.000000000000000000000000000000000000000", 1, 65536, 41},
    {"0.0000000000000000000000000000000000000000", 0, 0, 42},
    {"1234567890123456789012345678901234567890", 0, 0, 40},
};

static void test_fx_fixed(void)
{
    for (size_t i = 0; i < sizeof fx_cases / sizeof fx_cases[0]; i++) {
        const fx_case *c = &fx_cases[i];
        fx_t v = 12345;
        size_t used = 999;
        rt_status st = fx_of(c->s, &v, &used);
        if (!th_check((st == RT_OK) == c->ok, __FILE__, __LINE__,
                      "rt_parse_fx status"))
            printf("    input '%s': got %d\n", c->s, st);
        if (c->ok && !th_check(v == c->raw, __FILE__, __LINE__,
                               "rt_parse_fx value"))
            printf("    input '%s': got %d, want %lld\n", c->s, v,
                   (long long)c->raw);
        if (!c->ok)
            CHECK_EQ(v, 12345); /* untouched on failure */
        if (!th_check(used == c->used, __FILE__, __LINE__, "rt_parse_fx used"))
            printf("    input '%s': used %zu, want %zu\n", c->s, used,
                   c->used);
    }
    /* used may be NULL. */
    fx_t v;
    CHECK_EQ(rt_parse_fx("2", 1, &v, NULL), RT_OK);
    CHECK_EQ(v, 131072);
    /* len bounds the text: "12" with len 1 is 1. */
    CHECK_EQ(rt_parse_fx("12", 1, &v, NULL), RT_OK);
    CHECK_EQ(v, 65536);
    CHECK_EQ(rt_parse_fx(NULL, 0, &v, NULL), RT_ERR_PARSE);
}

/* ---- Numbers: against exact rational rounding --------------------------- */

#define POW5_17 ((u128)762939453125ULL) /* 5^17: 2^-17 = 5^17 / 10^17 */

/* A decimal: sign, integer digits, fraction digits (as text). */
typedef struct {
    int neg;
    char ip[48], fp[48];
    size_t ni, nf;
} dec;

static void dec_text(const dec *d, char *out)
{
    size_t n = 0;
    if (d->neg)
        out[n++] = '-';
    memcpy(out + n, d->ip, d->ni);
    n += d->ni;
    if (d->nf || d->ni == 0) {
        out[n++] = '.';
        memcpy(out + n, d->fp, d->nf);
        n += d->nf;
    }
    out[n] = '\0';
}

/* Compares |d| with b / 10^17: -1, 0 or 1. Independent of the parser:
 * digit strings against the bound written out in decimal. */
static int dec_cmp(const dec *d, u128 b)
{
    u128 bi = b / (u128)100000000000000000ULL;
    uint64_t bf = (uint64_t)(b % (u128)100000000000000000ULL);
    char bfd[17];
    for (int i = 16; i >= 0; i--) {
        bfd[i] = (char)('0' + bf % 10);
        bf /= 10;
    }
    size_t s = 0;
    while (s < d->ni && d->ip[s] == '0')
        s++;
    if (d->ni - s > 30)
        return 1;
    u128 xi = 0;
    for (size_t i = s; i < d->ni; i++)
        xi = xi * 10 + (u128)(d->ip[i] - '0');
    if (xi != bi)
        return xi < bi ? -1 : 1;
    size_t n = d->nf > 17 ? d->nf : 17;
    for (size_t i = 0; i < n; i++) {
        char x = i < d->nf ? d->fp[i] : '0';
        char y = i < 17 ? bfd[i] : '0';
        if (x != y)
            return x < y ? -1 : 1;
    }
    return 0;
}

/* Checks the parser's answer for d against the rounding definition:
 * magnitude m is right iff (m - 1/2) ulp <= |d| < (m + 1/2) ulp, and an
 * error is right iff |d| rounds past the range. Returns 1 when right. */
static int fx_answer_ok(const dec *d, rt_status st, fx_t v)
{
    u128 lim = d->neg ? (u128)1 << 31 : ((u128)1 << 31) - 1;
    if (st != RT_OK)
        return dec_cmp(d, (2 * lim + 1) * POW5_17) >= 0;
    if ((v < 0) != d->neg && v != 0)
        return 0;
    u128 m = (u128)(v < 0 ? -(int64_t)v : (int64_t)v);
    if (m > 0 && dec_cmp(d, (2 * m - 1) * POW5_17) < 0)
        return 0;
    return dec_cmp(d, (2 * m + 1) * POW5_17) < 0;
}

/* A second, arithmetic oracle for fractions of up to 33 digits:
 * round(f * 2^16) = (floor(f * 2^17) + 1) / 2, in 128-bit integers. */
static int fx_answer_ok128(const dec *d, rt_status st, fx_t v)
{
    if (d->nf > 33 || d->ni > 12)
        return 1;
    u128 ip = 0, f = 0, p10 = 1;
    for (size_t i = 0; i < d->ni; i++)
        ip = ip * 10 + (u128)(d->ip[i] - '0');
    for (size_t i = 0; i < d->nf; i++) {
        f = f * 10 + (u128)(d->fp[i] - '0');
        p10 *= 10;
    }
    u128 m = (ip << 16) + (((f << 17) / p10 + 1) >> 1);
    u128 lim = d->neg ? (u128)1 << 31 : ((u128)1 << 31) - 1;
    if (m > lim)
        return st != RT_OK;
    int64_t want = d->neg ? -(int64_t)m : (int64_t)m;
    return st == RT_OK && v == want;
}

static void check_dec(const dec *d)
{
    char text[100];
    fx_t v = 0;
    size_t used = 0;
    dec_text(d, text);
    rt_status st = fx_of(text, &v, &used);
    int ok = fx_answer_ok(d, st, v) && fx_answer_ok128(d, st, v) &&
             used == strlen(text) && (st == RT_OK || st == RT_ERR_PARSE);
    if (!ok && !th_check(0, __FILE__, __LINE__, "rounding of a decimal"))
        printf("    '%s': status %d value %d used %zu\n", text, st, v, used);
}

static void dec_from_u128(dec *d, int neg, u128 x, size_t frac_digits)
{
    char buf[48];
    size_t n = 0;
    do {
        buf[n++] = (char)('0' + (int)(x % 10));
        x /= 10;
    } while (x);
    while (n <= frac_digits)
        buf[n++] = '0';
    d->neg = neg;
    d->nf = frac_digits;
    d->ni = n - frac_digits;
    for (size_t i = 0; i < d->ni; i++)
        d->ip[i] = buf[n - 1 - i];
    for (size_t i = 0; i < d->nf; i++)
        d->fp[i] = buf[frac_digits - 1 - i];
}

static void test_fx_random(void)
{
    long before = th_failed;
    dec d;
    /* Random digit strings of every shape up to 40 digits. */
    for (int it = 0; it < 200000; it++) {
        d.neg = (int)rnd_below(2);
        d.ni = rnd_below(7);
        d.nf = rnd_below((unsigned)(41 - d.ni));
        if (d.ni + d.nf == 0)
            d.ni = 1;
        for (size_t i = 0; i < d.ni; i++)
            d.ip[i] = (char)('0' + rnd_below(10));
        /* Integer parts near the range ends now and then. */
        if (d.ni == 5 && rnd_below(4) == 0)
            memcpy(d.ip, rnd_below(2) ? "32767" : "32768", 5);
        for (size_t i = 0; i < d.nf; i++)
            d.fp[i] = (char)('0' + rnd_below(10));
        check_dec(&d);
    }
    /* Exactly representable values, ties and their neighbours: with 25
     * fraction digits, v = m / 2^16 is m * 5^16 * 10^9 and a tie is
     * (2m + 1) * 5^17 * 10^8. */
    const u128 e8 = 100000000, e9 = 1000000000;
    for (int it = 0; it < 100000; it++) {
        uint64_t m = rnd() & 0xFFFFFFFFu;
        if (it % 8 == 0)
            m = rnd_below(4); /* near zero */
        else if (it % 8 == 1)
            m = 0x80000000u - rnd_below(4); /* near the range ends */
        int neg = (int)rnd_below(2);
        u128 exact = (u128)m * (POW5_17 / 5) * e9;
        u128 tie = (2 * (u128)m + 1) * POW5_17 * e8;
        u128 nudge = 1 + rnd_below(1000);
        u128 vals[5] = {exact, tie, tie - nudge, tie + nudge,
                        exact + nudge};
        for (int k = 0; k < 5; k++) {
            dec_from_u128(&d, neg, vals[k], 25);
            check_dec(&d);
        }
        /* The shortest form too: trailing zeros dropped. */
        dec_from_u128(&d, neg, exact, 25);
        while (d.nf > 0 && d.fp[d.nf - 1] == '0')
            d.nf--;
        check_dec(&d);
    }
    CHECK_EQ(th_failed, before);
}

/* ---- Scenes ------------------------------------------------------------- */

static rt_scene S;

static rt_status parse_n(const char *text, size_t n, rt_parse_error *e)
{
    char *b = exact_copy(text, n);
    rt_status st = rt_parse(b, n, &S, e);
    free(b);
    return st;
}

static rt_status parse(const char *text, rt_parse_error *e)
{
    return parse_n(text, strlen(text), e);
}

#define CAM "camera eye 0 0 -10 look 0 0 0\n"
#define RED "material red color 1 0 0\n"

/* Expects an error: status, line, column, message fragment. */
static void bad_at(int tl, const char *text, rt_status want, uint32_t line,
                   uint32_t col, const char *frag)
{
    rt_parse_error e;
    rt_status st = parse(text, &e);
    int ok = st == want && e.line == line && e.col == col &&
             strstr(e.msg, frag) != NULL && strlen(e.msg) < sizeof e.msg &&
             e.line_off + e.line_len <= strlen(text) &&
             e.col - 1 + e.tok_len <= e.line_len;
    if (!th_check(ok, __FILE__, tl, "scene error"))
        printf("    input \"%s\"\n    got %d at %u:%u (tok %zu) \"%s\"\n"
               "    want %d at %u:%u \"...%s...\"\n",
               text, st, e.line, e.col, e.tok_len, e.msg, want, line, col,
               frag);
}
#define BAD(text, st, line, col, frag) \
    bad_at(__LINE__, text, st, line, col, frag)
#define PE RT_ERR_PARSE

static int good_at(int tl, const char *text)
{
    rt_parse_error e;
    rt_status st = parse(text, &e);
    if (!th_check(st == RT_OK, __FILE__, tl, "scene parses"))
        printf("    input \"%s\"\n    got %d at %u:%u \"%s\"\n", text, st,
               e.line, e.col, e.msg);
    return st == RT_OK;
}
#define GOOD(text) good_at(__LINE__, text)

static const char full_scene[] =
    "# every statement\n"
    "image 640 480 spp 4 depth 3\n"
    "camera eye 0 5 -20 look 0 1 0 up 0 1 0 fov 45\n"
    "background 0.1 0.1 0.2\n"
    "ambient 0.5 0.5 0.5\n"
    "light 10 40 -5\n"
    "light -10 20 -5 color 2 1.5 0.5\n"
    "material plain color 0.5 0.5 0.5\n"
    "material all color 1 0.5 0.25 ambient 0.2 diffuse 0.7 specular 0.3 "
    "shininess 50 reflect 0.25 transparency 0.5 ior 1.5 bump 0.25 2\n"
    "material st color 1 1 1 stripes z 0 0 1 0.5\n"
    "material ch color 1 1 1 checker 0 0 0 2\n"
    "material c3 color 1 1 1 checker3d 0 1 0 0.75\n"
    "sphere center 1 2 3 radius 1.5 material all\n"
    "quad corner -20 0 -20 edge1 40 0 0 edge2 0 0 40 material ch\n"
    "box min -1 0 -1 max 1 2 1 material c3\n"
    "cylinder base 3 0 0 radius 1 height 3 material st\n"
    "cylinder base 4 0 0 radius 1 height 3 material st open\n"
    "cylinder base 5 0 0 radius 1 height 3 material st caps top\n"
    "cylinder base 6 0 0 radius 1 height 3 material st caps bottom\n"
    "cylinder base 7 0 0 radius 1 height 3 material st caps none\n"
    "cone base -3 0 0 radius 1 height 2 material plain\n"
    "cone material plain height 2 radius 1 base -4 0 0 open\n";

static void test_full_scene(void)
{
    rt_parse_error e;
    memset(&S, 0xA5, sizeof S);
    CHECK_EQ(parse(full_scene, &e), RT_OK);
    CHECK_EQ(S.width, 640);
    CHECK_EQ(S.height, 480);
    CHECK_EQ(S.spp, 4);
    CHECK_EQ(S.depth, 3);
    CHECK_EQ(S.cam.eye.y, FX_INT(5));
    CHECK_EQ(S.cam.eye.z, FX_INT(-20));
    CHECK_EQ(S.cam.look.y, FX_ONE);
    CHECK_EQ(S.cam.fov, FX_INT(45));
    CHECK_EQ(S.background.r, 6554);
    CHECK_EQ(S.background.b, 13107);
    CHECK_EQ(S.ambient.g, FX_HALF);
    CHECK_EQ(S.n_lights, 2);
    CHECK_EQ(S.light[0].pos.x, FX_INT(10));
    CHECK_EQ(S.light[0].color.g, FX_ONE);
    CHECK_EQ(S.light[1].pos.x, FX_INT(-10));
    CHECK_EQ(S.light[1].color.r, FX_INT(2));
    CHECK_EQ(S.light[1].color.g, 98304);
    CHECK_EQ(S.n_materials, 5);
    const rt_material *m = &S.mat[0];
    CHECK_EQ(m->ambient, 6554);
    CHECK_EQ(m->diffuse, 58982);
    CHECK_EQ(m->specular, FX_HALF);
    CHECK_EQ(m->shininess, 10);
    CHECK_EQ(m->reflect, 0);
    CHECK_EQ(m->transparency, 0);
    CHECK_EQ(m->ior, FX_ONE);
    CHECK_EQ(m->texture, RT_TEX_NONE);
    CHECK_EQ(m->bump, 0);
    m = &S.mat[1];
    CHECK_EQ(m->color.g, FX_HALF);
    CHECK_EQ(m->color.b, FX_ONE / 4);
    CHECK_EQ(m->ambient, 13107);
    CHECK_EQ(m->diffuse, 45875);
    CHECK_EQ(m->specular, 19661);
    CHECK_EQ(m->shininess, 50);
    CHECK_EQ(m->reflect, FX_ONE / 4);
    CHECK_EQ(m->transparency, FX_HALF);
    CHECK_EQ(m->ior, 98304);
    CHECK_EQ(m->bump, FX_ONE / 4);
    CHECK_EQ(m->bump_scale, FX_INT(2));
    CHECK_EQ(m->bump_rcp, 0xFFFFFFFFu / (uint32_t)FX_INT(2)); /* prepared */
    m = &S.mat[2];
    CHECK_EQ(m->texture, RT_TEX_STRIPES);
    CHECK_EQ(m->axis, 2);
    CHECK_EQ(m->color2.b, FX_ONE);
    CHECK_EQ(m->color2.r, 0);
    CHECK_EQ(m->tex_scale, FX_HALF);
    CHECK_EQ(m->tex_rcp, 0xFFFFFFFFu / (uint32_t)FX_HALF);
    CHECK_EQ(S.mat[3].texture, RT_TEX_CHECKER);
    CHECK_EQ(S.mat[3].tex_scale, FX_INT(2));
    CHECK_EQ(S.mat[4].texture, RT_TEX_CHECKER3D);
    CHECK_EQ(S.mat[4].color2.g, FX_ONE);
    CHECK_EQ(S.n_objects, 10);
    const rt_object *o = &S.obj[0];
    CHECK_EQ(o->kind, RT_SPHERE);
    CHECK_EQ(o->material, 1);
    CHECK_EQ(o->u.sphere.center.z, FX_INT(3));
    CHECK_EQ(o->u.sphere.radius, 98304);
    CHECK_EQ(o->br, 98304); /* rt_object_prepare ran */
    o = &S.obj[1];
    CHECK_EQ(o->kind, RT_QUAD);
    CHECK_EQ(o->material, 3);
    CHECK_EQ(o->u.quad.edge1.x, FX_INT(40));
    CHECK_EQ(o->u.quad.edge2.z, FX_INT(40));
    /* edge1 x edge2 = (40,0,0) x (0,0,40) */
    CHECK_EQ(o->u.quad.normal.y, -FX_UONE);
    o = &S.obj[2];
    CHECK_EQ(o->kind, RT_BOX);
    CHECK_EQ(o->u.box.min.x, -FX_ONE);
    CHECK_EQ(o->u.box.max.y, FX_INT(2));
    CHECK_EQ(o->material, 4);
    for (int i = 3; i <= 7; i++) {
        CHECK_EQ(S.obj[i].kind, RT_CYLINDER);
        CHECK_EQ(S.obj[i].u.upright.height, FX_INT(3));
        CHECK_EQ(S.obj[i].material, 2);
    }
    CHECK_EQ(S.obj[3].caps, RT_CAP_BOTTOM | RT_CAP_TOP);
    CHECK_EQ(S.obj[3].convex, 1);
    CHECK_EQ(S.obj[4].caps, 0);
    CHECK_EQ(S.obj[4].convex, 1); /* open, but its solid is convex */
    CHECK_EQ(S.obj[5].caps, RT_CAP_TOP);
    CHECK_EQ(S.obj[6].caps, RT_CAP_BOTTOM);
    CHECK_EQ(S.obj[7].caps, 0);
    CHECK_EQ(S.obj[8].kind, RT_CONE);
    CHECK_EQ(S.obj[8].caps, RT_CAP_BOTTOM);
    CHECK_EQ(S.obj[8].u.upright.radius, FX_ONE);
    CHECK_EQ(S.obj[9].kind, RT_CONE);
    CHECK_EQ(S.obj[9].caps, 0);
    CHECK_EQ(S.obj[9].u.upright.base.x, FX_INT(-4));
    CHECK_EQ(S.obj[9].material, 0);
}

static void test_defaults_and_layout(void)
{
    rt_parse_error e;
    /* The smallest scene: a camera; no objects renders the background. */
    CHECK(GOOD("camera eye 0 0 -10 look 0 0 0"));
    CHECK_EQ(S.width, 320);
    CHECK_EQ(S.height, 240);
    CHECK_EQ(S.spp, 1);
    CHECK_EQ(S.depth, RT_MAX_DEPTH);
    CHECK_EQ(S.cam.fov, FX_INT(60));
    CHECK_EQ(S.cam.up.y, FX_ONE);
    CHECK_EQ(S.ambient.r, FX_ONE);
    CHECK_EQ(S.background.r, 0);
    CHECK_EQ(S.n_objects, 0);
    CHECK_EQ(S.n_lights, 0);
    /* A material built in C from rt_material_defaults() equals the parsed
     * one, and the defaults are the documented decimals. */
    CHECK(GOOD("material m color 0.5 0.25 1\n" CAM));
    {
        rt_material m;
        rt_material_defaults(&m);
        m.color.r = FX_CONST(0.5);
        m.color.g = FX_CONST(0.25);
        m.color.b = FX_CONST(1.0);
        CHECK_EQ(rt_material_prepare(&m), RT_OK);
        CHECK(memcmp(&m, &S.mat[0], sizeof m) == 0);
        CHECK_EQ(m.ambient, FX_CONST(0.1));
        CHECK_EQ(m.diffuse, FX_CONST(0.9));
        CHECK_EQ(m.specular, FX_CONST(0.5));
        CHECK_EQ(m.shininess, 10);
        CHECK_EQ(m.ior, FX_CONST(1.0));
        CHECK_EQ(m.reflect + m.transparency + m.bump + m.texture, 0);
    }
    /* Statements in any order, fields in any order, blank lines, tabs,
     * comments glued to tokens, CRLF, a byte order mark. */
    CHECK(GOOD("\xEF\xBB\xBF# bom\r\n\r\n" CAM));
    CHECK_EQ(parse("\xEF\xBB\xBFsphre material m", &e), RT_ERR_PARSE);
    CHECK_EQ(e.col, 1);
    CHECK_EQ(e.line_off, 3);
    CHECK(GOOD("material m color 1 1 1\r\n"
               "\t sphere\tmaterial m radius 2 center 1 2 3#glued\r\n"
               "   # indented comment\n"
               "light 1 2 3\n"
               "camera fov 30 look 0 0 0 eye 0 0 5\r\n"));
    CHECK_EQ(S.obj[0].u.sphere.radius, FX_INT(2));
    CHECK_EQ(S.obj[0].u.sphere.center.z, FX_INT(3));
    CHECK_EQ(S.cam.fov, FX_INT(30));
    /* A last line without a newline, and a lone CR before the end. */
    CHECK(GOOD(CAM "light 1 2 3"));
    CHECK(GOOD(CAM "light 1 2 3\r"));
    /* Line continuation, with comments after the backslash. */
    CHECK(GOOD(CAM "material m color 1 1 1 \\\n"
                   "   specular 0.25 \\   # more\n"
                   "   shininess 99\n"
                   "sphere center 0 0 0 \\\r\n radius 1 material m\n"));
    CHECK_EQ(S.mat[0].shininess, 99);
    CHECK_EQ(S.mat[0].specular, FX_ONE / 4);
    CHECK_EQ(S.n_objects, 1);
    /* Non-ASCII text and control bytes are fine inside comments. */
    CHECK(GOOD(CAM "# caf\xC3\xA9 \x01\x7F\r\n"));
    /* Names: letters, digits, '_', '-', up to RT_MAX_NAME bytes. */
    CHECK(GOOD(CAM "material _a-1 color 1 1 1\nsphere center 0 0 0 "
                   "radius 1 material _a-1\n"));
    char buf[256];
    snprintf(buf, sizeof buf,
             CAM "material %.*s color 1 1 1\nbox min 0 0 0 max 1 1 1 "
                 "material %.*s\n",
             RT_MAX_NAME, "abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyz",
             RT_MAX_NAME, "abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyz");
    CHECK(GOOD(buf));
    /* Names are case-sensitive; so are keywords. */
    BAD(CAM "material A color 1 1 1\nsphere center 0 0 0 radius 1 "
            "material a\n",
        PE, 3, 39, "material 'a' is not defined");
    BAD("Camera eye 0 0 -1 look 0 0 0", PE, 1, 1, "unknown keyword 'Camera'");
    /* Limits that pass: image and spp extremes, depth 0, fov near 0 and
     * 180, colour extremes, bump 0 (none) and 4. */
    char img[64];
    snprintf(img, sizeof img, CAM "image %d %d spp %d depth 0",
             RT_MAX_WIDTH, RT_MAX_HEIGHT, RT_MAX_SPP_SIDE * RT_MAX_SPP_SIDE);
    CHECK(GOOD(img));
    CHECK_EQ(S.width, RT_MAX_WIDTH);
    CHECK_EQ(S.depth, 0);
    CHECK(GOOD(CAM "image 1 1 spp 9"));
    CHECK(GOOD("camera eye 0 0 -1 look 0 0 0 fov 179.9999"));
    CHECK(GOOD("camera eye 0 0 -1 look 0 0 0 fov 0.00002"));
    CHECK_EQ(S.cam.fov, 1);
    CHECK(GOOD(CAM "light 0 0 0 color 16 0 16\nambient 16 16 0"));
    CHECK(GOOD(CAM "material m color 0 0 0 bump 0 1 reflect 1\n"));
    CHECK(GOOD(CAM "material m color 1 1 1 bump 4 0.001 transparency 1 "
                   "ior 0.01\n"));
    CHECK(GOOD(CAM "material m color 1 1 1 ior 100 reflect 0.3 "
                   "transparency 0.7 shininess 1024\n"));
    /* Camera: looking straight down is fine with another up. */
    CHECK(GOOD("camera eye 0 10 0 look 0 0 0 up 0 0 1"));
    /* Extreme coordinates are exact in the parallel test. */
    CHECK(GOOD("camera eye -32768 -32768 -32768 look 32767.99998 32767 "
               "32767.5 up -32768 32767 0"));
    BAD("camera eye -32768 -32768 -32768 look 32767 32767 32767 "
        "up -32768 -32768 -32768",
        PE, 1, 56, "parallel");
}

static void test_statement_errors(void)
{
    BAD("sphre", PE, 1, 1,
        "unknown keyword 'sphre' (expected one of: image light camera "
        "background ambient shadows material sphere quad box cylinder "
        "cone mesh)");
    /* shadows on|off, once. */
    {
        static rt_scene sh;
        rt_parse_error e;
        CHECK_EQ(rt_parse(CAM "shadows off\n", strlen(CAM "shadows off\n"),
                          &sh, &e), RT_OK);
        CHECK_EQ(sh.shadows, 0);
        CHECK_EQ(rt_parse(CAM, strlen(CAM), &sh, &e), RT_OK);
        CHECK_EQ(sh.shadows, 1);
    }
    BAD(CAM "shadows maybe", PE, 2, 9, "'shadows' needs 'on' or 'off'");
    BAD(CAM "shadows on\nshadows off", PE, 3, 1, "second 'shadows'");
    BAD(CAM "shadows on off", PE, 2, 12, "");
    BAD("\n\n  42 1 2", PE, 3, 3, "unknown keyword '42'");
    /* The camera. */
    BAD("", PE, 1, 1, "no camera statement");
    BAD("# only a comment", PE, 1, 17, "no camera statement");
    BAD(RED, PE, 1, 25, "no camera statement");
    BAD(RED "\n", PE, 2, 1, "no camera statement");
    BAD("camera eye 0 0 0 look 0 0 0", PE, 1, 18,
        "camera look must differ from eye");
    BAD("camera eye 0 5 0 look 0 0 0", PE, 1, 1, "default up (0 1 0)");
    BAD("camera eye 0 0 -1 look 0 0 0 up 0 0 2", PE, 1, 30,
        "camera up is parallel to the view direction");
    BAD("camera eye 0 0 -1 look 0 0 0 up 0 0 0", PE, 1, 30,
        "camera up must not be zero");
    BAD("camera look 0 0 0", PE, 1, 1, "missing 'eye' in camera");
    BAD("camera eye 0 0 0", PE, 1, 1, "missing 'look' in camera");
    BAD("camera eye 0 0 -1 look 0 0 0 fov 0", PE, 1, 34,
        "fov must be in (0, 180)");
    BAD("camera eye 0 0 -1 look 0 0 0 fov 180", PE, 1, 34, "fov must be");
    BAD("camera eye 0 0 -1 look 0 0 0 fov -5", PE, 1, 34, "fov must be");
    BAD("camera eye 0 0 -1 look 0 0 0 eye 1 1 1", PE, 1, 30,
        "'eye' given twice in camera");
    BAD("camera eye 0 0 look 0 0 0", PE, 1, 16,
        "'eye' needs 3 numbers (x y z); got 'look'");
    BAD("camera eye 0 0 -1 look 0 0 0 up", PE, 1, 32,
        "'up' needs 3 numbers (x y z); got end of line");
    BAD("camera eye 0 0 -1 look 0 0 0 zoom 2", PE, 1, 30,
        "unknown field 'zoom' in camera (expected one of: eye look up fov)");
    BAD(CAM "\n" CAM, PE, 3, 1,
        "second 'camera' statement (the first is on line 1)");
    /* image. */
    BAD("image 0 240", PE, 1, 7,
        "width must be a whole number in 1 .. 4096 (RT_MAX_WIDTH)");
    BAD("image 4097 240", PE, 1, 7, "width must be a whole number in 1 ..");
    BAD("image 320 99999999999999", PE, 1, 11,
        "height must be a whole number in 1 .. 4096 (RT_MAX_HEIGHT)");
    BAD("image 320.5 240", PE, 1, 7, "got '320.5'");
    BAD("image -1 240", PE, 1, 7, "width must be a whole number");
    BAD("image 320", PE, 1, 10,
        "'image' needs a whole number (height); got end of line");
    BAD("image wide 240", PE, 1, 7, "'image' needs a whole number (width)");
    BAD("image 320 240 spp 2", PE, 1, 19,
        "spp must be a square n*n with n <= RT_MAX_SPP_SIDE: 1, 4, 9 or 16");
    BAD("image 320 240 spp 0", PE, 1, 19, "spp must be a whole number in 1");
    BAD("image 320 240 spp 25", PE, 1, 19, "spp must be a whole number in 1");
    BAD("image 320 240 depth 6", PE, 1, 21,
        "depth must be a whole number in 0 .. 5 (RT_MAX_DEPTH)");
    BAD("image 320 240 4", PE, 1, 15,
        "unexpected number '4' in image (expected a field name: spp depth)");
    BAD("image 320 240 spp 4 spp 4", PE, 1, 21, "'spp' given twice");
    BAD("image 1 1\nimage 2 2", PE, 2, 1, "second 'image' statement");
    /* background, ambient, light. */
    BAD("background 1 1", PE, 1, 15,
        "'background' needs 3 numbers (r g b); got end of line");
    BAD("background 1 1 1 1", PE, 1, 18,
        "unexpected '1' at the end of background");
    BAD("background 1 1 1.5", PE, 1, 16, "background must be in [0, 1]");
    BAD("background -0.1 0 0", PE, 1, 12, "background must be in [0, 1]");
    BAD("ambient 17 0 0", PE, 1, 9, "ambient must be in [0, 16]");
    BAD("ambient 1 1 1\nambient 1 1 1", PE, 2, 1, "second 'ambient'");
    BAD("light 1 2", PE, 1, 10, "'light' needs 3 numbers (x y z)");
    BAD("light 1 2 3 color 1 1 16.5", PE, 1, 23, "color must be in [0, 16]");
    BAD("light 1 2 3 colour 1 1 1", PE, 1, 13,
        "unknown field 'colour' in light (expected one of: color)");
    BAD("light 1 2 3\nlight 1 2 3\nlight 1 2 3\nlight 1 2 3\nlight 1 2 3",
        RT_ERR_CAPACITY, 5, 1, "too many lights (RT_MAX_LIGHTS is 4)");
}

static void test_material_errors(void)
{
    BAD("material", PE, 1, 9, "'material' needs a name");
    BAD("material 1x color 1 1 1", PE, 1, 10, "got '1x'");
    BAD("material a.b color 1 1 1", PE, 1, 10, "'material' needs a name");
    /* A forgotten name: "color" is taken as the name. */
    BAD("material color 1 1 1", PE, 1, 16,
        "unexpected number '1' in material (expected a field name: color");
    /* Field names are fine as material names. */
    CHECK(GOOD(CAM "material checker color 1 1 1 checker 0 0 0 1\n"
                   "sphere center 0 0 0 radius 1 material checker"));
    BAD("material x", PE, 1, 1, "missing 'color' in material");
    BAD("material abcdefghijklmnopqrstuvwx color 1 1 1", RT_ERR_CAPACITY, 1,
        10, "material name longer than RT_MAX_NAME (23 bytes)");
    BAD(RED RED, PE, 2, 10, "material 'red' is already defined");
    BAD("material x colour 1 1 1", PE, 1, 12,
        "unknown field 'colour' in material (expected one of: color ambient "
        "diffuse specular shininess reflect transparency ior stripes checker "
        "checker3d bump)");
    BAD("material x color 1 1 1 color 1 1 1", PE, 1, 24,
        "'color' given twice in material");
    BAD("material x color 1 0 2", PE, 1, 22, "color must be in [0, 1]");
    BAD("material x color 1 1 1 diffuse 1.5", PE, 1, 32,
        "diffuse must be in [0, 1]");
    BAD("material x color 1 1 1 ambient -0.5", PE, 1, 32, "ambient must be");
    BAD("material x color 1 1 1 specular 2", PE, 1, 33, "specular must be");
    BAD("material x color 1 1 1 reflect 1.01", PE, 1, 32, "reflect must be");
    BAD("material x color 1 1 1 transparency 9", PE, 1, 37,
        "transparency must be in [0, 1]");
    BAD("material x color 1 1 1 shininess 0", PE, 1, 34,
        "shininess must be a whole number in 1 .. 1024");
    BAD("material x color 1 1 1 shininess 1025", PE, 1, 34, "1 .. 1024");
    BAD("material x color 1 1 1 shininess 10.5", PE, 1, 34, "got '10.5'");
    BAD("material x color 1 1 1 ior 0", PE, 1, 28,
        "ior must be in [0.01, 100]");
    BAD("material x color 1 1 1 ior 100.001", PE, 1, 28, "ior must be");
    BAD("material x color 1 1 1 reflect 0.5 transparency 0.6", PE, 1, 36,
        "reflect + transparency must be <= 1");
    BAD("material x color 1 1 1 transparency 0.6 reflect 0.5", PE, 1, 41,
        "reflect + transparency must be <= 1");
    BAD("material x color 1 1 1 stripes w 1 1 1 1", PE, 1, 32,
        "'stripes' needs an axis (x, y or z); got 'w'");
    BAD("material x color 1 1 1 stripes", PE, 1, 31, "got end of line");
    BAD("material x color 1 1 1 stripes x 1 1 1 0", PE, 1, 40,
        "stripes width must be at least 0.0000153 (2^-16, the smallest "
        "Q16.16 step)");
    /* A positive size below half an ulp rounds to 0: the same limit, at
     * the size. */
    BAD("material x color 1 1 1 stripes x 1 1 1 0.000007", PE, 1, 40,
        "stripes width must be at least 0.0000153");
    BAD("material x color 1 1 1 stripes x 1 1 1", PE, 1, 39,
        "'stripes' needs a number (width); got end of line");
    BAD("material x color 1 1 1 checker 1 1 1 -1", PE, 1, 38,
        "checker size must be at least 0.0000153");
    BAD("material x color 1 1 1 checker 1 1 1 0.000001", PE, 1, 38,
        "checker size must be at least 0.0000153 (2^-16, the smallest "
        "Q16.16 step)");
    BAD("material x color 1 1 1 checker3d 1 1 1 0.0000076", PE, 1, 40,
        "checker3d size must be at least 0.0000153");
    BAD("material x color 1 1 1 checker3d 1 1 2 1", PE, 1, 38,
        "checker3d must be in [0, 1]");
    BAD("material x color 1 1 1 checker 0 0 0 1 stripes x 0 0 0 1", PE, 1,
        40, "a material has at most one texture");
    BAD("material x color 1 1 1 checker3d 0 0 0 1 checker 0 0 0 1", PE, 1,
        42, "at most one texture");
    BAD("material x color 1 1 1 checker 0 0 0 1 checker 0 0 0 1", PE, 1, 40,
        "'checker' given twice");
    BAD("material x color 1 1 1 bump 5 1", PE, 1, 29,
        "bump amplitude must be in [0, 4]");
    BAD("material x color 1 1 1 bump 0.5 0", PE, 1, 33,
        "bump size must be at least 0.0000153");
    BAD("material x color 1 1 1 bump 0.5 0.000005", PE, 1, 33,
        "bump size must be at least 0.0000153 (2^-16, the smallest Q16.16 "
        "step)");
    BAD("material x color 1 1 1 bump 0.5", PE, 1, 32,
        "'bump' needs a number (size)");
    /* Capacity. */
    char *buf = malloc(64 * (RT_MAX_MATERIALS + 2));
    size_t n = (size_t)sprintf(buf, CAM);
    for (int i = 0; i < RT_MAX_MATERIALS; i++)
        n += (size_t)sprintf(buf + n, "material m%d color 1 1 1\n", i);
    CHECK(GOOD(buf));
    CHECK_EQ(S.n_materials, RT_MAX_MATERIALS);
    sprintf(buf + n, "material one-more color 1 1 1\n");
    BAD(buf, RT_ERR_CAPACITY, RT_MAX_MATERIALS + 2, 1,
        "too many materials (RT_MAX_MATERIALS is 32)");
    free(buf);
}

static void test_object_errors(void)
{
    BAD(CAM "sphere center 0 0 0 radius 1 material red", PE, 2, 39,
        "material 'red' is not defined (materials must be defined before "
        "use)");
    BAD(CAM "sphere center 0 0 0 radius 1 material red\n" RED, PE, 2, 39,
        "before use");
    BAD(CAM RED "sphere center 0 0 0 material red", PE, 3, 1,
        "missing 'radius' in sphere");
    BAD(CAM RED "sphere radius 1 material red", PE, 3, 1,
        "missing 'center' in sphere");
    BAD(CAM RED "sphere center 0 0 0 radius 1", PE, 3, 1,
        "missing 'material' in sphere");
    BAD(CAM RED "sphere center 0 0 0 radius 1 material", PE, 3, 38,
        "'material' needs a name; got end of line");
    BAD(CAM RED "sphere center 0 0 0 radius 0 material red", RT_ERR_DEGENERATE,
        3, 21, "degenerate sphere: radius must be > 0");
    BAD(CAM RED "sphere center 0 0 0 radius -2 material red",
        RT_ERR_DEGENERATE, 3, 21, "degenerate sphere: radius must be > 0");
    BAD(CAM RED "sphere center 0 0 0 radius 1 radius 2 material red", PE, 3,
        30, "'radius' given twice in sphere");
    BAD(CAM RED "sphere center 0 0 0 radius 1 height 2 material red", PE, 3,
        30,
        "unknown field 'height' in sphere (expected one of: center radius "
        "material)");
    BAD(CAM RED "sphere center 1 2 3 4 radius 1 material red", PE, 3, 21,
        "unexpected number '4' in sphere");
    BAD(CAM RED "quad corner 0 0 0 edge1 1 0 0 material red", PE, 3, 1,
        "missing 'edge2' in quad");
    BAD(CAM RED "quad corner 0 0 0 edge1 0 0 0 edge2 0 0 1 material red",
        RT_ERR_DEGENERATE, 3, 19, "degenerate quad: edge1 must not be zero");
    BAD(CAM RED "quad corner 0 0 0 edge1 1 0 0 edge2 0 0 0 material red",
        RT_ERR_DEGENERATE, 3, 31, "degenerate quad: edge2 must not be zero");
    BAD(CAM RED "quad corner 0 0 0 edge1 1 2 3 edge2 -2 -4 -6 material red",
        RT_ERR_DEGENERATE, 3, 31,
        "degenerate quad: edge1 and edge2 are parallel");
    /* Nearly parallel edges are fine: the test is exact. */
    CHECK(GOOD(CAM RED "quad corner 0 0 0 edge1 1 2 3 edge2 2 4 6.001 "
                       "material red"));
    BAD(CAM RED "box min 0 0 0 max 1 0 1 material red", RT_ERR_DEGENERATE, 3,
        15, "degenerate box: max y must be > min y");
    BAD(CAM RED "box min 0 0 0 max -1 1 1 material red", RT_ERR_DEGENERATE,
        3, 15, "degenerate box: max x must be > min x");
    BAD(CAM RED "box min 0 0 0 max 1 1 0 material red", RT_ERR_DEGENERATE, 3,
        15, "max z must be > min z");
    BAD(CAM RED "box min 0 0 0 material red", PE, 3, 1,
        "missing 'max' in box");
    BAD(CAM RED "cylinder base 0 0 0 radius 0 height 1 material red",
        RT_ERR_DEGENERATE, 3, 21, "degenerate cylinder: radius must be > 0");
    BAD(CAM RED "cylinder base 0 0 0 radius 1 height -1 material red",
        RT_ERR_DEGENERATE, 3, 30, "degenerate cylinder: height must be > 0");
    BAD(CAM RED "cylinder base 0 0 0 radius 1 material red", PE, 3, 1,
        "missing 'height' in cylinder");
    BAD(CAM RED "cylinder base 0 0 0 radius 1 height 1 material red open "
                "caps top",
        PE, 3, 57, "give either 'open' or 'caps', not both");
    BAD(CAM RED "cylinder caps none base 0 0 0 radius 1 height 1 open", PE, 3,
        49, "give either 'open' or 'caps', not both");
    BAD(CAM RED "cylinder base 0 0 0 radius 1 height 1 material red caps up",
        PE, 3, 57, "'caps' needs one of: both top bottom none; got 'up'");
    BAD(CAM RED "cylinder base 0 0 0 radius 1 height 1 material red open open",
        PE, 3, 57, "'open' given twice");
    BAD(CAM RED "cone base 0 0 0 radius 1 height 1 material red caps none",
        PE, 3, 48,
        "unknown field 'caps' in cone (expected one of: base radius height "
        "material open)");
    BAD(CAM RED "cone base 0 0 0 radius 1 height 0 material red",
        RT_ERR_DEGENERATE, 3, 26, "degenerate cone: height must be > 0");
    /* rt_object_prepare() refuses what the parser's own checks let by: */
    BAD(CAM RED "cone base 0 0 0 radius 1000 height 0.001 material red",
        RT_ERR_DEGENERATE, 3, 17,
        "degenerate cone: radius / height must be at most 64");
    BAD(CAM RED "cone base 0 0 0 radius 0.00002 height 30000 material red",
        RT_ERR_DEGENERATE, 3, 17,
        "degenerate cone: too thin or too flat for Q16.16 (the radius");
    /* Capacity: RT_MAX_OBJECTS objects parse, one more does not. */
    size_t cap = 64 * (RT_MAX_OBJECTS + 4);
    char *buf = malloc(cap);
    size_t n = (size_t)sprintf(buf, CAM RED);
    for (int i = 0; i < RT_MAX_OBJECTS; i++)
        n += (size_t)sprintf(buf + n, "sphere center %d 0 0 radius 1 "
                                      "material red\n", i);
    CHECK(GOOD(buf));
    CHECK_EQ(S.n_objects, RT_MAX_OBJECTS);
    CHECK_EQ(S.obj[RT_MAX_OBJECTS - 1].u.sphere.center.x,
             FX_INT(RT_MAX_OBJECTS - 1));
    sprintf(buf + n, "box min 0 0 0 max 1 1 1 material red\n");
    BAD(buf, RT_ERR_CAPACITY, RT_MAX_OBJECTS + 3, 1,
        "too many objects (RT_MAX_OBJECTS is 128)");
    free(buf);
}

static void test_lexical_errors(void)
{
    /* A quote that does not close on its line is reported at the quote;
     * a closed one may hold spaces and '#', and stays one token. */
    BAD(CAM "material m color 1 1 1\nmesh file \"a b.obj material m", PE, 3,
        11, "unclosed quote");
    BAD(CAM "material m color 1 1 1\nmesh file \"a b.obj\" material m",
        RT_ERR_UNSUPPORTED, 3, 1, "'mesh' reads a file");
    BAD(CAM "material m color 1 1 1\nsphere \"x # y\" 1", PE, 3, 8,
        "'\"x # y\"'");
    BAD("camera eye 1e5 0 0 look 0 0 0", PE, 1, 12,
        "exponents are not supported (write the number out): '1e5'");
    BAD("camera eye 2.5E-3 0 0 look 0 0 0", PE, 1, 12, "exponents");
    BAD("camera eye 0x10 0 0 look 0 0 0", PE, 1, 12,
        "hexadecimal numbers are not supported: '0x10'");
    BAD("camera eye -0X1f 0 0 look 0 0 0", PE, 1, 12, "hexadecimal");
    BAD("camera eye nan 0 0 look 0 0 0", PE, 1, 12,
        "'nan' is not allowed: numbers must be finite decimals");
    BAD("camera eye -Infinity 0 0 look 0 0 0", PE, 1, 12, "'-Infinity' is");
    BAD("camera eye +INF 0 0 look 0 0 0", PE, 1, 12, "finite decimals");
    BAD("camera eye 1.2.3 0 0 look 0 0 0", PE, 1, 12,
        "malformed number '1.2.3'");
    BAD("camera eye 12abc 0 0 look 0 0 0", PE, 1, 12, "malformed number");
    BAD("camera eye 00x1 0 0 look 0 0 0", PE, 1, 12, "malformed number");
    BAD("camera eye . 0 0 look 0 0 0", PE, 1, 12,
        "'eye' needs 3 numbers (x y z); got '.'");
    BAD("camera eye 32768 0 0 look 0 0 0", PE, 1, 12,
        "number out of Q16.16 range (-32768 .. 32767.99998)");
    BAD("camera eye 0 -32768.00001 0 look 0 0 0", PE, 1, 14,
        "out of Q16.16 range");
    BAD("camera eye 0 0 1.0000000000000000000000000000000000000000 look 0 0 "
        "0",
        PE, 1, 16, "number has more than 40 digits");
    /* Long tokens are shortened in messages. */
    BAD("abcdefghijklmnopqrstuvwxyz0123456789", PE, 1, 1,
        "unknown keyword 'abcdefghijklmnopqrstuvwx...'");
    /* Bytes. */
    BAD("camera\x01 eye", PE, 1, 7, "unexpected byte 0x01");
    BAD("cam\xC3\xA9ra", PE, 1, 4,
        "unexpected byte 0xc3 (non-ASCII text is allowed only in comments)");
    BAD("camera eye 0 0 -1 look 0 0 0\nlight 1\r2 3", PE, 2, 8,
        "unexpected byte 0x0d");
    BAD("light 1 2 3\x7F", PE, 1, 12, "unexpected byte 0x7f");
    BAD("light 1 2 3\x0b", PE, 1, 12, "unexpected byte 0x0b");
    BAD("light 1 2 3 \f", PE, 1, 13, "unexpected byte 0x0c");
    rt_parse_error e;
    static const char nul_comment[] = "light 1 2 3 # nul \0 in a comment";
    CHECK_EQ(parse_n(nul_comment, sizeof nul_comment - 1, &e), PE);
    CHECK_EQ(e.col, 19);
    CHECK(strstr(e.msg, "unexpected byte 0x00") != NULL);
    /* NUL bytes (a C string's terminator passed in len, say). */
    CHECK_EQ(parse_n(CAM "light 1 2 3\0", sizeof CAM + 11, &e), PE);
    CHECK_EQ(e.line, 2);
    CHECK_EQ(e.col, 12);
    CHECK(strstr(e.msg, "unexpected byte 0x00") != NULL);
    CHECK_EQ(parse_n("\0", 1, &e), PE);
    CHECK_EQ(e.col, 1);
    /* Line continuation. */
    BAD("camera eye 0 0 -1 \\ look 0 0 0", PE, 1, 19,
        "'\\' continues a statement on the next line and must be the last "
        "token on its line");
    BAD("camera eye 0 0 -1 \\", PE, 1, 19,
        "'\\' at the end of the input: no line to continue");
    BAD("camera eye 0 0 -1 \\\n", PE, 1, 19, "end of the input");
    /* An error on a continuation line is reported on that line. */
    BAD("camera eye 0 0 -1 \\\n  look 0 0 x", PE, 2, 12,
        "'look' needs 3 numbers (x y z); got 'x'");
    /* A blank line ends a continued statement. */
    CHECK(GOOD("camera eye 0 0 -1 \\\r\n  look 0 0 0 \\\n\n"));
    BAD(CAM "light 1 2 \\\n\n 3", PE, 3, 1,
        "'light' needs 3 numbers (x y z); got end of line");
    /* Missing fields are reported at the statement's keyword, even when
     * it spans lines. */
    BAD(CAM RED "\n   sphere center 0 0 0 \\\n  material red", PE, 4, 4,
        "missing 'radius' in sphere");
    /* CRLF: the reported line excludes the "\r\n". */
    CHECK_EQ(parse(CAM "sphre 1\r\nlight 1 2 3\r\n", &e), PE);
    CHECK_EQ(e.line, 2);
    CHECK_EQ(e.line_off, strlen(CAM));
    CHECK_EQ(e.line_len, 7);
    CHECK_EQ(e.tok_len, 5);
    /* Columns count bytes, a tab as one. */
    BAD("\t\tsphre", PE, 1, 3, "sphre");
}

/* ---- Robustness --------------------------------------------------------- */

static int err_sane(const char *text, size_t len, rt_status st,
                    const rt_parse_error *e)
{
    if (st == RT_OK)
        return 1;
    if (st != RT_ERR_PARSE && st != RT_ERR_CAPACITY &&
        st != RT_ERR_DEGENERATE)
        return 0;
    if (e->line < 1 || e->col < 1 || e->msg[0] == '\0')
        return 0;
    if (memchr(e->msg, '\0', sizeof e->msg) == NULL)
        return 0;
    if (e->line_off > len || e->line_len > len - e->line_off)
        return 0;
    if (e->col - 1 + e->tok_len > e->line_len)
        return 0;
    /* The line holds no newline. */
    if (memchr(text + e->line_off, '\n', e->line_len) != NULL)
        return 0;
    return 1;
}

static void test_prefixes_and_mutations(void)
{
    long before = th_failed;
    size_t len = strlen(full_scene);
    rt_parse_error e;
    /* Every prefix: parsed or refused, never a read past len. */
    for (size_t n = 0; n <= len; n++) {
        char *b = exact_copy(full_scene, n);
        rt_status st = rt_parse(b, n, &S, &e);
        if (!err_sane(b, n, st, &e))
            CHECK(!"sane error");
        free(b);
    }
    /* Random byte changes. */
    for (int it = 0; it < 20000; it++) {
        char *b = exact_copy(full_scene, len);
        int k = 1 + (int)rnd_below(4);
        for (int j = 0; j < k; j++) {
            static const char pool[] = " \t\n\r\\#.-+0123456789eEx\0\x80z";
            size_t at = rnd_below((unsigned)len);
            b[at] = rnd_below(2) ? (char)rnd_below(256)
                                 : pool[rnd_below(sizeof pool)];
        }
        rt_status st = rt_parse(b, len, &S, &e);
        if (!err_sane(b, len, st, &e))
            CHECK(!"sane error");
        free(b);
    }
    /* Random short token soups. */
    static const char *const words[] = {
        "image", "camera", "eye", "look", "up", "fov", "light", "color",
        "material", "m", "sphere", "quad", "box", "cylinder", "cone",
        "center", "radius", "height", "base", "min", "max", "corner",
        "edge1", "edge2", "open", "caps", "both", "1", "0", "-1", "0.5",
        "\\\n", "\n", "#", "stripes", "x", "checker", "bump", "ambient",
        "background", "spp", "4", "depth", "32768", "1e5"};
    for (int it = 0; it < 20000; it++) {
        char buf[512];
        size_t n = 0;
        n += (size_t)sprintf(buf, "%s", it & 1 ? "material m color 1 1 1\n"
                                               : "");
        int k = (int)rnd_below(40);
        for (int j = 0; j < k; j++)
            n += (size_t)sprintf(buf + n, "%s ",
                                 words[rnd_below(sizeof words /
                                                 sizeof words[0])]);
        char *b = exact_copy(buf, n);
        rt_status st = rt_parse(b, n, &S, &e);
        if (!err_sane(b, n, st, &e))
            CHECK(!"sane error");
        free(b);
    }
    CHECK_EQ(th_failed, before);
}

/* Large inputs finish in linear time: a quadratic parser would take hours
 * on these. */
static void test_large_inputs(void)
{
    rt_parse_error e;
    size_t n = (size_t)64 << 20, i = 0;
    char *b = malloc(n);
    clock_t t0 = clock();
    /* 64 MiB of comments, blank lines and lights, camera at the end. */
    static const char unit[] = "# comment line with some text in it\n"
                               "\n   \t\r\n";
    while (i + sizeof unit + 40 < n) {
        memcpy(b + i, unit, sizeof unit - 1);
        i += sizeof unit - 1;
    }
    memcpy(b + i, CAM, strlen(CAM));
    i += strlen(CAM);
    CHECK_EQ(rt_parse(b, i, &S, &e), RT_OK);
    /* One 64 MiB line of spaces, then a keyword. */
    memset(b, ' ', n);
    memcpy(b + n - 5, "sphre", 5);
    CHECK_EQ(rt_parse(b, n, &S, &e), PE);
    CHECK_EQ(e.col, n - 4);
    CHECK_EQ(e.line_len, n);
    /* A 64 MiB token: as a keyword and as a material name. */
    memset(b, 'a', n);
    CHECK_EQ(rt_parse(b, n, &S, &e), PE);
    CHECK_EQ(e.tok_len, n);
    memcpy(b, "material ", 9);
    CHECK_EQ(rt_parse(b, n, &S, &e), RT_ERR_CAPACITY);
    /* A 64 MiB number. */
    memset(b, '1', n);
    memcpy(b, "light ", 6);
    CHECK_EQ(rt_parse(b, n, &S, &e), PE);
    CHECK(strstr(e.msg, "more than 40 digits") != NULL);
    /* Many continuation lines. */
    for (i = 0; i + 3 <= n; i += 3)
        memcpy(b + i, " \\\n", 3);
    CHECK_EQ(rt_parse(b, i, &S, &e), PE);
    CHECK(strstr(e.msg, "end of the input") != NULL);
    double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
    CHECK(secs < 60);
    free(b);
}

/* The shipped scenes parse (paths relative to this file's directory). */
static void test_scene_files(void)
{
    static const char *const files[] = {"seed", "glass", "mirrors",
                                        "primitives", "textures", "many"};
    char dir[512];
    const char *slash = strrchr(__FILE__, '/');
    size_t dl = slash ? (size_t)(slash - __FILE__) + 1 : 0;
    snprintf(dir, sizeof dir, "%.*s../scenes/", (int)dl, __FILE__);
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        char path[600];
        snprintf(path, sizeof path, "%s%s.scene", dir, files[i]);
        FILE *f = fopen(path, "rb");
        if (!th_check(f != NULL, __FILE__, __LINE__, "scene file opens")) {
            printf("    %s\n", path);
            continue;
        }
        static char text[1 << 20];
        size_t n = fread(text, 1, sizeof text, f);
        fclose(f);
        rt_parse_error e;
        rt_status st = parse_n(text, n, &e);
        if (!th_check(st == RT_OK, __FILE__, __LINE__, "scene file parses"))
            printf("    %s:%u:%u: %s\n", path, e.line, e.col, e.msg);
        if (strcmp(files[i], "seed") == 0 && st == RT_OK) {
            CHECK_EQ(S.n_objects, 8);
            CHECK_EQ(S.n_lights, 1);
            CHECK_EQ(S.light[0].pos.x, FX_INT(10));
            CHECK_EQ(S.light[0].pos.y, FX_INT(40));
            CHECK_EQ(S.light[0].pos.z, FX_INT(-5));
            for (int m = 0; m < S.n_materials; m++)
                CHECK_EQ(S.mat[m].shininess, 10);
        }
        if (strcmp(files[i], "many") == 0 && st == RT_OK)
            CHECK(S.n_objects >= 100);
    }
}

int main(void)
{
    test_fx_fixed();
    test_fx_random();
    test_full_scene();
    test_defaults_and_layout();
    test_statement_errors();
    test_material_errors();
    test_object_errors();
    test_lexical_errors();
    test_prefixes_and_mutations();
    test_large_inputs();
    test_scene_files();
    return th_summary();
}
