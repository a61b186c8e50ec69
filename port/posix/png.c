/* SPDX-License-Identifier: MIT */
#include <stdlib.h>
#include <string.h>

#include "deflate.h"
#include "png.h"

uint32_t png_crc32(uint32_t crc, const uint8_t *p, size_t n)
{
    static uint32_t table[256];
    static int ready;
    if (!ready) {
        for (uint32_t i = 0; i < 256; i++) {
            uint32_t c = i;
            for (int k = 0; k < 8; k++)
                c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            table[i] = c;
        }
        ready = 1;
    }
    crc = ~crc;
    for (size_t i = 0; i < n; i++)
        crc = table[(crc ^ p[i]) & 0xFF] ^ (crc >> 8);
    return ~crc;
}

static void be32(uint8_t *b, uint32_t v)
{
    b[0] = (uint8_t)(v >> 24);
    b[1] = (uint8_t)(v >> 16);
    b[2] = (uint8_t)(v >> 8);
    b[3] = (uint8_t)v;
}

static int chunk(FILE *f, const char *type, const uint8_t *data, size_t n)
{
    uint8_t hdr[8], crcb[4];
    be32(hdr, (uint32_t)n);
    memcpy(hdr + 4, type, 4);
    uint32_t crc = png_crc32(png_crc32(0, hdr + 4, 4), data, n);
    be32(crcb, crc);
    return fwrite(hdr, 1, 8, f) == 8 && fwrite(data, 1, n, f) == n &&
                   fwrite(crcb, 1, 4, f) == 4
               ? 0
               : -1;
}

