/* SPDX-License-Identifier: MIT */
/*
 * test_deflate: the zlib encoder and decoder of port/posix (deflate.c,
 * inflate.c) and the PNG reader built on them. Every input round-trips
 * byte for byte (empty, one byte, long runs, noise, periodic data with
 * distances near the 32 KB window, several Huffman blocks); a stream from
 * real zlib with fixed Huffman codes decodes; damaged streams (cut short
 * at every length, single bits flipped, too small an output) are refused
 * without reading or writing out of bounds; and a PNG written by
 * png_write() decodes back to its pixels.
 */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "deflate.h"
#include "harness.h"
#include "png.h"

static uint64_t rng = 0x2545F4914F6CDD1DULL;

/* Compresses and decompresses in[0..n); checks the bytes come back. */
static size_t round_trip(const uint8_t *in, size_t n, const char *what)
{
    uint8_t *z = NULL, *back = malloc(n + 1);
    size_t zn = 0;
    const char *why = "";
    CHECK(back != NULL);
    if (!th_check(deflate_zlib(in, n, &z, &zn) == 0, __FILE__, __LINE__,
                  what)) {
        free(back);
        return 0;
    }
    long got = inflate_zlib(z, zn, back, n + 1, &why);
    if (!th_check(got == (long)n && memcmp(back, in, n) == 0, __FILE__,
                  __LINE__, what))
        printf("    %s: got %ld of %zu bytes (%s)\n", what, got, n,
               got < 0 ? why : "");
    /* One byte too little room: refused, not overrun. */
    if (n > 0)
        CHECK(inflate_zlib(z, zn, back, n - 1, &why) == -1);
    free(z);
    free(back);
    return zn;
}

static void test_round_trips(void)
{
    static uint8_t buf[300000];
    round_trip(buf, 0, "empty input");
    buf[0] = 'x';
    round_trip(buf, 1, "one byte");
    memset(buf, 'a', 100000);
    size_t zn = round_trip(buf, 100000, "a run of 100,000 bytes");
    CHECK(zn < 1000);
    for (size_t i = 0; i < sizeof buf; i++)
        buf[i] = (uint8_t)th_rnd64(&rng);
    zn = round_trip(buf, sizeof buf, "300,000 bytes of noise");
    CHECK(zn < sizeof buf + sizeof buf / 50); /* grows by under 2 % */
    /* Periodic data: a period just inside and just outside the window. */
    for (size_t period = 32767; period <= 32769; period++) {
        for (size_t i = 0; i < sizeof buf; i++)
            buf[i] = i < period ? (uint8_t)th_rnd64(&rng) : buf[i - period];
        zn = round_trip(buf, sizeof buf, "periodic data");
        if (period < 32768)
            CHECK(zn < period + period / 4);
    }
    /* Text-like data with every byte value and many short matches. */
    for (size_t i = 0; i < sizeof buf; i++)
        buf[i] = (uint8_t)(i % 7 == 0 ? (uint8_t)th_rnd64(&rng) : (uint8_t)"the rain "[i % 9]);
    round_trip(buf, sizeof buf, "text-like data");
}

static void test_zlib_fixed(void)
{
    /* zlib.compress(b'hello hello hello hello, fixed codes', 9) */
    static const uint8_t z[] = {
        0x78, 0xda, 0xcb, 0x48, 0xcd, 0xc9, 0xc9, 0x57, 0xc8, 0x40,
        0x27, 0x75, 0x14, 0xd2, 0x32, 0x2b, 0x52, 0x53, 0x14, 0x92,
        0xf3, 0x53, 0x52, 0x8b, 0x01, 0xf6, 0x28, 0x0d, 0x3b};
    static const char want[] = "hello hello hello hello, fixed codes";
    uint8_t out[64];
    const char *why = "";
    long n = inflate_zlib(z, sizeof z, out, sizeof out, &why);
    CHECK_EQ(n, (long)strlen(want));
    CHECK(n > 0 && memcmp(out, want, (size_t)n) == 0);
    /* Cut short anywhere, or one bit flipped anywhere: never a crash or
     * an overrun; a flip is caught by the structure or the Adler-32. */
    for (size_t k = 0; k < sizeof z; k++)
        CHECK_EQ(inflate_zlib(z, k, out, sizeof out, &why), -1);
    uint8_t bad[sizeof z];
    int caught = 0;
    for (size_t k = 0; k < sizeof z * 8; k++) {
        memcpy(bad, z, sizeof z);
        bad[k / 8] ^= (uint8_t)(1u << (k % 8));
        n = inflate_zlib(bad, sizeof bad, out, sizeof out, &why);
        caught += n == -1;
        CHECK(n <= (long)sizeof out);
    }
    CHECK_EQ(caught, (int)(sizeof z * 8));
}

static void test_png(void)
{
    enum { W = 37, H = 23 };
    static uint8_t rgb[W * H * 3];
    for (size_t i = 0; i < sizeof rgb; i++)
        rgb[i] = (uint8_t)(i % 3 == 0 ? i / 97 : th_rnd64(&rng) & 7);
    char path[] = "/tmp/test_deflate_XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    FILE *f = fdopen(fd, "w+b");
    CHECK(f && png_write(f, rgb, W, H) == 0);
    long len = ftell(f);
    uint8_t *buf = malloc((size_t)len);
    rewind(f);
    CHECK(buf && fread(buf, 1, (size_t)len, f) == (size_t)len);
    fclose(f);
    unlink(path);
    ppm_image img;
    char err[200];
    CHECK_EQ(png_decode(buf, (size_t)len, &img, err, sizeof err), 0);
    CHECK(img.width == W && img.height == H && img.data &&
          memcmp(img.data, rgb, sizeof rgb) == 0);
    ppm_free(&img);
    /* Damage: refused with a reason, every time. */
    for (long k = 0; k < len; k += 7) {
        buf[k] ^= 0x10;
        CHECK_EQ(png_decode(buf, (size_t)len, &img, err, sizeof err), -1);
        CHECK(img.data == NULL && err[0] != '\0');
        buf[k] ^= 0x10;
    }
    for (long k = 0; k < len; k += 5)
        CHECK_EQ(png_decode(buf, (size_t)k, &img, err, sizeof err), -1);
    free(buf);
}

int main(void)
{
    test_round_trips();
    test_zlib_fixed();
    test_png();
    return th_summary();
}
