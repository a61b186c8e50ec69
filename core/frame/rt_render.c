/* SPDX-License-Identifier: MIT */
/*
 * rt_render: the scanline boundary (rt_render.h). It checks the scene and
 * the options, sets up the tracer, and hands over one row at a time. Each
 * pixel depends only on its own x and y, so any banding of rows, and any
 * window of columns, gives the same bytes.
 */
#include "rt_draft.h"
#include "rt_pixel.h"

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
    o->draft = 0;
}

size_t rt_row_bytes(const rt_options *o)
{
    return rt_pixel_row_bytes(o);
}

size_t rt_window_bytes(const rt_options *o, unsigned n)
{
    size_t extra = 0;
    n = n < 1 ? 1 : (n > o->width ? o->width : n);
    /* Adaptive anti-aliasing looks one column past each side. */
    const unsigned nc = n + 2 < o->width ? n + 2 : o->width;
    if (RT_HAS_SUPERSAMPLING && o->adaptive && o->spp > 1) {
        extra = 9u * nc; /* three rows of 1-spp colours */
        if (RT_HAS_DRAFT && o->draft) /* then drafts give those colours */
            extra += rt_draft_bytes(o, nc);
    } else if (RT_HAS_DRAFT && o->draft) {
        extra += rt_draft_bytes(o, n);
    }
    return rt_pixel_bytes(o, n) + extra;
}

size_t rt_buffer_bytes(const rt_options *o)
{
    return rt_window_bytes(o, o->width);
}

/* Grid side n for spp = n * n, or 0 if spp is not a supported square. */
static unsigned grid_side(unsigned spp)
{
    if (!RT_HAS_SUPERSAMPLING)
        return spp == 1 ? 1 : 0; /* a constant: the sample loops fold away */
    for (unsigned n = 1; n <= RT_MAX_SPP_SIDE; n++)
        if (n * n == spp)
            return n;
    return 0;
}

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
 * the tracer's colour arithmetic relies on them (rt_colour.h). */
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
            s->obj[i].kind >= RT_KIND_COUNT ||
            (s->obj[i].kind == RT_MESH && !s->obj[i].u.mesh.tables))
            return 0;
    return 1;
}

rt_status rt_render_rows(const rt_scene *s, const rt_options *o, int y0,
                         int y1, uint8_t *row_buf, rt_row_fn fn, void *ctx,
                         rt_stats *stats)
{
    return rt_render_window(s, o, 0, y0, o ? (int)o->width : 1, y1, row_buf,
                            fn, ctx, stats);
}

/* The checks every entry point makes on the scene, the options and the
 * window's columns: RT_OK, or the status to return. */
static rt_status check_args(const rt_scene *s, const rt_options *o, int x0,
                            int x1, const uint8_t *row_buf, rt_row_fn fn)
{
    /* The scene's ranges and indices first: rt_scene_features reads
     * through them. */
    if (!s || !o || !scene_in_range(s))
        return RT_ERR_ARG;
    if ((rt_scene_features(s, o->spp) & ~rt_build_features()) ||
        (!RT_HAS_DRAFT && o->draft))
        return RT_ERR_UNSUPPORTED;
    if (!row_buf || !fn || grid_side(o->spp) == 0 || o->width < 1 ||
        o->width > RT_MAX_WIDTH || o->height < 1 ||
        o->height > RT_MAX_HEIGHT || o->depth > RT_MAX_DEPTH ||
        o->format > RT_RGB565_BE || x0 < 0 || x1 > (int)o->width ||
        x0 >= x1)
        return RT_ERR_ARG;
    return RT_OK;
}

/* Renders the band y0 <= y < y1 of columns c0 <= x < c1 with a tracer
 * already set up. */
static rt_status render_band(const rt_tracer *tr, rt_work *wk,
                             const rt_cam_frame *cf, const rt_options *o,
                             unsigned c0, int y0, unsigned c1, int y1,
                             uint8_t *row_buf, rt_row_fn fn, void *ctx)
{
    if (RT_HAS_SUPERSAMPLING && o->adaptive && o->spp > 1)
        return rt_aa_adaptive(tr, wk, cf, o, c0, y0, c1, y1, row_buf, fn,
                              ctx);
    if (RT_HAS_DRAFT && o->draft)
        return rt_draft_render(tr, wk, cf, o, c0, y0, c1, y1, row_buf, fn,
                               ctx);
    for (int y = y0; y < y1; y++) {
        rt_aa_row(tr, wk, cf, o, (unsigned)y, c0, c1, row_buf);
        if (fn(ctx, y, row_buf, rt_pixel_bytes(o, c1 - c0)) != 0)
            return RT_ERR_ABORTED;
    }
    return RT_OK;
}

/* What a render of any rows needs first: the tracer, the work and the
 * camera's frame. */
static void frame_setup(rt_tracer *tr, rt_work *wk, rt_cam_frame *cf,
                        const rt_scene *s, const rt_options *o,
                        rt_stats *stats)
{
    rt_tracer_init(tr, s, o);
    rt_work_init(wk, stats);
    rt_cam_setup(cf, s, o->width, o->height, grid_side(o->spp));
}

rt_status rt_render_window(const rt_scene *s, const rt_options *o, int x0,
                           int y0, int x1, int y1, uint8_t *row_buf,
                           rt_row_fn fn, void *ctx, rt_stats *stats)
{
    rt_status st = check_args(s, o, x0, x1, row_buf, fn);
    if (st != RT_OK)
        return st;
    if (y0 < 0 || y1 > (int)o->height || y0 > y1)
        return RT_ERR_ARG;

    rt_tracer tr;
    rt_work wk;
    rt_cam_frame cf;
    frame_setup(&tr, &wk, &cf, s, o, stats);
    return render_band(&tr, &wk, &cf, o, (unsigned)x0, y0, (unsigned)x1, y1,
                       row_buf, fn, ctx);
}

rt_status rt_render_row_set(const rt_scene *s, const rt_options *o,
                            rt_next_row_fn next, uint8_t *row_buf,
                            rt_row_fn fn, void *ctx, rt_stats *stats)
{
    rt_status st = check_args(s, o, 0, o ? (int)o->width : 1, row_buf, fn);
    if (st != RT_OK)
        return st;
    if (!next)
        return RT_ERR_ARG;

    rt_tracer tr;
    rt_work wk;
    rt_cam_frame cf;
    frame_setup(&tr, &wk, &cf, s, o, stats);
    for (int y = next(ctx); y >= 0; y = next(ctx)) {
        if (y >= (int)o->height)
            return RT_ERR_ARG;
        st = render_band(&tr, &wk, &cf, o, 0, y, o->width, y + 1, row_buf,
                         fn, ctx);
        if (st != RT_OK)
            return st;
    }
    return RT_OK;
}
