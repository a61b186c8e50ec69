/* SPDX-License-Identifier: MIT */
/*
 * rt_draft: draft renders by adaptive undersampling (rt_draft.h).
 *
 * Level L has spacing s = 2^L: its rows are y = 0, s, 2s, ... and the last
 * row, its columns likewise. Level RT_DRAFT_LEVELS is traced. A pixel of
 * level L < RT_DRAFT_LEVELS that is not on level L + 1 lies halfway
 * between two or four pixels of that level on a line through it: left and
 * right on a row of level L + 1; above and below, or the four diagonal
 * ones, on a row between. Next to the last column or row, where they are
 * not halfway, it is traced. It takes their rounded mean when they agree:
 * - the same signature: the objects and texture cells of every hit of the
 *   sample (draft_sign_hit), folded with which lights any of its
 *   shadow rays found blocked (the blocker cache of rt_work, emptied
 *   before each sample, tells: the cache changes which tests run, never
 *   their answers);
 * - colours no further apart than o->draft levels in any channel;
 * - no other object the row's spans allow at that column can be seen in
 *   front of them (rt_thin.h): this keeps thin objects and small far ones
 *   that fall between lattice pixels.
 * Otherwise it is traced, with the same samples as a full render. An
 * interpolated pixel keeps its neighbours' object and signature, their
 * farthest distance and the planes they all lie in front of, so finer
 * levels decide on it as on a traced one.
 *
 * Each level keeps two rows ("slots") of entries, ENTRY bytes per column
 * of that level, in the caller's scratch (put_entry: the layout).
 *
 * A window of the frame (columns c0..c1 of level 0) needs, on level l,
 * the columns that its pixels' neighbours reach: level l - 1's range
 * widened by 2^(l-1) on each side, clamped to the image, so 2^l - 1 in
 * all. Each entry depends only on its column, its row and the coarser
 * entries it is between, never on which other columns are computed, so
 * the window's pixels are those of the full frame.
 */
#include "rt_draft.h"
#include "rt_pixel.h"

#define MIXED 0xFFFEu /* the samples of a pixel hit different objects */
#define ENTRY 14u     /* bytes of a stored entry */

/* What the decisions keep of a pixel. */
typedef struct {
    uint8_t rgb[3];
    uint8_t interp; /* 1: interpolated, not traced */
    uint16_t obj;   /* object its samples hit, RT_NO_OBJECT, or MIXED */
    uint16_t sig;   /* signature: hits and shadows */
    uint16_t front; /* bit q: every hit lies in front of tracked quad q */
    fx_t t;         /* farthest hit distance (FX_MAX: a miss) */
} entry;

/* 1 if v is on the rows (or columns) of spacing s of an image n long. */
static int on_level(unsigned v, unsigned s, unsigned n)
{
    return v % s == 0 || v + 1 == n;
}

/* Index of v among them, and their count. */
static unsigned level_index(unsigned v, unsigned s)
{
    return v / s + (v % s != 0);
}

static unsigned level_count(unsigned s, unsigned n)
{
    return level_index(n - 1, s) + 1;
}

/* Column i of spacing s. */
static unsigned level_col(unsigned i, unsigned s, unsigned n)
{
    return i * s < n ? i * s : n - 1;
}

size_t rt_draft_flag_bytes(unsigned n)
{
    return ((size_t)n + 7) / 8;
}

/* At most this many columns of spacing s lie within level l's range for
 * n columns of level 0: it spans n - 1 + 2 (s - 1) columns (the margin
 * above), which hold (n - 1 + 2 s - 2) / s + 1 multiples of s, and the
 * image's last column may be one more. The whole row when that is less. */
static unsigned level_bound(unsigned s, unsigned n, unsigned w)
{
    const unsigned all = level_count(s, w);
    const unsigned most = (n - 1u + 2u * s - 2u) / s + 2u;
    return most < all ? most : all;
}

size_t rt_draft_slot_bytes(const rt_options *o, unsigned n)
{
    size_t b = 0;
    for (unsigned l = 1; l <= RT_DRAFT_LEVELS; l++)
        b += 2u * ENTRY * level_bound(1u << l, n, o->width);
    return b;
}

