/* SPDX-License-Identifier: MIT */
/*
 * dual.h: rendering one frame with both cores of a two-core board
 * (FW_CORES=2; dual.c). main.c calls it in place of rt_render_rows().
 */
#ifndef DUAL_H
#define DUAL_H

#include <stddef.h>
#include "rt_render.h"

/* Returned by dual_render() when the second core gave no sign of life
 * within DUAL_START_POLLS polls after port_core1_start(). */
#define DUAL_NO_CORE1 1

/* Renders rows 0 .. o->height - 1 of s on both cores and hands them to
 * emit(ctx, y, row, nbytes) in order, y = 0 first, on core 0, exactly as
 * rt_render_rows(s, o, 0, o->height, row_buf, emit, ctx, 0) would: the
 * same rows with the same bytes. row_buf (rt_buffer_bytes()) is core 0's;
 * dual.c owns core 1's buffer and the rows the cores pass on. Returns
 * RT_OK, a core's rt_status, or DUAL_NO_CORE1 (after saying so on the
 * text channel). */
int dual_render(const rt_scene *s, const rt_options *o, uint8_t *row_buf,
                rt_row_fn emit, void *ctx);

/* Logs the second core's figures after dual_render(): its rows, its stack
 * high-water mark and reservation ("core1_rows", "stack_bytes_core1",
 * "stack_reserved_core1"). Returns 0, or -1 when its stack came within
 * `guard` bytes of its end. */
int dual_report(size_t guard);

#endif /* DUAL_H */
