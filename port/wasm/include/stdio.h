/* SPDX-License-Identifier: MIT */
/*
 * stdio.h of the WebAssembly port: formatting into memory only
 * (port/wasm/format.c: %s, %c, %d, %u, %ld, %lu, %zu and %%). The page
 * has no files: the OBJ reader's file functions are declared for it to
 * compile, and never linked (port/wasm/mesh.c hands it the text).
 */
#ifndef FT_WASM_STDIO_H
#define FT_WASM_STDIO_H

#include <stdarg.h>
#include <stddef.h>

typedef struct ft_file FILE;

int vsnprintf(char *buf, size_t cap, const char *fmt, va_list ap);
int snprintf(char *buf, size_t cap, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

FILE *fopen(const char *path, const char *mode);
size_t fread(void *p, size_t size, size_t n, FILE *f);
int ferror(FILE *f);
int fclose(FILE *f);
int fprintf(FILE *f, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
int fputs(const char *s, FILE *f);
int fputc(int c, FILE *f);

#endif /* FT_WASM_STDIO_H */
