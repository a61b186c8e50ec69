/* SPDX-License-Identifier: MIT */
/* cli_util: argument checking, scene reading and error printing for the
 * host command. */
#ifndef CLI_UTIL_H
#define CLI_UTIL_H

#include <stddef.h>
#include <stdio.h>
#include "rt_parse.h"

/* Largest scene file read (the format is a few lines per object). */
#define CLI_MAX_SCENE_BYTES (16u << 20)

/* Prints "fixtrace: <message>" on stderr; returns 2 (bad usage). */
int cli_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* The value of option argv[*i] (the next argument), advancing *i; NULL
 * with a message when it is missing. */
const char *cli_value(int argc, char **argv, int *i, const char *opt);

/* 1 if opt names an option that takes a value (its value was missing). */
int cli_needs_value(const char *opt);

/* Parses a whole decimal integer in [lo, hi] into *out; prints a message
 * naming the option and returns 2 if it is not one. */
int cli_long(const char *opt, const char *val, long lo, long hi, long *out);

/* Says an option is unknown, with a hint for a glued value ("-j2" or
 * "--width=640"); returns 2. */
int cli_unknown_option(const char *opt);

/* Checks an output name: "-" (unless stdout is a terminal), or ending in
 * a name image_kind_of() knows, and not the scene file itself. Prints why not and
 * returns 2; 0 if fine. */
int cli_check_output(const char *out, const char *scene);

/* Reads a whole file (at most CLI_MAX_SCENE_BYTES) into a malloc'ed
 * buffer; NULL with a message in err on failure. */
char *cli_read_file(const char *path, size_t *len, char *err, size_t errlen);

/* Prints "path:line:col: error: msg", the offending line and a caret. */
void cli_print_parse_error(FILE *f, const char *path, const char *text,
                           size_t len, const rt_parse_error *e);

#endif /* CLI_UTIL_H */
