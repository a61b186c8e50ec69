/* SPDX-License-Identifier: MIT */
/*
 * rt_antialias: the camera rays of each pixel of a row, and their mean.
 * A row first learns which objects its rays may hit and in which columns
 * (rt_cull); each pixel then takes the mean of its n x n grid of samples,
 * or, with adaptive anti-aliasing, its centre sample unless its
 * neighbourhood differs.
 */
#include "rt_draft.h"
#include "rt_pixel.h"

static fx_t clamp01(fx_t v)
{
    return v < 0 ? 0 : (v > FX_ONE ? FX_ONE : v);
}

typedef rt_aa_spans row_spans;

static void row_setup(row_spans *rs, const rt_tracer *tr,
                      const rt_cam_frame *cf, const rt_options *o, unsigned y)
{
    const rt_scene *s = tr->scene;
    const unsigned n = cf->n;
    for (unsigned j = 0; j < n; j++) {
        int32_t sy = rt_cam_soff(cf, rt_cam_row_k(o->height, n, y, j));
        rs->base[j] = rt_cam_row_base(cf, sy);
    }
    if (RT_CULL) {
        rt_cull_row(s, cf, o->width, o->height, y, &rs->hit);
    } else {
        for (unsigned i = 0; i < s->n_objects; i++) {
            rs->hit.span[i].obj = (uint16_t)i;
            rs->hit.span[i].x0 = 0;
            rs->hit.span[i].x1 = INT16_MAX;
        }
        rs->hit.count = s->n_objects;
    }
    rs->lo = INT32_MAX;
    rs->hi = -1;
    for (unsigned k = 0; k < rs->hit.count; k++) {
        if (rs->hit.span[k].x0 < rs->lo)
            rs->lo = rs->hit.span[k].x0;
        if (rs->hit.span[k].x1 > rs->hi)
            rs->hi = rs->hit.span[k].x1;
    }
}

void rt_aa_row_setup(rt_aa_spans *rs, const rt_tracer *tr,
                     const rt_cam_frame *cf, const rt_options *o, unsigned y)
{
    row_setup(rs, tr, cf, o, y);
}

/* The sample at screen offset k (rt_cam_col_k) along the sample row whose
 * centre direction is base, in pixel column x. Not inlined: the row's
 * frame (under rt_cull_row) stays small. */
RT_NOINLINE static rt_rgb sample(const rt_tracer *tr, rt_work *wk,
                                 const rt_cam_frame *cf, const row_spans *rs,
                                 const rt_cam_ray *base, int32_t k,
                                 unsigned x)
{
    rt_ray r;
    rt_ray_set(&r, tr->scene->cam.eye,
               rt_cam_dir(cf, base, rt_cam_soff(cf, k)));
    RT_COUNT(wk, primary);
    return rt_trace_camera(tr, wk, &r, &rs->hit, x);
}

/* One pixel: the mean of its n x n samples (cf->n), rounded to 8 bits. */
static void pixel(const rt_tracer *tr, rt_work *wk, const rt_cam_frame *cf,
                  const row_spans *rs, const rt_options *o, unsigned x,
                  uint8_t rgb8[3])
{
    /* Without supersampling n is 1 at compile time: the loops fold away. */
    const unsigned n = RT_HAS_SUPERSAMPLING ? cf->n : 1, spp = n * n;
    /* At most 16 samples of at most 2^16 each: 32 bits hold the sum. */
    uint32_t sum[3] = { 0, 0, 0 };
    const int covered = (int32_t)x >= rs->lo && (int32_t)x <= rs->hi;
    if (n == 1) { /* the common case, without the loops and the mean */
        rt_rgb c = tr->scene->background;
        if (covered)
            c = sample(tr, wk, cf, rs, &rs->base[0],
                       rt_cam_col_k(o->width, 1, x, 0), x);
        else if (RT_STATS && wk->stats)
            wk->stats->primary++;
        rgb8[0] = fx_to_u8(c.r); /* it clamps as clamp01 does */
        rgb8[1] = fx_to_u8(c.g);
        rgb8[2] = fx_to_u8(c.b);
        return;
    }
    if (!covered) {
        /* No object can be hit: every sample sees the background, and
         * needs no ray (rt_trace_camera would return the background). */
        const rt_rgb bg = tr->scene->background;
        if (RT_STATS && wk->stats)
            wk->stats->primary += spp;
        sum[0] = (uint32_t)clamp01(bg.r) * spp;
        sum[1] = (uint32_t)clamp01(bg.g) * spp;
        sum[2] = (uint32_t)clamp01(bg.b) * spp;
    }
    for (unsigned j = 0; covered && j < n; j++) {
        const rt_cam_ray *base = &rs->base[j];
        for (unsigned i = 0; i < n; i++) {
            rt_rgb c = sample(tr, wk, cf, rs, base,
                              rt_cam_col_k(o->width, n, x, i), x);
            sum[0] += (uint32_t)clamp01(c.r);
            sum[1] += (uint32_t)clamp01(c.g);
            sum[2] += (uint32_t)clamp01(c.b);
        }
    }
    for (int k = 0; k < 3; k++)
        rgb8[k] =
            fx_to_u8((fx_t)(spp <= 1 ? sum[k] : (sum[k] + spp / 2) / spp));
}

