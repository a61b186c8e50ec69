/*
 * The shadow-ray light grid (core/rt_shadow.c) must be conservative: any
 * object that blocks a shadow ray must be listed in the ray's cell. Random
 * lights and shapes from tiny to huge, and rays aimed to graze each
 * object's bounding sphere, where a too-narrow cone would show first.
 */
#include <math.h>
#include <string.h>

#include "harness.h"
#include "rt_shadow.h"

#define D2F(x) ((fx_t)lround((x) * 65536.0))

static uint64_t rng = 0x5eed5eedULL;

static double uni(double lo, double hi)
{
    return lo + (hi - lo) * (double)(th_rnd64(&rng) >> 11) * 0x1p-53;
}

/* log-uniform in [lo, hi] */
static double logu(double lo, double hi)
{
    return exp(uni(log(lo), log(hi)));
}

static fx_vec3 v3(double x, double y, double z)
{
    return fx_v3(D2F(x), D2F(y), D2F(z));
}

static void random_object(rt_object *o, double spread)
{
    memset(o, 0, sizeof *o);
    double s = logu(1.0 / 64, 64);
    double x = uni(-spread, spread), y = uni(-spread, spread);
    double z = uni(-spread, spread);
    o->kind = (uint8_t)(th_rnd64(&rng) % RT_KIND_COUNT);
    o->caps = RT_CAP_BOTTOM | RT_CAP_TOP;
    o->a = v3(x, y, z);
    o->r = D2F(s);
    o->h = D2F(s * uni(0.2, 3));
    if (o->kind == RT_QUAD) {
        o->b = v3(uni(-s, s), uni(-s, s), uni(-s, s));
        o->c = v3(uni(-s, s), uni(-s, s), uni(-s, s));
    } else if (o->kind == RT_BOX) {
        o->b = v3(x + s * uni(0.1, 2), y + s * uni(0.1, 2),
                  z + s * uni(0.1, 2));
    }
    if (rt_object_prepare(o) != RT_OK)
        random_object(o, spread); /* degenerate draw: try again */
}

static int listed(const uint32_t *cell, unsigned i)
{
    return cell && ((cell[i / 32] >> (i % 32)) & 1u);
}

static void trial(double spread, long *hits, long *missing)
{
    static rt_scene s;
    static rt_shadow_grid g;
    memset(&s, 0, sizeof s);
    s.n_objects = (uint16_t)(1 + th_rnd64(&rng) % 12);
    for (unsigned i = 0; i < s.n_objects; i++)
        random_object(&s.obj[i], spread);
    const rt_object *near = &s.obj[th_rnd64(&rng) % s.n_objects];
    /* Lights anywhere, sometimes right beside (or in) an object. */
    fx_vec3 lp = th_rnd64(&rng) % 4 == 0
        ? fx_v3_add(near->bc, v3(uni(-2, 2), uni(-2, 2), uni(-2, 2)))
        : v3(uni(-spread, spread), uni(-spread, spread),
             uni(-spread, spread));
    rt_shadow_prepare(&g, &s, lp);
    for (int k = 0; k < 400; k++) {
        /* A ray from L that grazes object b's bounding sphere, then the
         * surface point p on it beyond b, as rt_trace would see it. */
        const rt_object *b = &s.obj[th_rnd64(&rng) % s.n_objects];
        double cx = b->bc.x / 65536.0 - lp.x / 65536.0;
        double cy = b->bc.y / 65536.0 - lp.y / 65536.0;
        double cz = b->bc.z / 65536.0 - lp.z / 65536.0;
        double d = sqrt(cx * cx + cy * cy + cz * cz);
        double r = b->br / 65536.0 * uni(0.9, 1.02);
        double ux = uni(-1, 1), uy = uni(-1, 1), uz = uni(-1, 1);
        double dot = (ux * cx + uy * cy + uz * cz) / d;
        ux -= dot * cx / d, uy -= dot * cy / d, uz -= dot * cz / d;
        double ul = sqrt(ux * ux + uy * uy + uz * uz);
        if (ul == 0 || d == 0)
            continue;
        double px = cx + ux / ul * r, py = cy + uy / ul * r;
        double pz = cz + uz / ul * r;
        double beyond = uni(1.0, 3.0);
        fx_vec3 p = fx_v3_add(lp, v3(px * beyond, py * beyond, pz * beyond));
        fx_vec3 lv = fx_v3_sub(lp, p);
        fx_vec3 ld = fx_v3_normalize(lv);
        /* Origin offset as shade() gives it: EPS along some normal. */
        fx_vec3 n = fx_v3_normalize(v3(uni(-1, 1), uni(-1, 1), uni(-1, 1)));
        rt_ray sr;
        sr.o = fx_v3_madd(p, n, RT_EPS);
        sr.d = ld;
        sr.e = rt_unit_err(ld);
        sr.small = (uint8_t)rt_small3(sr.o);
        fx_t tmax = fx_sub(fx_v3_dotn(lv, ld), RT_EPS);
        const uint32_t *cell = rt_shadow_cell(&g, ld);
        for (unsigned i = 0; i < s.n_objects; i++) {
            fx_t t;
            uint8_t part;
            if (!rt_intersect(&s.obj[i], &sr, RT_EPS, tmax, &t, &part))
                continue;
            ++*hits;
            if (!listed(cell, i) && ++*missing <= 5)
                printf("object %u (kind %d) blocks but is not listed\n", i,
                       s.obj[i].kind);
        }
    }
}

int main(void)
{
    long hits = 0, missing = 0;
    for (int t = 0; t < 1500; t++)
        trial(t % 10 == 0 ? 4000.0 : 40.0, &hits, &missing);
    CHECK_EQ(missing, 0);
    /* The aim must actually produce blockers, or the test checks nothing. */
    CHECK(hits > 100000);
    printf("shadow grid: %ld blocking shadow rays, %ld not listed\n", hits,
           missing);
    return th_summary();
}
