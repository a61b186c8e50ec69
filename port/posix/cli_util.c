/* SPDX-License-Identifier: MIT */
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli_util.h"
#include "image_out.h"

int cli_error(const char *fmt, ...)
{
    va_list ap;
    fputs("fixtrace: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return 2;
}

static const char *const valued[] = { "-o", "--output", "-W", "--width",
                                      "-H", "--height", "-s", "--spp",
                                      "-d", "--depth", "-j", "--jobs",
                                      "--format" };

int cli_needs_value(const char *opt)
{
    for (size_t k = 0; k < sizeof valued / sizeof valued[0]; k++)
        if (strcmp(opt, valued[k]) == 0)
            return 1;
    return 0;
}

const char *cli_value(int argc, char **argv, int *i, const char *opt)
{
    if (*i + 1 >= argc) {
        cli_error("option %s needs a value (see fixtrace --help)", opt);
        return NULL;
    }
    return argv[++*i];
}

int cli_unknown_option(const char *opt)
{
    for (size_t k = 0; k < sizeof valued / sizeof valued[0]; k++) {
        size_t n = strlen(valued[k]);
        if (strncmp(opt, valued[k], n) == 0 && opt[n] != '\0')
            return cli_error("unknown option '%s' (write '%s %s'; see "
                             "fixtrace --help)", opt, valued[k],
                             opt + n + (opt[n] == '='));
    }
    return cli_error("unknown option '%s' (see fixtrace --help)", opt);
}

int cli_check_output(const char *out, const char *scene)
{
    struct stat a, b;
    if (strcmp(out, "-") == 0) {
        if (isatty(STDOUT_FILENO))
            return cli_error("-o - writes a binary image to stdout, which "
                             "is a terminal; redirect it (> NAME.ppm, or a "
                             "pipe) or name a file with -o NAME.png");
        return 0;
    }
    if (image_kind_of(out) == IMAGE_UNKNOWN)
        return cli_error("cannot write '%s': the output name must end in "
                         ".ppm or .png (or .raw, .bin or .h for the rows "
                         "as they are, .pbm or .pgm with --format mono, "
                         "mono-page or grey4; or be - for PPM on stdout)",
                         out);
    if (stat(out, &a) == 0 && stat(scene, &b) == 0 && a.st_dev == b.st_dev &&
        a.st_ino == b.st_ino)
        return cli_error("the output '%s' is the scene file itself; name "
                         "the image with -o NAME.png", out);
    return 0;
}

int cli_long(const char *opt, const char *val, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(val, &end, 10);
    if (!*val || *end || errno == ERANGE || val[0] == ' ')
        return cli_error("%s needs a whole number from %ld to %ld "
                         "(got '%s')", opt, lo, hi, val);
    if (v < lo || v > hi)
        return cli_error("%s must be from %ld to %ld (got %s)", opt, lo, hi,
                         val);
    *out = v;
    return 0;
}

char *cli_read_file(const char *path, size_t *len, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "cannot open scene '%s': %s", path,
                 strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    while (buf) {
        size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (n > CLI_MAX_SCENE_BYTES) {
            snprintf(err, errlen, "scene '%s' is larger than %u MiB; scene "
                     "files are text, a few lines per object", path,
                     CLI_MAX_SCENE_BYTES >> 20);
            free(buf);
            fclose(f);
            return NULL;
        }
        if (got == 0)
            break;
        if (n == cap) {
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
    }
    if (!buf || ferror(f)) {
        snprintf(err, errlen, "cannot read scene '%s': %s", path,
                 buf ? strerror(errno) : "out of memory");
        free(buf);
        fclose(f);
        return NULL;
    }
    fclose(f);
    *len = n;
    return buf;
}

void cli_print_parse_error(FILE *f, const char *path, const char *text,
                           size_t len, const rt_parse_error *e)
{
    fprintf(f, "%s:%lu:%lu: error: %s\n", path, (unsigned long)e->line,
            (unsigned long)e->col, e->msg);
    if (e->line_off > len)
        return;
    size_t n = e->line_len;
    if (n > len - e->line_off)
        n = len - e->line_off;
    if (n > 200)
        n = 200; /* a binary file can have one enormous line */
    fputs("    ", f);
    for (size_t k = 0; k < n; k++) {
        unsigned char ch = (unsigned char)text[e->line_off + k];
        fputc(ch == '\t' ? ' ' : (ch < 32 || ch > 126 ? '?' : ch), f);
    }
    fputs("\n    ", f);
    for (size_t k = 1; k < e->col && k < 200; k++)
        fputc(' ', f);
    fputs("^\n", f);
}
