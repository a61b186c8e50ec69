/* SPDX-License-Identifier: MIT */
/* stdlib.h of the WebAssembly port (port/wasm/heap.c, port/wasm/libc.c). */
#ifndef FT_WASM_STDLIB_H
#define FT_WASM_STDLIB_H

#include <stddef.h>

/* The heap of port/wasm/heap.c: free() keeps the block until the region
 * it belongs to is released. */
void *malloc(size_t n);
void *calloc(size_t count, size_t size);
void *realloc(void *p, size_t n);
void free(void *p);

void qsort(void *base, size_t n, size_t size,
           int (*cmp)(const void *, const void *));
void *bsearch(const void *key, const void *base, size_t n, size_t size,
              int (*cmp)(const void *, const void *));

/* Decimal numbers exactly where the result is certain to be correctly
 * rounded (at most 19 significant digits, a power of ten up to 10^22);
 * otherwise no conversion (*end = s) with errno ERANGE. */
double strtod(const char *s, char **end);

#endif /* FT_WASM_STDLIB_H */
