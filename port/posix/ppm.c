/* SPDX-License-Identifier: MIT */
/* ppm: binary PPM (P6, maxval 255) reading and writing. */
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "png.h"
#include "ppm.h"

static void seterr(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (!err || errlen == 0)
        return;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

int ppm_alloc(ppm_image *img, int width, int height)
{
    memset(img, 0, sizeof *img);
    if (width < 1 || width > PPM_MAX_SIDE || height < 1 ||
        height > PPM_MAX_SIDE)
        return -1;
    img->data = calloc((size_t)width * (size_t)height, 3);
    if (!img->data)
        return -1;
    img->width = width;
    img->height = height;
    return 0;
}

void ppm_free(ppm_image *img)
{
    if (!img)
        return;
    free(img->data);
    memset(img, 0, sizeof *img);
}

static int is_space(uint8_t c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
           c == '\f';
}

/* Skips whitespace and '#' comments (to the end of their line). */
static size_t skip_blank(const uint8_t *buf, size_t len, size_t i)
{
    while (i < len) {
        if (is_space(buf[i])) {
            i++;
        } else if (buf[i] == '#') {
            while (i < len && buf[i] != '\n' && buf[i] != '\r')
                i++;
        } else {
            break;
        }
    }
    return i;
}

/* Reads one header number after optional blanks. Returns 0, or -1 with a
 * message about field `what`. */
static int header_number(const uint8_t *buf, size_t len, size_t *pos,
                         const char *what, long *out, char *err,
                         size_t errlen)
{
    size_t i = skip_blank(buf, len, *pos);
    long v = 0;
    if (i >= len) {
        seterr(err, errlen, "truncated header: no %s", what);
        return -1;
    }
    if (buf[i] < '0' || buf[i] > '9') {
        seterr(err, errlen, "bad header: %s is not a number", what);
        return -1;
    }
    while (i < len && buf[i] >= '0' && buf[i] <= '9') {
        v = v * 10 + (buf[i++] - '0');
        if (v > 1000000L) {
            seterr(err, errlen, "bad header: %s is too large", what);
            return -1;
        }
    }
    if (i < len && !is_space(buf[i]) && buf[i] != '#') {
        seterr(err, errlen, "bad header: junk after %s", what);
        return -1;
    }
    *out = v;
    *pos = i;
    return 0;
}

int ppm_parse(const uint8_t *buf, size_t len, ppm_image *img, char *err,
              size_t errlen)
{
    size_t pos = 2, need;
    long w, h, maxval;
    memset(img, 0, sizeof *img);
    if (len >= 4 && buf[0] == 0x89 && buf[1] == 'P' && buf[2] == 'N' &&
        buf[3] == 'G')
        return png_decode(buf, len, img, err, errlen);
    if (len < 2 || buf[0] != 'P' || buf[1] != '6') {
        seterr(err, errlen, "neither a binary PPM (P6) nor a PNG");
        return -1;
    }
    if (len > 2 && !is_space(buf[2]) && buf[2] != '#') {
        seterr(err, errlen, "bad header: junk after P6");
        return -1;
    }
    if (header_number(buf, len, &pos, "width", &w, err, errlen) ||
        header_number(buf, len, &pos, "height", &h, err, errlen) ||
        header_number(buf, len, &pos, "maxval", &maxval, err, errlen))
        return -1;
    if (w < 1 || w > PPM_MAX_SIDE || h < 1 || h > PPM_MAX_SIDE) {
        seterr(err, errlen, "bad header: size %ldx%ld is outside 1..%d", w,
               h, PPM_MAX_SIDE);
        return -1;
    }
    if (maxval != 255) {
        seterr(err, errlen, "maxval is %ld; only 255 (8-bit) is supported",
               maxval);
        return -1;
    }
    /* Exactly one whitespace byte separates the header from the pixels. */
    if (pos >= len) {
        seterr(err, errlen, "truncated: no pixel data");
        return -1;
    }
    if (!is_space(buf[pos])) {
        seterr(err, errlen, "bad header: maxval must be followed by one "
                            "whitespace byte");
        return -1;
    }
    pos++;
    need = (size_t)w * (size_t)h * 3;
    if (len - pos < need) {
        seterr(err, errlen, "truncated: %zu of %zu pixel bytes", len - pos,
               need);
        return -1;
    }
    if (ppm_alloc(img, (int)w, (int)h)) {
        seterr(err, errlen, "out of memory for %ldx%ld pixels", w, h);
        return -1;
    }
    memcpy(img->data, buf + pos, need);
    return 0;
}

/* Reads a whole stream into a malloc'd buffer. Returns 0, or -1 (errno
 * set). */
static int slurp(FILE *f, uint8_t **out, size_t *outlen)
{
    size_t cap = 1 << 16, n = 0;
    uint8_t *buf = malloc(cap);
    if (!buf)
        return -1;
    for (;;) {
        size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (n < cap) {
            if (ferror(f)) {
                free(buf);
                return -1;
            }
            break; /* end of file */
        }
        if (cap > ((size_t)1 << 31)) { /* far beyond any 65535^2 image */
            free(buf);
            errno = EFBIG;
            return -1;
        }
        uint8_t *more = realloc(buf, cap * 2);
        if (!more) {
            free(buf);
            return -1;
        }
        buf = more;
        cap *= 2;
    }
    *out = buf;
    *outlen = n;
    return 0;
}

int ppm_read(const char *path, ppm_image *img, char *err, size_t errlen)
{
    uint8_t *buf;
    size_t len;
    char why[160];
    FILE *f = fopen(path, "rb");
    int rc;
    memset(img, 0, sizeof *img);
    if (!f) {
        seterr(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    if (slurp(f, &buf, &len)) {
        seterr(err, errlen, "%s: %s", path, strerror(errno));
        fclose(f);
        return -1;
    }
    fclose(f);
    rc = ppm_parse(buf, len, img, why, sizeof why);
    free(buf);
    if (rc)
        seterr(err, errlen, "%s: %s", path, why);
    return rc;
}

int ppm_write_header(FILE *f, int width, int height)
{
    return fprintf(f, "P6\n%d %d\n255\n", width, height) < 0 ? -1 : 0;
}

int ppm_write(FILE *f, const ppm_image *img)
{
    size_t n = (size_t)img->width * (size_t)img->height * 3;
    if (ppm_write_header(f, img->width, img->height))
        return -1;
    return fwrite(img->data, 1, n, f) == n ? 0 : -1;
}

int ppm_save(const char *path, const ppm_image *img, char *err,
             size_t errlen)
{
    size_t plen = strlen(path);
    char *tmp = malloc(plen + 32);
    FILE *f;
    int fd, bad;
    if (!tmp) {
        seterr(err, errlen, "%s: out of memory", path);
        return -1;
    }
    snprintf(tmp, plen + 32, "%s.tmp.%ld", path, (long)getpid());
    /* O_EXCL: never write through a file or link someone else left. */
    fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL, 0666);
    if (fd < 0 || !(f = fdopen(fd, "wb"))) {
        seterr(err, errlen, "%s: %s", tmp, strerror(errno));
        if (fd >= 0) {
            close(fd);
            unlink(tmp);
        }
        free(tmp);
        return -1;
    }
    bad = ppm_write(f, img) != 0;
    bad |= fflush(f) != 0;
    bad |= fclose(f) != 0;
    if (bad || rename(tmp, path) != 0) {
        seterr(err, errlen, "%s: %s", bad ? tmp : path, strerror(errno));
        unlink(tmp);
        free(tmp);
        return -1;
    }
    free(tmp);
    return 0;
}
