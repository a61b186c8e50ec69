/* SPDX-License-Identifier: MIT */
/* image_out: an output image that reaches its final name only when
 * complete. The temporary file is created at open, beside the target, so a
 * missing or read-only directory is reported before any rendering. */
#ifndef IMAGE_OUT_H
#define IMAGE_OUT_H

#include <stddef.h>
#include <stdint.h>

typedef struct image_out image_out;

/* What an output name asks for, from its extension (any letter case):
 * .ppm and .pnm are binary PPM, .png is PNG; "-" is PPM on stdout. PPM
 * and PNG hold 8 bits a channel: RGB565 rows are expanded back, each
 * channel's top bits repeated below it (r5 -> r5 << 3 | r5 >> 2), so both
 * byte orders give the same picture. .raw and .bin are the rows exactly
 * as the core emits them in the chosen format (3 bytes a pixel for
 * rgb888, 2 in the chosen byte order for rgb565le/be), rows top to
 * bottom, no header; .h is the same bytes as a C array. */
typedef enum {
    IMAGE_UNKNOWN = 0,
    IMAGE_PPM,
    IMAGE_PNG,
    IMAGE_RAW,
    IMAGE_C_ARRAY,
    IMAGE_PANEL_PNM /* .pbm, .pgm: a mono or grey panel's picture */
} image_kind;

/* The kind of image a file name asks for; IMAGE_UNKNOWN for any other
 * extension. */
image_kind image_kind_of(const char *path);

/* Opens an output of w x h pixels whose rows come in `format`
 * (rt_format). path "-" means stdout (PPM). The kind follows
 * image_kind_of(); an unknown one is written as binary PPM (P6), so check
 * the name first. NULL with a message in err. */
image_out *image_out_open(const char *path, int w, int h, int format,
                          int any_order, char *err, size_t errlen);

/* Makes o a panel image: its RGB888 rows are converted at commit by
 * rt_panel (format and dither: rt_panel_format, rt_panel_dither). PPM,
 * PBM, PGM and stdout names then get the panel's picture, PBM (P4, 1 =
 * black) for the mono formats or PGM (P5, levels 0..15) for grey4; .raw
 * and .bin the panel's bytes exactly (mono rows, SSD1306 pages, packed
 * grey nibbles). Returns 0, or -1 for PNG and .h names, which do not
 * hold them. The image's top-left pixel is frame pixel (x0, y0): the
 * ordered dither and the pages follow the frame, so a window's picture is
 * that part of the frame's. */
int image_out_panel(image_out *o, int format, int dither, int x0, int y0);

/* Stores row y (rows may come in any order). Returns 0, or -1 on a bad
 * row. */
int image_out_row(image_out *o, int y, const uint8_t *row, size_t n);

/* Writes the image, then renames the temporary file into place. Frees o.
 * Returns 0, or -1 with a message in err (the target is then untouched). */
int image_out_commit(image_out *o, char *err, size_t errlen);

/* Removes the temporary file and frees o; the target is untouched. */
void image_out_abort(image_out *o);

#endif /* IMAGE_OUT_H */
