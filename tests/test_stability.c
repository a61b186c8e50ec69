/*
 * The numerical-stability suite (issue 5): a table of named hard cases, each
 * a tiny scene or a direct call into the core, with its expected behaviour
 * in the comment above it. Each case prints "PASS  name" or "FAIL  name";
 * a failed check also prints file:line. docs/stability-cases.md lists the
 * cases and the choices they document.
 *
 * Properties checked across the suite (helpers below):
 * - speckles: isolated pixels that differ from all 8 neighbours and from the
 *   double reference (ref_render_rows) by more than 64/255, where the
 *   reference is locally smooth (see count_speckles2);
 * - acne: pixels darker than the reference by more than 64/255 where the
 *   reference is not at an edge (a wrongly shadowed lit surface);
 * - determinism: the same bytes twice, and the same bytes in row bands;
 * - no wrap-around: huge values saturate, colours never wrap to dark.
 *
 * Usage: test_stability [substring] runs only the cases whose name
 * contains the substring. STAB_VERBOSE=1 prints the metrics of every
 * render comparison; STAB_DUMP=dir writes the fixed and reference images;
 * STAB_NOFORK=1 runs the cases in-process (each normally runs in a child,
 * so that a crash fails only its own case).
 */
#include <dirent.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "cli_util.h"
#include "compare.h"
#include "harness.h"
#include "ppm.h"
#include "ref_render.h"
#include "rt_shape.h"
#include "rt_texture.h"
#include "rt_parse.h"
#include "rt_render.h"
#include "rt_trace.h"

#define D2F(x) ((fx_t)lround((x) * 65536.0))
#define F2D(x) ((double)(x) / 65536.0)

/* A pixel differs when some channel is off by more than this (of 255). */
#define LEVEL 64

static int verbose;
static const char *dump_dir;
static const char *case_name; /* the case running now, for dumps */

/* Two scenes are enough for any case; static because they are large. */
static rt_scene scene_a, scene_b;

/* ---- Scenes ------------------------------------------------------------- */

/* Parses text into *s; a failure is a failed check with the message. */
static int parse(const char *text, rt_scene *s)
{
    rt_parse_error e;
    rt_status st = rt_parse(text, strlen(text), s, &e);
    if (!CHECK(st == RT_OK))
        printf("    scene:%u:%u: %s\n", (unsigned)e.line, (unsigned)e.col,
               e.msg);
    return st == RT_OK;
}

/* Parses text that must be refused with status want and a message that
 * contains msg. */
static void expect_reject(const char *text, rt_status want, const char *msg)
{
    rt_parse_error e;
    rt_status st = rt_parse(text, strlen(text), &scene_a, &e);
    CHECK_EQ(st, want);
    if (!CHECK(strstr(e.msg, msg) != NULL))
        printf("    message '%s', want it to contain '%s'\n", e.msg, msg);
}

/* ---- Rendering into images ---------------------------------------------- */

typedef struct {
    ppm_image *img;
} sink;

static int to_image(void *ctx, int y, const uint8_t *row, size_t n)
{
    sink *k = ctx;
    memcpy(k->img->data + (size_t)y * (size_t)k->img->width * 3, row, n);
    return 0;
}

typedef struct {
    int w, h;  /* 0: the scene's own */
    int spp;   /* 0: the scene's own */
    int depth; /* -1: the scene's own */
    int band;  /* rows per rt_render_rows call; 0: all at once */
} view;

static rt_options options(const rt_scene *s, view v)
{
    rt_options o;
    rt_options_from_scene(&o, s);
    if (v.w > 0)
        o.width = (uint16_t)v.w;
    if (v.h > 0)
        o.height = (uint16_t)v.h;
    if (v.spp > 0)
        o.spp = (uint8_t)v.spp;
    if (v.depth >= 0)
        o.depth = (uint8_t)v.depth;
    o.adaptive = 0; /* every pixel gets its full grid, as the reference */
    return o;
}

/* Renders s with the fixed-point core (ref = 0) or the double reference
 * (ref = 1) into *img (allocated here). Returns the render status. */
static rt_status render(const rt_scene *s, view v, int ref, ppm_image *img,
                        rt_stats *stats)
{
    rt_options o = options(s, v);
    uint8_t *row = malloc(rt_buffer_bytes(&o));
    sink k = { img };
    rt_status st = RT_OK;
    int band = v.band > 0 ? v.band : o.height;
    if (ppm_alloc(img, o.width, o.height) != 0 || !row) {
        free(row);
        return RT_ERR_ARG;
    }
    for (int y = 0; y < o.height && st == RT_OK; y += band) {
        int y1 = y + band > o.height ? o.height : y + band;
        st = ref ? ref_render_rows(s, &o, y, y1, row, to_image, &k, stats)
                 : rt_render_rows(s, &o, y, y1, row, to_image, &k, stats);
    }
    free(row);
    return st;
}

static int same_bytes(const ppm_image *a, const ppm_image *b)
{
    return a->width == b->width && a->height == b->height &&
           memcmp(a->data, b->data, (size_t)a->width * a->height * 3) == 0;
}

static const uint8_t *pix(const ppm_image *m, int x, int y)
{
    return m->data + 3 * ((size_t)y * m->width + x);
}

/* Largest channel difference of two pixels. */
static int pdiff(const uint8_t *a, const uint8_t *b)
{
    int e = 0;
    for (int c = 0; c < 3; c++) {
        int d = a[c] > b[c] ? a[c] - b[c] : b[c] - a[c];
        e = d > e ? d : e;
    }
    return e;
}

/* Some channel spans more than LEVEL in the 3x3 block around (x, y). */
static int at_edge(const ppm_image *m, int x, int y)
{
    for (int c = 0; c < 3; c++) {
        int lo = 255, hi = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                int xx = x + dx, yy = y + dy;
                if (xx < 0 || yy < 0 || xx >= m->width || yy >= m->height)
                    continue;
                int v = pix(m, xx, yy)[c];
                lo = v < lo ? v : lo;
                hi = v > hi ? v : hi;
            }
        if (hi - lo > LEVEL)
            return 1;
    }
    return 0;
}

/* Neighbours of (x, y) in m (of at most 8) whose colour is within LEVEL of
 * (x, y)'s; *nb gets how many neighbours there are. */
static int agreeing(const ppm_image *m, int x, int y, int *nb)
{
    int n = 0;
    *nb = 0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int xx = x + dx, yy = y + dy;
            if ((dx == 0 && dy == 0) || xx < 0 || yy < 0 ||
                xx >= m->width || yy >= m->height)
                continue;
            (*nb)++;
            n += pdiff(pix(m, x, y), pix(m, xx, yy)) <= LEVEL;
        }
    return n;
}

/* Speckles of fx against the reference ref: pixels off from the reference
 * by more than LEVEL that also differ by more than LEVEL from every one of
 * their neighbours in fx (at least two neighbours: a 1x1 image has none).
 * *loose gets that count. The returned count leaves out pixels where the
 * reference itself shows a sub-pixel feature (its pixel agrees with fewer
 * than 3 of its neighbours: a thin reflection, a silhouette's tip), where a
 * hit error well inside the budget of docs/numerics.md may flip the pixel
 * in either renderer; on a locally smooth reference an isolated wrong
 * pixel is a defect. */
static long count_speckles2(const ppm_image *fx, const ppm_image *ref,
                            long *loose)
{
    long n = 0;
    *loose = 0;
    for (int y = 0; y < fx->height; y++)
        for (int x = 0; x < fx->width; x++) {
            const uint8_t *p = pix(fx, x, y), *q = pix(ref, x, y);
            int nb, nb_ref;
            if (pdiff(p, q) <= LEVEL || agreeing(fx, x, y, &nb) != 0 ||
                nb < 2)
                continue;
            (*loose)++;
            int smooth = agreeing(ref, x, y, &nb_ref) >= (nb_ref < 3 ? nb_ref : 3);
            if (verbose && *loose <= 8)
                printf("    speckle at (%d, %d): fixed %d %d %d, reference "
                       "%d %d %d%s\n", x, y, p[0], p[1], p[2], q[0], q[1],
                       q[2], smooth ? "" : " (a sub-pixel feature there)");
            n += smooth;
        }
    return n;
}

