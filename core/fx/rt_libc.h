/* SPDX-License-Identifier: MIT */
/*
 * The only C library functions the core uses. Declared here rather than
 * taken from <string.h> because bare-metal toolchains without newlib have
 * no <string.h>; every port provides these three (GCC emits calls to them
 * for struct copies even with -ffreestanding).
 */
#ifndef RT_LIBC_H
#define RT_LIBC_H

#include <stddef.h>

void *memcpy(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
void *memmove(void *dst, const void *src, size_t n);

#endif /* RT_LIBC_H */
