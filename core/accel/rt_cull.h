/* SPDX-License-Identifier: MIT */
/* rt_cull: which objects a row of camera rays can hit. Internal. */
#ifndef RT_CULL_H
#define RT_CULL_H

#include "rt_camera.h"

/* Columns of one row an object may be hit in: x0 <= x <= x1. */
typedef struct {
    uint16_t obj;
    int16_t x0, x1;
} rt_span;

/* The objects camera rays of one pixel row may hit, in object order. */
typedef struct {
    rt_span span[RT_MAX_OBJECTS];
    unsigned count;
} rt_row_spans;

/* Fills *rs (in object order) with the objects that camera rays of pixel
 * row y may hit, with their column ranges. The ranges are conservative:
 * an object left out, or a column outside its range, cannot be hit by any
 * sample of that pixel. */
void rt_cull_row(const rt_scene *s, const rt_cam_frame *cf, unsigned width,
                 unsigned height, unsigned y, rt_row_spans *rs);

#endif /* RT_CULL_H */
