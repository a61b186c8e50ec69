/*
 * rt_parse: the text scene format (docs/scene-format.md) into an rt_scene.
 * No allocation: the caller provides the scene; names live on the parser's
 * stack while it runs. Works on a device as on a host.
 */
#ifndef RT_PARSE_H
#define RT_PARSE_H

#include <stddef.h>
#include "rt_scene.h"

typedef struct {
    uint32_t line;   /* 1-based line of the problem */
    uint32_t col;    /* 1-based column (bytes) */
    size_t line_off; /* offset of that line's first byte in the input */
    size_t line_len; /* its length, without the newline */
    char msg[96];    /* what is wrong, NUL-terminated, no position */
} rt_parse_error;

/* Parses len bytes of scene text into *s (which it initialises first).
 * Never reads outside text[0..len). Returns RT_OK; or RT_ERR_PARSE,
 * RT_ERR_CAPACITY or RT_ERR_DEGENERATE with *err filled in. */
rt_status rt_parse(const char *text, size_t len, rt_scene *s,
                   rt_parse_error *err);

/* Parses one decimal number [+-]digits[.digits] at text[0..len) straight
 * to Q16.16, correctly rounded to nearest (ties away from zero). Stores the
 * count of bytes used in *used. Returns RT_OK, or RT_ERR_PARSE for no
 * number, a value outside the Q16.16 range, or more than 40 digits. */
rt_status rt_parse_fx(const char *text, size_t len, fx_t *out, size_t *used);

#endif /* RT_PARSE_H */
