/* SPDX-License-Identifier: MIT */
/*
 * fw_buffers.h: the sizes of the firmware's row buffers, from the build's
 * fw_config.h (FW_WIDTH, FW_ADAPTIVE, FW_DRAFT) and the board's
 * FW_ROW_PIXELS. main.c owns core 0's buffer, dual.c core 1's and the
 * rows the two cores pass on.
 */
#ifndef FW_BUFFERS_H
#define FW_BUFFERS_H

#include "fw_config.h"
#include "rt_render.h"

/* Widest row the firmware can send; boards short of RAM set it lower than
 * RT_MAX_WIDTH (mk/firmware.mk). */
#ifndef FW_ROW_PIXELS
#define FW_ROW_PIXELS RT_MAX_WIDTH
#endif

#ifndef FW_DRAFT
#define FW_DRAFT 0
#endif

/* The row buffer (rt_buffer_bytes()): the RGB888 row, plus three rows of
 * centre samples for adaptive anti-aliasing, plus the rows of a draft
 * render's levels, a row and its flags (below 25 bytes a pixel and 128
 * bytes) for the width asked for, or the widest row. */
#define FW_BUF_PIXELS                                                         \
    (FW_WIDTH > 0 && FW_WIDTH < FW_ROW_PIXELS ? FW_WIDTH : FW_ROW_PIXELS)
#define FW_BUF_BYTES                                                          \
    (FW_ROW_PIXELS * (FW_ADAPTIVE > 0 ? 12 : 3) +                             \
     (FW_DRAFT > 0 ? FW_BUF_PIXELS * 25 + 128 : 0))

/* One finished RGB888 row of the widest image the build renders. */
#define FW_ROW_BYTES (FW_BUF_PIXELS * 3)

#endif /* FW_BUFFERS_H */