static long count_speckles(const ppm_image *fx, const ppm_image *ref)
{
    long loose;
    return count_speckles2(fx, ref, &loose);
}

/* Shadow acne of fx against ref: a pixel where the reference is not at an
 * edge (its 3x3 block spans at most LEVEL in every channel) and the fixed
 * render is darker than the reference by more than LEVEL in some channel:
 * the reference sees a lit surface there and the core a shadowed one. */
static long count_acne(const ppm_image *fx, const ppm_image *ref)
{
    long n = 0;
    for (int y = 0; y < fx->height; y++)
        for (int x = 0; x < fx->width; x++) {
            const uint8_t *p = pix(fx, x, y), *q = pix(ref, x, y);
            int dark = 0;
            for (int c = 0; c < 3; c++)
                dark |= q[c] - p[c] > LEVEL;
            if (dark && !at_edge(ref, x, y)) {
                if (verbose && n < 8)
                    printf("    acne at (%d, %d): fixed %d %d %d, reference "
                           "%d %d %d\n", x, y, p[0], p[1], p[2], q[0], q[1],
                           q[2]);
                n++;
            }
        }
    return n;
}

/* Pixels whose mirror image across the vertical centre line differs, and
 * the largest such difference. */
static long mirror_diffs(const ppm_image *m, int *max_err)
{
    long n = 0;
    *max_err = 0;
    for (int y = 0; y < m->height; y++)
        for (int x = 0; x < m->width / 2; x++) {
            int e = pdiff(pix(m, x, y), pix(m, m->width - 1 - x, y));
            if (e) {
                n++;
                *max_err = e > *max_err ? e : *max_err;
            }
        }
    return n;
}

/* Pixels (of all) that show exactly the colour c. */
static long count_colour(const ppm_image *m, uint8_t r, uint8_t g, uint8_t b)
{
    long n = 0;
    for (size_t i = 0; i < (size_t)m->width * m->height; i++)
        n += m->data[3 * i] == r && m->data[3 * i + 1] == g &&
             m->data[3 * i + 2] == b;
    return n;
}

static int dump_seq; /* numbers the dumps of one case */

static void dump(const char *tag, const ppm_image *m)
{
    char path[512], err[256];
    if (!dump_dir || !m->data)
        return;
    snprintf(path, sizeof path, "%s/%s-%d-%s.ppm", dump_dir, case_name,
             dump_seq / 2, tag);
    dump_seq++;
    if (ppm_save(path, m, err, sizeof err) != 0)
        printf("    %s\n", err);
}

/* What a render comparison found. */
typedef struct {
    compare_result cmp;
    long speckles, speckles_loose, acne;
    rt_stats fx_stats, ref_stats;
} verdict;

/* Renders s with the core twice (all rows at once, then in bands of 7) and
 * with the reference; checks the two core renders are byte-identical and
 * fills *v. The fixed image is left in *fx_out if it is not NULL (the
 * caller frees it). */
static void judge(const rt_scene *s, view vw, verdict *v, ppm_image *fx_out)
{
    ppm_image fx = { 0, 0, NULL }, fx2 = { 0, 0, NULL }, ref = { 0, 0, NULL };
    memset(v, 0, sizeof *v);
    CHECK_EQ(render(s, vw, 0, &fx, &v->fx_stats), RT_OK);
    view banded = vw;
    banded.band = 7;
    CHECK_EQ(render(s, banded, 0, &fx2, NULL), RT_OK);
    if (!CHECK(same_bytes(&fx, &fx2)))
        printf("    the banded render differs from the whole one\n");
    CHECK_EQ(render(s, vw, 1, &ref, &v->ref_stats), RT_OK);
    if (fx.data && ref.data) {
        compare_images(&fx, &ref, &v->cmp);
        v->speckles = count_speckles2(&fx, &ref, &v->speckles_loose);
        v->acne = count_acne(&fx, &ref);
    }
    if (verbose)
        printf("    %dx%d: psnr %.1f dB, max %d, bad %.2f%%, outliers %ld "
               "(interior %ld), speckles %ld, acne %ld\n", fx.width,
               fx.height, v->cmp.psnr, v->cmp.max_err, v->cmp.bad_pct,
               v->cmp.outliers, v->cmp.interior_outliers, v->speckles,
               v->acne);
    dump("fx", &fx);
    dump("ref", &ref);
    if (fx_out)
        *fx_out = fx;
    else
        ppm_free(&fx);
    ppm_free(&fx2);
    ppm_free(&ref);
}

/* The usual verdict for a render case: deterministic, no speckles, and at
 * least min_psnr dB from the reference. */
static void expect_close(const rt_scene *s, view vw, double min_psnr)
{
    verdict v;
    judge(s, vw, &v, NULL);
    CHECK_EQ(v.speckles, 0);
    if (!CHECK(v.cmp.psnr >= min_psnr))
        printf("    psnr %.2f dB, want >= %.1f (max err %d, outliers %ld)\n",
               v.cmp.psnr, min_psnr, v.cmp.max_err, v.cmp.outliers);
}

/* ---- Direct calls ------------------------------------------------------- */

static rt_object obj(int kind, double ax, double ay, double az)
{
    rt_object o;
    memset(&o, 0, sizeof o);
    o.kind = (uint8_t)kind;
    o.a = fx_v3(D2F(ax), D2F(ay), D2F(az));
    o.caps = RT_CAP_BOTTOM | RT_CAP_TOP;
    return o;
}

static rt_object sphere(double cx, double cy, double cz, double r)
{
    rt_object o = obj(RT_SPHERE, cx, cy, cz);
    o.r = D2F(r);
    CHECK_EQ(rt_object_prepare(&o), RT_OK);
    return o;
}

static rt_object upright(int kind, double ax, double ay, double az, double r,
                         double h)
{
    rt_object o = obj(kind, ax, ay, az);
    o.r = D2F(r);
    o.h = D2F(h);
    CHECK_EQ(rt_object_prepare(&o), RT_OK);
    return o;
}

static rt_object box(double x0, double y0, double z0, double x1, double y1,
                     double z1)
{
    rt_object o = obj(RT_BOX, x0, y0, z0);
    o.b = fx_v3(D2F(x1), D2F(y1), D2F(z1));
    CHECK_EQ(rt_object_prepare(&o), RT_OK);
    return o;
}

static rt_object quad(fx_vec3 a, fx_vec3 e1, fx_vec3 e2)
{
    rt_object o;
    memset(&o, 0, sizeof o);
    o.kind = RT_QUAD;
    o.a = a;
    o.b = e1;
    o.c = e2;
    CHECK_EQ(rt_object_prepare(&o), RT_OK);
    return o;
}

static fx_vec3 V(double x, double y, double z)
{
    return fx_v3(D2F(x), D2F(y), D2F(z));
}

/* A ray with raw origin and direction (the direction is used as given). */
static rt_ray ray_raw(fx_vec3 o, fx_vec3 d)
{
    rt_ray r;
    rt_ray_set(&r, o, d);
    return r;
}

/* A ray from a double origin along the normalised double direction. */
static rt_ray ray(double ox, double oy, double oz, double dx, double dy,
                  double dz)
{
    double l = sqrt(dx * dx + dy * dy + dz * dz);
    return ray_raw(V(ox, oy, oz), V(dx / l, dy / l, dz / l));
}

/* The core's nearest hit with t_min = EPS, t_max unbounded: 1 and *t. */
static int cast(const rt_object *o, const rt_ray *r, double *t, uint8_t *part)
{
    fx_t tf;
    uint8_t p = 0;
    int hit = rt_intersect(o, r, RT_EPS, FX_MAX, &tf, &p);
    *t = hit ? F2D(tf) : -1;
    if (part)
        *part = p;
    return hit;
}

