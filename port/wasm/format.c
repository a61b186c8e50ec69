/* SPDX-License-Identifier: MIT */
/*
 * format.c: snprintf for the WebAssembly port, the conversions the host
 * code it reuses writes: %s, %c, %d, %u, %ld, %lu, %zu, %lld, %llu and %%,
 * without flags, width or precision (a conversion it does not know is
 * copied as it stands).
 */
#include <stdint.h>
#include <stdio.h>

typedef struct {
    char *buf;
    size_t cap, n; /* n counts every byte, written or not */
} out;

static void put(out *o, char c)
{
    if (o->n + 1 < o->cap)
        o->buf[o->n] = c;
    o->n++;
}

static void put_unsigned(out *o, unsigned long long v)
{
    char d[24];
    int k = 0;
    do {
        d[k++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    while (k)
        put(o, d[--k]);
}

static void put_signed(out *o, long long v)
{
    if (v < 0) {
        put(o, '-');
        put_unsigned(o, 0ull - (unsigned long long)v);
    } else {
        put_unsigned(o, (unsigned long long)v);
    }
}

int vsnprintf(char *buf, size_t cap, const char *fmt, va_list ap)
{
    out o = {buf, cap, 0};
    for (const char *f = fmt; *f; f++) {
        if (*f != '%') {
            put(&o, *f);
            continue;
        }
        const char *start = f++;
        int longs = 0, size = 0;
        for (; *f == 'l'; f++)
            longs++;
        if (*f == 'z') {
            size = 1;
            f++;
        }
        switch (*f) {
        case '%':
            put(&o, '%');
            break;
        case 'c':
            put(&o, (char)va_arg(ap, int));
            break;
        case 's':
            for (const char *s = va_arg(ap, const char *); *s; s++)
                put(&o, *s);
            break;
        case 'd':
            put_signed(&o, longs > 1 ? va_arg(ap, long long)
                           : longs ? va_arg(ap, long) : va_arg(ap, int));
            break;
        case 'u':
            put_unsigned(&o, size ? va_arg(ap, size_t)
                             : longs > 1 ? va_arg(ap, unsigned long long)
                             : longs ? va_arg(ap, unsigned long)
                                     : va_arg(ap, unsigned));
            break;
        default:
            for (; start <= f && *start; start++)
                put(&o, *start);
            if (!*f)
                f--;
            break;
        }
    }
    if (cap)
        buf[o.n < cap ? o.n : cap - 1] = '\0';
    return (int)o.n;
}

int snprintf(char *buf, size_t cap, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf, cap, fmt, ap);
    va_end(ap);
    return n;
}
