/*
 * rt_render: camera rays, supersampling and the scanline boundary.
 * Each row depends only on its own y, so any banding of rows gives the
 * same bytes.
 */
#include "rt_libc.h"
#include "rt_trace.h"

void rt_options_from_scene(rt_options *o, const rt_scene *s)
{
    o->width = s->width;
    o->height = s->height;
    o->spp = s->spp;
    o->depth = s->depth;
    o->format = RT_RGB888;
    o->dither = 0;
    o->adaptive = 0;
    o->trace_all = 0;
}

size_t rt_row_bytes(const rt_options *o)
{
    return (size_t)o->width * (o->format == RT_RGB888 ? 3u : 2u);
}

/* Grid side n for spp = n * n, or 0 if spp is not a supported square. */
static unsigned grid_side(unsigned spp)
{
#if defined(RT_NO_SUPERSAMPLING)
    return spp == 1 ? 1 : 0; /* a constant: the sample loops fold away */
#else
    for (unsigned n = 1; n <= RT_MAX_SPP_SIDE; n++)
        if (n * n == spp)
            return n;
    return 0;
#endif
}

uint32_t rt_scene_features(const rt_scene *s, uint8_t spp)
{
    static const uint32_t kind_bit[RT_KIND_COUNT] = {
        RT_FEAT_SPHERE, RT_FEAT_QUAD, RT_FEAT_BOX, RT_FEAT_CYLINDER,
        RT_FEAT_CONE
    };
    uint32_t f = 0;
    for (unsigned i = 0; i < s->n_objects; i++) {
        const rt_material *m = &s->mat[s->obj[i].material];
        f |= kind_bit[s->obj[i].kind];
        if (m->reflect > 0)
            f |= RT_FEAT_REFLECTION;
        if (m->transparency > 0)
            f |= RT_FEAT_REFRACTION;
        if (m->texture != RT_TEX_NONE)
            f |= RT_FEAT_TEXTURES;
        if (m->bump != 0)
            f |= RT_FEAT_BUMP;
        if (m->specular > 0 && s->n_lights > 0)
            f |= RT_FEAT_SPECULAR;
    }
    if (s->shadows && s->n_lights > 0 && s->n_objects > 0)
        f |= RT_FEAT_SHADOWS;
    if (s->n_lights > 1)
        f |= RT_FEAT_MULTILIGHT;
    if (spp > 1)
        f |= RT_FEAT_SUPERSAMPLING;
    return f;
}

uint32_t rt_build_features(void)
{
    uint32_t f = 0xFFFFFFFFu;
#ifdef RT_NO_SHADOWS
    f &= ~RT_FEAT_SHADOWS;
#endif
#ifdef RT_NO_REFLECTION
    f &= ~RT_FEAT_REFLECTION;
#endif
#ifdef RT_NO_REFRACTION
    f &= ~RT_FEAT_REFRACTION;
#endif
#ifdef RT_NO_TEXTURES
    f &= ~RT_FEAT_TEXTURES;
#endif
#ifdef RT_NO_BUMP
    f &= ~RT_FEAT_BUMP;
#endif
#ifdef RT_NO_SPECULAR
    f &= ~RT_FEAT_SPECULAR;
#endif
#ifdef RT_NO_MULTILIGHT
    f &= ~RT_FEAT_MULTILIGHT;
#endif
#ifdef RT_NO_SUPERSAMPLING
    f &= ~RT_FEAT_SUPERSAMPLING;
#endif
#ifdef RT_NO_SPHERE
    f &= ~RT_FEAT_SPHERE;
#endif
#ifdef RT_NO_QUAD
    f &= ~RT_FEAT_QUAD;
#endif
#ifdef RT_NO_BOX
    f &= ~RT_FEAT_BOX;
#endif
#ifdef RT_NO_CYLINDER
    f &= ~RT_FEAT_CYLINDER;
#endif
#ifdef RT_NO_CONE
    f &= ~RT_FEAT_CONE;
#endif
    return f;
}