/* The reference's answer for the same quantised ray. */
static int cast_ref(const rt_object *o, const rt_ray *r, double *t,
                    ref_vec3 *n)
{
    ref_shape sh;
    ref_hit h;
    ref_vec3 ro = { F2D(r->o.x), F2D(r->o.y), F2D(r->o.z) };
    ref_vec3 rd = { F2D(r->d.x), F2D(r->d.y), F2D(r->d.z) };
    ref_shape_from_object(o, &sh);
    int hit = ref_intersect(&sh, ro, rd, HUGE_VAL, &h);
    *t = hit ? h.t : -1;
    if (n && hit)
        *n = h.n_out;
    return hit;
}

/* Outward normal of the core at its own hit. */
static fx_vec3 normal_at(const rt_object *o, const rt_ray *r, double t,
                         uint8_t part)
{
    return rt_normal(o, fx_v3_madd(r->o, r->d, D2F(t)), part);
}

/* |n - (x, y, z)| summed per component, in units. */
static double nerr(fx_vec3 n, double x, double y, double z)
{
    return fabs(F2D(n.x) - x) + fabs(F2D(n.y) - y) + fabs(F2D(n.z) - z);
}

/* Expects a hit within tol of t_want. */
#define HIT_AT(o, r, t_want, tol)                                             \
    do {                                                                      \
        double t_;                                                            \
        if (CHECK(cast(&(o), &(r), &t_, NULL)) &&                             \
            !CHECK(fabs(t_ - (t_want)) <= (tol)))                             \
            printf("    t = %.7f, want %.7f +- %g\n", t_, (double)(t_want),  \
                   (double)(tol));                                            \
    } while (0)

#define MISS(o, r)                                                            \
    do {                                                                      \
        double t_;                                                            \
        if (!CHECK(!cast(&(o), &(r), &t_, NULL)))                             \
            printf("    unexpected hit at t = %.7f\n", t_);                   \
    } while (0)

/* Moves the ray origin o by k * step (raw units) for k = -n..n, direction
 * d, and requires the core to agree with the reference on hit or miss for
 * |k| >= k_sure (closer to the tangent either answer is right), and on t
 * within tol where both hit. Returns the disagreements with |k| < k_sure. */
static int sweep(const rt_object *ob, fx_vec3 o, fx_vec3 step, fx_vec3 d,
                 int n, int k_sure, double tol)
{
    int unsure = 0;
    for (int k = -n; k <= n; k++) {
        rt_ray r = ray_raw(fx_v3(o.x + k * step.x, o.y + k * step.y,
                                 o.z + k * step.z), d);
        double t, tr;
        int h = cast(ob, &r, &t, NULL), hr = cast_ref(ob, &r, &tr, NULL);
        if (h != hr && abs(k) < k_sure) {
            unsure++;
            if (verbose)
                printf("    k = %d: core %s, reference %s (t %.6f)\n", k,
                       h ? "hits" : "misses", hr ? "hits" : "misses",
                       h ? t : tr);
            continue;
        }
        if (!CHECK(h == hr))
            printf("    k = %d: core %s, reference %s (t %.6f)\n", k,
                   h ? "hits" : "misses", hr ? "hits" : "misses",
                   h ? t : tr);
        else if (h && !CHECK(fabs(t - tr) <= tol))
            printf("    k = %d: t %.7f, reference %.7f\n", k, t, tr);
    }
    return unsure;
}

/* ==== Tangents and grazing rays ========================================== */

/* A ray that touches a sphere (discriminant exactly 0) is a hit at the
 * touching point, t = 5, with the normal (0, 1, 0); one ulp outside misses,
 * one ulp inside hits within sqrt(2^-15) of the touching point. */
static void case_tangent_sphere_exact(void)
{
    rt_object s = sphere(0, 0, 5, 1);
    rt_ray r = ray_raw(V(0, 1, 0), V(0, 0, 1));
    double t;
    uint8_t part;
    if (CHECK(cast(&s, &r, &t, &part))) {
        CHECK(fabs(t - 5) <= 1.0 / 65536);
        CHECK(nerr(normal_at(&s, &r, t, part), 0, 1, 0) < 1e-4);
    }
    rt_ray out = ray_raw(fx_v3(0, FX_ONE + 1, 0), V(0, 0, 1));
    MISS(s, out);
    rt_ray in = ray_raw(fx_v3(0, FX_ONE - 1, 0), V(0, 0, 1));
    HIT_AT(s, in, 5 - sqrt(2.0 / 65536), 1.0 / 8192);
    /* Oblique rays along (0.6, 0, 0.8) pass 0.6 from the centre in the
     * xz-plane, so they touch the sphere at height 0.8: swept across that
     * height, they agree with double from 16 ulps off and beyond. */
    sweep(&s, V(-3, 0.8, 0), fx_v3(0, 1, 0), V(0.6, 0, 0.8), 64, 16,
          1.0 / 64);
}

/* Tangent to the cylinder's side (x = r): within 8 ulps of the tangent
 * line either answer is right; beyond, hit or miss agrees with double and
 * t agrees to 1/64 (the half chord grows as the square root of the
 * offset). */
static void case_tangent_cylinder_side(void)
{
    rt_object c = upright(RT_CYLINDER, 0, 0, 5, 1, 2);
    sweep(&c, V(1, 1, 0), fx_v3(1, 0, 0), V(0, 0, 1), 64, 8, 1.0 / 64);
    /* The same across a tilted ray. */
    sweep(&c, V(1, 0.2, 0), fx_v3(1, 0, 0), V(0, 0.28, 0.96), 64, 8,
          1.0 / 64);
}

/* Tangent to the cone's side at height 0.5 (radius 0.5 there), level and
 * descending: as for the cylinder, agreement with double from 8 ulps off
 * the tangent line. */
static void case_tangent_cone_side(void)
{
    rt_object k = upright(RT_CONE, 0, 0, 5, 1, 1);
    sweep(&k, V(0.5, 0.5, 0), fx_v3(1, 0, 0), V(0, 0, 1), 64, 8, 1.0 / 64);
    /* And a descending ray in the tangent plane at (0.5, 0.5, 5) (normal
     * along (1, 1, 0)), swept along that normal. */
    sweep(&k, V(0.5 - 5 * 0.42426407, 0.5 + 5 * 0.42426407, 1),
          fx_v3(1, 1, 0), V(0.42426407, -0.42426407, 0.8), 64, 8, 1.0 / 64);
}

/* A ray with d.n of exactly 1 ulp (= PAR, so not parallel) 0.01 above a big
 * floor quad hits it at t = 0.01 / 2^-16 = 655.36; 3 ulps gives 218.45.
 * d.n = 0 is parallel: a miss. From 1 unit above, d.n = -1 ulp would need
 * t = 65536, beyond the range: a miss, never a wrapped small t. */
static void case_grazing_quad_dn_1ulp(void)
{
    rt_object q = quad(V(-1000, 0, -1000), V(0, 0, 2000), V(2000, 0, 0));
    rt_ray r1 = ray_raw(V(0, 0.01, 0), fx_v3(FX_ONE, -1, 0));
    HIT_AT(q, r1, F2D(D2F(0.01)) * 65536, 1.0 / 16);
    rt_ray r3 = ray_raw(V(0, 0.01, 0), fx_v3(FX_ONE, -3, 0));
    HIT_AT(q, r3, F2D(D2F(0.01)) * 65536 / 3, 1.0 / 16);
    rt_ray r0 = ray_raw(V(0, 0.01, 0), fx_v3(FX_ONE, 0, 0));
    MISS(q, r0);
    rt_ray far = ray_raw(V(0, 1, 0), fx_v3(FX_ONE, -1, 0));
    MISS(q, far);
    rt_ray in_plane = ray_raw(V(0, 0, 0), fx_v3(FX_ONE, -1, 0));
    MISS(q, in_plane);
}