/* Pixels x0 <= x < x1 of row y (whose first pixel is column base) in
 * the background's bytes bg. */
RT_NOINLINE static void put_background(uint8_t *row, rt_work *wk,
                                       const rt_options *o, unsigned y,
                                       unsigned base, int32_t x0, int32_t x1,
                                       const uint8_t bg[3])
{
    if (RT_STATS && wk->stats && x1 > x0)
        wk->stats->primary += (unsigned)(x1 - x0);
    for (int32_t x = x0; x < x1; x++)
        rt_put_pixel(row, o, base, (unsigned)x, y, bg);
}

/* A row of at most this many spans is walked with only the spans that
 * cover each column handed to rt_trace_camera (active_spans). */
#define ACTIVE_MAX 16

/* Into *act, in object order, the spans of all[0..n) that cover column
 * x; returns the next column where that set changes (INT32_MAX: none).
 * Why: rt_nearest_camera tests every span's columns at every pixel; the
 * set changes only at the spans' ends, a few times a row. Out of
 * line: so rarely called, it would only add flash. */
RT_NOINLINE static int32_t active_spans(rt_row_spans *act, const rt_span *all,
                            unsigned n, int32_t x)
{
    int32_t next = INT32_MAX;
    unsigned c = 0;
    for (unsigned k = 0; k < n; k++) {
        if (all[k].x0 > x) {
            next = all[k].x0 < next ? all[k].x0 : next;
        } else if (all[k].x1 >= x) {
            act->span[c++] = all[k];
            next = all[k].x1 < next ? all[k].x1 + 1 : next;
        }
    }
    act->count = c;
    return next;
}

/* One sample per pixel: the columns outside lo..hi see the background
 * (its bytes made once), and the camera rays of lo..hi are walked
 * (rt_cam_walk), not each made afresh, in one ray whose origin and
 * fx_v3_small are set once. Why: the per-pixel tests, calls and copies
 * of a general loop cost more than the walk itself saves. */
static void row_1spp(const rt_tracer *tr, rt_work *wk, row_spans *rs,
                     const rt_cam_frame *cf, const rt_options *o,
                     unsigned y, unsigned x0, unsigned x1, uint8_t *row)
{
    const int32_t w = (int32_t)x1, b = (int32_t)x0;
    const int32_t lo = rs->lo > b ? rs->lo : b;
    const int32_t hi = rs->hi < w ? rs->hi : w - 1;
    const rt_rgb bgc = tr->scene->background;
    const uint8_t bg[3] = { fx_to_u8(bgc.r), fx_to_u8(bgc.g),
                            fx_to_u8(bgc.b) }; /* as pixel() */
    if (lo > hi) {
        put_background(row, wk, o, y, x0, b, w, bg);
        return;
    }
    put_background(row, wk, o, y, x0, b, lo, bg);
    rt_cam_walk cw;
    rt_cam_walk_init(&cw, cf, &rs->base[0], o->width, (unsigned)lo,
                     (unsigned)hi);
    rt_ray r;
    r.o = tr->scene->cam.eye;
    r.small = (uint8_t)fx_v3_small(r.o);
    /* With few spans rs->hit holds only those covering x (all[] has
     * them all); a column none covers needs no ray: rt_trace_camera
     * would return the background. */
    rt_span all[ACTIVE_MAX];
    unsigned n_all = 0; /* the spans in all[]: none when there are more */
    int32_t next = INT32_MAX;
    if (rs->hit.count <= ACTIVE_MAX) {
        n_all = rs->hit.count;
        for (unsigned k = 0; k < n_all; k++)
            all[k] = rs->hit.span[k];
        next = lo;
    }
    for (int32_t x = lo;; x++) {
        if (x == next)
            next = active_spans(&rs->hit, all, n_all, x);
        rt_rgb c = bgc;
        RT_COUNT(wk, primary);
        if (rs->hit.count != 0) {
            r.d = rt_cam_walk_dir(&cw);
            r.e = fx_d3_unit_err(r.d);
            c = rt_trace_camera(tr, wk, &r, &rs->hit, (unsigned)x);
        }
        const uint8_t rgb8[3] = { fx_to_u8(c.r), fx_to_u8(c.g),
                                  fx_to_u8(c.b) }; /* as pixel() */
        rt_put_pixel(row, o, x0, (unsigned)x, y, rgb8);
        if (x == hi)
            break;
        rt_cam_walk_step(&cw);
    }
    put_background(row, wk, o, y, x0, hi + 1, w, bg);
}

void rt_aa_row(const rt_tracer *tr, rt_work *wk, const rt_cam_frame *cf,
               const rt_options *o, unsigned y, unsigned x0, unsigned x1,
               uint8_t *row)
{
    row_spans rs;
    row_setup(&rs, tr, cf, o, y);
    if ((RT_HAS_SUPERSAMPLING ? cf->n : 1) == 1) {
        row_1spp(tr, wk, &rs, cf, o, y, x0, x1, row);
        return;
    }
    for (unsigned x = x0; x < x1; x++) {
        uint8_t rgb8[3];
        pixel(tr, wk, cf, &rs, o, x, rgb8);
        rt_put_pixel(row, o, x0, x, y, rgb8);
    }
}

