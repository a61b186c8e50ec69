/* SPDX-License-Identifier: MIT */
/*
 * receive: `fixtrace receive`, the host end of the firmware's UART output
 * (port/baremetal/out_uart.c, which documents the frame). It reads the
 * serial line, shows the device's text on stderr, checks the image frame
 * (magic, header, size, CRC-32) and only then writes the image, through
 * image_out, so a bad or cut transmission never leaves a file and never
 * harms an existing one.
 */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <fcntl.h>

#include "cli_util.h"
#include "image_out.h"
#include "png.h"
#include "receive.h"
#include "rt_render.h"

#define FRAME_VERSION 1
#define FRAME_HEADER 12 /* bytes after the magic */
#define FRAME_MAX_SIDE 16384
#define EOT 0x04
/* The device's text comes in short lines; a longer "line" is binary. */
#define LINE_MAX_TEXT 160

static const uint8_t magic[4] = { 'F', 'X', 'I', 'M' };

typedef struct {
    int fd;
    uint8_t buf[4096];
    size_t pos, len;
    int err; /* errno of a failed read */
    unsigned long hidden; /* bytes outside the frame not shown as text */
    char line[LINE_MAX_TEXT]; /* the device's text line being read */
    size_t line_len;
    int line_bad; /* the line holds a byte that is not text */
} reader;

/* The next byte, or -1 at the end of the input (or on a read error). */
static int next_byte(reader *r)
{
    if (r->pos == r->len) {
        ssize_t n;
        do
            n = read(r->fd, r->buf, sizeof r->buf);
        while (n < 0 && errno == EINTR);
        if (n <= 0) {
            if (n < 0)
                r->err = errno;
            return -1;
        }
        r->pos = 0;
        r->len = (size_t)n;
    }
    return r->buf[r->pos++];
}

/* Reads n bytes into p; returns how many arrived before the end. */
static size_t read_bytes(reader *r, uint8_t *p, size_t n)
{
    size_t got = 0;
    while (got < n) {
        if (r->pos < r->len) {
            size_t k = r->len - r->pos;
            if (k > n - got)
                k = n - got;
            memcpy(p + got, r->buf + r->pos, k);
            r->pos += k;
            got += k;
        } else {
            int c = next_byte(r);
            if (c < 0)
                break;
            p[got++] = (uint8_t)c;
        }
    }
    return got;
}

/* Shows the device's text on stderr a line at a time, and only lines of
 * printable ASCII no longer than LINE_MAX_TEXT, so that binary input (a
 * wrong port speed, an image file) never reaches the terminal; the bytes
 * of other lines are counted in r->hidden. c < 0 flushes the last line. */
static void show_text(reader *r, int c)
{
    if (c >= 0 && c != '\n') {
        if (r->line_len == sizeof r->line) {
            r->hidden += r->line_len;
            r->line_len = 0;
            r->line_bad = 1;
        }
        r->line[r->line_len++] = (char)c;
        if (!((c >= 0x20 && c < 0x7f) || c == '\r' || c == '\t'))
            r->line_bad = 1;
        return;
    }
    if (r->line_bad)
        r->hidden += r->line_len + (c == '\n');
    else if (r->line_len > 0 || c == '\n')
        fprintf(stderr, "%.*s%s", (int)r->line_len, r->line,
                c == '\n' ? "\n" : "");
    r->line_len = 0;
    r->line_bad = 0;
}

/* Copies the device's text to stderr up to the frame's magic (returns 1)
 * or to an EOT or the end of the input (returns 0). */
static int text_until_magic(reader *r, int show)
{
    size_t k = 0; /* bytes of the magic matched so far */
    for (;;) {
        int c = next_byte(r);
        if (c < 0 || c == EOT)
            break;
        if (c == magic[k]) {
            if (++k == sizeof magic) {
                if (show)
                    show_text(r, -1);
                return 1;
            }
            continue;
        }
        for (size_t j = 0; show && j < k; j++)
            show_text(r, magic[j]);
        k = c == magic[0];
        if (!k && show)
            show_text(r, c);
    }
    for (size_t j = 0; show && j < k; j++)
        show_text(r, magic[j]);
    if (show)
        show_text(r, -1);
    return 0;
}

static unsigned get16(const uint8_t *p)
{
    return (unsigned)p[0] | (unsigned)p[1] << 8;
}

static uint32_t get32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
           (uint32_t)p[3] << 24;
}

static const char *const format_name[] = { "rgb888", "rgb565le",
                                           "rgb565be" };

/* Receives one frame from r and writes it to out. Returns 0, or 1 with a
 * message on stderr. */
