/* SPDX-License-Identifier: MIT */
/*
 * ppm: binary PPM (P6, maxval 255) images on the host. The reader takes
 * any header the format allows (comments, any whitespace between fields)
 * and refuses anything else with a message; the writers go to a FILE* or,
 * atomically, to a path.
 */
#ifndef PPM_H
#define PPM_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Largest width or height the reader accepts. */
#define PPM_MAX_SIDE 65535

/* An RGB888 image: width * height * 3 bytes, rows top to bottom. */
typedef struct {
    int width, height;
    uint8_t *data; /* malloc'd; ppm_free() releases it */
} ppm_image;

/* Allocates a zeroed width x height image. Returns 0, or -1 for sizes out
 * of 1..PPM_MAX_SIDE or no memory. */
int ppm_alloc(ppm_image *img, int width, int height);

/* Releases the pixels and zeroes *img; safe on a zeroed or freed image. */
void ppm_free(ppm_image *img);

/* Parses a P6 file held in memory; a PNG (by its signature) goes to
 * png_decode() instead, so every reader takes both. Returns 0 with *img filled (the caller
 * frees it), or -1 with a NUL-terminated reason in err[0..errlen) and
 * *img zeroed. Bytes after the pixel data are ignored. */
int ppm_parse(const uint8_t *buf, size_t len, ppm_image *img, char *err,
              size_t errlen);

/* Reads a P6 or PNG file. As ppm_parse(); the message names the file. */
int ppm_read(const char *path, ppm_image *img, char *err, size_t errlen);

/* Writes the P6 header for a width x height image ("P6\nW H\n255\n").
 * Returns 0, or -1 when the write failed. */
int ppm_write_header(FILE *f, int width, int height);

/* Writes a whole image, header and pixels. Returns 0, or -1 on a write
 * error. */
int ppm_write(FILE *f, const ppm_image *img);

/* Writes a whole image to path atomically: to a temporary file beside it,
 * then renamed over it, so readers never see half an image. Returns 0, or
 * -1 with a reason naming the file in err[0..errlen). */
int ppm_save(const char *path, const ppm_image *img, char *err,
             size_t errlen);

#endif /* PPM_H */