/* d.n within a few ulps of 0 on a tilted quad (normal (0, -0.6, -0.8)):
 * the core and double agree on hit or miss and on t (relative 2^-10)
 * whenever |d.n| is not within 1 ulp of PAR, where either is right. */
static void case_plane_parallel_few_ulps(void)
{
    rt_object q = quad(V(-50, -40, -30), V(100, 0, 0), V(0, -80, 60));
    fx_vec3 n = q.n;
    /* A direction in the plane: n x (1, 0, 0), then tilted by k ulps. */
    fx_vec3 in = fx_v3_cross_unit(n, fx_v3(FX_ONE, 0, 0));
    for (int k = -6; k <= 6; k++) {
        fx_vec3 d = fx_v3(in.x, in.y + k, in.z);
        rt_ray r = ray_raw(V(0, 0.001, 0.0), d);
        int64_t dn = fx_v3_dot_q32(d, n);
        double t, tr;
        int h = cast(&q, &r, &t, NULL), hr = cast_ref(&q, &r, &tr, NULL);
        if (llabs(llabs(dn) - RT_PAR_Q32) <= 65536)
            continue; /* on the PAR boundary: either answer */
        if (!CHECK(h == hr))
            printf("    k = %d, d.n = %lld/2^32: core %d, reference %d\n", k,
                   (long long)dn, h, hr);
        else if (h && !CHECK(fabs(t - tr) <= tr / 1024))
            printf("    k = %d: t %.4f, reference %.4f\n", k, t, tr);
    }
}

/* Rays along +z at y = 1 + k ulps past the top face of a box (y <= 1):
 * above the face (k > 0) they miss, below it (k < 0) they hit the front
 * face at t = 4, as the reference does. In the face's plane (k = 0) the
 * box is closed, so the ray hits, as it does in the plane of the bottom
 * face (y = -1): the two faces behave alike. Nearly grazing rays (d.y a
 * few ulps) agree with double. */
static void case_grazing_box_face(void)
{
    rt_object b = box(-1, -1, 4, 1, 1, 6);
    for (int k = -3; k <= 3; k++) {
        rt_ray r = ray_raw(fx_v3(0, FX_ONE + k, 0), V(0, 0, 1));
        if (k > 0)
            MISS(b, r);
        else if (k < 0)
            HIT_AT(b, r, 4, 1.0 / 65536);
        else
            HIT_AT(b, r, 4, 1.0 / 65536); /* in the face's plane */
        rt_ray low = ray_raw(fx_v3(0, -FX_ONE + k, 0), V(0, 0, 1));
        if (k < 0)
            MISS(b, low);
        else
            HIT_AT(b, low, 4, 1.0 / 65536);
    }
    for (int k = 1; k <= 4; k++) {
        /* From (0, 1 + 0.05, 0) descending by k ulps per unit. */
        rt_ray r = ray_raw(V(0, 1.05, 0), fx_v3(0, -k, FX_ONE));
        double t, tr;
        int h = cast(&b, &r, &t, NULL), hr = cast_ref(&b, &r, &tr, NULL);
        if (CHECK(h == hr) && h)
            CHECK(fabs(t - tr) < 1.0 / 256);
    }
    /* A ray parallel to a face inside its slab is unconstrained by it. */
    rt_ray inside = ray_raw(V(0, 0.999, 0), V(0, 0, 1));
    HIT_AT(b, inside, 4, 1.0 / 65536);
}

/* Rays parallel to a cylinder's axis just inside its side (r - k ulps, k =
 * 1..4) hit the top cap at t = 1; an open cylinder lets them through.
 * Outside by 16 ulps and more they miss (within a few ulps of the rim the
 * cap may reach past the side by a couple of frame ulps, which keeps the
 * rim watertight). A ray grazing the side along z agrees with double 8
 * ulps away from the tangent. */
static void case_grazing_cylinder_side(void)
{
    rt_object c = upright(RT_CYLINDER, 0, 0, 0, 1, 2);
    rt_object open = c;
    open.caps = 0;
    CHECK_EQ(rt_object_prepare(&open), RT_OK);
    for (int k = 1; k <= 4; k++) {
        rt_ray in = ray_raw(fx_v3(FX_ONE - k, FX_INT(3), 0), V(0, -1, 0));
        rt_ray out = ray_raw(fx_v3(FX_ONE + 16 * k, FX_INT(3), 0),
                             V(0, -1, 0));
        HIT_AT(c, in, 1, 1.0 / 8192);
        MISS(c, out);
        MISS(open, in);
    }
    sweep(&c, V(1, 1.5, -4), fx_v3(1, 0, 0), V(0, 0.01, 1), 48, 8, 1.0 / 64);
}

/* A ray parallel to one of the cone's generators (the quadratic's leading
 * coefficient is 0): 0.01 outside it misses, 0.02 inside it enters through
 * the base cap (from below) and meets the side once; both as double. */
static void case_grazing_cone_generator(void)
{
    rt_object k = upright(RT_CONE, 0, 0, 0, 1, 1);
    /* Generator from (1, 0, 0) to the apex (0, 1, 0): direction (-1, 1). */
    fx_vec3 d = V(-0.70710678, 0.70710678, 0);
    double t, tr;
    rt_ray out = ray_raw(V(1.5 + 0.01, -0.5, 0), d);
    CHECK_EQ(cast(&k, &out, &t, NULL), cast_ref(&k, &out, &tr, NULL));
    MISS(k, out);
    rt_ray in = ray_raw(V(1.5 - 0.02, -0.5, 0), d);
    int h = cast(&k, &in, &t, NULL), hr = cast_ref(&k, &in, &tr, NULL);
    CHECK(h && hr);
    if (h && hr && !CHECK(fabs(t - tr) < 1.0 / 256))
        printf("    t %.6f, reference %.6f\n", t, tr);
    /* A sweep across the generator line, 16 ulps of certainty. */
    sweep(&k, V(1.5, -0.5, 0), fx_v3(1, 0, 0), d, 48, 16, 1.0 / 64);
    /* From inside the cone along a generator direction (the leading
     * coefficient is exactly 0: one root) it meets the far side at
     * (-0.15, 0.85, 0), t = 0.65 sqrt 2, as the reference does. */
    rt_ray along = ray_raw(V(0.5, 0.2, 0), fx_v3(-46341, 46341, 0));
    HIT_AT(k, along, 0.65 * sqrt(2), 1.0 / 1024);
}

/* ==== Ray origins on a surface =========================================== */

/* From a point on a sphere: outward misses (the root at t = 0 is below
 * EPS), inward hits the far side at t = 2, along the tangent plane misses
 * (both roots are within EPS of 0). */
static void case_origin_on_sphere(void)
{
    rt_object s = sphere(0, 0, 5, 1);
    rt_ray out = ray_raw(V(0, 0, 4), V(0, 0, -1));
    rt_ray in = ray_raw(V(0, 0, 4), V(0, 0, 1));
    rt_ray tan = ray_raw(V(0, 0, 4), V(1, 0, 0));
    MISS(s, out);
    HIT_AT(s, in, 2, 1.0 / 8192);
    MISS(s, tan);
}

/* From a point in a quad's plane, any direction misses: t = 0 <= EPS. */
static void case_origin_on_quad(void)
{
    rt_object q = quad(V(-1, 0, -1), V(0, 0, 2), V(2, 0, 0));
    rt_ray down = ray(0.3, 0, 0.2, 0.1, -1, 0.2);
    rt_ray up = ray(0.3, 0, 0.2, 0.1, 1, 0.2);
    rt_ray along = ray(0.3, 0, 0.2, 1, 0, 0);
    MISS(q, down);
    MISS(q, up);
    MISS(q, along);
}

/* From a point on a box face: outward misses; inward hits the opposite
 * face at t = 2; from an edge and from a corner inward along the diagonal
 * the exit is the opposite edge or corner. */
