/* SPDX-License-Identifier: MIT */
/*
 * heap.c: malloc and friends over the memory past the module's data
 * (__heap_base, which wasm-ld defines), grown with memory.grow when a
 * block does not fit. A block is 8-byte aligned (doubles, int64_t) and
 * starts after a header with its size, for realloc. The last block grows
 * in place, so the OBJ reader's doubling arrays cost no copy.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "heap.h"

extern unsigned char __heap_base;

#define ALIGN 8u
#define PAGE 65536u

static size_t top;  /* offset of the next free byte from __heap_base */
static size_t last = SIZE_MAX; /* the last block's header, or none */

static int ensure(size_t end)
{
    const uintptr_t need = (uintptr_t)&__heap_base + end;
    const uintptr_t have = __builtin_wasm_memory_size(0) * PAGE;
    if (need <= have)
        return 0;
    const size_t pages = (need - have + PAGE - 1) / PAGE;
    return __builtin_wasm_memory_grow(0, pages) == SIZE_MAX ? -1 : 0;
}

static size_t *header(void *p) { return (size_t *)p - 2; }

void *malloc(size_t n)
{
    const size_t at = top, body = (n + ALIGN - 1) & ~(size_t)(ALIGN - 1);
    if (n > SIZE_MAX / 2 || ensure(at + 2 * sizeof(size_t) + body) != 0)
        return NULL;
    size_t *h = (size_t *)(void *)(&__heap_base + at);
    h[0] = n;
    top = at + 2 * sizeof(size_t) + body;
    last = at;
    return h + 2;
}

void *calloc(size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    void *p = malloc(count * size);
    if (p)
        memset(p, 0, count * size);
    return p;
}

void *realloc(void *p, size_t n)
{
    if (!p)
        return malloc(n);
    size_t *h = header(p);
    const size_t at = (size_t)((unsigned char *)h - &__heap_base);
    if (at == last) {
        const size_t body = (n + ALIGN - 1) & ~(size_t)(ALIGN - 1);
        if (n > SIZE_MAX / 2 || ensure(at + 2 * sizeof(size_t) + body) != 0)
            return NULL;
        h[0] = n;
        top = at + 2 * sizeof(size_t) + body;
        return p;
    }
    void *q = malloc(n);
    if (q)
        memcpy(q, p, h[0] < n ? h[0] : n);
    return q;
}

void free(void *p)
{
    (void)p; /* the region goes as a whole: wasm_heap_release */
}

size_t wasm_heap_mark(void)
{
    return top;
}

void wasm_heap_release(size_t mark)
{
    if (mark < top) {
        top = mark;
        last = SIZE_MAX;
    }
}
