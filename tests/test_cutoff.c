/* SPDX-License-Identifier: MIT */
/*
 * What the tracer skips.
 * The ray cut-off (rt_options.trace_all = 0) must stay below its budget:
 * - the colour bounds rt_tracer_init() derives hold for every ray
 *   traced in full, in random scenes with bright lights, mirrors and
 *   glass;
 * - a render with the cut-off differs from one that traces every ray by
 *   at most one 8-bit level per channel, and it does skip rays.
 * A highlight is skipped for cosines up to rt_tracer.spec_min: exactly
 * those whose ks rv^n rounds to 0.
 */
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "rt_parse.h"
#include "rt_render.h"
#include "rt_trace.h"

#define W 40
#define H 30

static uint64_t rng = 0xc0ffee11ULL;

static double uni(double lo, double hi)
{
    return lo + (hi - lo) * (double)(th_rnd64(&rng) >> 11) * 0x1p-53;
}

static int pick(int n)
{
    return (int)(th_rnd64(&rng) % (uint64_t)n);
}

/* Appends to the scene text; the buffer is far larger than any scene. */
static void put(char *buf, size_t cap, const char *fmt, double a, double b,
                double c)
{
    size_t n = strlen(buf);
    snprintf(buf + n, cap - n, fmt, a, b, c);
}

/* Objects around the origin seen from -z; lights and ambient up to 16,
 * and every material glossy, reflective or transparent at random. */
static void random_scene(rt_scene *s, unsigned depth)
{
    static char text[8192];
    rt_parse_error err;
    text[0] = 0;
    put(text, sizeof text, "image 40 30 spp 1 depth %.0f\n", depth, 0, 0);
    put(text, sizeof text, "camera eye 0 2 -12 look 0 0 0 fov %.0f\n",
        uni(30, 80), 0, 0);
    /* Dim, so that the bound comes from the materials and lights. */
    put(text, sizeof text, "background %.3f %.3f %.3f\n", uni(0, 0.2),
        uni(0, 0.2), uni(0, 0.2));
    put(text, sizeof text, "ambient %.3f %.3f %.3f\n", uni(0, 16),
        uni(0, 4), uni(0, 1));
    int lights = 1 + pick(3);
    for (int i = 0; i < lights; i++) {
        put(text, sizeof text, "light %.2f %.2f %.2f ", uni(-20, 20),
            uni(-5, 30), uni(-20, 10));
        put(text, sizeof text, "color %.3f %.3f %.3f\n", uni(0, 16),
            uni(0, 4), uni(0, 1));
    }
    int mats = 1 + pick(4);
    for (int i = 0; i < mats; i++) {
        double kr = uni(0, 1), kt = uni(0, 1 - kr);
        put(text, sizeof text, "material m%.0f color %.3f %.3f ", i,
            uni(0, 1), uni(0, 1));
        put(text, sizeof text, "%.3f ambient %.3f diffuse %.3f ", uni(0, 1),
            uni(0, 1), uni(0, 1));
        put(text, sizeof text, "specular %.3f shininess %.0f reflect %.3f ",
            uni(0, 1), 1 + pick(300), kr);
        put(text, sizeof text, "transparency %.3f ior %.3f", kt,
            uni(0.5, 2.5), 0);
        if (pick(2))
            put(text, sizeof text, " checker %.3f %.3f %.3f 1", uni(0, 1),
                uni(0, 1), uni(0, 1));
        put(text, sizeof text, "\n", 0, 0, 0);
    }
    put(text, sizeof text,
        "quad corner -30 -2 -30 edge1 0 0 60 edge2 60 0 0 material m%.0f\n",
        pick(mats), 0, 0);
    int objs = 2 + pick(6);
    for (int i = 0; i < objs; i++) {
        double x = uni(-5, 5), y = uni(-1, 3), z = uni(-3, 6);
        switch (pick(4)) {
        case 0:
            put(text, sizeof text, "sphere center %.2f %.2f %.2f ", x, y, z);
            put(text, sizeof text, "radius %.2f ", uni(0.3, 2.5), 0, 0);
            break;
        case 1:
            put(text, sizeof text, "box min %.2f %.2f %.2f ", x, y, z);
            put(text, sizeof text, "max %.2f %.2f %.2f ", x + uni(0.2, 3),
                y + uni(0.2, 3), z + uni(0.2, 3));
            break;
        case 2:
            put(text, sizeof text, "cylinder base %.2f %.2f %.2f ", x, y, z);
            put(text, sizeof text, "radius %.2f height %.2f ", uni(0.3, 2),
                uni(0.3, 3), 0);
            break;
        default:
            put(text, sizeof text, "cone base %.2f %.2f %.2f ", x, y, z);
            put(text, sizeof text, "radius %.2f height %.2f ", uni(0.3, 2),
                uni(0.3, 3), 0);
            break;
        }
        put(text, sizeof text, "material m%.0f\n", pick(mats), 0, 0);
    }
    if (!CHECK(rt_parse(text, strlen(text), s, &err) == RT_OK))
        printf("    %s\n", text);
}

/* ks rv^n as shade() computes it. */
static fx_t highlight(const rt_material *m, fx_t rv)
{
    fx_t r = FX_ONE, x = rv;
    for (unsigned n = m->shininess; n; n >>= 1) {
        if (n & 1)
            r = fx_mul(r, x);
        if (n > 1)
            x = fx_mul(x, x);
    }
    return fx_mul(m->specular, r);
}