/* Paeth predictor (PNG 9.4). */
static uint8_t paeth(int a, int b, int c)
{
    int p = a + b - c;
    int pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return (uint8_t)(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

/* Filters row cur (prev: the row above, or NULL) with filter type f into
 * out[0..n); returns the sum of the bytes taken as signed, the usual
 * guess at how well the row will compress. */
static unsigned long filter_row(int f, const uint8_t *cur, const uint8_t *prev,
                                size_t n, uint8_t *out)
{
    unsigned long cost = 0;
    for (size_t i = 0; i < n; i++) {
        int a = i >= 3 ? cur[i - 3] : 0, b = prev ? prev[i] : 0;
        int c = i >= 3 && prev ? prev[i - 3] : 0, pred;
        switch (f) {
        case 1: pred = a; break;
        case 2: pred = b; break;
        case 3: pred = (a + b) / 2; break;
        case 4: pred = paeth(a, b, c); break;
        default: pred = 0; break;
        }
        out[i] = (uint8_t)(cur[i] - pred);
        cost += out[i] < 128 ? out[i] : 256u - out[i];
    }
    return cost;
}

int png_write(FILE *f, const uint8_t *rgb, int w, int h)
{
    if (w <= 0 || h <= 0)
        return -1;
    static const uint8_t sig[8] = { 137, 80, 78, 71, 13, 10, 26, 10 };
    uint8_t ihdr[13];
    be32(ihdr, (uint32_t)w);
    be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 2;  /* colour type: RGB */
    ihdr[10] = ihdr[11] = ihdr[12] = 0;
    /* Scanlines, each with the filter that makes it smallest by
     * filter_row's measure. */
    size_t row = (size_t)w * 3, stride = row + 1, raw_n = stride * (size_t)h;
    uint8_t *raw = malloc(raw_n), *try = malloc(row), *z = NULL;
    size_t z_n = 0;
    int rc = -1;
    if (!raw || !try)
        goto out;
    for (int y = 0; y < h; y++) {
        const uint8_t *cur = rgb + (size_t)y * row;
        const uint8_t *prev = y > 0 ? cur - row : NULL;
        uint8_t *dst = raw + (size_t)y * stride;
        unsigned long best = 0;
        for (int ft = 0; ft < 5; ft++) {
            unsigned long cost = filter_row(ft, cur, prev, row, try);
            if (ft == 0 || cost < best) {
                best = cost;
                dst[0] = (uint8_t)ft;
                memcpy(dst + 1, try, row);
            }
        }
    }
    if (deflate_zlib(raw, raw_n, &z, &z_n) != 0)
        goto out;
    if (fwrite(sig, 1, 8, f) == 8 && chunk(f, "IHDR", ihdr, 13) == 0 &&
        chunk(f, "IDAT", z, z_n) == 0 && chunk(f, "IEND", ihdr, 0) == 0)
        rc = 0;
out:
    free(raw);
    free(try);
    free(z);
    return rc;
}

static uint32_t rd32(const uint8_t *b)
{
    return (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 |
           b[3];
}

int png_decode(const uint8_t *buf, size_t len, ppm_image *img, char *err,
               size_t errlen)
{
    static const uint8_t sig[8] = { 137, 80, 78, 71, 13, 10, 26, 10 };
    uint8_t *z = NULL, *raw = NULL;
    size_t zn = 0, pos = 8;
    uint32_t w = 0, h = 0;
    int ctype = -1, got_end = 0;
    memset(img, 0, sizeof *img);
#define PNG_FAIL(...)                                                         \
    do {                                                                      \
        snprintf(err, errlen, __VA_ARGS__);                                   \
        goto fail;                                                            \
    } while (0)
    if (len < 8 || memcmp(buf, sig, 8) != 0)
        PNG_FAIL("not a PNG (bad signature)");
    while (!got_end) {
        if (len - pos < 12)
            PNG_FAIL("truncated PNG: no IEND chunk");
        uint32_t n = rd32(buf + pos);
        const uint8_t *type = buf + pos + 4, *body = buf + pos + 8;
        if (n > len - pos - 12)
            PNG_FAIL("truncated PNG chunk '%.4s'", (const char *)type);
        if (png_crc32(0, type, (size_t)n + 4) != rd32(body + n))
            PNG_FAIL("bad CRC in PNG chunk '%.4s'", (const char *)type);
        if (pos == 8 && memcmp(type, "IHDR", 4) != 0)
            PNG_FAIL("PNG does not start with IHDR");
        if (memcmp(type, "IHDR", 4) == 0) {
            if (n != 13 || pos != 8)
                PNG_FAIL("bad PNG IHDR");
            w = rd32(body);
            h = rd32(body + 4);
            ctype = body[9];
            if (body[8] != 8 || (ctype != 0 && ctype != 2) || body[10] ||
                body[11] || body[12])
                PNG_FAIL("PNG of bit depth %u, colour type %u%s: only "
                         "8-bit RGB or grey, not interlaced, is read",
                         body[8], body[9], body[12] ? ", interlaced" : "");
            if (w < 1 || w > PPM_MAX_SIDE || h < 1 || h > PPM_MAX_SIDE)
                PNG_FAIL("PNG size %lux%lu is outside 1..%d",
                         (unsigned long)w, (unsigned long)h, PPM_MAX_SIDE);
        } else if (memcmp(type, "IDAT", 4) == 0) {
            uint8_t *nz = realloc(z, zn + n + 1);
            if (!nz)
                PNG_FAIL("out of memory");
            z = nz;
            memcpy(z + zn, body, n);
            zn += n;
        } else if (memcmp(type, "IEND", 4) == 0) {
            got_end = 1;
        } else if (!(type[0] & 0x20)) {
            PNG_FAIL("PNG has a critical chunk '%.4s' this reader does not "
                     "know", (const char *)type);
        }
        pos += (size_t)n + 12;
    }
    if (!z)
        PNG_FAIL("PNG has no image data (IDAT)");
    if (w == 0 || h == 0 || ctype < 0)
        PNG_FAIL("PNG has no IHDR");
    size_t bpp = ctype == 2 ? 3 : 1, row = (size_t)w * bpp;
    size_t raw_n = (row + 1) * h;
    raw = malloc(raw_n);
    if (!raw || ppm_alloc(img, (int)w, (int)h))
        PNG_FAIL("out of memory for %lux%lu pixels", (unsigned long)w,
                 (unsigned long)h);
    const char *why = NULL;
    long got = inflate_zlib(z, zn, raw, raw_n, &why);
    if (got < 0)
        PNG_FAIL("bad PNG image data: %s", why);
    if ((size_t)got != raw_n)
        PNG_FAIL("PNG image data is %ld bytes, want %zu", got, raw_n);
    /* Undo the filters in place, then expand grey to RGB. */
    for (uint32_t y = 0; y < h; y++) {
        uint8_t *cur = raw + y * (row + 1) + 1;
        const uint8_t *prev = y ? cur - (row + 1) : NULL;
        int f = cur[-1];
        if (f > 4)
            PNG_FAIL("bad PNG filter type %d on row %lu", f,
                     (unsigned long)y);
        for (size_t i = 0; i < row; i++) {
            int a = i >= bpp ? cur[i - bpp] : 0, b = prev ? prev[i] : 0;
            int c = i >= bpp && prev ? prev[i - bpp] : 0;
            int pred = f == 1 ? a : f == 2 ? b : f == 3 ? (a + b) / 2
                       : f == 4 ? paeth(a, b, c) : 0;
            cur[i] = (uint8_t)(cur[i] + pred);
        }
        uint8_t *dst = img->data + (size_t)y * w * 3;
        for (size_t x = 0; x < w; x++)
            for (int k = 0; k < 3; k++)
                dst[3 * x + k] = cur[bpp == 3 ? 3 * x + k : x];
    }
#undef PNG_FAIL
    free(z);
    free(raw);
    return 0;
fail:
    free(z);
    free(raw);
    ppm_free(img);
    return -1;
}
