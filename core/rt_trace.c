/*
 * rt_trace: Whitted ray tracing in Q16.16 (docs/render-model.md):
 * ambient + Lambert + Phong from point lights with hard shadows, recursive
 * reflection and refraction with total internal reflection. Recursion is
 * capped by RT_MAX_DEPTH at compile time and by the caller's depth.
 */
#include "rt_libc.h"
#include "rt_trace.h"

#define NO_SKIP 0xFFFFu

static rt_rgb rgb(fx_t r, fx_t g, fx_t b)
{
    rt_rgb c;
    c.r = r;
    c.g = g;
    c.b = b;
    return c;
}

/* Colour arithmetic needs no saturation: rt_render_rows accepts only
 * scenes whose colours and coefficients lie in the parser's ranges (lights
 * and ambient <= 16, the rest <= 1, kr + kt <= 1), so a channel stays below
 * RT_COLOUR_BOUND through every bounce. Rounding is fx_mul's. */
#define RT_COLOUR_BOUND ((16 + 32 * RT_MAX_LIGHTS) * (RT_MAX_DEPTH + 1))
#if RT_COLOUR_BOUND * 16 >= 32768
#error "RT_MAX_LIGHTS and RT_MAX_DEPTH allow colours beyond Q16.16"
#endif

static fx_t cmul(fx_t a, fx_t b)
{
    return (fx_t)(((int64_t)a * b + 0x8000) >> 16);
}

/* c += w * a (per channel). */
static void rgb_madd(rt_rgb *c, rt_rgb a, fx_t w)
{
    c->r += cmul(a.r, w);
    c->g += cmul(a.g, w);
    c->b += cmul(a.b, w);
}

/* a (*) b, per channel. */
static rt_rgb rgb_mul(rt_rgb a, rt_rgb b)
{
    return rgb(cmul(a.r, b.r), cmul(a.g, b.g), cmul(a.b, b.b));
}


#if RT_SEALED
/* Bit i of a set over objects. */
static int has(const uint32_t *set, unsigned i)
{
    return (int)((set[i / 32] >> (i % 32)) & 1u);
}
#endif

/* Tests object i for a nearer hit than *best. */
static void try_nearest(const rt_tracer *tr, const rt_ray *r, unsigned i,
                        fx_t *best, uint16_t *obj, uint8_t *part)
{
    fx_t ti;
    uint8_t pi;
    RT_COUNT(tr, tests);
    if (rt_intersect(&tr->scene->obj[i], r, RT_EPS, *best, &ti, &pi)) {
        *best = ti;
        *obj = (uint16_t)i;
        *part = pi;
    }
}

/* Nearest hit among all objects but `skip`, of a ray leaving object
 * `from` (NO_SKIP: unknown). Objects go in index order either way, so
 * exact ties resolve alike. */
static int nearest(const rt_tracer *tr, const rt_ray *r, unsigned skip,
                   unsigned from, fx_t *t, uint16_t *obj, uint8_t *part)
{
    const rt_scene *s = tr->scene;
    fx_t best = FX_MAX;
#if RT_SEALED
    /* A closed convex object skips itself exactly for rays leaving its
     * outside, so this ray runs inside `from`. */
    if (skip == NO_SKIP && from < s->n_objects && has(tr->alone, from)) {
        try_nearest(tr, r, from, &best, obj, part);
        *t = best;
        return best != FX_MAX;
    }
#endif
#if RT_DIR_GRIDS
    const rt_dir_grids *gs = &tr->grids;
    if (from < s->n_objects && gs->from[from] != RT_DIR_NONE) {
        const uint32_t *cand = rt_dir_cell(&gs->grid[gs->from[from]],
                                           r->d.x, r->d.y, r->d.z,
                                           gs->words);
        for (unsigned w = 0; cand && w < gs->words; w++) {
            for (uint32_t m = cand[w]; m; m &= m - 1) {
                unsigned i = w * 32 + (unsigned)fx_ctz32(m);
                if (i != skip)
                    try_nearest(tr, r, i, &best, obj, part);
            }
        }
        *t = best;
        return best != FX_MAX;
    }
#else
    (void)from;
#endif
    for (unsigned i = 0; i < s->n_objects; i++)
        if (i != skip)
            try_nearest(tr, r, i, &best, obj, part);
    *t = best;
    return best != FX_MAX;
}

