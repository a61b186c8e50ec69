/* SPDX-License-Identifier: MIT */
/*
 * rt_render: the core's one boundary to a platform. The caller owns the
 * scene, a row buffer of rt_row_bytes() bytes and a callback; the renderer
 * fills one scanline at a time and hands it over. There is no frame buffer.
 */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include <stddef.h>
#include "rt_options.h"

/* Receives finished row y. `row` holds rt_row_bytes() bytes and belongs to
 * the caller that passed it to rt_render_rows(); it is valid only until the
 * callback returns. Return 0 to go on, non-zero to stop the render. */
typedef int (*rt_row_fn)(void *ctx, int y, const uint8_t *row, size_t nbytes);

/* Fills *o from the scene's defaults (size, spp, depth), RGB888. */
void rt_options_from_scene(rt_options *o, const rt_scene *s);

/* Bytes in one row handed to the callback (width * 3 or width * 2). */
size_t rt_row_bytes(const rt_options *o);

/* Bytes the caller's row buffer must hold: rt_row_bytes(), plus 9 * width
 * of scratch when adaptive anti-aliasing is on, plus about 25 * width for
 * a draft render (its lattice rows). */
size_t rt_buffer_bytes(const rt_options *o);

/* Renders rows y0 <= y < y1 (top row is 0) into row_buf (rt_buffer_bytes()
 * bytes), calling fn after each. Rows are independent: any split into
 * bands gives the same bytes.
 * stats may be NULL. Returns RT_OK, RT_ERR_ARG for bad options or rows, or
 * for a scene outside the parser's ranges (colours in [0, 1], light and
 * ambient colours in [0, 16], coefficients in [0, 1], reflect +
 * transparency <= 1, shininess 1..1024, valid indices),
 * RT_ERR_UNSUPPORTED when the scene needs an effect this build removed, or
 * RT_ERR_ABORTED when fn returned non-zero. */
rt_status rt_render_rows(const rt_scene *s, const rt_options *o, int y0,
                         int y1, uint8_t *row_buf, rt_row_fn fn, void *ctx,
                         rt_stats *stats);

#endif /* RT_RENDER_H */