size_t rt_draft_bytes(const rt_options *o, unsigned n)
{
    return rt_draft_slot_bytes(o, n) + 3u * (size_t)n +
           rt_draft_flag_bytes(n);
}

/* Entries are stored little-endian: rgb, interp, obj, sig, front, t. */
static void put_entry(uint8_t *p, const entry *e)
{
    const uint32_t t = (uint32_t)e->t;
    p[0] = e->rgb[0];
    p[1] = e->rgb[1];
    p[2] = e->rgb[2];
    p[3] = e->interp;
    p[4] = (uint8_t)e->obj;
    p[5] = (uint8_t)(e->obj >> 8);
    p[6] = (uint8_t)e->sig;
    p[7] = (uint8_t)(e->sig >> 8);
    p[8] = (uint8_t)e->front;
    p[9] = (uint8_t)(e->front >> 8);
    for (unsigned b = 0; b < 4; b++)
        p[10 + b] = (uint8_t)(t >> (8 * b));
}

static void get_entry(const uint8_t *p, entry *e)
{
    uint32_t t = 0;
    e->rgb[0] = p[0];
    e->rgb[1] = p[1];
    e->rgb[2] = p[2];
    e->interp = p[3];
    e->obj = (uint16_t)(p[4] | p[5] << 8);
    e->sig = (uint16_t)(p[6] | p[7] << 8);
    e->front = (uint16_t)(p[8] | p[9] << 8);
    for (unsigned b = 0; b < 4; b++)
        t |= (uint32_t)p[10 + b] << (8 * b);
    e->t = (fx_t)t; /* the bits put_entry stored */
}

static void draft_sign_hit(void *ctx, const rt_scene *s, unsigned oi,
                           const rt_ray *r, fx_t t, fx_t w);

void rt_draft_init(rt_draft *d, const rt_tracer *tr, rt_work *wk,
                   const rt_cam_frame *cf, const rt_options *o, unsigned c0,
                   unsigned c1, uint8_t *scratch)
{
    const unsigned w = o->width;
    unsigned a = c0, b = c1; /* level l's range of columns */
    d->tr = tr;
    d->wk = wk;
    d->cf = cf;
    d->o = o;
    d->first[0] = c0;
    d->last[0] = c1;
    for (unsigned l = 1; l <= RT_DRAFT_LEVELS; l++) {
        const unsigned s = 1u << l, h = s / 2;
        a = a > h ? a - h : 0;
        b = b + h < w ? b + h : w - 1;
        /* The first column of the level at or after a, the last at or
         * before b; none (last < first) when no column lies between. */
        d->first[l] = level_index(a, s);
        d->last[l] = b + 1 == w ? level_count(s, w) - 1 : b / s;
        const unsigned count =
            d->last[l] + 1 > d->first[l] ? d->last[l] + 1 - d->first[l] : 0;
        for (unsigned k = 0; k < 2; k++) {
            d->slot[l - 1][k] = scratch;
            d->slot_y[l - 1][k] = -1;
            scratch += ENTRY * count;
        }
    }
    d->rs_y = -1;
    rt_thin_init(&d->thin, tr->scene);
    /* A hit of weight w moves its pixel by at most about 255 w levels:
     * below the threshold, its object and cell need not match. */
    d->sig = 0;
    d->sign_w = (fx_t)(((int64_t)o->draft << 16) / 255);
    wk->on_hit = draft_sign_hit;
    wk->hit_ctx = d;
}

/* The tracer's hit hook (rt_work.on_hit) during a draft render: folds
 * the hit into d->sig, the object and, if its material has a texture,
 * the cell; hits too faint to matter are left out. */