#if !defined(RT_NO_SHADOWS)
#if RT_DIR_GRIDS
/* 1 if the bit set cand (NULL: empty) lists an object other than skip:
 * a shadow ray from a floor point often has only the floor to test. */
static int listed_besides(const uint32_t *cand, unsigned words,
                          unsigned skip)
{
    for (unsigned w = 0; cand && w < words; w++) {
        uint32_t m = cand[w];
        if (skip / 32 == w)
            m &= ~((uint32_t)1 << (skip % 32));
        if (m)
            return 1;
    }
    return 0;
}
#endif

/* Tests object i for a blocker of shadow ray r; remembers it. */
static int blocks(const rt_tracer *tr, const rt_ray *r, fx_t tmax,
                  unsigned i, unsigned light)
{
    fx_t ti;
    uint8_t pi;
    RT_COUNT(tr, tests);
    if (!rt_intersect(&tr->scene->obj[i], r, RT_EPS, tmax, &ti, &pi))
        return 0;
    tr->blocker[light] = (uint16_t)i;
    return 1;
}

/* Any blocker with RT_EPS < t < tmax among the candidates (a bit set of
 * object indices, or NULL for all objects): stops at the first. The
 * light's last blocker is tried first (neighbouring shadow rays tend to
 * share it); the answer does not depend on the order, only the count of
 * tests does. */
static int occluded(const rt_tracer *tr, const rt_ray *r, fx_t tmax,
                    unsigned skip, unsigned light, const uint32_t *cand)
{
    const rt_scene *s = tr->scene;
    unsigned first = tr->blocker[light];
    if (first < s->n_objects && first != skip &&
        (!cand || ((cand[first / 32] >> (first % 32)) & 1u)) &&
        blocks(tr, r, tmax, first, light))
        return 1;
#if RT_DIR_GRIDS
    if (cand) {
        for (unsigned w = 0; w < tr->grids.words; w++)
            for (uint32_t m = cand[w]; m; m &= m - 1) {
                unsigned i = w * 32 + (unsigned)fx_ctz32(m);
                if (i != skip && i != first &&
                    blocks(tr, r, tmax, i, light))
                    return 1;
            }
        return 0;
    }
#endif
    for (unsigned i = 0; i < s->n_objects; i++)
        if (i != skip && i != first && blocks(tr, r, tmax, i, light))
            return 1;
    return 0;
}
#endif

#if !defined(RT_NO_SPECULAR)
/* x^n for 0 <= x <= 1 by squaring; each step rounds to nearest. */
static fx_t fx_powi(fx_t x, unsigned n)
{
    fx_t r = FX_ONE;
    while (n) {
        if (n & 1)
            r = fx_mul(r, x);
        n >>= 1;
        if (n)
            x = fx_mul(x, x);
    }
    return r;
}
#endif

#if !defined(RT_NO_REFLECTION) || !defined(RT_NO_REFRACTION)
/* Weight of a ray spawned with coefficient k by a ray of weight w, rounded
 * up so that it never understates what the ray can add. */
static fx_t child_weight(fx_t w, fx_t k)
{
    return (fx_t)(((int64_t)w * k + 0xFFFF) >> 16);
}

/* 1 if a ray of weight w at this depth must be traced. If not, its colour
 * is taken as 0: its bound w B is taken off the sample's budget, so all
 * the rays a sample skips add up to less than its budget per channel. */
static int worth_tracing(const rt_tracer *tr, fx_t w, unsigned depth)
{
    uint64_t cost = (uint64_t)(uint32_t)w * tr->bound[tr->max_depth - depth];
    if (cost >= *tr->budget)
        return 1;
    *tr->budget -= (uint32_t)cost;
    RT_COUNT(tr, cut);
    return 0;
}

/* Mirror direction d - 2 (d.n) n, renormalised. */
static fx_vec3 reflect_dir(fx_vec3 d, fx_vec3 n)
{
    /* d and n are unit vectors: |2 d.n| <= 2. */
    return fx_v3_normalize(fx_v3_madd_unit(d, n, -2 * fx_v3_dotn(d, n)));
}
#endif

