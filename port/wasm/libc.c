/* SPDX-License-Identifier: MIT */
/*
 * libc.c: the C library of the WebAssembly port, which links none. The
 * core calls only memcpy, memset and memmove (core/fx/rt_libc.h); built
 * with -mbulk-memory, each is one instruction (memory.copy, memory.fill),
 * so the builtins below never become calls back into these functions.
 * The rest is what the host files the page reuses call (the OBJ reader,
 * port/posix/mesh_obj.c): strings, sorting and searching, strtod.
 */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int errno;

void *memcpy(void *restrict dst, const void *restrict src, size_t n)
{
    __builtin_memcpy(dst, src, n);
    return dst;
}

/* memory.copy is defined for overlapping ranges, as memmove is. */
void *memmove(void *dst, const void *src, size_t n)
{
    __builtin_memmove(dst, src, n);
    return dst;
}

void *memset(void *dst, int c, size_t n)
{
    __builtin_memset(dst, c, n);
    return dst;
}

int memcmp(const void *a, const void *b, size_t n)
{
    const unsigned char *p = a, *q = b;
    for (; n > 0; n--, p++, q++) {
        if (*p != *q)
            return *p < *q ? -1 : 1;
    }
    return 0;
}

size_t strlen(const char *s)
{
    const char *e = s;
    while (*e)
        e++;
    return (size_t)(e - s);
}

char *strrchr(const char *s, int c)
{
    const char *found = NULL;
    do {
        if (*s == (char)c)
            found = s;
    } while (*s++);
    return (char *)(uintptr_t)found;
}

int strcmp(const char *a, const char *b)
{
    for (; *a && *a == *b; a++, b++)
        ;
    return (unsigned char)*a - (unsigned char)*b;
}

char *strerror(int e)
{
    return e == ENOENT ? "No such file or directory"
           : e == ERANGE ? "Numerical result out of range"
                         : "Unknown error";
}

static void swap(unsigned char *a, unsigned char *b, size_t size)
{
    for (size_t k = 0; k < size; k++) {
        const unsigned char t = a[k];
        a[k] = b[k];
        b[k] = t;
    }
}

/* Shell sort: in place, no recursion, no allocation; the order of equal
 * elements is unspecified, as qsort's is. */
void qsort(void *base, size_t n, size_t size,
           int (*cmp)(const void *, const void *))
{
    unsigned char *a = base;
    size_t gap = 1;
    while (gap < n / 3)
        gap = 3 * gap + 1;
    for (; gap > 0; gap /= 3)
        for (size_t i = gap; i < n; i++)
            for (size_t j = i; j >= gap && cmp(a + (j - gap) * size,
                                               a + j * size) > 0; j -= gap)
                swap(a + (j - gap) * size, a + j * size, size);
}

void *bsearch(const void *key, const void *base, size_t n, size_t size,
              int (*cmp)(const void *, const void *))
{
    const unsigned char *a = base;
    size_t lo = 0, hi = n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        const int c = cmp(key, a + mid * size);
        if (c == 0)
            return (void *)(uintptr_t)(a + mid * size);
        if (c < 0)
            hi = mid;
        else
            lo = mid + 1;
    }
    return NULL;
}

/* Clinger's fast path: a mantissa below 2^53 times or over an exactly
 * representable power of ten is one correctly rounded operation. */
double strtod(const char *s, char **end)
{
    static const double pow10[23] = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char *p = s;
    int neg = 0, digits = 0, frac = 0, any = 0;
    uint64_t m = 0;
    while (*p == ' ' || *p == '\t')
        p++;
    if (*p == '+' || *p == '-')
        neg = *p++ == '-';
    for (int point = 0;; p++) {
        if (*p == '.' && !point) {
            point = 1;
            continue;
        }
        if (*p < '0' || *p > '9')
            break;
        any = 1;
        if (m == 0 && *p == '0') {
            frac += point;
            continue;
        }
        if (digits == 19) { /* beyond: only zeros, as a power of ten */
            if (*p != '0')
                goto refuse;
            frac -= !point;
            continue;
        }
        digits++;
        m = m * 10 + (uint64_t)(*p - '0');
        frac += point;
    }
    if (!any)
        goto refuse;
    long e = 0;
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        int eneg = 0;
        if (*q == '+' || *q == '-')
            eneg = *q++ == '-';
        if (*q >= '0' && *q <= '9') {
            for (; *q >= '0' && *q <= '9'; q++)
                if (e < 100000)
                    e = e * 10 + (*q - '0');
            e = eneg ? -e : e;
            p = q;
        }
    }
    e -= frac;
    double v;
    if (m == 0)
        v = 0;
    else if (m <= ((uint64_t)1 << 53) && e >= 0 && e <= 22)
        v = (double)m * pow10[e];
    else if (m <= ((uint64_t)1 << 53) && e < 0 && e >= -22)
        v = (double)m / pow10[-e];
    else
        goto refuse;
    if (end)
        *end = (char *)(uintptr_t)p;
    return neg ? -v : v;
refuse:
    errno = ERANGE;
    if (end)
        *end = (char *)(uintptr_t)s;
    return 0;
}