static int receive(reader *r, const char *in_name, const char *out,
                   int quiet)
{
    uint8_t hdr[FRAME_HEADER], tail[4];
    char err[256];

    if (!text_until_magic(r, 1)) {
        if (r->err)
            fprintf(stderr, "fixtrace receive: cannot read %s: %s\n",
                    in_name, strerror(r->err));
        else if (r->hidden)
            fprintf(stderr, "fixtrace receive: no image frame in %s (no "
                    "\"FXIM\" before the end of the input); %lu bytes of "
                    "it are not text and were not shown: is it the "
                    "firmware's UART output (make firmware OUTPUT=uart), "
                    "read at the right speed?\n", in_name, r->hidden);
        else
            fprintf(stderr, "fixtrace receive: no image frame in %s (no "
                    "\"FXIM\" before the end of the input)\n", in_name);
        return 1;
    }
    size_t got = read_bytes(r, hdr, sizeof hdr);
    if (got < sizeof hdr) {
        fprintf(stderr, "fixtrace receive: the frame ends in its header "
                "(%zu of %d bytes)\n", got, FRAME_HEADER);
        return 1;
    }
    unsigned version = hdr[0], format = hdr[1];
    unsigned w = get16(hdr + 2), h = get16(hdr + 4);
    uint32_t payload = get32(hdr + 8);
    if (version != FRAME_VERSION) {
        fprintf(stderr, "fixtrace receive: frame version %u, this receiver "
                "reads version %d\n", version, FRAME_VERSION);
        return 1;
    }
    if (format > RT_RGB565_BE || get16(hdr + 6) != 0 || w == 0 || h == 0 ||
        w > FRAME_MAX_SIDE || h > FRAME_MAX_SIDE) {
        fprintf(stderr, "fixtrace receive: bad frame header (format %u, "
                "%ux%u, reserved %u)\n", format, w, h, get16(hdr + 6));
        return 1;
    }
    uint64_t want = (uint64_t)w * h * (format == RT_RGB888 ? 3 : 2);
    if (payload != want) {
        fprintf(stderr, "fixtrace receive: the frame says %lu payload "
                "bytes, but %ux%u %s needs %llu\n", (unsigned long)payload,
                w, h, format_name[format], (unsigned long long)want);
        return 1;
    }
    uint8_t *data = malloc(payload);
    if (!data) {
        fprintf(stderr, "fixtrace receive: out of memory for %lu bytes\n",
                (unsigned long)payload);
        return 1;
    }
    got = read_bytes(r, data, payload);
    if (got < payload || read_bytes(r, tail, 4) < 4) {
        fprintf(stderr, "fixtrace receive: the frame is cut short: %zu of "
                "%lu payload bytes%s\n", got, (unsigned long)payload,
                got == payload ? " and part of the checksum" : "");
        free(data);
        return 1;
    }
    uint32_t crc = png_crc32(png_crc32(0, hdr, sizeof hdr), data, payload);
    uint32_t sent = get32(tail);
    if (crc != sent) {
        fprintf(stderr, "fixtrace receive: checksum mismatch: the frame "
                "says CRC-32 0x%08lx, the bytes received give 0x%08lx; "
                "nothing written\n", (unsigned long)sent,
                (unsigned long)crc);
        free(data);
        return 1;
    }

    image_out *o = image_out_open(out, (int)w, (int)h, (int)format, 0, err,
                                  sizeof err);
    if (!o) {
        fprintf(stderr, "fixtrace receive: %s\n", err);
        free(data);
        return 1;
    }
    size_t row = payload / h;
    for (unsigned y = 0; y < h; y++)
        image_out_row(o, (int)y, data + row * y, row);
    free(data);
    if (image_out_commit(o, err, sizeof err) != 0) {
        fprintf(stderr, "fixtrace receive: %s\n", err);
        return 1;
    }
    /* The text the device sends after the image (its figures). */
    text_until_magic(r, 1);
    if (!quiet)
        fprintf(stderr, "fixtrace receive: wrote %s (%ux%u %s, %lu bytes, "
                "CRC-32 0x%08lx)\n", out, w, h, format_name[format],
                (unsigned long)payload, (unsigned long)crc);
    return 0;
}

int receive_main(int argc, char **argv)
{
    const char *out = NULL, *in = NULL;
    int quiet = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            if (!(out = cli_value(argc, argv, &i, a)))
                return 2;
        } else if (strcmp(a, "-i") == 0 || strcmp(a, "--input") == 0) {
            if (!(in = cli_value(argc, argv, &i, a)))
                return 2;
        } else if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0) {
            quiet = 1;
        } else if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            fputs("usage: fixtrace receive -o OUT.png|OUT.ppm [-i INPUT] "
                  "[-q]\n"
                  "Reads the firmware's UART output (make firmware "
                  "OUTPUT=uart) from INPUT\n"
                  "or stdin, shows the device's text on stderr and writes "
                  "the image once\n"
                  "its frame and CRC-32 check out. Set a serial port up "
                  "first, e.g.\n"
                  "  stty -F /dev/ttyUSB0 115200 raw -echo; fixtrace receive "
                  "-o out.png < /dev/ttyUSB0\n"
                  "Exit status: 0 written, 1 no frame, a bad frame or a "
                  "write error, 2 bad usage.\n", stdout);
            return 0;
        } else {
            return cli_unknown_option(a);
        }
    }
    if (!out)
        return cli_error("receive needs -o OUT.png or -o OUT.ppm");
    int rc = cli_check_output(out, in ? in : "-");
    if (rc)
        return rc;
    reader r;
    memset(&r, 0, sizeof r);
    r.fd = 0;
    if (in) {
        r.fd = open(in, O_RDONLY);
        if (r.fd < 0)
            return cli_error("cannot read '%s': %s", in, strerror(errno));
    }
    rc = receive(&r, in ? in : "stdin", out, quiet);
    if (in)
        close(r.fd);
    return rc;
}