#if !defined(RT_NO_SHADOWS) || !defined(RT_NO_REFLECTION) || \
    !defined(RT_NO_REFRACTION)
/* Moves the hit point *p off the surface by off along the unit normal ng
 * (towards the ray), once. |off| <= 2^17. */
static inline void out_point(fx_vec3 *p, int *done, fx_vec3 ng, fx_t off)
{
    if (!*done) {
        *p = fx_v3_madd_unit(*p, ng, off);
        *done = 1;
    }
}
#endif

/* Colour of the hit (object oi, part, distance t) seen along r. */
static rt_rgb shade(const rt_tracer *tr, const rt_ray *r, unsigned depth,
                    fx_t w, uint16_t oi, uint8_t part, fx_t t)
{
    const rt_scene *s = tr->scene;
    const rt_object *o = &s->obj[oi];
    const rt_material *m = &s->mat[o->material];
    /* d is a unit vector: below 16384 units the cheaper form is exact. */
    fx_vec3 p = t <= ((fx_t)1 << 30) ? fx_v3_madd_unit(r->o, r->d, t)
                                     : fx_v3_madd(r->o, r->d, t);
    const fx_vec3 ng_out = rt_normal(o, p, part);
    fx_vec3 ng = ng_out;
    int outside = o->kind == RT_QUAD || fx_v3_dot_q32(r->d, ng) <= 0;
    if (fx_v3_dot_q32(r->d, ng) > 0)
        ng = fx_v3_neg(ng); /* face the ray */
    fx_vec3 n = ng;
#if !defined(RT_NO_BUMP)
    if (m->bump != 0)
        n = rt_bump(m, o, p, ng);
#endif
    unsigned tex = 0; /* which colour: m->color, or color2 */
#if !defined(RT_NO_TEXTURES)
    if (m->texture != RT_TEX_NONE) /* read inside: see render-model.md */
        tex = rt_texel(m, o, fx_v3_madd_unit(p, ng_out, -RT_EPS));
#endif
    const rt_rgb base = tex ? m->color2 : m->color;
    /* Cylinders and cones are solved in a frame whose unit is 2^ushift
     * ulps, so a secondary ray's root on its own surface is off by about
     * that much over the cosine of its angle to the surface. Starting it
     * 4 frame units off the surface (never less than EPS) keeps that root
     * behind it at any angle: no acne on large open shapes' inner walls. */
    fx_t off = RT_EPS;
    if ((o->kind == RT_CYLINDER || o->kind == RT_CONE) && o->ushift > 4)
        off = (fx_t)1 << (o->ushift + 2);
    /* Where rays leaving on the ray's side start: made on first use, as
     * many hits cast no ray at all. */
    fx_vec3 p_out = p;
    int have_out = 0;
    unsigned skip_out = (o->convex && outside) ? oi : NO_SKIP;
#if defined(RT_NO_SHADOWS) && defined(RT_NO_REFLECTION) && \
    defined(RT_NO_REFRACTION)
    (void)off, (void)p_out, (void)have_out, (void)skip_out; /* no rays */
#endif
    rt_rgb c = tr->amb[o->material][tex];
    fx_t kdl = tr->kdl[o->material];
#if defined(RT_NO_MULTILIGHT)
    const unsigned n_lights = s->n_lights ? 1 : 0; /* checked at start */
#else
    const unsigned n_lights = s->n_lights;
#endif
#if RT_SEALED
    /* Inside a closed object every light outside it is hidden. */
    const int dark = !outside && has(tr->dark, oi);
#else
    const int dark = 0;
#endif
    for (unsigned li = 0; !dark && li < n_lights; li++) {
        const rt_light *l = &s->light[li];
        fx_vec3 lv = fx_v3_sub(l->pos, p);
        fx_vec3 ld = fx_v3_normalize(lv);
        fx_t ndl = fx_v3_dotn(n, ld);
        if (ndl <= 0)
            continue;
#if !defined(RT_NO_SHADOWS)
        if (tr->feat & RT_FEAT_SHADOWS) {
            const uint32_t *cand = 0; /* every object */
            int any = 1;
#if RT_DIR_GRIDS
            const rt_dir_grids *gs = &tr->grids;
            if (gs->light[li] != RT_DIR_NONE) {
                /* Seen from the light, the ray runs along -ld. */
                cand = rt_dir_cell(&gs->grid[gs->light[li]], -ld.x, -ld.y,
                                   -ld.z, gs->words);
                any = listed_besides(cand, gs->words, skip_out);
            }
#endif
            RT_COUNT(tr, shadow);
            if (any) {
                rt_ray sr;
                out_point(&p_out, &have_out, ng, off);
                rt_ray_set(&sr, p_out, ld);
                /* |lv| = lv . norm(lv): a bounded dot product instead of
                 * a second square root; its error (~1e-5 |lv|) only moves
                 * the far end of the shadow ray, by far less than
                 * RT_EPS. */
                if (occluded(tr, &sr, fx_sub(fx_v3_dotn(lv, ld), RT_EPS),
                             skip_out, li, cand))
                    continue;
            }
        }
#endif
        rt_rgb lc;
        if (li == 0)
            lc = tr->lit[o->material][tex];
        else
            lc = rgb_mul(base, l->color);
        rgb_madd(&c, lc, fx_mul(kdl, ndl));
#if !defined(RT_NO_SPECULAR)
        if (m->specular > 0) {
            /* R = 2 (n.l) n - l; rv = R.v with v = -d. */
            fx_vec3 rl = fx_v3_madd_unit(fx_v3_neg(ld), n, 2 * ndl);
            fx_t rv = fx_neg(fx_v3_dotn(rl, r->d));
            if (rv > tr->spec_min[o->material])
                rgb_madd(&c, l->color, fx_mul(m->specular,
                                              fx_powi(rv, m->shininess)));
        }
#endif
    }
    if (depth >= tr->max_depth)
        return c;
#if defined(RT_NO_REFLECTION) && defined(RT_NO_REFRACTION)
    (void)w;
#endif
#if !defined(RT_NO_REFLECTION)
    fx_t wr = child_weight(w, m->reflect);
    if (m->reflect > 0 && worth_tracing(tr, wr, depth + 1)) {
        rt_ray rr;
        out_point(&p_out, &have_out, ng, off);
        rt_ray_set(&rr, p_out, reflect_dir(r->d, n));
        RT_COUNT(tr, reflection);
        rgb_madd(&c, rt_trace(tr, &rr, depth + 1, wr, skip_out, oi),
                 m->reflect);
    }
#endif
#if !defined(RT_NO_REFRACTION)
    fx_t wt = child_weight(w, m->transparency);
    if (m->transparency > 0 && worth_tracing(tr, wt, depth + 1)) {
        fx_t eta = outside ? m->ior_inv : m->ior;
        fx_t cosi = fx_neg(fx_v3_dotn(r->d, n));
        fx_t sin2 = fx_sub(FX_ONE, fx_mul(cosi, cosi));
        fx_t k = fx_sub(FX_ONE, fx_mul(fx_mul(eta, eta), sin2));
        rt_ray tr2;
        if (k < 0) { /* total internal reflection */
            out_point(&p_out, &have_out, ng, off);
            rt_ray_set(&tr2, p_out, reflect_dir(r->d, n));
            RT_COUNT(tr, reflection);
            rgb_madd(&c, rt_trace(tr, &tr2, depth + 1, wt, skip_out, oi),
                     m->transparency);
        } else { /* Snell's law */
            fx_t f = fx_sub(fx_mul(eta, cosi), fx_sqrt(k));
            fx_vec3 td = fx_v3_normalize(
                fx_v3_madd(fx_v3_scale(r->d, eta), n, f));
            unsigned skip_in =
                (o->convex && (!outside || o->kind == RT_QUAD)) ? oi
                                                                 : NO_SKIP;
            rt_ray_set(&tr2, fx_v3_madd_unit(p, ng, -off), td);
            RT_COUNT(tr, refraction);
            rgb_madd(&c, rt_trace(tr, &tr2, depth + 1, wt, skip_in, oi),
                     m->transparency);
        }
    }
#endif
    return c;
}

