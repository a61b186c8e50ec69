/* SPDX-License-Identifier: MIT */
/* inflate: the decoder of deflate.h. Codes are decoded canonically, one
 * bit at a time against the count of codes of each length, which is slow
 * next to table lookups but short and easy to check; it reads our own PNG
 * output and any other zlib stream. Every read is bounds-checked. */
#include <string.h>

#include "deflate.h"

typedef struct {
    const uint8_t *in;
    size_t n, pos;
    uint32_t acc;
    int nbits;
    uint8_t *out;
    size_t cap, len;
    const char *why;
} state;

/* Fails the stream with a reason; returns -1. */
static int fail(state *s, const char *why)
{
    if (!s->why)
        s->why = why;
    return -1;
}

/* n bits (0..16), least significant first; -1 past the end. */
static long bits(state *s, int n)
{
    while (s->nbits < n) {
        if (s->pos >= s->n)
            return fail(s, "truncated deflate data");
        s->acc |= (uint32_t)s->in[s->pos++] << s->nbits;
        s->nbits += 8;
    }
    long v = (long)(s->acc & ((1u << n) - 1));
    s->acc >>= n;
    s->nbits -= n;
    return v;
}

typedef struct {
    uint16_t count[16];  /* codes of each length */
    uint16_t symbol[320]; /* symbols in canonical order */
} huff;

/* Builds a decoder from code lengths; -1 for an over-subscribed set. An
 * incomplete set is allowed (a single distance code is common). */
static int build(huff *h, const uint8_t *len, int n)
{
    uint16_t offs[16];
    memset(h->count, 0, sizeof h->count);
    for (int i = 0; i < n; i++)
        h->count[len[i]]++;
    int left = 1;
    for (int b = 1; b < 16; b++) {
        left = left * 2 - h->count[b];
        if (left < 0)
            return -1;
    }
    offs[1] = 0;
    for (int b = 1; b < 15; b++)
        offs[b + 1] = (uint16_t)(offs[b] + h->count[b]);
    for (int i = 0; i < n; i++)
        if (len[i])
            h->symbol[offs[len[i]]++] = (uint16_t)i;
    return 0;
}

static int decode(state *s, const huff *h)
{
    int code = 0, first = 0, index = 0;
    for (int b = 1; b < 16; b++) {
        long bit = bits(s, 1);
        if (bit < 0)
            return -1;
        code |= (int)bit;
        int count = h->count[b];
        if (code - first < count)
            return h->symbol[index + code - first];
        index += count;
        first = (first + count) << 1;
        code <<= 1;
    }
    return fail(s, "bad Huffman code");
}


static int put(state *s, uint8_t v)
{
    if (s->len >= s->cap)
        return fail(s, "more data than the image holds");
    s->out[s->len++] = v;
    return 0;
}

/* The symbols of one Huffman block, up to its end code. */
static int codes(state *s, const huff *lit, const huff *dist)
{
    for (;;) {
        int sym = decode(s, lit);
        if (sym < 0)
            return -1;
        if (sym < 256) {
            if (put(s, (uint8_t)sym))
                return -1;
            continue;
        }
        if (sym == 256)
            return 0;
        sym -= 257;
        if (sym >= 29)
            return fail(s, "bad length code");
        long e = bits(s, len_extra[sym]);
        int d = decode(s, dist);
        if (e < 0 || d < 0)
            return -1;
        if (d >= 30)
            return fail(s, "bad distance code");
        long de = bits(s, dist_extra[d]);
        if (de < 0)
            return -1;
        size_t len = len_base[sym] + (size_t)e, back = dist_base[d] + (size_t)de;
        if (back > s->len)
            return fail(s, "distance before the start of the data");
        for (size_t k = 0; k < len; k++)
            if (put(s, s->out[s->len - back]))
                return -1;
    }
}

static int stored(state *s)
{
    s->acc = 0;
    s->nbits = 0; /* to the byte boundary */
    if (s->n - s->pos < 4)
        return fail(s, "truncated stored block");
    unsigned len = s->in[s->pos] | (unsigned)s->in[s->pos + 1] << 8;
    unsigned nlen = s->in[s->pos + 2] | (unsigned)s->in[s->pos + 3] << 8;
    s->pos += 4;
    if (len != (~nlen & 0xFFFF))
        return fail(s, "bad stored block length");
    if (s->n - s->pos < len)
        return fail(s, "truncated stored block");
    if (s->cap - s->len < len)
        return fail(s, "more data than the image holds");
    memcpy(s->out + s->len, s->in + s->pos, len);
    s->pos += len;
    s->len += len;
    return 0;
}

