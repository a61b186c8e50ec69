/* SPDX-License-Identifier: MIT */
/* deflate: the encoder. LZ77 turns the input into literals and
 * (length, distance) pairs; each run of up to BLOCK_TOKENS of them becomes
 * one dynamic Huffman block whose codes are built from that block's own
 * symbol counts. The inverse is in inflate.c. */
#include <stdlib.h>
#include <string.h>

#include "deflate.h"

#define WINDOW 32768u
#define MIN_MATCH 3
#define MAX_MATCH 258
#define HASH_BITS 15
#define MAX_CHAIN 128   /* candidates tried per position */
#define GOOD_ENOUGH 128 /* a match this long is taken without lazy look */
#define BLOCK_TOKENS 32768u

#define N_LITLEN 286 /* 0..255 literals, 256 end of block, 257.. lengths */
#define N_DIST 30
#define N_CLEN 19

uint32_t deflate_adler32(uint32_t a, const uint8_t *p, size_t n)
{
    uint32_t s1 = a & 0xFFFF, s2 = a >> 16;
    while (n > 0) {
        size_t k = n < 5552 ? n : 5552; /* no 32-bit overflow before % */
        n -= k;
        while (k--) {
            s1 += *p++;
            s2 += s1;
        }
        s1 %= 65521u;
        s2 %= 65521u;
    }
    return s2 << 16 | s1;
}

/* ---- Bits out, least significant first (RFC 1951 3.1.1) ----------------- */

typedef struct {
    uint8_t *buf;
    size_t n, cap;
    uint32_t acc;
    int nbits;
    int failed;
} bits_out;

static void put_byte(bits_out *b, uint8_t v)
{
    if (b->n == b->cap) {
        size_t cap = b->cap ? b->cap * 2 : 1 << 16;
        uint8_t *nb = realloc(b->buf, cap);
        if (!nb) {
            b->failed = 1;
            return;
        }
        b->buf = nb;
        b->cap = cap;
    }
    b->buf[b->n++] = v;
}

static void put_bits(bits_out *b, uint32_t v, int n)
{
    b->acc |= v << b->nbits;
    b->nbits += n;
    while (b->nbits >= 8) {
        put_byte(b, (uint8_t)b->acc);
        b->acc >>= 8;
        b->nbits -= 8;
    }
}

static void flush_bits(bits_out *b)
{
    if (b->nbits > 0)
        put_byte(b, (uint8_t)b->acc);
    b->acc = 0;
    b->nbits = 0;
}

/* ---- Length and distance symbols (RFC 1951 3.2.5) ----------------------- */


static int len_code(unsigned len)
{
    int c = 28;
    while (len_base[c] > len)
        c--;
    return c;
}

static int dist_code(unsigned d)
{
    int c = 29;
    while (dist_base[c] > d)
        c--;
    return c;
}

/* ---- Huffman codes ------------------------------------------------------- */

/* Code lengths for n symbols of counts freq, none longer than limit; at
 * least two symbols get a code, so every tree is complete. */
static void build_lengths(const uint32_t *freq_in, int n, int limit,
                          uint8_t *len)
{
    uint32_t freq[N_LITLEN];
    int used = 0;
    for (int i = 0; i < n; i++) {
        freq[i] = freq_in[i];
        used += freq[i] != 0;
    }
    for (int i = 0; used < 2 && i < n; i++)
        if (freq[i] == 0) {
            freq[i] = 1;
            used++;
        }
    for (;;) {
        /* Nodes: leaves 0..n-1, then inner nodes; parent links. */
        uint32_t w[2 * N_LITLEN];
        int parent[2 * N_LITLEN], alive[2 * N_LITLEN];
        int nodes = n, left = 0;
        for (int i = 0; i < n; i++) {
            w[i] = freq[i];
            alive[i] = freq[i] != 0;
            parent[i] = -1;
            left += alive[i];
        }
        while (left > 1) {
            int a = -1, b = -1;
            for (int i = 0; i < nodes; i++) {
                if (!alive[i])
                    continue;
                if (a < 0 || w[i] < w[a]) {
                    b = a;
                    a = i;
                } else if (b < 0 || w[i] < w[b]) {
                    b = i;
                }
            }
            if (a < 0 || b < 0)
                break; /* cannot happen: left > 1 nodes are alive */
            w[nodes] = w[a] + w[b];
            alive[nodes] = 1;
            parent[nodes] = -1;
            alive[a] = alive[b] = 0;
            parent[a] = parent[b] = nodes;
            nodes++;
            left--;
        }
        int longest = 0;
        for (int i = 0; i < n; i++) {
            int d = 0;
            if (freq[i])
                for (int p = parent[i]; p >= 0; p = parent[p])
                    d++;
            len[i] = (uint8_t)d;
            longest = d > longest ? d : longest;
        }
        if (longest <= limit)
            return;
        /* Too deep: flatten the counts and build again. */
        for (int i = 0; i < n; i++)
            if (freq[i])
                freq[i] = (freq[i] >> 1) | 1;
    }
}