rt_rgb rt_trace(const rt_tracer *tr, const rt_ray *r, unsigned depth,
                fx_t w, unsigned skip, unsigned from)
{
    fx_t t;
    uint16_t oi = 0;
    uint8_t part = 0;
    if (!nearest(tr, r, skip, from, &t, &oi, &part))
        return tr->scene->background;
    return shade(tr, r, depth, w, oi, part, t);
}

rt_rgb rt_trace_camera(const rt_tracer *tr, const rt_ray *r,
                       const rt_span *spans, unsigned n_spans, unsigned x)
{
    const rt_scene *s = tr->scene;
    fx_t best = FX_MAX;
    uint16_t oi = 0;
    uint8_t part = 0;
    int found = 0;
#if RT_CUTOFF
    *tr->budget = tr->cut_budget; /* a new sample */
#endif
    for (unsigned k = 0; k < n_spans; k++) {
        fx_t ti;
        uint8_t pi;
        if (x < (unsigned)spans[k].x0 || x > (unsigned)spans[k].x1)
            continue;
        RT_COUNT(tr, tests);
        if (rt_intersect(&s->obj[spans[k].obj], r, RT_EPS, best, &ti, &pi)) {
            best = ti;
            oi = spans[k].obj;
            part = pi;
            found = 1;
        }
    }
    if (!found)
        return s->background;
    return shade(tr, r, 0, FX_ONE, oi, part, best);
}

