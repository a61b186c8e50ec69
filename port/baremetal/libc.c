/* SPDX-License-Identifier: MIT */
/*
 * libc.c: the four memory functions GCC may call on its own (struct copies
 * and clears), even with -ffreestanding. There is no C library on the
 * device. Build this file with -fno-tree-loop-distribute-patterns, or GCC
 * turns the loops below back into calls to themselves.
 */
#include <stddef.h>
#include <stdint.h>

void *memcpy(void *restrict dst, const void *restrict src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);

/* A word that may alias any object, so the word loops are well defined. */
typedef uint32_t __attribute__((may_alias)) word_t;

#define WORD_ALIGNED(p) (((uintptr_t)(p) & (sizeof(uint32_t) - 1)) == 0)

void *memcpy(void *restrict dst, const void *restrict src, size_t n)
{
    uint8_t *d = dst;
    const uint8_t *s = src;
    /* Struct copies are word-aligned: move words while both are. */
    if (WORD_ALIGNED(d) && WORD_ALIGNED(s)) {
        for (; n >= 4; n -= 4, d += 4, s += 4)
            *(word_t *)(void *)d = *(const word_t *)(const void *)s;
    }
    while (n--)
        *d++ = *s++;
    return dst;
}

void *memmove(void *dst, const void *src, size_t n)
{
    uint8_t *d = dst;
    const uint8_t *s = src;
    if (d < s || d >= s + n) {
        while (n--)
            *d++ = *s++;
    } else {
        /* Overlap with dst above src: copy from the end. */
        while (n--)
            d[n] = s[n];
    }
    return dst;
}

void *memset(void *dst, int c, size_t n)
{
    uint8_t *d = dst;
    uint8_t b = (uint8_t)c;
    if (WORD_ALIGNED(d)) {
        word_t w = b * 0x01010101u;
        for (; n >= 4; n -= 4, d += 4)
            *(word_t *)(void *)d = w;
    }
    while (n--)
        *d++ = b;
    return dst;
}

int memcmp(const void *a, const void *b, size_t n)
{
    const uint8_t *p = a;
    const uint8_t *q = b;
    for (; n > 0; n--, p++, q++) {
        if (*p != *q)
            return *p < *q ? -1 : 1;
    }
    return 0;
}
