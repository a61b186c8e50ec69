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