#if RT_SEALED
/* 1 if the sphere (c, r) holds no point within d of p: |p - c| > r + d,
 * decided conservatively (distance rounded down, radii up). */
static int apart(fx_vec3 p, fx_vec3 c, fx_t r, fx_t d)
{
    int64_t lim = (int64_t)r + d; /* < 2^32 */
    int64_t dx = (int64_t)p.x - c.x, dy = (int64_t)p.y - c.y;
    int64_t dz = (int64_t)p.z - c.z;
    dx = dx < 0 ? -dx : dx;
    dy = dy < 0 ? -dy : dy;
    dz = dz < 0 ? -dz : dz;
    if (dx > lim || dy > lim || dz > lim)
        return 1;
    /* Every term is now below 2^32; 2 bits less keep the sum in 64. */
    uint64_t ux = (uint64_t)dx >> 2, uy = (uint64_t)dy >> 2;
    uint64_t uz = (uint64_t)dz >> 2, ul = ((uint64_t)lim + 3) >> 2;
    return ux * ux + uy * uy + uz * uz > ul * ul;
}

static int closed(const rt_object *o)
{
    return o->kind == RT_SPHERE || o->kind == RT_BOX ||
           (o->kind == RT_CYLINDER &&
            o->caps == (RT_CAP_BOTTOM | RT_CAP_TOP)) ||
           (o->kind == RT_CONE && (o->caps & RT_CAP_BOTTOM));
}

/* tr->alone and tr->dark, for the objects rays can enter (transparent
 * ones): inside rays come only from refraction. */
static void find_sealed(rt_tracer *tr)
{
    const rt_scene *s = tr->scene;
    memset(tr->alone, 0, sizeof tr->alone);
    memset(tr->dark, 0, sizeof tr->dark);
    for (unsigned i = 0; i < s->n_objects; i++) {
        const rt_object *o = &s->obj[i];
        if (!closed(o) || s->mat[o->material].transparency == 0)
            continue;
        int alone = 1, dark = (tr->feat & RT_FEAT_SHADOWS) != 0;
        for (unsigned j = 0; alone && j < s->n_objects; j++)
            if (j != i && !apart(s->obj[j].bc, o->bc, o->br, s->obj[j].br))
                alone = 0;
        for (unsigned li = 0; dark && li < s->n_lights; li++)
            if (!apart(s->light[li].pos, o->bc, o->br, 0))
                dark = 0;
        tr->alone[i / 32] |= (uint32_t)alone << (i % 32);
        tr->dark[i / 32] |= (uint32_t)dark << (i % 32);
    }
}
#endif

