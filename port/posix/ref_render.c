/* SPDX-License-Identifier: MIT */
/*
 * ref_render: docs/render-model.md in plain double. Read it beside the
 * spec: each section below follows one section there, and the formulas are
 * the textbook ones, not the fixed-point core's rearrangements. The shapes
 * are in ref_shapes.c; this file is everything after the hit: bump noise,
 * the scene in double, shading and textures, the camera and the pixels.
 */
#include <math.h>
#include <string.h>
#include "ref_internal.h"

#define REF_PI 3.14159265358979323846

/* ---- Bump noise ------------------------------------------------------ */

/* The lattice hash on cell coordinates taken modulo 2^32. */
static double lattice(uint32_t seed, uint32_t ix, uint32_t iy, uint32_t iz)
{
    /* Unsigned arithmetic: every product is taken modulo 2^32. */
    uint32_t h = (ix * 73856093u) ^ (iy * 19349663u) ^ (iz * 83492791u) ^
                 (seed * 2654435761u);
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return ((double)(h >> 15) - 65536.0) / 65536.0;
}

double ref_lattice(uint32_t seed, int32_t ix, int32_t iy, int32_t iz)
{
    return lattice(seed, (uint32_t)ix, (uint32_t)iy, (uint32_t)iz);
}

/* floor(v) as a lattice coordinate modulo 2^32 (v is already floored). */
static uint32_t cell(double v)
{
    const double lim = 4611686018427387904.0; /* 2^62: keeps int64 safe */
    return (uint32_t)(int64_t)(v < -lim ? -lim : (v > lim ? lim : v));
}

static double smooth(double f) { return f * f * (3.0 - 2.0 * f); }
static double lerp(double lo, double hi, double s) { return lo + s * (hi - lo); }

double ref_noise(uint32_t seed, ref_vec3 u)
{
    double fx = floor(u.x), fy = floor(u.y), fz = floor(u.z);
    uint32_t ix = cell(fx), iy = cell(fy), iz = cell(fz);
    double sx = smooth(u.x - fx), sy = smooth(u.y - fy), sz = smooth(u.z - fz);
    double c[2][2];
    uint32_t dy, dz;
    for (dz = 0; dz < 2; dz++) /* along x first */
        for (dy = 0; dy < 2; dy++)
            c[dz][dy] = lerp(lattice(seed, ix, iy + dy, iz + dz),
                             lattice(seed, ix + 1u, iy + dy, iz + dz), sx);
    return lerp(lerp(c[0][0], c[0][1], sy), lerp(c[1][0], c[1][1], sy), sz);
}

/* ---- Scene in double ------------------------------------------------- */

typedef struct {
    vec color, color2;
    double ka, kd, ks, shininess, kr, kt, ior;
    int texture, axis;
    double tex_scale, bump, bump_scale;
} ref_material;

typedef struct {
    vec eye, w, right, up;
    double half;
    vec background, ambient;
    int n_obj, n_lights, depth, shadows;
    ref_shape shape[RT_MAX_OBJECTS];
    int mat_of[RT_MAX_OBJECTS];
    ref_material mat[RT_MAX_MATERIALS];
    vec light_pos[RT_MAX_LIGHTS], light_col[RT_MAX_LIGHTS];
    rt_stats *stats;
} ref_scene;

#define COUNT(field) \
    do { if (rs->stats) rs->stats->field++; } while (0)