static void draft_sign_hit(void *ctx, const rt_scene *s, unsigned oi,
                           const rt_ray *r, fx_t t, fx_t w)
{
    rt_draft *d = ctx;
    const rt_object *o = &s->obj[oi];
    const rt_material *m = &s->mat[o->material];
    uint32_t h = d->sig * 31u + oi + 1u;
    if (w <= d->sign_w)
        return;
    if (RT_HAS_TEXTURES && m->texture != RT_TEX_NONE) {
        /* The cell (as rt_texel finds it, but at the hit itself), not
         * just its colour: two cells of one colour with another between
         * them look alike. */
        const fx_vec3 p = fx_v3_madd_d(r->o, r->d, t);
        const fx_t pk[3] = { p.x, p.y, p.z };
        const fx_vec3 a = o->u.origin;
        const fx_t ak[3] = { a.x, a.y, a.z };
        for (unsigned k = 0; k < 3; k++) {
            fx_t rem;
            int64_t c = fx_floor_div((int64_t)pk[k] - ak[k], m->tex_scale,
                                     m->tex_rcp, &rem);
            h = h * 131u + (uint32_t)c; /* wraps: a hash */
        }
    }
    d->sig = h;
}

/* Sets up d->rs for row y, unless it already is. */
static void setup_row(rt_draft *d, unsigned y)
{
    if (d->rs_y != (int32_t)y) {
        rt_aa_row_setup(&d->rs, d->tr, d->cf, d->o, y);
        rt_thin_row(&d->rs, d->tr->scene, d->cf, d->o->height, y);
        d->rs_y = (int32_t)y;
    }
}

/* The colour of camera ray r (nearest hit *h) as rt_trace_camera gives
 * it; *sig gets its signature. */
RT_NOINLINE static rt_rgb shade_sample(rt_draft *d, const rt_ray *r,
                                       const rt_hit *h, uint16_t *sig)
{
    rt_work *wk = d->wk;
    const unsigned n_lights = d->tr->scene->n_lights;
    for (unsigned li = 0; li < n_lights; li++)
        wk->blocker[li] = RT_NO_OBJECT; /* a blocker found now is set */
    d->sig = 0;
    rt_rgb c = rt_shade_camera(d->tr, wk, r, h);
    uint32_t v = d->sig;
    for (unsigned li = 0; li < n_lights; li++)
        v = v * 31u + (wk->blocker[li] != RT_NO_OBJECT);
    *sig = (uint16_t)(v ^ (v >> 16));
    return c;
}

static fx_t clamp01(fx_t v)
{
    return v < 0 ? 0 : (v > FX_ONE ? FX_ONE : v);
}

/* Traces pixel x of row d->rs_y as rt_aa_row would, into *e. r1, when not
 * NULL, is its centre ray (one sample per pixel only). */
static void trace_pixel(rt_draft *d, unsigned x, entry *e, const rt_ray *r1)
{
    const rt_tracer *tr = d->tr;
    rt_work *wk = d->wk;
    const unsigned n = RT_HAS_SUPERSAMPLING ? d->cf->n : 1, spp = n * n;
    const rt_aa_spans *rs = &d->rs;
    uint32_t sum[3] = { 0, 0, 0 };
    e->interp = 0;
    e->obj = RT_NO_OBJECT;
    e->sig = 0;
    e->t = FX_MAX;
    e->front = 0xFFFFu;
    if ((int32_t)x < rs->lo || (int32_t)x > rs->hi) {
        /* No object can be hit: the background, without a ray. */
        const rt_rgb bg = tr->scene->background;
        if (RT_STATS && wk->stats)
            wk->stats->primary += spp;
        e->rgb[0] = fx_to_u8(bg.r);
        e->rgb[1] = fx_to_u8(bg.g);
        e->rgb[2] = fx_to_u8(bg.b);
        e->sig = 0; /* as shade_sample signs a miss */
        e->front = 0; /* unknown: no plane is ruled out */
        return;
    }
    for (unsigned j = 0; j < n; j++) {
        for (unsigned i = 0; i < n; i++) {
            rt_ray r;
            rt_hit h;
            uint16_t sig;
            if (r1 && n == 1)
                r = *r1;
            else
                rt_thin_ray(tr->scene, d->cf, &rs->base[j],
                            rt_cam_col_k(d->o->width, n, x, i), &r);
            rt_probe_camera(tr, wk, &r, &rs->hit, x, &h);
            RT_COUNT(wk, primary);
            rt_rgb c = shade_sample(d, &r, &h, &sig);
            e->front &= rt_thin_front(&d->thin, tr->scene, &r, h.t);
            if (n == 1) {
                e->rgb[0] = fx_to_u8(c.r); /* it clamps as clamp01 does */
                e->rgb[1] = fx_to_u8(c.g);
                e->rgb[2] = fx_to_u8(c.b);
                e->obj = h.obj;
                e->sig = sig;
                e->t = h.t;
                return;
            }
            sum[0] += (uint32_t)clamp01(c.r);
            sum[1] += (uint32_t)clamp01(c.g);
            sum[2] += (uint32_t)clamp01(c.b);
            e->obj = (i == 0 && j == 0) || e->obj == h.obj ? h.obj : MIXED;
            e->sig = (uint16_t)(e->sig * 31u + sig);
            e->t = (i == 0 && j == 0) || h.t > e->t ? h.t : e->t;
        }
    }
    for (unsigned k = 0; k < 3; k++)
        e->rgb[k] = fx_to_u8(
            (fx_t)(spp <= 1 ? sum[k] : (sum[k] + spp / 2) / spp));
}

