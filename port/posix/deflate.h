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

#endif /* DEFLATE_H */
