/* SPDX-License-Identifier: MIT */
/*
 * rt_render: the core's one boundary to a platform. The caller owns the
 * scene, a row buffer (rt_buffer_bytes(), or rt_window_bytes() for a
 * window of the frame) and a callback; the renderer fills one scanline at
 * a time, whole or the window's part, and hands it over. There is no
 * frame buffer.
 */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include <stddef.h>
#include "rt_options.h"

/* Receives finished row y. `row` holds nbytes bytes, rt_row_bytes() (or a
 * window's row, rt_render_window()), and belongs to the caller that passed
 * it to rt_render_rows(); it is valid only until the callback returns.
 * Return 0 to go on, non-zero to stop the render. */
typedef int (*rt_row_fn)(void *ctx, int y, const uint8_t *row, size_t nbytes);

/* Fills *o from the scene's defaults (size, spp, depth), RGB888. */
void rt_options_from_scene(rt_options *o, const rt_scene *s);

/* Bytes in one row handed to the callback (width * 3 or width * 2). */
size_t rt_row_bytes(const rt_options *o);

/* Bytes the caller's row buffer must hold for full rows:
 * rt_window_bytes(o, o->width). */
size_t rt_buffer_bytes(const rt_options *o);

/* Bytes the caller's buffer must hold for any window n columns wide
 * (rt_render_window, n = x1 - x0, taken into 1..width): its row (n * 3
 * or n * 2); plus, with adaptive anti-aliasing, three rows of centre
 * samples, 9 bytes a column, one column past each side; plus, for a
 * draft, about 25 bytes a column and its lattice's margin of
 * 2^RT_DRAFT_LEVELS - 1 columns a side (two rows of 14-byte entries a
 * level). No term exceeds the full row's, and for n = width this is
 * rt_buffer_bytes(). It depends on n alone, not on where the window
 * lies: one buffer serves every tile of a size. */
size_t rt_window_bytes(const rt_options *o, unsigned n);

/* Renders rows y0 <= y < y1 (top row is 0) into row_buf (rt_buffer_bytes()
 * bytes), calling fn after each. Rows are independent: any split into
 * bands gives the same bytes. rt_render_window() over all columns.
 * stats may be NULL. Returns RT_OK, RT_ERR_ARG for bad options or rows, or
 * for a scene outside the parser's ranges (colours in [0, 1], light and
 * ambient colours in [0, 16], coefficients in [0, 1], reflect +
 * transparency <= 1, shininess 1..1024, valid indices),
 * RT_ERR_UNSUPPORTED when the scene needs an effect this build removed, or
 * RT_ERR_ABORTED when fn returned non-zero. */
rt_status rt_render_rows(const rt_scene *s, const rt_options *o, int y0,
                         int y1, uint8_t *row_buf, rt_row_fn fn, void *ctx,
                         rt_stats *stats);

/* Renders the window x0 <= x < x1, y0 <= y < y1 of the frame (0 <= x0 <
 * x1 <= width, 0 <= y0 <= y1 <= height) into row_buf
 * (rt_window_bytes(o, x1 - x0) bytes), calling fn after each row with
 * its x1 - x0 pixels, column x0 first, in o->format: y is the frame's
 * row, nbytes (x1 - x0) * 3 or * 2. Every pixel has the bytes of
 * the same pixel in a full render, at any spp, with adaptive
 * anti-aliasing, drafts and dithering: the neighbours those look at
 * outside the window are computed, not emitted. So tiles and dirty
 * rectangles can be rendered one at a time and sent where they go. Memory
 * is O(x1 - x0); the time is that of the window's pixels plus its margin:
 * centre samples a row and a column past each side with adaptive
 * anti-aliasing, a draft's lattice up to 2^RT_DRAFT_LEVELS - 1 rows and
 * columns away. Returns as rt_render_rows(), and RT_ERR_ARG for an empty
 * or out-of-frame window. */
rt_status rt_render_window(const rt_scene *s, const rt_options *o, int x0,
                           int y0, int x1, int y1, uint8_t *row_buf,
                           rt_row_fn fn, void *ctx, rt_stats *stats);

/* Names the next row for rt_render_row_set() to render: a row
 * 0 <= y < height, or a negative value when there is none left. */
typedef int (*rt_next_row_fn)(void *ctx);

/* Renders the rows that next(ctx) names, in the order it names them, until
 * it returns a negative value, into row_buf (rt_buffer_bytes() bytes),
 * calling fn(ctx, ...) after each as rt_render_rows() does. Each row has
 * the bytes of the same row in a full render. The set-up (checks, the
 * tracer's tables) is done once a call, not once a row, so a port that
 * shares a frame among cores or threads can hand rows out one at a time.
 * The core keeps no state between or across calls: calls with their own
 * row_buf and stats may run at once on different CPUs over one scene.
 * With adaptive anti-aliasing or a draft, each row also computes the
 * margin a one-row band needs (neighbouring rows' samples). Returns as
 * rt_render_rows(), and RT_ERR_ARG for a row outside the frame (fn is not
 * called for it). */
rt_status rt_render_row_set(const rt_scene *s, const rt_options *o,
                            rt_next_row_fn next, uint8_t *row_buf,
                            rt_row_fn fn, void *ctx, rt_stats *stats);

#endif /* RT_RENDER_H */