static rt_status load_scene(const rt_scene *s, int depth, ref_scene *rs)
{
    int i;
    double fov = fxd(s->cam.fov);
    if (s->n_objects > RT_MAX_OBJECTS || s->n_materials > RT_MAX_MATERIALS ||
        s->n_lights > RT_MAX_LIGHTS || !(fov > 0 && fov < 180))
        return RT_ERR_ARG;
    rs->eye = fxv(s->cam.eye);
    rs->w = norm(sub(fxv(s->cam.look), rs->eye));
    rs->right = norm(cross(fxv(s->cam.up), rs->w));
    rs->up = cross(rs->w, rs->right);
    if (len(rs->w) == 0 || len(rs->right) == 0)
        return RT_ERR_ARG; /* eye == look, or up along the view */
    rs->half = tan(fov * (REF_PI / 360.0)); /* tan(fov / 2), in degrees */
    rs->background = fxc(s->background);
    rs->ambient = fxc(s->ambient);
    rs->n_obj = s->n_objects;
    rs->n_lights = s->n_lights;
    rs->depth = depth;
    rs->shadows = s->shadows != 0;
    for (i = 0; i < s->n_materials; i++) {
        const rt_material *m = &s->mat[i];
        ref_material *r = &rs->mat[i];
        r->color = fxc(m->color);
        r->color2 = fxc(m->color2);
        r->ka = fxd(m->ambient);
        r->kd = fxd(m->diffuse);
        r->ks = fxd(m->specular);
        r->shininess = m->shininess;
        r->kr = fxd(m->reflect);
        r->kt = fxd(m->transparency);
        r->ior = fxd(m->ior);
        r->texture = m->texture;
        r->axis = m->axis;
        r->tex_scale = fxd(m->tex_scale);
        r->bump = fxd(m->bump);
        r->bump_scale = fxd(m->bump_scale);
        if (r->texture > RT_TEX_CHECKER3D || r->axis > 2 ||
            (r->texture != RT_TEX_NONE && !(r->tex_scale > 0)) ||
            (r->bump > 0 && !(r->bump_scale > 0)) ||
            (r->kt > 0 && !(r->ior > 0)))
            return RT_ERR_ARG;
    }
    for (i = 0; i < s->n_lights; i++) {
        rs->light_pos[i] = fxv(s->light[i].pos);
        rs->light_col[i] = fxc(s->light[i].color);
    }
    for (i = 0; i < s->n_objects; i++) {
        const rt_object *ob = &s->obj[i];
        if (ob->kind >= RT_KIND_COUNT || ob->material >= s->n_materials)
            return RT_ERR_ARG;
        ref_shape_from_object(ob, &rs->shape[i]);
        if (!ref_shape_ok(&rs->shape[i]))
            return RT_ERR_DEGENERATE;
        if (ob->kind == RT_MESH && ref_mesh_setup(&rs->shape[i]) != 0)
            return RT_ERR_CAPACITY;
        rs->mat_of[i] = ob->material;
    }
    return RT_OK;
}

/* ---- Rays -------------------------------------------------------------- */

/* Nearest hit over all objects but `skip` (-1: none); returns its index or
 * -1. */
static int nearest(const ref_scene *rs, vec o, vec d, int skip, ref_hit *hit)
{
    int i, found = -1;
    double best = HUGE_VAL;
    ref_hit h;
    for (i = 0; i < rs->n_obj; i++) {
        if (i == skip)
            continue;
        COUNT(tests);
        if (ref_intersect(&rs->shape[i], o, d, best, &h)) {
            best = h.t;
            *hit = h;
            found = i;
        }
    }
    return found;
}

/* Any hit with t < tmax, stopping at the first (the shadow query). */
static int blocked(const ref_scene *rs, vec o, vec d, double tmax, int skip)
{
    int i;
    ref_hit h;
    for (i = 0; i < rs->n_obj; i++) {
        if (i == skip)
            continue;
        COUNT(tests);
        if (ref_intersect(&rs->shape[i], o, d, tmax, &h))
            return 1;
    }
    return 0;
}

static int is_odd(double cell)
{
    return (long long)cell & 1; /* two's complement: odd negatives too */
}

static vec texel(const ref_material *m, vec q)
{
    double s = m->tex_scale, idx;
    switch (m->texture) {
    case RT_TEX_STRIPES:
        idx = floor(comp(q, m->axis) / s);
        break;
    case RT_TEX_CHECKER:
        idx = floor(q.x / s) + floor(q.z / s);
        break;
    case RT_TEX_CHECKER3D:
        idx = floor(q.x / s) + floor(q.y / s) + floor(q.z / s);
        break;
    default:
        return m->color;
    }
    return is_odd(idx) ? m->color2 : m->color;
}

static vec trace(const ref_scene *rs, vec o, vec d, int depth, int skip);

static vec mirror(vec d, vec N) { return norm(madd(d, N, -2.0 * dot(d, N))); }

/* Snell's law about N (eta, and N facing the ray): 1 and *t, or 0 for
 * total internal reflection. */
static int snell(vec d, vec N, double eta, vec *t)
{
    double cosi = -dot(d, N);
    double k = 1.0 - eta * eta * (1.0 - cosi * cosi); /* Snell's law */
    if (k < 0)
        return 0;
    *t = norm(madd(scale(d, eta), N, eta * cosi - sqrt(k)));
    return 1;
}