#if RT_CUTOFF
static fx_t channel(rt_rgb c, unsigned k)
{
    return k == 0 ? c.r : (k == 1 ? c.g : c.b);
}

/* a b / 2^16 rounded up, for a, b >= 0. */
static int64_t mul_up(int64_t a, int64_t b)
{
    return (a * b + 0xFFFF) >> 16;
}

/* Above every channel of any colour shade() can return before it adds
 * reflected and refracted light, and of the background (Q16.16). Each
 * term is rounded up. A highlight is allowed 1/8 more than ks, because
 * a cosine rounded to just past 1 grows under a high power; 16 ulps per
 * light cover the rest of shade()'s roundings. */
static int64_t local_bound(const rt_scene *s)
{
    int64_t top = 0;
    for (unsigned k = 0; k < 3; k++) {
        if (channel(s->background, k) > top)
            top = channel(s->background, k);
        for (unsigned i = 0; i < s->n_materials; i++) {
            const rt_material *m = &s->mat[i];
            int64_t base = channel(m->color, k), wl;
            if (m->texture != RT_TEX_NONE && channel(m->color2, k) > base)
                base = channel(m->color2, k);
            wl = (int64_t)FX_ONE - m->reflect - m->transparency;
            wl = wl < 0 ? 0 : wl;
            int64_t c = mul_up(mul_up(base, channel(s->ambient, k)),
                               mul_up(wl, m->ambient));
            int64_t spec = m->specular + m->specular / 8 + 1;
            for (unsigned li = 0; li < s->n_lights; li++) {
                int64_t lc = channel(s->light[li].color, k);
                c += mul_up(lc, mul_up(mul_up(wl, m->diffuse), base) + spec) +
                     16;
            }
            if (c > top)
                top = c;
        }
    }
    return top;
}
#endif

void rt_tracer_prepare(rt_tracer *tr)
{
    const rt_scene *s = tr->scene;
    for (unsigned i = 0; i < s->n_materials; i++) {
        const rt_material *m = &s->mat[i];
        fx_t wl = fx_sub(fx_sub(FX_ONE, m->reflect), m->transparency);
        if (wl < 0)
            wl = 0;
        for (unsigned k = 0; k < 2; k++) {
            rt_rgb base = k ? m->color2 : m->color, c = rgb(0, 0, 0);
            rgb_madd(&c, rgb_mul(base, s->ambient), fx_mul(wl, m->ambient));
            tr->amb[i][k] = c;
            tr->lit[i][k] =
                s->n_lights ? rgb_mul(base, s->light[0].color) : c;
        }
        tr->kdl[i] = fx_mul(wl, m->diffuse);
#if !defined(RT_NO_SPECULAR)
        /* ks rv^n rounds up monotonically in rv (each step does), so the
         * cosines whose highlight is 0 end at one found by bisection; the
         * test against it skips a power and a product that add 0. */
        fx_t lo = 0, hi = FX_ONE;
        while (hi - lo > 1) {
            fx_t mid = lo + (hi - lo) / 2;
            if (fx_mul(m->specular, fx_powi(mid, m->shininess)) == 0)
                lo = mid;
            else
                hi = mid;
        }
        tr->spec_min[i] = lo;
#endif
    }
#if RT_CUTOFF
    /* With k bounces left a ray adds at most kr + kt <= 1 times the
     * bound for k - 1 (plus two roundings) to its local colour. */
    int64_t local = local_bound(s), kmax = 0;
    for (unsigned i = 0; i < s->n_materials; i++)
        if ((int64_t)s->mat[i].reflect + s->mat[i].transparency > kmax)
            kmax = (int64_t)s->mat[i].reflect + s->mat[i].transparency;
    int64_t b = local;
    for (unsigned k = 0; k <= RT_MAX_DEPTH; k++) {
        tr->bound[k] = b > INT32_MAX ? (uint32_t)INT32_MAX : (uint32_t)b;
        b = local + mul_up(kmax, b) + 2;
    }
#endif
#if RT_SEALED
    find_sealed(tr);
#endif
#if RT_DIR_GRIDS
    rt_dir_grids_prepare(&tr->grids, s);
#endif
}
