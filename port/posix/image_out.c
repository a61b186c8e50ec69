/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image_out.h"
#include "png.h"
#include "rt_panel.h"
#include "rt_render.h"

struct image_out {
    int w, h, format, to_stdout;
    image_kind kind;
    int panel, panel_dither; /* rt_panel_format + 1 (0: none), its dither */
    int panel_x0, panel_y0;  /* the frame pixel at the image's top left */
    size_t bpp;     /* bytes a pixel in rgb: 3, or the row format's */
    uint8_t *rgb;   /* w * h * bpp: RGB888, or the rows as given */
    char *target;   /* final name */
    char *tmp;      /* temporary name */
    FILE *f;
    char err[200];
};

static int ends_with_ci(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    return n >= m && strcasecmp(s + n - m, suffix) == 0;
}

image_kind image_kind_of(const char *path)
{
    if (strcmp(path, "-") == 0 || ends_with_ci(path, ".ppm") ||
        ends_with_ci(path, ".pnm"))
        return IMAGE_PPM;
    if (ends_with_ci(path, ".png"))
        return IMAGE_PNG;
    if (ends_with_ci(path, ".raw") || ends_with_ci(path, ".bin"))
        return IMAGE_RAW;
    if (ends_with_ci(path, ".h"))
        return IMAGE_C_ARRAY;
    if (ends_with_ci(path, ".pbm") || ends_with_ci(path, ".pgm"))
        return IMAGE_PANEL_PNM;
    return IMAGE_UNKNOWN;
}

image_out *image_out_open(const char *path, int w, int h, int format,
                          int any_order, char *err, size_t errlen)
{
    (void)any_order; /* rows are kept until commit, so any order works */
    image_out *o = calloc(1, sizeof *o);
    if (!o) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    o->w = w;
    o->h = h;
    o->format = format;
    o->kind = image_kind_of(path);
    o->to_stdout = strcmp(path, "-") == 0;
    o->bpp = (o->kind == IMAGE_RAW || o->kind == IMAGE_C_ARRAY) &&
                     format != RT_RGB888
                 ? 2
                 : 3;
    o->rgb = malloc((size_t)w * (size_t)h * o->bpp);
    if (!o->rgb) {
        snprintf(err, errlen, "out of memory for a %dx%d image", w, h);
        free(o);
        return NULL;
    }
    if (o->to_stdout)
        return o;
    o->target = strdup(path);
    o->tmp = malloc(strlen(path) + 16);
    if (!o->target || !o->tmp) {
        snprintf(err, errlen, "out of memory");
        image_out_abort(o);
        return NULL;
    }
    /* The temporary lives in the target's directory so rename() is atomic. */
    const char *slash = strrchr(path, '/');
    size_t dirlen = slash ? (size_t)(slash - path) + 1 : 0;
    memcpy(o->tmp, path, dirlen);
    strcpy(o->tmp + dirlen, ".fixtrace-XXXXXX");
    int fd = mkstemp(o->tmp);
    if (fd < 0) {
        snprintf(err, errlen, "cannot write '%s': %s%s", path,
                 strerror(errno),
                 errno == ENOENT ? " (does its directory exist?)" : "");
        free(o->tmp);
        o->tmp = NULL;
        image_out_abort(o);
        return NULL;
    }
    /* mkstemp makes 0600; give the image the usual umask-based mode. */
    mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    o->f = fdopen(fd, "wb");
    if (!o->f) {
        snprintf(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        close(fd);
        image_out_abort(o);
        return NULL;
    }
    return o;
}

int image_out_row(image_out *o, int y, const uint8_t *row, size_t n)
{
    if (y < 0 || y >= o->h)
        return -1;
    uint8_t *dst = o->rgb + (size_t)y * (size_t)o->w * o->bpp;
    if (o->format == RT_RGB888 || o->bpp == 2) { /* kept as given */
        if (n != (size_t)o->w * o->bpp)
            return -1;
        memcpy(dst, row, n);
        return 0;
    }
    if (n != (size_t)o->w * 2)
        return -1;
    /* Expand 5:6:5 back to 8 bits so the result stays viewable. */
    for (int x = 0; x < o->w; x++) {
        unsigned v = o->format == RT_RGB565_LE
                         ? (unsigned)row[2 * x] | (unsigned)row[2 * x + 1] << 8
                         : (unsigned)row[2 * x] << 8 | (unsigned)row[2 * x + 1];
        unsigned r = v >> 11, g = (v >> 5) & 63, b = v & 31;
        dst[3 * x] = (uint8_t)(r << 3 | r >> 2);
        dst[3 * x + 1] = (uint8_t)(g << 2 | g >> 4);
        dst[3 * x + 2] = (uint8_t)(b << 3 | b >> 2);
    }
    return 0;
}

/* The C identifier for an array written to path: its base name without
 * the extension, other characters as '_'. */
static void c_name(const char *path, char *name, size_t cap)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    size_t n = 0;
    if (!((*base >= 'A' && *base <= 'Z') || (*base >= 'a' && *base <= 'z')))
        name[n++] = 'f';
    for (const char *p = base; *p && *p != '.' && n + 1 < cap; p++) {
        int ok = (*p >= 'A' && *p <= 'Z') || (*p >= 'a' && *p <= 'z') ||
                 (*p >= '0' && *p <= '9');
        name[n++] = ok ? *p : '_';
    }
    name[n] = '\0';
}