static void case_origin_on_box_face(void)
{
    rt_object b = box(-1, -1, 4, 1, 1, 6);
    rt_ray out = ray_raw(V(1, 0, 5), V(1, 0, 0));
    rt_ray in = ray_raw(V(1, 0, 5), V(-1, 0, 0));
    rt_ray edge = ray(1, 1, 5, -1, -1, 0);
    rt_ray corner = ray(1, 1, 6, -1, -1, -1);
    MISS(b, out);
    HIT_AT(b, in, 2, 1.0 / 65536);
    HIT_AT(b, edge, 2 * sqrt(2), 1.0 / 4096);
    HIT_AT(b, corner, 2 * sqrt(3), 1.0 / 4096);
}

/* From a point on a cylinder's top rim: outward and upward miss; inward and
 * down it meets the far side or the bottom cap as double does. */
static void case_origin_on_cylinder_rim(void)
{
    rt_object c = upright(RT_CYLINDER, 0, 0, 0, 1, 2);
    rt_ray out = ray(1, 2, 0, 1, 0.5, 0);
    rt_ray up = ray(1, 2, 0, 0, 1, 0);
    MISS(c, out);
    MISS(c, up);
    const double dirs[][3] = { { -1, -0.5, 0 }, { -1, -2, 0 },
                               { -1, -0.2, 0.3 }, { -0.2, -1, 0.1 } };
    for (int i = 0; i < 4; i++) {
        rt_ray r = ray(1, 2, 0, dirs[i][0], dirs[i][1], dirs[i][2]);
        double t, tr;
        int h = cast(&c, &r, &t, NULL), hr = cast_ref(&c, &r, &tr, NULL);
        if (CHECK(h && hr) && !CHECK(fabs(t - tr) < 1.0 / 1024))
            printf("    dir %d: t %.6f, reference %.6f\n", i, t, tr);
    }
}

/* ==== Tiny shapes ======================================================== */

/* A sphere of radius 3 ulps one unit away: the axial ray hits at exactly
 * t = 1 - 3 ulps with normal (0, 0, -1); 2 ulps off the axis hits, 4 ulps
 * off misses (|h|^2 = 16 > 9, exact in 64 bits). */
static void case_tiny_sphere_3ulp(void)
{
    rt_object s = obj(RT_SPHERE, 0, 0, 1);
    s.r = 3;
    CHECK_EQ(rt_object_prepare(&s), RT_OK);
    rt_ray r = ray_raw(fx_v3(0, 0, 0), fx_v3(0, 0, FX_ONE));
    double t;
    uint8_t part;
    if (CHECK(cast(&s, &r, &t, &part))) {
        CHECK_EQ(D2F(t), FX_ONE - 3);
        CHECK(nerr(normal_at(&s, &r, t, part), 0, 0, -1) < 1e-4);
    }
    rt_ray near = ray_raw(fx_v3(2, 0, 0), fx_v3(0, 0, FX_ONE));
    rt_ray off = ray_raw(fx_v3(4, 0, 0), fx_v3(0, 0, FX_ONE));
    HIT_AT(s, near, 1, 4.0 / 65536);
    MISS(s, off);
}

/* A cylinder and a cone of radius and height 4 ulps: straight down the
 * axis from y = 1 the cylinder's top cap is at t = 1 - 4 ulps and the
 * cone's apex too (normal (0, 1, 0) there); sideways through the middle the
 * cylinder's side is 4 ulps before the axis. 6 ulps off the axis both
 * miss. */
static void case_tiny_upright_4ulp(void)
{
    rt_object c = obj(RT_CYLINDER, 0, 0, 0), k = obj(RT_CONE, 0, 0, 0);
    c.r = c.h = k.r = k.h = 4;
    CHECK_EQ(rt_object_prepare(&c), RT_OK);
    CHECK_EQ(rt_object_prepare(&k), RT_OK);
    rt_ray down = ray_raw(fx_v3(0, FX_ONE, 0), fx_v3(0, -FX_ONE, 0));
    double t;
    uint8_t part;
    if (CHECK(cast(&c, &down, &t, &part))) {
        CHECK_NEAR(D2F(t), FX_ONE - 4, 1);
        CHECK(nerr(normal_at(&c, &down, t, part), 0, 1, 0) < 1e-4);
    }
    if (CHECK(cast(&k, &down, &t, &part))) {
        CHECK_NEAR(D2F(t), FX_ONE - 4, 1);
        CHECK(nerr(normal_at(&k, &down, t, part), 0, 1, 0) < 1e-4);
    }
    rt_ray side = ray_raw(fx_v3(-FX_ONE, 2, 0), fx_v3(FX_ONE, 0, 0));
    if (CHECK(cast(&c, &side, &t, &part))) {
        CHECK_NEAR(D2F(t), FX_ONE - 4, 1);
        CHECK(nerr(normal_at(&c, &side, t, part), -1, 0, 0) < 1e-4);
    }
    rt_ray off = ray_raw(fx_v3(6, FX_ONE, 0), fx_v3(0, -FX_ONE, 0));
    MISS(c, off);
    MISS(k, off);
}

/* A quad with 1-ulp edges still has a unit normal (from the exact 64-bit
 * cross product); a ray through its far corner hits (edges are inclusive),
 * 3 ulps past it misses (quads may reach a couple of ulps past their edges
 * so that neighbours leave no crack). A box 1 ulp on a side: its far
 * corner hits, one ulp past misses. (The bounding sphere that culls rays
 * first must not be smaller than the shape.) */
static void case_tiny_quad_box_1ulp(void)
{
    rt_object q = quad(fx_v3(0, 0, FX_ONE), fx_v3(1, 0, 0), fx_v3(0, 1, 0));
    CHECK(nerr(q.n, 0, 0, 1) < 1e-4);
    rt_ray corner = ray_raw(fx_v3(1, 1, 0), fx_v3(0, 0, FX_ONE));
    rt_ray past = ray_raw(fx_v3(4, 1, 0), fx_v3(0, 0, FX_ONE));
    HIT_AT(q, corner, 1, 1.0 / 65536);
    MISS(q, past);
    past = ray_raw(fx_v3(2, 1, 0), fx_v3(0, 0, FX_ONE));
    rt_object b = obj(RT_BOX, 0, 0, 0);
    b.a = fx_v3(0, 0, FX_ONE);
    b.b = fx_v3(1, 1, FX_ONE + 1);
    CHECK_EQ(rt_object_prepare(&b), RT_OK);
    HIT_AT(b, corner, 1, 1.0 / 65536);
    MISS(b, past);
}

/* ==== Huge coordinates =================================================== */

/* Near +-32767 nothing wraps:
 * - a sphere 63900 units away is beyond the far plane: a miss;
 * - a unit sphere at (30000, 30000, 30000) seen from 10 units is hit at
 *   exactly t = 9;
 * - a box spanning the whole range, from inside: the exit face at
 *   32766.99 is hit; at exactly FX_MAX (t = t_max) it is not;
 * - a hit point beyond the range saturates at FX_MAX (madd), not wraps. */
static void case_huge_coords_saturate(void)
{
    rt_object far = sphere(32000, 0, 0, 100);
    rt_ray r = ray_raw(V(-32000, 0, 0), V(1, 0, 0));
    MISS(far, r);
    rt_ray back = ray_raw(V(-32000, 0, 0), V(-1, 0, 0));
    MISS(far, back);
    rt_object s = sphere(30000, 30000, 30000, 1);
    rt_ray r2 = ray_raw(V(29990, 30000, 30000), V(1, 0, 0));
    HIT_AT(s, r2, 9, 0);
    rt_object all = obj(RT_BOX, 0, 0, 0);
    all.a = fx_v3(FX_MIN, FX_MIN, FX_MIN);
    all.b = fx_v3(FX_MAX, FX_MAX, FX_MAX);
    CHECK_EQ(rt_object_prepare(&all), RT_OK);
    rt_ray in = ray_raw(V(1, 0, 0), V(1, 0, 0));
    HIT_AT(all, in, F2D(FX_MAX) - 1, 1.0 / 65536);
    rt_ray edge = ray_raw(V(0, 0, 0), V(1, 0, 0));
    MISS(all, edge);
    rt_ray diag = ray(-30000, -30000, -30000, 1, 1, 1);
    MISS(all, diag); /* exit 60000 * sqrt(3) away */
    fx_vec3 p = fx_v3_madd(V(32000, -32000, 0), V(1, -1, 0), FX_INT(30000));
    CHECK_EQ(p.x, FX_MAX);
    CHECK_EQ(p.y, FX_MIN);
}