/* Pixel x of row d->rs_y halfway between the m (2 or 4) entries nb: their
 * mean when they agree (*e interpolated), else traced. */
static void between(rt_draft *d, unsigned x, unsigned m,
                    const entry *const nb[4], entry *e)
{
    const rt_aa_spans *rs = &d->rs;
    const entry *a = nb[0];
    fx_t tmax = a->t;
    unsigned front = a->front;
    rt_ray r;
    int have_ray = 0;
    if ((int32_t)x < rs->lo || (int32_t)x > rs->hi || a->obj == MIXED)
        goto trace; /* the background (exact and cheap), or mixed */
    for (unsigned i = 1; i < m; i++) {
        if (nb[i]->obj != a->obj || nb[i]->sig != a->sig)
            goto trace;
        tmax = nb[i]->t > tmax ? nb[i]->t : tmax;
        front &= nb[i]->front;
    }
    for (unsigned ch = 0; ch < 3; ch++) {
        unsigned lo = a->rgb[ch], hi = lo;
        for (unsigned i = 1; i < m; i++) {
            unsigned v = nb[i]->rgb[ch];
            lo = v < lo ? v : lo;
            hi = v > hi ? v : hi;
        }
        if (hi - lo > d->o->draft)
            goto trace;
    }
    if (rt_thin_may_hide(&d->thin, d->tr, d->wk, d->cf, rs, d->o->width, x,
                         a->obj, tmax, front, &r, &have_ray))
        goto trace;
    for (unsigned ch = 0; ch < 3; ch++) {
        unsigned sum = m / 2; /* rounded to nearest */
        for (unsigned i = 0; i < m; i++)
            sum += nb[i]->rgb[ch];
        e->rgb[ch] = (uint8_t)(sum >> (m / 2)); /* m is 2 or 4 */
    }
    e->interp = 1;
    e->obj = a->obj;
    e->sig = a->sig;
    e->t = tmax;
    e->front = (uint16_t)front;
    return;
trace:
    trace_pixel(d, x, e, have_ray ? &r : 0);
}

static void get_row(rt_draft *d, unsigned l, unsigned y, uint8_t **row);