static int write_c_array(image_out *o, FILE *f)
{
    static const char *const fmt[] = {"rgb888", "rgb565le", "rgb565be"};
    char name[64];
    size_t n = (size_t)o->w * (size_t)o->h * o->bpp;
    c_name(o->target, name, sizeof name);
    if (fprintf(f, "/* Written by fixtrace: %dx%d pixels, %s (%u bytes a "
                "pixel), rows top to bottom. */\n#include <stdint.h>\n"
                "#define %s_WIDTH %d\n#define %s_HEIGHT %d\n"
                "static const uint8_t %s[%zu] = {\n",
                o->w, o->h, fmt[o->format <= 2 ? o->format : 0],
                (unsigned)o->bpp, name, o->w, name, o->h, name, n) < 0)
        return -1;
    for (size_t i = 0; i < n; i++)
        if (fprintf(f, "%s0x%02x,%s", i % 12 ? " " : "    ", o->rgb[i],
                    i % 12 == 11 || i + 1 == n ? "\n" : "") < 0)
            return -1;
    return fputs("};\n", f) < 0 ? -1 : 0;
}

int image_out_panel(image_out *o, int format, int dither, int x0, int y0)
{
    if (o->format != RT_RGB888 || format < 0 || format >= RT_PANEL_FORMATS ||
        dither < 0 || dither >= RT_PANEL_DITHERS ||
        (!o->to_stdout &&
         (o->kind == IMAGE_PNG || o->kind == IMAGE_C_ARRAY)))
        return -1;
    o->panel = format + 1;
    o->panel_dither = dither;
    o->panel_x0 = x0;
    o->panel_y0 = y0;
    return 0;
}

/* The panel's bytes (.raw, .bin) or its picture (PBM, PGM): each row
 * through rt_panel, in order, with O(width) buffers. */