/* ==== Watertight edges =================================================== */

static uint32_t rng_state = 2463534242u;

static double rnd(void) /* uniform in [0, 1) */
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return (rng_state >> 8) / 16777216.0;
}

/* Casts a ray at point p (jittered by up to +-jitter/2 per axis) from
 * direction -d at distance 3: returns 1 on a hit near p (t < 3.25; a ray
 * that slips through the surface meets the far side much later), and
 * counts in *bad_t a hit farther than tol from t = 3. */
static int aim(const rt_object *o, double px, double py, double pz,
               double dx, double dy, double dz, double jitter, double tol,
               int *bad_t)
{
    double l = sqrt(dx * dx + dy * dy + dz * dz);
    dx /= l, dy /= l, dz /= l;
    px += (rnd() - 0.5) * jitter;
    py += (rnd() - 0.5) * jitter;
    pz += (rnd() - 0.5) * jitter;
    rt_ray r = ray(px - 3 * dx, py - 3 * dy, pz - 3 * dz, dx, dy, dz);
    double t;
    if (!cast(o, &r, &t, NULL) || t > 3.25)
        return 0;
    *bad_t += fabs(t - 3) > tol;
    return 1;
}

/* Rays that enter a capped cylinder through its rim (both the cap and the
 * side face them) must hit one or the other: no ray slips between them to
 * the far side. 4000 rays at the top and bottom rims, aimed within +-4
 * ulps of the rim; every one hits there, at t within 2^-10. */
static void case_cylinder_cap_rim_watertight(void)
{
    rt_object c = upright(RT_CYLINDER, 0.3, -0.7, 0.2, 1.25, 2.5);
    int miss = 0, bad_t = 0;
    for (int i = 0; i < 2000; i++) {
        double ph = rnd() * 6.283185307179586, cx = cos(ph), cz = sin(ph);
        double px = 0.3 + 1.25 * cx, pz = 0.2 + 1.25 * cz;
        double e = rnd() + 0.2; /* the inward-down slope varies */
        miss += !aim(&c, px, 1.8, pz, -cx, -e, -cz, 8.0 / 65536,
                     1.0 / 1024, &bad_t);
        miss += !aim(&c, px, -0.7, pz, -cx, e, -cz, 8.0 / 65536, 1.0 / 1024,
                     &bad_t);
    }
    if (!CHECK(miss == 0 && bad_t == 0))
        printf("    %d misses, %d hits off the rim\n", miss, bad_t);
}

/* The same at the rim of a cone's base cap (t within 2^-10), and at its
 * apex: rays steeper than the side that pass within 4 ulps of the apex
 * must hit there, not slip through to the base cap. The apex is a double
 * root of the cone's quadratic, whose coefficients are rounded to half a
 * frame ulp, so the hit may lie up to sqrt(2^-17) of the frame (2^-8.5,
 * about 2% of this cone's height) along the ray from it: t within 1/16.
 * Straight down the axis the normal there is (0, 1, 0). */
static void case_cone_apex_and_rim(void)
{
    rt_object k = upright(RT_CONE, -0.4, 0.1, 0.6, 1, 2);
    int miss = 0, bad_t = 0, apex_miss = 0, apex_bad_t = 0;
    for (int i = 0; i < 2000; i++) {
        double ph = rnd() * 6.283185307179586, cx = cos(ph), cz = sin(ph);
        double e = rnd() + 0.2;
        miss += !aim(&k, -0.4 + cx, 0.1, 0.6 + cz, -cx, e, -cz, 8.0 / 65536,
                     1.0 / 1024, &bad_t);
        /* Apex at (-0.4, 2.1, 0.6); the side slopes at r / h = 0.5, so a
         * ray steeper than 2 (down per sideways) enters through it. */
        double s = rnd() * 0.45;
        apex_miss += !aim(&k, -0.4, 2.1, 0.6, s * cx, -1, s * cz,
                          8.0 / 65536, 1.0 / 16, &apex_bad_t);
    }
    if (!CHECK(miss == 0 && bad_t == 0))
        printf("    rim: %d rays slipped through, %d hits off the rim\n",
               miss, bad_t);
    if (!CHECK(apex_miss == 0 && apex_bad_t == 0))
        printf("    apex: %d rays slipped through, %d hits off by more "
               "than 1/16\n", apex_miss, apex_bad_t);
    rt_ray axis = ray(-0.4, 5, 0.6, 0, -1, 0);
    double t;
    uint8_t part;
    if (CHECK(cast(&k, &axis, &t, &part))) {
        CHECK(fabs(t - 2.9) < 1.0 / 8192);
        CHECK(nerr(normal_at(&k, &axis, t, part), 0, 1, 0) < 1e-3);
    }
}

/* A camera looking down at a cone's apex from slightly off its axis: the
 * centre pixel's ray (an odd-sized image) aims 0.001 below the apex on
 * the axis, so it enters the cone within 0.001 of the apex (the exact apex
 * is singular in double too). It must show the cone's lit surface like its
 * neighbours and the reference, not the inside of the base cap through a
 * hole at the apex nor a point deep inside: the centre pixel within 64
 * levels of the reference, and no speckles. */
static void case_cone_apex_centre_pixel(void)
{
    if (!parse("camera eye 0.35 5 -0.15 look 0 1.999 0 fov 20\n"
               "background 0.2 0.3 0.4\n"
               "light 1 6 -1\n"
               "material a color 0.8 0.5 0.3 specular 0\n"
               "cone base 0 0 0 radius 1 height 2 material a\n", &scene_a))
        return;
    ppm_image fx, ref;
    view vw = { 33, 33, 1, -1, 0 };
    render(&scene_a, vw, 0, &fx, NULL);
    render(&scene_a, vw, 1, &ref, NULL);
    if (!CHECK(pdiff(pix(&fx, 16, 16), pix(&ref, 16, 16)) <= LEVEL))
        printf("    centre pixel %d %d %d, reference %d %d %d\n",
               pix(&fx, 16, 16)[0], pix(&fx, 16, 16)[1], pix(&fx, 16, 16)[2],
               pix(&ref, 16, 16)[0], pix(&ref, 16, 16)[1],
               pix(&ref, 16, 16)[2]);
    CHECK_EQ(count_speckles(&fx, &ref), 0);
    ppm_free(&fx);
    ppm_free(&ref);
}

/* Rays entering a box through an edge or a corner (both or all three faces
 * face the ray) must hit it, at t within 2^-12. */
static void case_box_edges_watertight(void)
{
    rt_object b = box(-1.1, -0.6, 2.3, 0.9, 1.7, 3.1);
    int miss = 0, bad_t = 0;
    for (int i = 0; i < 3000; i++) {
        double sx = rnd() < 0.5 ? -1 : 1, sy = rnd() < 0.5 ? -1 : 1;
        double sz = rnd() < 0.5 ? -1 : 1, u = rnd();
        double x = sx < 0 ? -1.1 : 0.9, y = sy < 0 ? -0.6 : 1.7;
        double z = sz < 0 ? 2.3 : 3.1;
        double dx = -sx * (0.2 + rnd()), dy = -sy * (0.2 + rnd());
        double dz = -sz * (0.2 + rnd());
        switch (i % 4) { /* an edge along x, y or z, or a corner */
        case 0: x = -1.1 + 2 * u; dx = rnd() - 0.5; break;
        case 1: y = -0.6 + 2.3 * u; dy = rnd() - 0.5; break;
        case 2: z = 2.3 + 0.8 * u; dz = rnd() - 0.5; break;
        default: break;
        }
        miss += !aim(&b, x, y, z, dx, dy, dz, 2.0 / 65536, 1.0 / 4096,
                     &bad_t);
    }
    if (!CHECK(miss == 0 && bad_t == 0))
        printf("    %d misses, %d hits off the edge\n", miss, bad_t);
}

