/* SPDX-License-Identifier: MIT */
/* deflate: a zlib stream encoder (RFC 1950 around RFC 1951) of our own,
 * for PNG output: LZ77 over a 32 KB window with hash chains and one step
 * of lazy matching, then dynamic Huffman blocks. And its inverse, a small
 * inflate for reading PNG files back (stored, fixed and dynamic blocks). */
#ifndef DEFLATE_H
#define DEFLATE_H

#include <stddef.h>
#include <stdint.h>

/* Compresses n bytes into a malloc'ed zlib stream (header, blocks,
 * Adler-32) at *out, of *out_n bytes. Returns 0, or -1 when memory runs
 * out (then *out is NULL). */
int deflate_zlib(const uint8_t *in, size_t n, uint8_t **out, size_t *out_n);

/* Decompresses the zlib stream z[0..zn) into out[0..cap), checking the
 * header and the Adler-32. Returns the number of bytes written, or -1 when
 * the stream is malformed, truncated, fails its check, or holds more than
 * cap bytes; *why then says which (a static string). */
long inflate_zlib(const uint8_t *z, size_t zn, uint8_t *out, size_t cap,
                  const char **why);

/* Adler-32 of n bytes, continuing from a (start with 1). */
uint32_t deflate_adler32(uint32_t a, const uint8_t *p, size_t n);

/* RFC 1951 3.2.5: the base length and extra bits of length symbols 257..285
 * and the base distance and extra bits of distance symbols 0..29
 * (deflate_tables.c). */
extern const uint16_t len_base[29];
extern const uint8_t len_extra[29];
extern const uint16_t dist_base[30];
extern const uint8_t dist_extra[30];

#endif /* DEFLATE_H */