static int write_panel(image_out *o, FILE *f)
{
    const int raw = !o->to_stdout && o->kind == IMAGE_RAW;
    const int grey = o->panel - 1 == RT_PANEL_GREY4;
    /* A picture of a mono panel is the same pixels in plain rows. */
    const int fmt = raw || grey ? o->panel - 1 : RT_PANEL_MONO;
    const unsigned w = (unsigned)o->w;
    rt_panel p;
    uint8_t *out = malloc(rt_panel_out_bytes((unsigned)fmt, w));
    int16_t *err = malloc((rt_panel_err_count((unsigned)o->panel_dither, w) +
                           1) * sizeof *err);
    uint8_t *line = malloc(w);
    int rc = -1;
    if (!out || !err || !line ||
        rt_panel_init(&p, (unsigned)fmt, (unsigned)o->panel_dither,
                      (unsigned)o->panel_x0, w, out, err) != RT_OK)
        goto done;
    if (!raw && fprintf(f, grey ? "P5\n%d %d\n15\n" : "P4\n%d %d\n", o->w,
                        o->h) < 0)
        goto done;
    for (int y = 0; y < o->h; y++) {
        size_t n = rt_panel_row(&p, (unsigned)(y + o->panel_y0),
                                o->rgb + (size_t)y * (size_t)o->w * 3);
        const uint8_t *src = out;
        if (!raw && grey) { /* PGM: a byte a level */
            for (unsigned x = 0; x < w; x++)
                line[x] = x % 2 ? out[x / 2] & 15u : out[x / 2] >> 4;
            src = line;
            n = w;
        } else if (!raw) { /* PBM: 1 is black, the pad bits 0 */
            const unsigned pad = w % 8 ? 0xFF00u >> (w % 8) : 0xFFu;
            for (size_t i = 0; i < n; i++)
                line[i] = (uint8_t)(~out[i] & (i + 1 < n ? 0xFFu : pad));
            src = line;
        }
        if (fwrite(src, 1, n, f) != n)
            goto done;
    }
    size_t n = rt_panel_flush(&p);
    rc = fwrite(out, 1, n, f) == n ? 0 : -1;
done:
    free(out);
    free(err);
    free(line);
    return rc;
}

static int write_image(image_out *o, FILE *f)
{
    if (o->panel)
        return write_panel(o, f);
    if (!o->to_stdout && o->kind == IMAGE_PNG)
        return png_write(f, o->rgb, o->w, o->h);
    if (!o->to_stdout && o->kind == IMAGE_C_ARRAY)
        return write_c_array(o, f);
    if (!o->to_stdout && o->kind == IMAGE_RAW) {
        size_t n = (size_t)o->w * (size_t)o->h * o->bpp;
        return fwrite(o->rgb, 1, n, f) == n ? 0 : -1;
    }
    if (fprintf(f, "P6\n%d %d\n255\n", o->w, o->h) < 0)
        return -1;
    size_t n = (size_t)o->w * (size_t)o->h * 3;
    return fwrite(o->rgb, 1, n, f) == n ? 0 : -1;
}

int image_out_commit(image_out *o, char *err, size_t errlen)
{
    int rc = 0;
    if (o->to_stdout) {
        if (write_image(o, stdout) != 0 || fflush(stdout) != 0) {
            snprintf(err, errlen, "cannot write the image to stdout: %s",
                     strerror(errno));
            rc = -1;
        }
        image_out_abort(o);
        return rc;
    }
    if (write_image(o, o->f) != 0 || fflush(o->f) != 0 ||
        fsync(fileno(o->f)) != 0) {
        snprintf(err, errlen, "cannot write '%s': %s; the file was not "
                 "changed", o->target, strerror(errno));
        image_out_abort(o);
        return -1;
    }
    fclose(o->f);
    o->f = NULL;
    if (rename(o->tmp, o->target) != 0) {
        snprintf(err, errlen, "cannot replace '%s': %s; the file was not "
                 "changed", o->target, strerror(errno));
        image_out_abort(o);
        return -1;
    }
    free(o->tmp);
    o->tmp = NULL;
    image_out_abort(o);
    return 0;
}

void image_out_abort(image_out *o)
{
    if (!o)
        return;
    if (o->f)
        fclose(o->f);
    if (o->tmp)
        unlink(o->tmp);
    free(o->tmp);
    free(o->target);
    free(o->rgb);
    free(o);
}