static int fixed(state *s)
{
    uint8_t len[288 + 30];
    huff lit, dist;
    for (int i = 0; i < 288; i++)
        len[i] = i < 144 ? 8 : i < 256 ? 9 : i < 280 ? 7 : 8;
    for (int i = 0; i < 30; i++)
        len[288 + i] = 5;
    build(&lit, len, 288);
    build(&dist, len + 288, 30);
    return codes(s, &lit, &dist);
}

static int dynamic(state *s)
{
    static const uint8_t order[19] = {
        16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    uint8_t len[320];
    huff lit, dist, cl;
    long nlen = bits(s, 5), ndist = bits(s, 5), ncode = bits(s, 4);
    if (nlen < 0 || ndist < 0 || ncode < 0)
        return -1;
    nlen += 257;
    ndist += 1;
    ncode += 4;
    if (nlen > 286 || ndist > 30)
        return fail(s, "bad code counts");
    memset(len, 0, 19);
    for (int i = 0; i < ncode; i++) {
        long v = bits(s, 3);
        if (v < 0)
            return -1;
        len[order[i]] = (uint8_t)v;
    }
    if (build(&cl, len, 19))
        return fail(s, "bad code-length code");
    for (int i = 0; i < nlen + ndist;) {
        int sym = decode(s, &cl);
        long rep;
        uint8_t v = 0;
        if (sym < 0)
            return -1;
        if (sym < 16) {
            len[i++] = (uint8_t)sym;
            continue;
        }
        if (sym == 16) {
            if (i == 0)
                return fail(s, "repeat with no length before it");
            v = len[i - 1];
            rep = bits(s, 2);
            rep = rep < 0 ? rep : rep + 3;
        } else if (sym == 17) {
            rep = bits(s, 3);
            rep = rep < 0 ? rep : rep + 3;
        } else {
            rep = bits(s, 7);
            rep = rep < 0 ? rep : rep + 11;
        }
        if (rep < 0)
            return -1;
        if (i + rep > nlen + ndist)
            return fail(s, "code lengths run past their count");
        while (rep--)
            len[i++] = v;
    }
    if (len[256] == 0)
        return fail(s, "no end-of-block code");
    if (build(&lit, len, (int)nlen) || build(&dist, len + nlen, (int)ndist))
        return fail(s, "over-subscribed Huffman code");
    return codes(s, &lit, &dist);
}

long inflate_zlib(const uint8_t *z, size_t zn, uint8_t *out, size_t cap,
                  const char **why)
{
    state s = {z, zn, 2, 0, 0, out, cap, 0, NULL};
    if (zn < 6 || (z[0] & 0x0F) != 8 || (z[0] >> 4) > 7 ||
        ((unsigned)z[0] << 8 | z[1]) % 31 != 0 || (z[1] & 0x20)) {
        *why = "not a zlib stream (bad header)";
        return -1;
    }
    long last;
    do {
        last = bits(&s, 1);
        long type = bits(&s, 2);
        int rc = last < 0 || type < 0 ? -1
                 : type == 0          ? stored(&s)
                 : type == 1          ? fixed(&s)
                 : type == 2          ? dynamic(&s)
                                      : fail(&s, "bad block type");
        if (rc) {
            *why = s.why ? s.why : "bad deflate data";
            return -1;
        }
    } while (!last);
    /* The Adler-32 follows at the next byte boundary. */
    if (s.n - s.pos < 4) {
        *why = "truncated: no Adler-32";
        return -1;
    }
    const uint8_t *a = s.in + s.pos;
    uint32_t want = (uint32_t)a[0] << 24 | (uint32_t)a[1] << 16 |
                    (uint32_t)a[2] << 8 | a[3];
    if (deflate_adler32(1, out, s.len) != want) {
        *why = "Adler-32 mismatch (corrupt data)";
        return -1;
    }
    return (long)s.len;
}
