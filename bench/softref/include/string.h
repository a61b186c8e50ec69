/* SPDX-License-Identifier: MIT */
/*
 * string.h for the bench-only bare-metal build of the double reference
 * renderer (bench/softref); port/baremetal/libc.c defines these.
 */
#ifndef SOFTREF_STRING_H
#define SOFTREF_STRING_H

#include <stddef.h>

void *memcpy(void *dst, const void *src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);

#endif /* SOFTREF_STRING_H */