/* The colour seen along d at hit `hit` on object `obj`. */
static vec shade(const ref_scene *rs, vec o, vec d, int depth, int obj,
                 const ref_hit *hit)
{
    const ref_shape *sh = &rs->shape[obj];
    const ref_material *m = &rs->mat[rs->mat_of[obj]];
    vec P = madd(o, d, hit->t), q = sub(P, sh->a), V = scale(d, -1.0);
    int outside = sh->kind == RT_QUAD || dot(d, hit->n_out) <= 0;
    vec Ng = dot(d, hit->n_out) <= 0 ? hit->n_out : scale(hit->n_out, -1.0);
    /* Textures are read a hair inside the surface, so a face lying on a
     * cell boundary does not flip cells on rounding noise. */
    vec N = Ng, C = texel(m, sub(madd(P, hit->n_out, -REF_EPS), sh->a));
    vec colour;
    vec P_out = madd(P, Ng, REF_EPS), P_in = madd(P, Ng, -REF_EPS);
    /* Convex and leaving its outside: the ray cannot meet it again. Both
     * sides of a quad are its outside, so its transmitted ray skips it too
     * (the spec's list of cases leaves the quad out; its rule covers it). */
    int skip_out = sh->convex && outside ? obj : -1;
    int skip_in = sh->convex && (!outside || sh->kind == RT_QUAD) ? obj : -1;
    double diffuse = fmax(1.0 - m->kr - m->kt, 0.0);
    int i;

    if (m->bump > 0) {
        vec u = scale(q, 1.0 / m->bump_scale);
        vec b = v3(ref_noise(1, u), ref_noise(2, u), ref_noise(3, u));
        N = norm(madd(Ng, b, m->bump));
        /* Not a normal that sends a secondary ray through the surface. */
        if (m->kr > 0 || m->kt > 0) {
            double eta = outside ? 1.0 / m->ior : m->ior;
            vec T;
            if (dot(mirror(d, N), Ng) < 0 ||
                (m->kt > 0 && snell(d, N, eta, &T) && dot(T, Ng) > 0))
                N = Ng;
        }
    }
    colour = scale(mul(C, rs->ambient), diffuse * m->ka);
    for (i = 0; i < rs->n_lights; i++) {
        /* Seen from P_out, where the shadow ray starts: it ends at the
         * light, so a surface through the light never hides it. */
        vec toL = sub(rs->light_pos[i], P_out), Lc = rs->light_col[i];
        double dist = len(toL), ndl, rv;
        vec L = norm(toL), R;
        ndl = dot(N, L);
        if (!(ndl > 0))
            continue;
        if (rs->shadows) { /* the scene may turn shadows off */
            COUNT(shadow);
            if (blocked(rs, P_out, L, dist - REF_EPS, skip_out))
                continue;
        }
        colour = add(colour, scale(mul(C, Lc), diffuse * m->kd * ndl));
        R = sub(scale(N, 2.0 * ndl), L); /* Phong */
        rv = dot(R, V);
        if (rv > 0)
            colour = add(colour, scale(Lc, m->ks * pow(rv, m->shininess)));
    }
    if (depth >= rs->depth)
        return colour;
    if (m->kr > 0) {
        COUNT(reflection);
        colour = madd(colour, trace(rs, P_out, mirror(d, N), depth + 1,
                                    skip_out), m->kr);
    }
    if (m->kt > 0) {
        /* N faces the ray either way, so eta flips with the side. */
        double eta = outside ? 1.0 / m->ior : m->ior;
        vec t, T;
        if (!snell(d, N, eta, &T)) { /* total internal reflection */
            COUNT(reflection);
            t = trace(rs, P_out, mirror(d, N), depth + 1, skip_out);
        } else {
            COUNT(refraction);
            t = trace(rs, P_in, T, depth + 1, skip_in);
        }
        colour = madd(colour, t, m->kt);
    }
    return colour;
}

static vec trace(const ref_scene *rs, vec o, vec d, int depth, int skip)
{
    /* Set only when a shape is hit; zeroed so that no compiler (the
     * float32 build's in particular) sees it read uninitialised. */
    ref_hit hit = {0, {0, 0, 0}};
    int obj = nearest(rs, o, d, skip, &hit);
    if (obj < 0)
        return rs->background;
    return shade(rs, o, d, depth, obj, &hit);
}