const char *rt_feature_name(uint32_t bit)
{
    static const char *const names[] = {
        "shadows", "reflection", "refraction", "textures", "bump",
        "specular", "multiple lights", "supersampling", "sphere", "quad",
        "box", "cylinder", "cone"
    };
    for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
        if (bit == (1u << i))
            return names[i];
    return "unknown";
}

typedef rt_cam_frame cam_frame;

static void cam_setup(cam_frame *cf, const rt_scene *s, const rt_options *o,
                      unsigned n)
{
    cf->w = fx_v3_normalize(fx_v3_sub(s->cam.look, s->cam.eye));
    cf->right = rt_cross_unit(s->cam.up, cf->w);
    cf->up = rt_cross_unit(cf->w, cf->right);
    cf->n = n;
    /* half < 2^31 in Q16.16, so half << 16 < 2^47. */
    int64_t half = rt_tan_half_deg(s->cam.fov);
    cf->step = (half * 65536) / (int64_t)(n * o->height);
}

/* Screen offset k * half / (n H) as Q16.16; |k| <= n * 2 * RT_MAX_WIDTH. */
static fx_t cam_offset(const cam_frame *cf, int32_t k)
{
    return fx_sat64(((int64_t)k * cf->step + 0x8000) >> 16);
}

static const uint8_t bayer4[4][4] = {
    { 0, 8, 2, 10 }, { 12, 4, 14, 6 }, { 3, 11, 1, 9 }, { 15, 7, 13, 5 }
};

/* Adds an ordered-dither threshold below one output step (8 for 5 bits,
 * 4 for 6 bits), so rounding down to 5/6 bits averages out. */
static unsigned dith(unsigned v, unsigned step, unsigned t)
{
    v += (t * step) / 16;
    return v > 255 ? 255 : v;
}