/* Counts crack rays through the shared edge of q1 and q2 (aimed at
 * corner + s * edge for random s, from random directions): rays that miss
 * both quads although the reference, given the same quantised ray, hits
 * one of them. */
static int seam_cracks(const rt_object *q1, const rt_object *q2,
                       fx_vec3 corner, fx_vec3 edge, double dist, int *n)
{
    int crack = 0;
    *n = 0;
    for (int i = 0; i < 5000; i++) {
        double s = rnd();
        double px = F2D(corner.x) + s * F2D(edge.x);
        double py = F2D(corner.y) + s * F2D(edge.y);
        double pz = F2D(corner.z) + s * F2D(edge.z);
        double dx = rnd() - 0.5, dy = rnd() - 0.5, dz = 0.5 + rnd();
        double l = sqrt(dx * dx + dy * dy + dz * dz);
        rt_ray r = ray(px - dist * dx / l, py - dist * dy / l,
                       pz - dist * dz / l, dx, dy, dz);
        double t;
        if (fabs(F2D(fx_v3_dotn(r.d, q1->n))) < 0.05)
            continue; /* too grazing for the plane to matter */
        (*n)++;
        if (cast(q1, &r, &t, NULL) || cast(q2, &r, &t, NULL))
            continue;
        if (!cast_ref(q1, &r, &t, NULL) && !cast_ref(q2, &r, &t, NULL))
            continue; /* passes outside the hinge's edge: a miss */
        if (verbose && crack < 4)
            printf("    crack: o (%d %d %d) d (%d %d %d)\n", r.o.x, r.o.y,
                   r.o.z, r.d.x, r.d.y, r.d.z);
        crack++;
    }
    return crack;
}

/* Two quads that share an edge exactly (the second's corner is the first's
 * corner + edge1, in exact integers): in one tilted plane, and as a hinge
 * at an angle; about 2, 16 and 128 units in size, each seen from 2 and
 * from 20 times its size. A ray through the shared edge that the
 * reference sees hit one of them must hit one in the core too: no cracks
 * between adjacent quads. */
static void case_quad_seam_no_crack(void)
{
    for (int scale = 1; scale <= 64; scale *= 8) {
        fx_vec3 a = V(-1.3, 0.2, 4.1), e1 = V(1.7, 0.3, 0.4);
        fx_vec3 e2 = V(0.2, 1.9, -0.7), e1b = V(1.1, 0.1, 0.9);
        a = fx_v3(a.x * scale, a.y * scale, a.z * scale);
        e1 = fx_v3(e1.x * scale, e1.y * scale, e1.z * scale);
        e2 = fx_v3(e2.x * scale, e2.y * scale, e2.z * scale);
        e1b = fx_v3(e1b.x * scale, e1b.y * scale, e1b.z * scale);
        fx_vec3 e1c = fx_v3(e1.x / 2, e1.y / 2, e1.z / 2);
        rt_object hinge1 = quad(a, e1, e2);
        rt_object hinge2 = quad(fx_v3_add(a, e1), e1b, e2);
        rt_object flat1 = quad(a, e1c, e2);
        rt_object flat2 = quad(fx_v3_add(a, e1c), e1c, e2);
        for (int far = 0; far < 2; far++) {
            double dist = (far ? 40.0 : 4.0) * scale;
            int n, nf;
            int c = seam_cracks(&hinge1, &hinge2, fx_v3_add(a, e1), e2,
                                dist, &n);
            int cf = seam_cracks(&flat1, &flat2, fx_v3_add(a, e1c), e2,
                                 dist, &nf);
            if (!CHECK(c == 0 && cf == 0) || verbose)
                printf("    size x%d from %g: hinge %d of %d rays cracked, "
                       "plane %d of %d\n", scale, dist, c, n, cf, nf);
        }
    }
}

/* ==== Cameras inside objects ============================================= */

/* Background blue, which no surface in these scenes shows. */
#define BG_BLUE "background 0 0 1\n"

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
static void case_camera_inside_sphere(void)
{
    inside_case("camera eye 0 0 0 look 0.3 -0.2 1 fov 100\n" BG_BLUE
                "light 0 2 -1\n"
                "material wall color 0.8 0.7 0.6 specular 0\n"
                "material ball color 0.2 0.8 0.3\n"
                "sphere center 0 0 0 radius 5 material wall\n"
                "sphere center 1 -1 3 radius 0.8 material ball\n", 40);
}

/* Inside a capped cylinder: side and both caps, lit from inside. */
static void case_camera_inside_cylinder(void)
{
    inside_case("camera eye 0 0 0 look 1 0.6 2 fov 110\n" BG_BLUE
                "light 0.5 2 -1\n"
                "material wall color 0.8 0.7 0.6 specular 0\n"
                "cylinder base 0 -3 0 radius 4 height 6 material wall\n", 40);
}

/* Inside a capped cone, looking up towards its apex. */
static void case_camera_inside_cone(void)
{
    inside_case("camera eye 0 0 0 look 0.2 2 1 fov 100\n" BG_BLUE
                "light 0 1 -0.5\n"
                "material wall color 0.8 0.7 0.6 specular 0\n"
                "cone base 0 -2 0 radius 4 height 6 material wall\n", 40);
}

/* Inside a box, looking into a corner. */
static void case_camera_inside_box(void)
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
static const char translated_fmt[] =
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

static void translated(double o, char *buf, size_t n)
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
static void case_translated_30000(void)
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

/* Objects 20000 units away under a 3-degree view: the hit error grows as
 * 2^-15 t (0.6 units at 20000, against objects of radius 300 and more), so
 * the image still matches the reference with no speckles. */
static void case_far_objects_20000(void)
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
static void case_beyond_range_background(void)
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
static void case_huge_ground_shapes(void)
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

#define CAM "camera eye 0 0 -5 look 0 0 0\nmaterial m color 1 1 1\n"

/* Zero or negative radius: "degenerate sphere: radius must be > 0",
 * status RT_ERR_DEGENERATE. A radius of one ulp is accepted. */
static void case_degenerate_sphere(void)
{
    expect_reject(CAM "sphere center 0 0 0 radius 0 material m\n",
                  RT_ERR_DEGENERATE, "degenerate sphere: radius must be > 0");
    expect_reject(CAM "sphere center 0 0 0 radius -1 material m\n",
                  RT_ERR_DEGENERATE, "degenerate sphere: radius must be > 0");
    parse(CAM "sphere center 0 0 0 radius 0.0000153 material m\n", &scene_a);
}

/* A box with max <= min on an axis: "degenerate box: max y must be > min
 * y". A box one ulp thick is accepted. */
static void case_degenerate_box(void)
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
static void case_degenerate_quad(void)
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
 * radius / height = 64: "degenerate cone: too thin or too flat for
 * Q16.16". The steepest accepted slope is exactly 64. A height of one ulp
 * is refused the same way (its half height, the frame's unit, rounds to
 * 0); two ulps are accepted. */
static void case_degenerate_upright(void)
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
                  RT_ERR_DEGENERATE, "degenerate cone: too thin or too flat");
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

/* Flat colours (ambient only) so a pixel says which quad it shows. */
#define BG_GREEN "background 0 1 0\n"
#define FLAT_MATS                                                             \
    "material red color 1 0 0 ambient 1 diffuse 0 specular 0\n"               \
    "material blue color 0 0 1 ambient 1 diffuse 0 specular 0\n"