/* Canonical codes from lengths (RFC 1951 3.2.2), bit-reversed for
 * put_bits. */
static void build_codes(const uint8_t *len, int n, uint16_t *code)
{
    uint16_t count[16] = {0}, next[16];
    for (int i = 0; i < n; i++)
        count[len[i]]++;
    count[0] = 0;
    uint16_t c = 0;
    for (int b = 1; b < 16; b++) {
        c = (uint16_t)((c + count[b - 1]) << 1);
        next[b] = c;
    }
    for (int i = 0; i < n; i++) {
        if (!len[i]) {
            code[i] = 0;
            continue;
        }
        uint16_t v = next[len[i]]++, r = 0;
        for (int k = 0; k < len[i]; k++)
            r = (uint16_t)(r << 1 | ((v >> k) & 1));
        code[i] = r;
    }
}

/* ---- Blocks -------------------------------------------------------------- */

/* A token: a literal (dist 0, value the byte) or a match. */
typedef struct {
    uint16_t len_or_lit;
    uint16_t dist;
} token;

/* Run-length codes 16, 17, 18 over the code lengths of both trees. */
static int rle_lengths(const uint8_t *lens, int n, uint8_t *sym,
                       uint8_t *extra)
{
    int out = 0;
    for (int i = 0; i < n;) {
        int run = 1;
        while (i + run < n && lens[i + run] == lens[i])
            run++;
        if (lens[i] == 0 && run >= 3) {
            int k = run > 138 ? 138 : run;
            sym[out] = k >= 11 ? 18 : 17;
            extra[out++] = (uint8_t)(k >= 11 ? k - 11 : k - 3);
            i += k;
        } else if (lens[i] != 0 && run >= 4) {
            sym[out] = lens[i];
            extra[out++] = 0;
            int k = run - 1 > 6 ? 6 : run - 1;
            sym[out] = 16;
            extra[out++] = (uint8_t)(k - 3);
            i += 1 + k;
        } else {
            sym[out] = lens[i];
            extra[out++] = 0;
            i++;
        }
    }
    return out;
}