static void check_spec_min(const rt_tracer *tr, long *checked)
{
    const rt_scene *s = tr->scene;
    for (unsigned i = 0; i < s->n_materials; i++) {
        fx_t lim = tr->spec_min[i];
        CHECK(lim >= 0 && lim < FX_ONE);
        CHECK_EQ(highlight(&s->mat[i], lim), 0);
        if (lim + 1 < FX_ONE)
            CHECK(highlight(&s->mat[i], lim + 1) != 0);
        for (int k = 0; k < 20; k++) { /* and everything below */
            fx_t rv = (fx_t)(th_rnd64(&rng) % (uint64_t)(lim + 1));
            CHECK_EQ(highlight(&s->mat[i], rv), 0);
        }
        ++*checked;
    }
}

static fx_t unit(double x)
{
    return (fx_t)(x * 65536.0);
}

/* Traces random rays in full and checks each colour against the bound
 * for the bounces the ray has left. Returns the largest colour over its
 * bound, in 1/1000. */
static long bound_trial(long *rays, long *over, long *mats)
{
    static rt_scene s;
    static rt_tracer tr;
    rt_work wk;
    rt_options opt;
    unsigned depth = 1 + (unsigned)pick(RT_MAX_DEPTH);
    long worst = 0;
    random_scene(&s, depth);
    rt_options_from_scene(&opt, &s);
    opt.spp = 1;
    opt.depth = (uint8_t)depth;
    opt.trace_all = 1; /* a budget of 0: every ray is traced */
    rt_tracer_init(&tr, &s, &opt);
    rt_work_init(&wk, NULL);
    check_spec_min(&tr, mats);
    for (int k = 0; k < 300; k++) {
        unsigned d = (unsigned)pick((int)depth + 1);
        fx_vec3 o = fx_v3(unit(uni(-8, 8)), unit(uni(-1, 8)),
                          unit(uni(-14, -4)));
        fx_vec3 aim = fx_v3(unit(uni(-5, 5)), unit(uni(-2, 4)),
                            unit(uni(-3, 6)));
        rt_ray r;
        rt_ray_set(&r, o, fx_d3_normalize(fx_v3_sub(aim, o)));
        rt_rgb c =
            rt_trace(&tr, &wk, &r, d, FX_ONE, RT_NO_OBJECT, RT_NO_OBJECT);
        fx_t top = c.r > c.g ? (c.r > c.b ? c.r : c.b)
                             : (c.g > c.b ? c.g : c.b);
        long ratio = (long)((int64_t)top * 1000 / tr.bound[depth - d]);
        worst = ratio > worst ? ratio : worst;
        ++*rays;
        if (top > (fx_t)tr.bound[depth - d] && ++*over <= 5)
            printf("colour %d over the bound %u (%u bounces left)\n",
                   (int)top, (unsigned)tr.bound[depth - d], depth - d);
    }
    return worst;
}

typedef struct {
    uint8_t img[W * H * 3];
} image;

static int to_image(void *ctx, int y, const uint8_t *row, size_t n)
{
    memcpy(((image *)ctx)->img + (size_t)y * W * 3, row, n);
    return 0;
}

/* Renders a random scene with and without the cut-off; returns the
 * largest difference of a channel, and adds the rays cut. */
static int render_trial(unsigned long long *cut, long *changed)
{
    static rt_scene s;
    static image full, fast;
    rt_options o;
    rt_stats st;
    random_scene(&s, 5);
    rt_options_from_scene(&o, &s);
    o.trace_all = 1;
    memset(&st, 0, sizeof st);
    CHECK_EQ(rt_render_rows(&s, &o, 0, H, full.img, to_image, &full, &st),
             RT_OK);
    CHECK_EQ(st.cut, 0);
    o.trace_all = 0;
    memset(&st, 0, sizeof st);
    CHECK_EQ(rt_render_rows(&s, &o, 0, H, fast.img, to_image, &fast, &st),
             RT_OK);
    *cut += st.cut;
    int worst = 0;
    for (size_t i = 0; i < sizeof full.img; i++) {
        int d = full.img[i] - fast.img[i];
        d = d < 0 ? -d : d;
        *changed += d != 0;
        worst = d > worst ? d : worst;
    }
    return worst;
}

int main(void)
{
    long rays = 0, over = 0, worst = 0, mats = 0;
    for (int t = 0; t < 300; t++) {
        long w = bound_trial(&rays, &over, &mats);
        worst = w > worst ? w : worst;
    }
    CHECK_EQ(over, 0);
    /* The bound must come near what rays reach, or it cuts nothing. */
    CHECK(worst > 250);
    printf("colour bounds: %ld rays, %ld over, largest at %.3f of its "
           "bound\n", rays, over, worst / 1000.0);
    printf("highlight thresholds: %ld materials exact\n", mats);

    unsigned long long cut = 0;
    long changed = 0;
    int diff = 0;
    for (int t = 0; t < 200; t++) {
        int d = render_trial(&cut, &changed);
        diff = d > diff ? d : diff;
    }
    CHECK(diff <= 1);
    CHECK(cut > 1000); /* the renders did skip rays */
    printf("cut-off: %llu rays cut in 200 renders, %ld channels changed, "
           "by at most %d\n", cut, changed, diff);
    return th_summary();
}
