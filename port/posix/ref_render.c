/*
 * ref_render: docs/render-model.md in plain double. Read it beside the
 * spec: each section below follows one section there, and the formulas are
 * the textbook ones, not the fixed-point core's rearrangements.
 */
#include <math.h>
#include <string.h>
#include "ref_render.h"

#define REF_PI 3.14159265358979323846

typedef ref_vec3 vec;

static inline vec v3(double x, double y, double z)
{
    vec v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}
static inline vec add(vec a, vec b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec sub(vec a, vec b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec scale(vec a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec mul(vec a, vec b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline vec madd(vec a, vec b, double s) { return add(a, scale(b, s)); }
static inline double dot(vec a, vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline double len(vec a) { return sqrt(dot(a, a)); }
static inline vec cross(vec a, vec b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
              a.x * b.y - a.y * b.x);
}
static inline vec norm(vec a)
{
    double l = len(a);
    return l > 0 ? scale(a, 1.0 / l) : a;
}
static inline double comp(vec a, int axis)
{
    return axis == 0 ? a.x : (axis == 1 ? a.y : a.z);
}
/* The unit vector along axis 0, 1 or 2, times s. */
static inline vec axis_vec(int axis, double s)
{
    return v3(axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0);
}

static double fxd(fx_t v) { return (double)v / 65536.0; }
static vec fxv(fx_vec3 v) { return v3(fxd(v.x), fxd(v.y), fxd(v.z)); }
static vec fxc(rt_rgb c) { return v3(fxd(c.r), fxd(c.g), fxd(c.b)); }

/* ---- Shapes --------------------------------------------------------- */

void ref_shape_from_object(const rt_object *obj, ref_shape *sh)
{
    const unsigned both = RT_CAP_BOTTOM | RT_CAP_TOP;
    memset(sh, 0, sizeof *sh);
    sh->kind = obj->kind;
    sh->caps = obj->caps & both;
    sh->a = fxv(obj->a);
    sh->b = fxv(obj->b);
    sh->c = fxv(obj->c);
    sh->r = fxd(obj->r);
    sh->h = fxd(obj->h);
    if (sh->kind == RT_CONE)
        sh->caps &= RT_CAP_BOTTOM; /* a cone has no top cap */
    /* Every shape bounds a convex solid (an open cylinder or cone too):
     * a ray leaving its outside cannot meet it again. */
    sh->convex = 1;
}

/* Keeps t if it is a nearer acceptable hit than *best. */
static int closer(double t, double tmin, double best)
{
    return t > tmin && t < best;
}

/* Roots of A t^2 + 2 B t + C = 0 given disc = B^2 - A C >= 0, computed
 * without cancellation; a root that does not exist is -1 (never accepted). */
static void stable_roots(double A, double B, double C, double disc,
                         double *t0, double *t1)
{
    double q = -(B + copysign(sqrt(disc), B));
    *t0 = A != 0 ? q / A : -1.0;
    *t1 = q != 0 ? C / q : -1.0;
}

static int hit_sphere(const ref_shape *s, vec o, vec d, double tmax,
                      ref_hit *hit)
{
    /* Geometric form (Ray Tracing Gems, ch. 7): the discriminant comes
     * from the distance of the centre to the line, not from b^2 - c. */
    vec f = sub(o, s->a);
    double b = -dot(f, d);
    vec perp = madd(f, d, b); /* f - (f.d) d */
    double disc = s->r * s->r - dot(perp, perp);
    double c = dot(f, f) - s->r * s->r;
    double t0, t1, t = tmax;
    if (disc < 0)
        return 0;
    stable_roots(1.0, -b, c, disc, &t0, &t1);
    if (closer(t0, REF_EPS, t))
        t = t0;
    if (closer(t1, REF_EPS, t))
        t = t1;
    if (!(t < tmax))
        return 0;
    hit->t = t;
    hit->n_out = scale(sub(madd(o, d, t), s->a), 1.0 / s->r);
    return 1;
}

static int hit_quad(const ref_shape *s, vec o, vec d, double tmax,
                    ref_hit *hit)
{
    vec N = cross(s->b, s->c), n = norm(N);
    double denom = dot(d, n);
    double t, nn = dot(N, N), u, v;
    vec w;
    if (fabs(denom) < REF_PAR)
        return 0; /* parallel to the plane */
    t = dot(sub(s->a, o), n) / denom;
    if (!closer(t, REF_EPS, tmax))
        return 0;
    /* Solve w = u e1 + v e2 in the plane. */
    w = sub(madd(o, d, t), s->a);
    u = dot(cross(w, s->c), N) / nn;
    v = dot(cross(s->b, w), N) / nn;
    if (u < 0 || u > 1 || v < 0 || v > 1)
        return 0;
    hit->t = t;
    hit->n_out = n;
    return 1;
}

static int hit_box(const ref_shape *s, vec o, vec d, double tmax,
                   ref_hit *hit)
{
    double tn = -HUGE_VAL, tf = HUGE_VAL, dn = 0, df = 0;
    int an = -1, af = -1, i;
    for (i = 0; i < 3; i++) {
        double oi = comp(o, i), di = comp(d, i);
        double lo = comp(s->a, i), hi = comp(s->b, i), t1, t2;
        if (fabs(di) < REF_PAR) { /* parallel to both faces of the slab */
            if (oi < lo || oi > hi)
                return 0;
            continue;
        }
        t1 = (lo - oi) / di;
        t2 = (hi - oi) / di;
        if (t1 > t2) {
            double tmp = t1;
            t1 = t2;
            t2 = tmp;
        }
        if (t1 > tn) {
            tn = t1;
            an = i;
            dn = di;
        }
        if (t2 < tf) {
            tf = t2;
            af = i;
            df = di;
        }
    }
    if (tn > tf)
        return 0;
    if (an >= 0 && closer(tn, REF_EPS, tmax)) {
        hit->t = tn; /* entering face: its normal opposes d */
        hit->n_out = axis_vec(an, dn > 0 ? -1.0 : 1.0);
        return 1;
    }
    if (af >= 0 && closer(tf, REF_EPS, tmax)) {
        hit->t = tf; /* exit face, seen from inside: normal along d */
        hit->n_out = axis_vec(af, df > 0 ? 1.0 : -1.0);
        return 1;
    }
    return 0;
}

/* A horizontal disc of radius r centred at c, facing ny (+1 or -1). */
static void hit_disc(vec c, double r, double ny, vec o, vec d, double *best,
                     ref_hit *hit)
{
    double t, x, z;
    if (fabs(d.y) < REF_PAR)
        return; /* parallel to the cap's plane */
    t = (c.y - o.y) / d.y;
    if (!closer(t, REF_EPS, *best))
        return;
    x = o.x + t * d.x - c.x;
    z = o.z + t * d.z - c.z;
    if (x * x + z * z > r * r)
        return;
    *best = t;
    hit->n_out = v3(0, ny, 0);
}

/* The side root t is on the surface part ay <= y <= ay + h. */
static int in_height(const ref_shape *s, vec o, vec d, double t)
{
    double y = o.y + t * d.y;
    return y >= s->a.y && y <= s->a.y + s->h;
}

static int hit_cylinder(const ref_shape *s, vec o, vec d, double tmax,
                        ref_hit *hit)
{
    double best = tmax, px = o.x - s->a.x, pz = o.z - s->a.z;
    double A = d.x * d.x + d.z * d.z;
    /* The side is parallel to the ray when the ray's horizontal part is
     * below PAR: then |d . n| < PAR for every side normal n. */
    if (sqrt(A) >= REF_PAR) {
        double B = px * d.x + pz * d.z, C = px * px + pz * pz - s->r * s->r;
        double fx = px - (B / A) * d.x, fz = pz - (B / A) * d.z;
        double disc = A * (s->r * s->r - (fx * fx + fz * fz));
        double t[2];
        int i;
        if (disc >= 0) {
            stable_roots(A, B, C, disc, &t[0], &t[1]);
            for (i = 0; i < 2; i++) {
                if (closer(t[i], REF_EPS, best) && in_height(s, o, d, t[i])) {
                    best = t[i];
                    hit->n_out = norm(v3(px + t[i] * d.x, 0, pz + t[i] * d.z));
                }
            }
        }
    }
    if (s->caps & RT_CAP_BOTTOM)
        hit_disc(s->a, s->r, -1.0, o, d, &best, hit);
    if (s->caps & RT_CAP_TOP)
        hit_disc(v3(s->a.x, s->a.y + s->h, s->a.z), s->r, 1.0, o, d, &best,
                 hit);
    if (!(best < tmax))
        return 0;
    hit->t = best;
    return 1;
}

static int hit_cone(const ref_shape *s, vec o, vec d, double tmax,
                    ref_hit *hit)
{
    /* |(x, z) - axis|^2 = k^2 Y^2 with Y = ay + h - y the depth below the
     * apex; along the ray Y = Y0 - t dy. */
    double k = s->r / s->h, k2 = k * k, best = tmax;
    double px = o.x - s->a.x, pz = o.z - s->a.z, Y0 = s->a.y + s->h - o.y;
    double A = d.x * d.x + d.z * d.z - k2 * d.y * d.y;
    double B = px * d.x + pz * d.z + k2 * Y0 * d.y;
    double C = px * px + pz * pz - k2 * Y0 * Y0;
    double disc = B * B - A * C, t[2];
    int i;
    if (disc >= 0) {
        /* A = 0 (ray along a generator) leaves the one root C / q. */
        stable_roots(A, B, C, disc, &t[0], &t[1]);
        for (i = 0; i < 2; i++) {
            if (closer(t[i], REF_EPS, best) && in_height(s, o, d, t[i])) {
                double x = px + t[i] * d.x, z = pz + t[i] * d.z;
                double rho = sqrt(x * x + z * z);
                best = t[i];
                hit->n_out = rho == 0 ? v3(0, 1, 0) : norm(v3(x, k * rho, z));
            }
        }
    }
    if (s->caps & RT_CAP_BOTTOM)
        hit_disc(s->a, s->r, -1.0, o, d, &best, hit);
    if (!(best < tmax))
        return 0;
    hit->t = best;
    return 1;
}

int ref_intersect(const ref_shape *sh, ref_vec3 o, ref_vec3 d, double tmax,
                  ref_hit *hit)
{
    switch (sh->kind) {
    case RT_SPHERE:
        return hit_sphere(sh, o, d, tmax, hit);
    case RT_QUAD:
        return hit_quad(sh, o, d, tmax, hit);
    case RT_BOX:
        return hit_box(sh, o, d, tmax, hit);
    case RT_CYLINDER:
        return hit_cylinder(sh, o, d, tmax, hit);
    case RT_CONE:
        return hit_cone(sh, o, d, tmax, hit);
    default:
        return 0;
    }
}

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

static int shape_ok(const ref_shape *sh)
{
    switch (sh->kind) {
    case RT_SPHERE:
        return sh->r > 0;
    case RT_QUAD:
        return len(cross(sh->b, sh->c)) > 0;
    case RT_BOX:
        return sh->b.x > sh->a.x && sh->b.y > sh->a.y && sh->b.z > sh->a.z;
    default:
        return sh->r > 0 && sh->h > 0;
    }
}

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
        if (!shape_ok(&rs->shape[i]))
            return RT_ERR_DEGENERATE;
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
    }
    colour = scale(mul(C, rs->ambient), diffuse * m->ka);
    for (i = 0; i < rs->n_lights; i++) {
        vec toL = sub(rs->light_pos[i], P), Lc = rs->light_col[i];
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
        double cosi = -dot(d, N);
        double k = 1.0 - eta * eta * (1.0 - cosi * cosi); /* Snell's law */
        vec t;
        if (k < 0) { /* total internal reflection */
            COUNT(reflection);
            t = trace(rs, P_out, mirror(d, N), depth + 1, skip_out);
        } else {
            COUNT(refraction);
            t = trace(rs, P_in,
                      norm(madd(scale(d, eta), N, eta * cosi - sqrt(k))),
                      depth + 1, skip_in);
        }
        colour = madd(colour, t, m->kt);
    }
    return colour;
}

static vec trace(const ref_scene *rs, vec o, vec d, int depth, int skip)
{
    ref_hit hit;
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
    if (st != RT_OK)
        return st;
    rs.stats = stats;
    for (y = y0; y < y1; y++) {
        size_t nbytes = (size_t)o->width * (o->format == RT_RGB888 ? 3 : 2);
        for (x = 0; x < o->width; x++) {
            uint8_t rgb[3];
            pixel(&rs, o->width, o->height, n, x, y, rgb);
            store(row_buf, o, x, y, rgb);
        }
        if (fn(ctx, y, row_buf, nbytes))
            return RT_ERR_ABORTED;
    }
    return RT_OK;
}