static void put_pixel(uint8_t *row, const rt_options *o, unsigned x,
                      unsigned y, const uint8_t rgb8[3])
{
    if (o->format == RT_RGB888) {
        row[3 * x] = rgb8[0];
        row[3 * x + 1] = rgb8[1];
        row[3 * x + 2] = rgb8[2];
        return;
    }
    unsigned r = rgb8[0], g = rgb8[1], b = rgb8[2];
    if (o->dither) {
        unsigned t = bayer4[y & 3][x & 3];
        r = dith(r, 8, t);
        g = dith(g, 4, t);
        b = dith(b, 8, t);
    }
    unsigned v = ((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3);
    uint8_t lo = (uint8_t)(v & 0xFF), hi = (uint8_t)(v >> 8);
    row[2 * x] = o->format == RT_RGB565_LE ? lo : hi;
    row[2 * x + 1] = o->format == RT_RGB565_LE ? hi : lo;
}

static fx_t clamp01(fx_t v)
{
    return v < 0 ? 0 : (v > FX_ONE ? FX_ONE : v);
}

/* Objects camera rays of one pixel row may hit (rt_cull). */
typedef struct {
    rt_span span[RT_MAX_OBJECTS];
    unsigned count;
    int32_t lo, hi; /* columns outside [lo, hi] can hit nothing */
    fx_vec3 base[RT_MAX_SPP_SIDE]; /* w + sy up for each sample row */
} row_spans;

static void row_setup(row_spans *rs, const rt_tracer *tr, const cam_frame *cf,
                      const rt_options *o, unsigned y)
{
    const rt_scene *s = tr->scene;
    const unsigned n = cf->n;
    for (unsigned j = 0; j < n; j++) {
        fx_t sy = cam_offset(cf, (int32_t)(o->height * n) -
                                     (int32_t)(2 * y * n + 2 * j + 1));
        rs->base[j] = fx_v3_madd(cf->w, cf->up, sy);
    }
#if RT_CULL
    rs->count = rt_cull_row(s, cf, o->width, o->height, y, rs->span);
#else
    (void)cf, (void)o, (void)y;
    for (unsigned i = 0; i < s->n_objects; i++) {
        rs->span[i].obj = (uint16_t)i;
        rs->span[i].x0 = 0;
        rs->span[i].x1 = INT16_MAX;
    }
    rs->count = s->n_objects;
#endif
    rs->lo = INT32_MAX;
    rs->hi = -1;
    for (unsigned k = 0; k < rs->count; k++) {
        if (rs->span[k].x0 < rs->lo)
            rs->lo = rs->span[k].x0;
        if (rs->span[k].x1 > rs->hi)
            rs->hi = rs->span[k].x1;
    }
}

/* The sample at screen offset k (cam_offset) along the row whose centre
 * direction is base, in pixel column x. */
static rt_rgb sample(const rt_tracer *tr, const cam_frame *cf,
                     const row_spans *rs, fx_vec3 base, int32_t k,
                     unsigned x)
{
    const fx_t lim = (fx_t)1 << 30; /* fx_v3_madd_unit's range */
    fx_t sx = cam_offset(cf, k);
    /* right is a unit vector: the cheaper madd gives the same values. */
    fx_vec3 d = sx >= -lim && sx <= lim ? fx_v3_madd_unit(base, cf->right, sx)
                                        : fx_v3_madd(base, cf->right, sx);
    rt_ray r;
    rt_ray_set(&r, tr->scene->cam.eye, fx_v3_normalize(d));
    RT_COUNT(tr, primary);
    return rt_trace_camera(tr, &r, rs->span, rs->count, x);
}

/* One pixel: the mean of its n x n samples (cf->n), rounded to 8 bits. */
static void pixel(const rt_tracer *tr, const cam_frame *cf,
                  const row_spans *rs, const rt_options *o, unsigned x,
                  unsigned y, uint8_t rgb8[3])
{
    const unsigned n = cf->n, spp = n * n;
    const int32_t wn = (int32_t)(o->width * n);
    (void)y;
    /* At most 16 samples of at most 2^16 each: 32 bits hold the sum. */
    uint32_t sum[3] = { 0, 0, 0 };
    const int covered = (int32_t)x >= rs->lo && (int32_t)x <= rs->hi;
    if (n == 1) { /* the common case, without the loops and the mean */
        rt_rgb c = tr->scene->background;
        if (covered)
            c = sample(tr, cf, rs, rs->base[0], (int32_t)(2 * x + 1) - wn, x);
#if RT_STATS
        else if (tr->stats)
            tr->stats->primary++;
#endif
        rgb8[0] = fx_to_u8(c.r); /* it clamps as clamp01 does */
        rgb8[1] = fx_to_u8(c.g);
        rgb8[2] = fx_to_u8(c.b);
        return;
    }
    if (!covered) {
        /* No object can be hit: every sample sees the background, and
         * needs no ray (rt_trace_camera would return the background). */
        const rt_rgb bg = tr->scene->background;
#if RT_STATS
        if (tr->stats)
            tr->stats->primary += spp;
#endif
        sum[0] = (uint32_t)clamp01(bg.r) * spp;
        sum[1] = (uint32_t)clamp01(bg.g) * spp;
        sum[2] = (uint32_t)clamp01(bg.b) * spp;
    }
    for (unsigned j = 0; covered && j < n; j++) {
        fx_vec3 base = rs->base[j];
        for (unsigned i = 0; i < n; i++) {
            rt_rgb c = sample(tr, cf, rs, base,
                              (int32_t)(2 * x * n + 2 * i + 1) - wn, x);
            sum[0] += (uint32_t)clamp01(c.r);
            sum[1] += (uint32_t)clamp01(c.g);
            sum[2] += (uint32_t)clamp01(c.b);
        }
    }
    for (int k = 0; k < 3; k++)
        rgb8[k] = fx_to_u8(
            (fx_t)(spp == 1 ? sum[k] : (sum[k] + spp / 2) / spp));
}

size_t rt_buffer_bytes(const rt_options *o)
{
    size_t extra = 0;
#if !defined(RT_NO_SUPERSAMPLING)
    if (o->adaptive && o->spp > 1)
        extra = 9u * o->width; /* three rows of 1-spp colours */
#endif
    return rt_row_bytes(o) + extra;
}

#if !defined(RT_NO_SUPERSAMPLING)
/* Adaptive anti-aliasing: each pixel starts from its centre sample; only a
 * pixel whose 3x3 neighbourhood of centre samples differs by more than
 * o->adaptive (in 8-bit levels, any channel) gets the full n x n grid. The
 * centre samples of rows y-1..y+1 live in the scratch part of row_buf, so a
 * band computes the rows around it too and any banding gives the same
 * bytes. */
static rt_status render_adaptive(const rt_tracer *tr, const cam_frame *cfn,
                                 const rt_options *o, int y0, int y1,
                                 uint8_t *row_buf, rt_row_fn fn, void *ctx)
{
    cam_frame cf1_store;
    const cam_frame *cf1 = &cf1_store;
    row_spans rs;
    cam_setup(&cf1_store, tr->scene, o, 1);
    const unsigned w = o->width;
    uint8_t *slot[3];
    int slot_y[3] = { -1, -1, -1 };
    for (int k = 0; k < 3; k++)
        slot[k] = row_buf + rt_row_bytes(o) + (size_t)k * 3u * w;
    for (int y = y0; y < y1; y++) {
        /* Centre samples of rows y-1, y, y+1 (clamped to the image). */
        const uint8_t *near[3];
        for (int d = -1; d <= 1; d++) {
            int yy = y + d < 0 ? 0 : (y + d >= o->height ? o->height - 1
                                                         : y + d);
            int k = yy % 3;
            if (slot_y[k] != yy) {
                row_setup(&rs, tr, cf1, o, (unsigned)yy);
                for (unsigned x = 0; x < w; x++)
                    pixel(tr, cf1, &rs, o, x, (unsigned)yy, slot[k] + 3 * x);
                slot_y[k] = yy;
            }
            near[d + 1] = slot[k];
        }
        row_setup(&rs, tr, cfn, o, (unsigned)y);
        for (unsigned x = 0; x < w; x++) {
            const uint8_t *c = near[1] + 3 * x;
            unsigned contrast = 0;
            for (int d = 0; d < 3; d++) {
                for (int dx = -1; dx <= 1; dx++) {
                    unsigned xx = (x == 0 && dx < 0) ? 0
                                  : (x + 1 == w && dx > 0) ? x
                                                           : x + (unsigned)dx;
                    for (int ch = 0; ch < 3; ch++) {
                        int diff = (int)near[d][3 * xx + ch] - (int)c[ch];
                        unsigned a = (unsigned)(diff < 0 ? -diff : diff);
                        if (a > contrast)
                            contrast = a;
                    }
                }
            }
            uint8_t rgb8[3] = { c[0], c[1], c[2] };
            if (contrast > o->adaptive)
                pixel(tr, cfn, &rs, o, x, (unsigned)y, rgb8);
            put_pixel(row_buf, o, x, (unsigned)y, rgb8);
        }
        if (fn(ctx, y, row_buf, rt_row_bytes(o)) != 0)
            return RT_ERR_ABORTED;
    }
    return RT_OK;
}
#endif

static rt_status render_plain(const rt_tracer *tr, const cam_frame *cf,
                              const rt_options *o, int y0, int y1,
                              uint8_t *row_buf, rt_row_fn fn, void *ctx);

static int in01(fx_t v)
{
    return v >= 0 && v <= FX_ONE;
}

static int rgb_in(rt_rgb c, fx_t hi)
{
    return c.r >= 0 && c.r <= hi && c.g >= 0 && c.g <= hi && c.b >= 0 &&
           c.b <= hi;
}

/* The ranges the parser enforces, checked again for scenes built in C:
 * the tracer's colour arithmetic relies on them (rt_trace.c). */
static int scene_in_range(const rt_scene *s)
{
    if (s->n_materials > RT_MAX_MATERIALS || s->n_lights > RT_MAX_LIGHTS ||
        s->n_objects > RT_MAX_OBJECTS || !rgb_in(s->background, FX_ONE) ||
        !rgb_in(s->ambient, FX_INT(16)))
        return 0;
    for (unsigned i = 0; i < s->n_lights; i++)
        if (!rgb_in(s->light[i].color, FX_INT(16)))
            return 0;
    for (unsigned i = 0; i < s->n_materials; i++) {
        const rt_material *m = &s->mat[i];
        if (!rgb_in(m->color, FX_ONE) || !rgb_in(m->color2, FX_ONE) ||
            !in01(m->ambient) || !in01(m->diffuse) || !in01(m->specular) ||
            !in01(m->reflect) || !in01(m->transparency) ||
            m->reflect + m->transparency > FX_ONE || m->shininess < 1 ||
            m->shininess > 1024 || m->texture > RT_TEX_CHECKER3D ||
            m->axis > 2)
            return 0;
    }
    for (unsigned i = 0; i < s->n_objects; i++)
        if (s->obj[i].material >= s->n_materials ||
            s->obj[i].kind >= RT_KIND_COUNT)
            return 0;
    return 1;
}

rt_status rt_render_rows(const rt_scene *s, const rt_options *o, int y0,
                         int y1, uint8_t *row_buf, rt_row_fn fn, void *ctx,
                         rt_stats *stats)
{
    /* The scene's ranges and indices first: rt_scene_features reads
     * through them. */
    if (!s || !o || !scene_in_range(s))
        return RT_ERR_ARG;
    if (rt_scene_features(s, o->spp) & ~rt_build_features())
        return RT_ERR_UNSUPPORTED;
    unsigned n = grid_side(o->spp);
    if (!row_buf || !fn || n == 0 || o->width < 1 ||
        o->width > RT_MAX_WIDTH || o->height < 1 ||
        o->height > RT_MAX_HEIGHT || o->depth > RT_MAX_DEPTH ||
        o->format > RT_RGB565_BE || y0 < 0 || y1 > (int)o->height ||
        y0 > y1)
        return RT_ERR_ARG;

    rt_tracer tr;
    memset(&tr, 0, sizeof tr); /* every field defined, grids included */
    uint16_t blocker[RT_MAX_LIGHTS];
    for (unsigned i = 0; i < RT_MAX_LIGHTS; i++)
        blocker[i] = 0xFFFFu;
    tr.blocker = blocker;
#if RT_CUTOFF
    uint32_t budget = 0;
    tr.budget = &budget;
    tr.cut_budget = o->trace_all ? 0 : RT_CUT_BUDGET / (n * n);
#endif
    tr.scene = s;
    tr.max_depth = o->depth;
    tr.feat = rt_scene_features(s, o->spp);
    tr.stats = stats;
    rt_tracer_prepare(&tr);
    cam_frame cf;
    cam_setup(&cf, s, o, n);
#if !defined(RT_NO_SUPERSAMPLING)
    if (o->adaptive && n > 1)
        return render_adaptive(&tr, &cf, o, y0, y1, row_buf, fn, ctx);
#endif
    return render_plain(&tr, &cf, o, y0, y1, row_buf, fn, ctx);
}

/* Every pixel gets its cf->n x cf->n grid. */
static rt_status render_plain(const rt_tracer *tr, const cam_frame *cf,
                              const rt_options *o, int y0, int y1,
                              uint8_t *row_buf, rt_row_fn fn, void *ctx)
{
    row_spans rs;
    for (int y = y0; y < y1; y++) {
        row_setup(&rs, tr, cf, o, (unsigned)y);
        for (unsigned x = 0; x < o->width; x++) {
            uint8_t rgb8[3];
            pixel(tr, cf, &rs, o, x, (unsigned)y, rgb8);
            put_pixel(row_buf, o, x, (unsigned)y, rgb8);
        }
        if (fn(ctx, y, row_buf, rt_row_bytes(o)) != 0)
            return RT_ERR_ABORTED;
    }
    return RT_OK;
}
