/* SPDX-License-Identifier: MIT */
/* string.h of the WebAssembly port (port/wasm/libc.c). */
#ifndef FT_WASM_STRING_H
#define FT_WASM_STRING_H

#include <stddef.h>

void *memcpy(void *restrict dst, const void *restrict src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);
size_t strlen(const char *s);
char *strrchr(const char *s, int c);
int strcmp(const char *a, const char *b);
/* A message for an errno value (the port has only ENOENT and ERANGE). */
char *strerror(int e);

#endif /* FT_WASM_STRING_H */