/* Two quads in the plane y = 0, the big red one first, a small blue one
 * inside it second. Both give the same t bit for bit (the plane distance
 * is exact for an axis normal), and the nearest-hit loop keeps the first
 * object on a tie (it needs t < best), so no blue pixel shows. In the
 * other order the blue quad shows wherever it is hit alone. Deterministic
 * both ways. */
static void case_coplanar_quads_axis(void)
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
static void case_coplanar_quads_tilted(void)
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
static void case_coplanar_bottom_on_floor(void)
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
            uint8_t pf, ps;
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
static void case_coplanar_glass_on_floor(void)
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
static void case_tir_just_below_and_above(void)
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
static void case_tir_at_critical(void)
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
static void case_glass_ior1_invisible(void)
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
static void case_light_inside_object(void)
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
static void case_light_on_surface(void)
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
static void case_facing_mirrors_depth_max_spp16(void)
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
static void case_image_1x1(void)
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

/* The room scene used by the wide views below. */
static const char room[] =
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
static void case_image_4096x1(void)
{
    if (parse_room("1", &scene_a))
        expect_close(&scene_a, (view){ 4096, 1, 1, -1, 0 }, 35);
}

/* A field of view of 0.001 degrees (half-height 8.7e-6, below one ulp of a
 * direction): every camera ray is the view direction to within an ulp, so
 * the image is one flat colour, the reference's centre pixel (within 2
 * levels). The smallest fov the parser takes (2^-16 degrees) too. */
static void case_fov_near_0(void)
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
static void case_fov_small_scale(void)
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
static void case_fov_near_180(void)
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
static void case_colour_saturates_monotone(void)
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
static void case_dither_white_no_wrap(void)
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
static void case_symmetric_scene_mirrors(void)
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
static void case_apex_and_rim_render(void)
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
static void case_acne_open_shapes(void)
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
static void case_adaptive_bands_deterministic(void)
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

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Every scenes/ *.scene at 160x120 (its own spp and depth): deterministic
 * (same bytes twice and in bands) and no speckles against the reference.
 * seed.scene also has no shadow acne. The PSNR of each is printed. */
static void case_scenes_no_speckles(void)
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
        rt_status st = rt_parse(text, len, &scene_a, &pe);
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
    if (!CHECK(seen_seed))
        printf("    scenes/seed.scene is missing\n");
}

/* seed.scene at 320x240: no shadow acne (see count_acne) and no
 * speckles. */
static void case_seed_no_acne_320(void)
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

/* ==== The table ========================================================== */

typedef struct {
    const char *name;
    void (*run)(void);
} stab_case;

#define CASE(n) { #n, case_##n }

static const stab_case cases[] = {
    CASE(tangent_sphere_exact),
    CASE(tangent_cylinder_side),
    CASE(tangent_cone_side),
    CASE(grazing_quad_dn_1ulp),
    CASE(plane_parallel_few_ulps),
    CASE(grazing_box_face),
    CASE(grazing_cylinder_side),
    CASE(grazing_cone_generator),
    CASE(origin_on_sphere),
    CASE(origin_on_quad),
    CASE(origin_on_box_face),
    CASE(origin_on_cylinder_rim),
    CASE(tiny_sphere_3ulp),
    CASE(tiny_upright_4ulp),
    CASE(tiny_quad_box_1ulp),
    CASE(huge_coords_saturate),
    CASE(cylinder_cap_rim_watertight),
    CASE(cone_apex_and_rim),
    CASE(cone_apex_centre_pixel),
    CASE(box_edges_watertight),
    CASE(quad_seam_no_crack),
    CASE(camera_inside_sphere),
    CASE(camera_inside_cylinder),
    CASE(camera_inside_cone),
    CASE(camera_inside_box),
    CASE(translated_30000),
    CASE(far_objects_20000),
    CASE(beyond_range_background),
    CASE(huge_ground_shapes),
    CASE(degenerate_sphere),
    CASE(degenerate_box),
    CASE(degenerate_quad),
    CASE(degenerate_upright),
    CASE(coplanar_quads_axis),
    CASE(coplanar_quads_tilted),
    CASE(coplanar_bottom_on_floor),
    CASE(coplanar_glass_on_floor),
    CASE(tir_just_below_and_above),
    CASE(tir_at_critical),
    CASE(glass_ior1_invisible),
    CASE(light_inside_object),
    CASE(light_on_surface),
    CASE(facing_mirrors_depth_max_spp16),
    CASE(image_1x1),
    CASE(image_4096x1),
    CASE(fov_near_0),
    CASE(fov_small_scale),
    CASE(fov_near_180),
    CASE(colour_saturates_monotone),
    CASE(dither_white_no_wrap),
    CASE(symmetric_scene_mirrors),
    CASE(apex_and_rim_render),
    CASE(acne_open_shapes),
    CASE(adaptive_bands_deterministic),
    CASE(scenes_no_speckles),
    CASE(seed_no_acne_320),
};

/* Runs one case in a child process, so that a crash (a core defect this
 * suite exists to find) fails that case and the others still run. The
 * child's check counts come back through a pipe. STAB_NOFORK=1 runs the
 * cases in-process (for a debugger). */
static int run_case(const stab_case *c, int nofork)
{
    long before = th_failed;
    if (nofork) {
        c->run();
        return th_failed == before;
    }
    int fd[2];
    long counts[2] = { 0, 0 };
    fflush(stdout);
    if (pipe(fd) != 0) {
        c->run();
        return th_failed == before;
    }
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        th_passed = th_failed = 0;
        c->run();
        fflush(stdout);
        counts[0] = th_passed;
        counts[1] = th_failed;
        ssize_t w = write(fd[1], counts, sizeof counts);
        _exit(w == (ssize_t)sizeof counts ? 0 : 3);
    }
    close(fd[1]);
    ssize_t got = pid > 0 ? read(fd[0], counts, sizeof counts) : -1;
    close(fd[0]);
    int status = 0;
    if (pid > 0)
        waitpid(pid, &status, 0);
    if (got != (ssize_t)sizeof counts || !WIFEXITED(status) ||
        WEXITSTATUS(status) != 0) {
        th_check(0, __FILE__, __LINE__, "the case ran to its end");
        if (WIFSIGNALED(status))
            printf("    crashed with signal %d (%s)\n", WTERMSIG(status),
                   strsignal(WTERMSIG(status)));
        else
            printf("    exit status %d\n", WEXITSTATUS(status));
        return 0;
    }
    th_passed += counts[0];
    th_failed += counts[1];
    return counts[1] == 0;
}

int main(int argc, char **argv)
{
    const char *only = argc > 1 ? argv[1] : NULL;
    int n_cases = (int)(sizeof cases / sizeof cases[0]), failed = 0, run = 0;
    int nofork = getenv("STAB_NOFORK") != NULL;
    struct timespec t_start, t0, t1;
    verbose = getenv("STAB_VERBOSE") != NULL;
    dump_dir = getenv("STAB_DUMP");
    clock_gettime(CLOCK_MONOTONIC, &t_start);
    for (int i = 0; i < n_cases; i++) {
        if (only && !strstr(cases[i].name, only))
            continue;
        case_name = cases[i].name;
        dump_seq = 0;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        int ok = run_case(&cases[i], nofork);
        clock_gettime(CLOCK_MONOTONIC, &t1);
        double ms = 1e3 * (double)(t1.tv_sec - t0.tv_sec) +
                    1e-6 * (double)(t1.tv_nsec - t0.tv_nsec);
        failed += !ok;
        run++;
        printf("%s  %-34s %8.1f ms\n", ok ? "PASS" : "FAIL", cases[i].name,
               ms);
        fflush(stdout);
    }
    double secs = (double)(t1.tv_sec - t_start.tv_sec) +
                  1e-9 * (double)(t1.tv_nsec - t_start.tv_nsec);
    printf("%d cases, %d failed, %.1f s\n", run, failed, run ? secs : 0.0);
    return th_summary();
}