/* Adaptive anti-aliasing: each pixel starts from its centre sample; only a
 * pixel whose 3x3 neighbourhood of centre samples differs by more than
 * o->adaptive (in 8-bit levels, any channel) gets the full n x n grid. The
 * centre samples of rows y-1..y+1 live in the scratch part of row_buf, so a
 * band computes the rows around it too and any banding gives the same
 * bytes. Likewise a window's centre samples reach one column past each
 * side (c0..c1), which are computed and not emitted. With o->draft the
 * centre samples are a draft render's rows (rt_draft.h), whose scratch
 * follows. */
rt_status rt_aa_adaptive(const rt_tracer *tr, rt_work *wk,
                         const rt_cam_frame *cfn, const rt_options *o,
                         unsigned x0, int y0, unsigned x1, int y1,
                         uint8_t *row_buf, rt_row_fn fn, void *ctx)
{
    if (!RT_HAS_SUPERSAMPLING) /* rt_render_rows does not call it then */
        return RT_ERR_UNSUPPORTED;
    rt_cam_frame cf1_store;
    const rt_cam_frame *cf1 = &cf1_store;
    row_spans rs;
    rt_cam_setup(&cf1_store, tr->scene, o->width, o->height, 1);
    const unsigned w = o->width;
    /* The columns whose centre samples the window's pixels look at. */
    const unsigned c0 = x0 > 0 ? x0 - 1 : 0, c1 = x1 < w ? x1 : w - 1;
    const unsigned nc = c1 - c0 + 1;
    uint8_t *slot[3], *flags[3];
    int slot_y[3] = { -1, -1, -1 };
    rt_draft draft; /* with o->draft: the centre samples are a draft */
    for (int k = 0; k < 3; k++)
        slot[k] = row_buf + rt_pixel_bytes(o, x1 - x0) + (size_t)k * 3u * nc;
    if (RT_HAS_DRAFT && o->draft) {
        uint8_t *scratch = slot[2] + 3u * nc;
        rt_draft_init(&draft, tr, wk, cf1, o, c0, c1, scratch);
        for (int k = 0; k < 3; k++)
            flags[k] = scratch + rt_draft_slot_bytes(o, nc) +
                       (size_t)k * rt_draft_flag_bytes(nc);
    }
    for (int y = y0; y < y1; y++) {
        /* Centre samples of rows y-1, y, y+1 (clamped to the image). */
        const uint8_t *near[3];
        for (int d = -1; d <= 1; d++) {
            int yy =
                y + d < 0 ? 0 : (y + d >= o->height ? o->height - 1 : y + d);
            unsigned k = (unsigned)yy % 3u; /* yy >= 0: o->height >= 1 */
            if (slot_y[k] != yy && RT_HAS_DRAFT && o->draft) {
                rt_draft_row(&draft, (unsigned)yy, slot[k], flags[k]);
            } else if (slot_y[k] != yy) {
                row_setup(&rs, tr, cf1, o, (unsigned)yy);
                for (unsigned x = c0; x <= c1; x++)
                    pixel(tr, wk, cf1, &rs, o, x, slot[k] + 3 * (x - c0));
            }
            slot_y[k] = yy;
            near[d + 1] = slot[k];
        }
        row_setup(&rs, tr, cfn, o, (unsigned)y);
        for (unsigned x = x0; x < x1; x++) {
            const uint8_t *c = near[1] + 3 * (x - c0);
            unsigned contrast = 0;
            for (int d = 0; d < 3; d++) {
                for (int dx = -1; dx <= 1; dx++) {
                    unsigned xx = (x == 0 && dx < 0)       ? 0
                                  : (x + 1 == w && dx > 0) ? x
                                                           : x + (unsigned)dx;
                    const uint8_t *p = near[d] + 3 * (xx - c0);
                    for (int ch = 0; ch < 3; ch++) {
                        int diff = (int)p[ch] - (int)c[ch];
                        unsigned a = (unsigned)(diff < 0 ? -diff : diff);
                        if (a > contrast)
                            contrast = a;
                    }
                }
            }
            uint8_t rgb8[3] = { c[0], c[1], c[2] };
            if (contrast > o->adaptive)
                pixel(tr, wk, cfn, &rs, o, x, rgb8);
            else if (RT_STATS && RT_HAS_DRAFT && wk->stats && o->draft &&
                     ((flags[(unsigned)y % 3u][(x - c0) / 8] >>
                       ((x - c0) % 8)) & 1u))
                wk->stats->interpolated++;
            rt_put_pixel(row_buf, o, x0, x, (unsigned)y, rgb8);
        }
        if (fn(ctx, y, row_buf, rt_pixel_bytes(o, x1 - x0)) != 0)
            return RT_ERR_ABORTED;
    }
    return RT_OK;
}
