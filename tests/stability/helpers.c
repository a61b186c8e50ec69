/* SPDX-License-Identifier: MIT */
/* Helpers of the stability suite: scenes, renders, image metrics and
 * direct calls (stability.h). */
#include "stability.h"


int verbose;
const char *dump_dir;
const char *case_name; /* the case running now, for dumps */

/* Two scenes are enough for any case; static because they are large. */
rt_scene scene_a, scene_b;

/* ---- Scenes ------------------------------------------------------------- */

/* Parses text into *s; a failure is a failed check with the message. */
int parse(const char *text, rt_scene *s)
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
void expect_reject(const char *text, rt_status want, const char *msg)
{
    rt_parse_error e;
    rt_status st = rt_parse(text, strlen(text), &scene_a, &e);
    CHECK_EQ(st, want);
    if (!CHECK(strstr(e.msg, msg) != NULL))
        printf("    message '%s', want it to contain '%s'\n", e.msg, msg);
}

/* ---- Rendering into images ---------------------------------------------- */


int to_image(void *ctx, int y, const uint8_t *row, size_t n)
{
    sink *k = ctx;
    memcpy(k->img->data + (size_t)y * (size_t)k->img->width * 3, row, n);
    return 0;
}


rt_options options(const rt_scene *s, view v)
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
rt_status render(const rt_scene *s, view v, int ref, ppm_image *img,
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

int same_bytes(const ppm_image *a, const ppm_image *b)
{
    return a->width == b->width && a->height == b->height &&
           memcmp(a->data, b->data, (size_t)a->width * a->height * 3) == 0;
}

const uint8_t *pix(const ppm_image *m, int x, int y)
{
    return m->data + 3 * ((size_t)y * m->width + x);
}

/* Largest channel difference of two pixels. */
int pdiff(const uint8_t *a, const uint8_t *b)
{
    int e = 0;
    for (int c = 0; c < 3; c++) {
        int d = a[c] > b[c] ? a[c] - b[c] : b[c] - a[c];
        e = d > e ? d : e;
    }
    return e;
}

/* Some channel spans more than LEVEL in the 3x3 block around (x, y). */
int at_edge(const ppm_image *m, int x, int y)
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
int agreeing(const ppm_image *m, int x, int y, int *nb)
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
long count_speckles2(const ppm_image *fx, const ppm_image *ref,
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

long count_speckles(const ppm_image *fx, const ppm_image *ref)
{
    long loose;
    return count_speckles2(fx, ref, &loose);
}

/* Shadow acne of fx against ref: a pixel where the reference is not at an
 * edge (its 3x3 block spans at most LEVEL in every channel) and the fixed
 * render is darker than the reference by more than LEVEL in some channel:
 * the reference sees a lit surface there and the core a shadowed one. */
long count_acne(const ppm_image *fx, const ppm_image *ref)
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
long mirror_diffs(const ppm_image *m, int *max_err)
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
long count_colour(const ppm_image *m, uint8_t r, uint8_t g, uint8_t b)
{
    long n = 0;
    for (size_t i = 0; i < (size_t)m->width * m->height; i++)
        n += m->data[3 * i] == r && m->data[3 * i + 1] == g &&
             m->data[3 * i + 2] == b;
    return n;
}

int dump_seq; /* numbers the dumps of one case */

void dump(const char *tag, const ppm_image *m)
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


/* Renders s with the core twice (all rows at once, then in bands of 7) and
 * with the reference; checks the two core renders are byte-identical and
 * fills *v. The fixed image is left in *fx_out if it is not NULL (the
 * caller frees it). */
void judge(const rt_scene *s, view vw, verdict *v, ppm_image *fx_out)
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
void expect_close(const rt_scene *s, view vw, double min_psnr)
{
    verdict v;
    judge(s, vw, &v, NULL);
    CHECK_EQ(v.speckles, 0);
    if (!CHECK(v.cmp.psnr >= min_psnr))
        printf("    psnr %.2f dB, want >= %.1f (max err %d, outliers %ld)\n",
               v.cmp.psnr, min_psnr, v.cmp.max_err, v.cmp.outliers);
}

/* The verdict of issue 18's cases, with what failed named by `what`:
 * deterministic, no speckle in either sense (count_speckles2, and
 * fixtrace compare's outliers away from the reference's edges: pixels off
 * by more than 64/255 where the reference's 3x3 block is smooth), and at
 * least min_psnr dB from the reference. */
void expect_clean(const rt_scene *s, view vw, double min_psnr,
                  const char *what)
{
    verdict v;
    judge(s, vw, &v, NULL);
    if (!CHECK(v.speckles == 0 && v.cmp.interior_outliers == 0 &&
               v.cmp.psnr >= min_psnr) || verbose)
        printf("    %s: %ld speckles, %ld outliers away from edges (%ld in "
               "all), psnr %.2f dB (want >= %.1f)\n", what, v.speckles,
               v.cmp.interior_outliers, v.cmp.outliers, v.cmp.psnr,
               min_psnr);
}

/* ---- Direct calls ------------------------------------------------------- */

rt_object obj(int kind, double ax, double ay, double az)
{
    rt_object o;
    memset(&o, 0, sizeof o);
    o.kind = (uint8_t)kind;
    o.u.origin = fx_v3(D2F(ax), D2F(ay), D2F(az)); /* any kind's first */
    o.caps = RT_CAP_BOTTOM | RT_CAP_TOP;
    return o;
}

rt_object sphere(double cx, double cy, double cz, double r)
{
    rt_object o = obj(RT_SPHERE, cx, cy, cz);
    o.u.sphere.radius = D2F(r);
    CHECK_EQ(rt_object_prepare(&o), RT_OK);
    return o;
}

rt_object upright(int kind, double ax, double ay, double az, double r,
                         double h)
{
    rt_object o = obj(kind, ax, ay, az);
    o.u.upright.radius = D2F(r);
    o.u.upright.height = D2F(h);
    CHECK_EQ(rt_object_prepare(&o), RT_OK);
    return o;
}

rt_object box(double x0, double y0, double z0, double x1, double y1,
                     double z1)
{
    rt_object o = obj(RT_BOX, x0, y0, z0);
    o.u.box.max = fx_v3(D2F(x1), D2F(y1), D2F(z1));
    CHECK_EQ(rt_object_prepare(&o), RT_OK);
    return o;
}

rt_object quad(fx_vec3 a, fx_vec3 e1, fx_vec3 e2)
{
    rt_object o;
    memset(&o, 0, sizeof o);
    o.kind = RT_QUAD;
    o.u.quad.corner = a;
    o.u.quad.edge1 = e1;
    o.u.quad.edge2 = e2;
    CHECK_EQ(rt_object_prepare(&o), RT_OK);
    return o;
}

fx_vec3 V(double x, double y, double z)
{
    return fx_v3(D2F(x), D2F(y), D2F(z));
}

/* A Q16.16 direction as a unit vector, exactly (its low bits zero). */
fx_dir3 dir16(fx_vec3 d)
{
    const int32_t m = (int32_t)1 << FX_USHIFT;
    return fx_d3(d.x * m, d.y * m, d.z * m);
}

/* A ray with raw origin and a Q16.16 direction, used as given. */
rt_ray ray_raw(fx_vec3 o, fx_vec3 d)
{
    rt_ray r;
    rt_ray_set(&r, o, dir16(d));
    return r;
}

/* A ray from a double origin along the normalised double direction,
 * rounded to the unit vectors' precision. */
rt_ray ray(double ox, double oy, double oz, double dx, double dy,
                  double dz)
{
    double l = sqrt(dx * dx + dy * dy + dz * dz);
    rt_ray r;
    rt_ray_set(&r, V(ox, oy, oz),
               fx_d3((int32_t)lround(dx / l * FX_UONE),
                     (int32_t)lround(dy / l * FX_UONE),
                     (int32_t)lround(dz / l * FX_UONE)));
    return r;
}

/* The core's nearest hit with t_min = EPS, t_max unbounded: 1 and *t. */
int cast(const rt_object *o, const rt_ray *r, double *t, uint16_t *part)
{
    fx_t tf;
    uint16_t p = 0;
    int hit = rt_intersect(o, r, RT_EPS, FX_MAX, &tf, &p);
    *t = hit ? F2D(tf) : -1;
    if (part)
        *part = p;
    return hit;
}

/* The reference's answer for the same quantised ray. */
int cast_ref(const rt_object *o, const rt_ray *r, double *t,
                    ref_vec3 *n)
{
    ref_shape sh;
    ref_hit h;
    ref_vec3 ro = { F2D(r->o.x), F2D(r->o.y), F2D(r->o.z) };
    ref_vec3 rd = { U2D(r->d.x), U2D(r->d.y), U2D(r->d.z) };
    ref_shape_from_object(o, &sh);
    int hit = ref_intersect(&sh, ro, rd, HUGE_VAL, &h);
    *t = hit ? h.t : -1;
    if (n && hit)
        *n = h.n_out;
    return hit;
}

/* Outward normal of the core at its own hit. */
fx_dir3 normal_at(const rt_object *o, const rt_ray *r, double t,
                         uint16_t part)
{
    fx_vec3 p = fx_v3_madd_d(r->o, r->d, D2F(t));
    return rt_normal(o, r, D2F(t), &p, part, 1);
}

/* |n - (x, y, z)| summed per component, in units. */
double nerr(fx_dir3 n, double x, double y, double z)
{
    return fabs(U2D(n.x) - x) + fabs(U2D(n.y) - y) + fabs(U2D(n.z) - z);
}



/* Moves the ray origin o by k * step (raw units) for k = -n..n, direction
 * d, and requires the core to agree with the reference on hit or miss for
 * |k| >= k_sure (closer to the tangent either answer is right), and on t
 * within tol where both hit. Returns the disagreements with |k| < k_sure. */
int sweep(const rt_object *ob, fx_vec3 o, fx_vec3 step, fx_vec3 d,
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