static void write_block(bits_out *b, const token *t, size_t nt, int last)
{
    static const uint8_t clen_order[N_CLEN] = {
        16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    uint32_t lf[N_LITLEN] = {0}, df[N_DIST] = {0}, cf[N_CLEN] = {0};
    uint8_t ll[N_LITLEN], dl[N_DIST], cl[N_CLEN];
    uint16_t lc[N_LITLEN], dc[N_DIST], cc[N_CLEN];
    for (size_t i = 0; i < nt; i++) {
        if (t[i].dist == 0) {
            lf[t[i].len_or_lit]++;
        } else {
            lf[257 + len_code(t[i].len_or_lit)]++;
            df[dist_code(t[i].dist)]++;
        }
    }
    lf[256] = 1;
    build_lengths(lf, N_LITLEN, 15, ll);
    build_lengths(df, N_DIST, 15, dl);
    int hlit = N_LITLEN, hdist = N_DIST;
    while (hlit > 257 && ll[hlit - 1] == 0)
        hlit--;
    while (hdist > 1 && dl[hdist - 1] == 0)
        hdist--;
    /* Both trees' lengths, run-length coded as one sequence. */
    uint8_t all[N_LITLEN + N_DIST], sym[N_LITLEN + N_DIST],
        extra[N_LITLEN + N_DIST];
    memcpy(all, ll, (size_t)hlit);
    memcpy(all + hlit, dl, (size_t)hdist);
    int ns = rle_lengths(all, hlit + hdist, sym, extra);
    for (int i = 0; i < ns; i++)
        cf[sym[i]]++;
    build_lengths(cf, N_CLEN, 7, cl);
    int hclen = N_CLEN;
    while (hclen > 4 && cl[clen_order[hclen - 1]] == 0)
        hclen--;
    build_codes(ll, N_LITLEN, lc);
    build_codes(dl, N_DIST, dc);
    build_codes(cl, N_CLEN, cc);

    put_bits(b, last ? 1u : 0u, 1);
    put_bits(b, 2, 2); /* dynamic Huffman codes */
    put_bits(b, (uint32_t)(hlit - 257), 5);
    put_bits(b, (uint32_t)(hdist - 1), 5);
    put_bits(b, (uint32_t)(hclen - 4), 4);
    for (int i = 0; i < hclen; i++)
        put_bits(b, cl[clen_order[i]], 3);
    for (int i = 0; i < ns; i++) {
        put_bits(b, cc[sym[i]], cl[sym[i]]);
        if (sym[i] == 16)
            put_bits(b, extra[i], 2);
        else if (sym[i] == 17)
            put_bits(b, extra[i], 3);
        else if (sym[i] == 18)
            put_bits(b, extra[i], 7);
    }
    for (size_t i = 0; i < nt; i++) {
        if (t[i].dist == 0) {
            put_bits(b, lc[t[i].len_or_lit], ll[t[i].len_or_lit]);
            continue;
        }
        int l = len_code(t[i].len_or_lit), d = dist_code(t[i].dist);
        put_bits(b, lc[257 + l], ll[257 + l]);
        put_bits(b, (uint32_t)(t[i].len_or_lit - len_base[l]), len_extra[l]);
        put_bits(b, dc[d], dl[d]);
        put_bits(b, (uint32_t)(t[i].dist - dist_base[d]), dist_extra[d]);
    }
    put_bits(b, lc[256], ll[256]);
}

/* ---- LZ77 ---------------------------------------------------------------- */

typedef struct {
    const uint8_t *in;
    size_t n;
    int32_t *head; /* 1 << HASH_BITS: last position with that hash, or -1 */
    int32_t *prev; /* WINDOW: the previous position with the same hash */
} matcher;

static unsigned hash3(const uint8_t *p)
{
    return ((unsigned)p[0] << 10 ^ (unsigned)p[1] << 5 ^ p[2]) &
           ((1u << HASH_BITS) - 1);
}

static void insert(matcher *m, size_t pos)
{
    if (pos + MIN_MATCH > m->n)
        return;
    unsigned h = hash3(m->in + pos);
    m->prev[pos % WINDOW] = m->head[h];
    m->head[h] = (int32_t)pos;
}

/* The longest match for pos among earlier positions in the window;
 * returns its length (0 if under MIN_MATCH) and sets *dist. */
static unsigned longest(const matcher *m, size_t pos, unsigned *dist)
{
    if (pos + MIN_MATCH > m->n)
        return 0;
    size_t maxlen = m->n - pos < MAX_MATCH ? m->n - pos : MAX_MATCH;
    unsigned best = 0;
    int32_t cand = m->head[hash3(m->in + pos)];
    for (int chain = 0; cand >= 0 && chain < MAX_CHAIN; chain++) {
        size_t c = (size_t)cand;
        if (pos - c > WINDOW - 1 || c >= pos)
            break;
        if (m->in[c + best] == m->in[pos + best]) {
            size_t k = 0;
            while (k < maxlen && m->in[c + k] == m->in[pos + k])
                k++;
            if (k > best) {
                best = (unsigned)k;
                *dist = (unsigned)(pos - c);
                if (k == maxlen)
                    break;
            }
        }
        int32_t nx = m->prev[c % WINDOW];
        if (nx >= cand)
            break; /* the slot was reused by a newer position */
        cand = nx;
    }
    return best >= MIN_MATCH ? best : 0;
}

int deflate_zlib(const uint8_t *in, size_t n, uint8_t **out, size_t *out_n)
{
    bits_out b = {0};
    matcher m = {in, n, malloc(sizeof(int32_t) << HASH_BITS),
                 malloc(sizeof(int32_t) * WINDOW)};
    token *t = malloc(sizeof *t * BLOCK_TOKENS);
    size_t nt = 0;
    *out = NULL;
    if (!m.head || !m.prev || !t)
        goto fail;
    memset(m.head, 0xFF, sizeof(int32_t) << HASH_BITS);
    put_byte(&b, 0x78); /* deflate, 32 KB window */
    put_byte(&b, 0xDA); /* "maximum compression"; 0x78DA % 31 == 0 */
    size_t pos = 0;
    while (pos < n) {
        unsigned dist = 0, len = longest(&m, pos, &dist);
        if (len && len < GOOD_ENOUGH && pos + 1 < n) {
            /* Lazy: a longer match one byte on wins over this one. */
            unsigned d2 = 0;
            insert(&m, pos);
            unsigned l2 = longest(&m, pos + 1, &d2);
            if (l2 > len) {
                t[nt++] = (token){in[pos], 0};
                pos++;
                len = l2;
                dist = d2;
            } else {
                pos++;
                for (unsigned k = 1; k < len; k++)
                    insert(&m, pos++);
                t[nt++] = (token){(uint16_t)len, (uint16_t)dist};
                len = 0;
            }
            if (len) {
                for (unsigned k = 0; k < len; k++)
                    insert(&m, pos++);
                t[nt++] = (token){(uint16_t)len, (uint16_t)dist};
            }
        } else if (len) {
            for (unsigned k = 0; k < len; k++)
                insert(&m, pos++);
            t[nt++] = (token){(uint16_t)len, (uint16_t)dist};
        } else {
            insert(&m, pos);
            t[nt++] = (token){in[pos++], 0};
        }
        if (nt >= BLOCK_TOKENS - 2) {
            write_block(&b, t, nt, pos >= n);
            nt = 0;
        }
    }
    if (nt > 0 || n == 0)
        write_block(&b, t, nt, 1);
    flush_bits(&b);
    uint32_t a = deflate_adler32(1, in, n);
    for (int k = 3; k >= 0; k--)
        put_byte(&b, (uint8_t)(a >> (8 * k)));
    if (b.failed)
        goto fail;
    free(m.head);
    free(m.prev);
    free(t);
    *out = b.buf;
    *out_n = b.n;
    return 0;
fail:
    free(m.head);
    free(m.prev);
    free(t);
    free(b.buf);
    return -1;
}