/* ---- Pixels ------------------------------------------------------------ */

static double clamp01(double v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }

/* One pixel as 8-bit R, G, B: the mean of the n x n clamped samples. */
static void pixel(const ref_scene *rs, int W, int H, int n, int x, int y,
                  uint8_t out[3])
{
    vec sum = v3(0, 0, 0), mean;
    int i, j;
    for (j = 0; j < n; j++) {
        for (i = 0; i < n; i++) {
            double k = 2.0 * x * n + 2.0 * i + 1 - (double)W * n;
            double m = (double)H * n - 2.0 * y * n - 2.0 * j - 1;
            double sx = k * rs->half / ((double)n * H);
            double sy = m * rs->half / ((double)n * H);
            vec d = norm(madd(madd(rs->w, rs->right, sx), rs->up, sy));
            vec c = trace(rs, rs->eye, d, 0, -1);
            COUNT(primary);
            sum = add(sum, v3(clamp01(c.x), clamp01(c.y), clamp01(c.z)));
        }
    }
    mean = scale(sum, 1.0 / (n * n));
    out[0] = (uint8_t)floor(mean.x * 255.0 + 0.5); /* ties up */
    out[1] = (uint8_t)floor(mean.y * 255.0 + 0.5);
    out[2] = (uint8_t)floor(mean.z * 255.0 + 0.5);
}

static const uint8_t bayer4[4][4] = {
    {0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};

/* Top bits of an 8-bit value, keeping 8 - drop; with dithering, first adds
 * the Bayer threshold scaled to one output step (t * 2^drop / 16). */
static unsigned quantise(unsigned v, int drop, int dither, int x, int y)
{
    if (dither) {
        v += ((unsigned)bayer4[y & 3][x & 3] << drop) >> 4;
        if (v > 255)
            v = 255;
    }
    return v >> drop;
}

static void store(uint8_t *row, const rt_options *o, int x, int y,
                  const uint8_t rgb[3])
{
    unsigned p;
    if (o->format == RT_RGB888) {
        memcpy(row + 3 * x, rgb, 3);
        return;
    }
    p = quantise(rgb[0], 3, o->dither, x, y) << 11 |
        quantise(rgb[1], 2, o->dither, x, y) << 5 |
        quantise(rgb[2], 3, o->dither, x, y);
    row[2 * x + (o->format == RT_RGB565_BE)] = (uint8_t)(p & 0xFF);
    row[2 * x + (o->format != RT_RGB565_BE)] = (uint8_t)(p >> 8);
}

static int spp_side(int spp)
{
    int n;
    for (n = 1; n <= RT_MAX_SPP_SIDE; n++)
        if (n * n == spp)
            return n;
    return 0;
}

rt_status ref_render_rows(const rt_scene *s, const rt_options *o, int y0,
                          int y1, uint8_t *row_buf, rt_row_fn fn, void *ctx,
                          rt_stats *stats)
{
    ref_scene rs;
    int n, x, y;
    rt_status st;
    if (!s || !o || !row_buf || !fn)
        return RT_ERR_ARG;
    n = spp_side(o->spp);
    if (o->width < 1 || o->width > RT_MAX_WIDTH || o->height < 1 ||
        o->height > RT_MAX_HEIGHT || n == 0 || o->depth > RT_MAX_DEPTH ||
        o->format > RT_RGB565_BE || y0 < 0 || y0 > y1 || y1 > o->height)
        return RT_ERR_ARG;
    memset(&rs, 0, sizeof rs);
    st = load_scene(s, o->depth, &rs);
    rs.stats = stats;
    for (y = y0; st == RT_OK && y < y1; y++) {
        size_t nbytes = (size_t)o->width * (o->format == RT_RGB888 ? 3 : 2);
        for (x = 0; x < o->width; x++) {
            uint8_t rgb[3];
            pixel(&rs, o->width, o->height, n, x, y, rgb);
            store(row_buf, o, x, y, rgb);
        }
        if (fn(ctx, y, row_buf, nbytes))
            st = RT_ERR_ABORTED;
    }
    for (x = 0; x < RT_MAX_OBJECTS; x++)
        ref_mesh_release(&rs.shape[x]);
    return st;
}