/* Row y of level l into out (entries; level 0: rgb and flags). */
static void level_row(rt_draft *d, unsigned l, unsigned y, uint8_t *out,
                      uint8_t *flags)
{
    const unsigned w = d->o->width, h = d->o->height, s = 1u << l;
    const unsigned s2 = 2 * s, first = d->first[l], last = d->last[l];
    /* Entries of level l + 1 are stored from its first column on. */
    const unsigned up = l < RT_DRAFT_LEVELS ? d->first[l + 1] : 0;
    uint8_t *ra = 0, *rb = 0; /* rows of level l + 1: above, below */
    int between_rows = 0;
    if (l < RT_DRAFT_LEVELS) {
        if (on_level(y, s2, h)) {
            get_row(d, l + 1, y, &ra);
        } else if (y + s < h) {
            get_row(d, l + 1, y - s, &ra);
            get_row(d, l + 1, y + s, &rb);
            between_rows = 1;
        }
    }
    setup_row(d, y);
    for (unsigned i = first; i <= last; i++) {
        const unsigned x = level_col(i, s, w);
        entry e, nb[4];
        const entry *p[4] = { &nb[0], &nb[1], &nb[2], &nb[3] };
        const int on_col = on_level(x, s2, w), halfway = x + s < w;
        if (!ra || (!on_col && !halfway)) {
            trace_pixel(d, x, &e, 0); /* top level, or not halfway */
        } else if (!between_rows && on_col) {
            get_entry(ra + ENTRY * (level_index(x, s2) - up), &e);
        } else if (!between_rows) { /* left and right */
            get_entry(ra + ENTRY * (level_index(x - s, s2) - up), &nb[0]);
            get_entry(ra + ENTRY * (level_index(x + s, s2) - up), &nb[1]);
            between(d, x, 2, p, &e);
        } else if (on_col) { /* above and below */
            get_entry(ra + ENTRY * (level_index(x, s2) - up), &nb[0]);
            get_entry(rb + ENTRY * (level_index(x, s2) - up), &nb[1]);
            between(d, x, 2, p, &e);
        } else { /* the four diagonal ones */
            const unsigned i0 = level_index(x - s, s2) - up;
            const unsigned i1 = level_index(x + s, s2) - up;
            get_entry(ra + ENTRY * i0, &nb[0]);
            get_entry(ra + ENTRY * i1, &nb[1]);
            get_entry(rb + ENTRY * i0, &nb[2]);
            get_entry(rb + ENTRY * i1, &nb[3]);
            between(d, x, 4, p, &e);
        }
        if (l > 0) {
            put_entry(out + ENTRY * (i - first), &e);
        } else {
            const unsigned j = x - first; /* level 0: i is the column */
            out[3 * j] = e.rgb[0];
            out[3 * j + 1] = e.rgb[1];
            out[3 * j + 2] = e.rgb[2];
            if (j % 8 == 0)
                flags[j / 8] = 0;
            flags[j / 8] |= (uint8_t)(e.interp << (j % 8));
        }
    }
}

/* The entries of row y of level l >= 1 (y on that level), computed into
 * one of the level's two slots unless there. Consecutive rows of a level
 * alternate slots, so the two a finer row needs are both kept. */
static void get_row(rt_draft *d, unsigned l, unsigned y, uint8_t **row)
{
    const unsigned k = level_index(y, 1u << l) & 1u;
    if (d->slot_y[l - 1][k] != (int32_t)y) {
        level_row(d, l, y, d->slot[l - 1][k], 0);
        d->slot_y[l - 1][k] = (int32_t)y;
    }
    *row = d->slot[l - 1][k];
}

void rt_draft_row(rt_draft *d, unsigned y, uint8_t *rgb, uint8_t *flags)
{
    level_row(d, 0, y, rgb, flags);
}

rt_status rt_draft_render(const rt_tracer *tr, rt_work *wk,
                          const rt_cam_frame *cf, const rt_options *o,
                          unsigned x0, int y0, unsigned x1, int y1,
                          uint8_t *row_buf, rt_row_fn fn, void *ctx)
{
    rt_draft d;
    const unsigned n = x1 - x0;
    uint8_t *scratch = row_buf + rt_pixel_bytes(o, n);
    uint8_t *rgb = scratch + rt_draft_slot_bytes(o, n);
    uint8_t *flags = rgb + 3u * (size_t)n;
    rt_draft_init(&d, tr, wk, cf, o, x0, x1 - 1, scratch);
    for (int y = y0; y < y1; y++) {
        rt_draft_row(&d, (unsigned)y, rgb, flags);
        for (unsigned j = 0; j < n; j++) {
            rt_put_pixel(row_buf, o, x0, j + x0, (unsigned)y, rgb + 3 * j);
            if (RT_STATS && wk->stats && ((flags[j / 8] >> (j % 8)) & 1u))
                wk->stats->interpolated++;
        }
        if (fn(ctx, y, row_buf, rt_pixel_bytes(o, n)) != 0)
            return RT_ERR_ABORTED;
    }
    return RT_OK;
}
