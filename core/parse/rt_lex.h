/* SPDX-License-Identifier: MIT */
/*
 * rt_lex: the reading layer of the scene parser, shared by its files and
 * by nothing else. rt_lex.c turns text into lines, tokens and numbers and
 * builds the error message; rt_lex_field.c reads a statement's typed values
 * (numbers, vectors, colours, whole numbers) and field names on top of it.
 * rt_parse.c and rt_parse_obj.c hold the statements.
 *
 * Every function that finds a problem records it in the parser's
 * rt_parse_error (position and message) and returns its status; the first
 * problem ends the parse, so callers only pass the status up (TRY).
 */
#ifndef RT_LEX_H
#define RT_LEX_H

#include "rt_parse.h"

/* Returns the status of x from the calling function unless it is RT_OK.
 * Only the parser's files include this header, so the short name is safe. */
#define TRY(x)                                                                \
    do {                                                                      \
        rt_status try_st_ = (x);                                              \
        if (try_st_ != RT_OK)                                                 \
            return try_st_;                                                   \
    } while (0)

/* A token: text[off .. off + len), on line `line` starting at line_off. A
 * token of length 0 marks the end of a statement. */
typedef struct {
    size_t off, len, line_off;
    uint32_t line;
} rt_lex_token;

/* The parser's state: the text, the current line and the error report. */
typedef struct {
    const char *t;
    size_t len;
    size_t pos;      /* next byte to read on the current line */
    size_t line_off; /* first byte of the current line */
    size_t line_end; /* end of its text, before "\n" or "\r\n" */
    size_t next;     /* first byte of the following line, or len */
    uint32_t line;   /* 1-based number of the current line; 0 before */
    rt_parse_error *err;
    size_t mlen;     /* bytes in err->msg */
    rt_mesh_loader load; /* reads mesh files; NULL: none (rt_parse) */
    void *load_ctx;
} rt_lex;

/* The material names, indexed like rt_scene.mat; on the parser's stack. */
typedef char rt_parse_names[RT_MAX_MATERIALS][RT_MAX_NAME + 1];

/* ---- Numbers (rt_lex.c) ------------------------------------------------- */

/* Why a number did not read: the messages differ for each. */
typedef enum {
    RT_LEX_NUM_OK, RT_LEX_NUM_NONE, RT_LEX_NUM_RANGE, RT_LEX_NUM_DIGITS
} rt_lex_num;

static inline int rt_lex_is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* rt_parse_fx with a reason for failure; *used is always written. */
rt_lex_num rt_lex_scan_fx(const char *t, size_t len, fx_t *out,
                          size_t *used);

/* ---- Lines and tokens (rt_lex.c) ---------------------------------------- */

/* Moves to the line that starts at p->next. */
void rt_lex_start_line(rt_lex *p);

/* Reads the statement's next token into *tk; tk->len == 0 at its end. A
 * "\" token as the last on a line continues the statement on the next. */
rt_status rt_lex_next(rt_lex *p, rt_lex_token *tk);

/* The index of the token in the NULL-terminated names, or -1. */
int rt_lex_find(const rt_lex *p, const rt_lex_token *tk,
                const char *const *names);

/* ---- Messages (rt_lex.c) ------------------------------------------------ */

/* Records the position of the problem at *at, starts the message with msg
 * and returns st; the say functions below then append to the message,
 * which stops growing when full. */
rt_status rt_lex_fail(rt_lex *p, const rt_lex_token *at, rt_status st,
                      const char *msg);
void rt_lex_say(rt_lex *p, const char *s);
void rt_lex_say_u32(rt_lex *p, uint32_t v);

/* Fails at kw with "too many <what> (<limit_name> is <limit>)", the
 * capacity error; returns RT_ERR_CAPACITY. */
rt_status rt_lex_too_many(rt_lex *p, const rt_lex_token *kw,
                          const char *what, const char *limit_name,
                          uint32_t limit);
/* The token in quotes, shortened to 24 bytes. */
void rt_lex_say_tok(rt_lex *p, const rt_lex_token *tk);
/* "; got" and the token, or "end of line" for the end marker. */
void rt_lex_say_got(rt_lex *p, const rt_lex_token *tk);
/* The NULL-terminated names, separated by spaces. */
void rt_lex_say_list(rt_lex *p, const char *const *names);

/* ---- Field values (rt_lex_field.c) -------------------------------------- */

/* Fails at *tk with "'what' needs 3 numbers (x y z); got 'tok'" (n values
 * of kind, labels may be NULL); returns RT_ERR_PARSE. */
rt_status rt_lex_need(rt_lex *p, const rt_lex_token *tk, const char *what,
                      const char *labels, int n, const char *kind);

/* Reads n numbers for field `what` (labels names them for messages, as
 * "x y z") and checks each lies in [lo, hi]; else "what must be rule". */
rt_status rt_lex_get_fxs(rt_lex *p, const char *what, const char *labels,
                         int n, fx_t *out, fx_t lo, fx_t hi,
                         const char *rule);
/* Three numbers of any value. */
rt_status rt_lex_get_vec(rt_lex *p, const char *what, fx_vec3 *v);
/* Three numbers in [0, hi], hi being FX_ONE or the light limit 16. */
rt_status rt_lex_get_rgb(rt_lex *p, const char *what, rt_rgb *c, fx_t hi);
/* Reads a whole number in [lo, hi]; `label` names a positional value, and
 * note follows the range in the message. *where gets the token. */
rt_status rt_lex_get_uint(rt_lex *p, const char *what, const char *label,
                          uint32_t lo, uint32_t hi, const char *note,
                          uint32_t *out, rt_lex_token *where);

/* Requires the statement to end here. */
rt_status rt_lex_end_stmt(rt_lex *p, const char *stmt);

/* Reads the next field name of a statement into keys index *k (-1 at the
 * statement's end), noting it in *seen and at[*k]; repeats are errors. */
rt_status rt_lex_next_key(rt_lex *p, const char *stmt,
                          const char *const *keys, rt_lex_token *at,
                          uint32_t *seen, int *k);

/* Fails at the statement keyword for the first required field not seen. */
rt_status rt_lex_require(rt_lex *p, const rt_lex_token *kw, const char *stmt,
                         const char *const *keys, uint32_t seen,
                         uint32_t required);

/* ---- Statements (rt_parse_obj.c), called by rt_parse.c ------------------ */

/* The 'material' statement after its keyword kw; adds its name to names. */
rt_status rt_parse_material(rt_lex *p, const rt_lex_token *kw, rt_scene *s,
                            rt_parse_names names);

/* An object statement of rt_kind `kind` after its keyword kw. */
rt_status rt_parse_object(rt_lex *p, const rt_lex_token *kw, int kind,
                          rt_scene *s, const rt_parse_names names);

/* The material a statement names in token tk (the next one): its index in
 * *m, or the error that it is missing or not defined. */
rt_status rt_parse_material_ref(rt_lex *p, const rt_scene *s,
                                const rt_parse_names names, int *m);

/* ---- The mesh statement (rt_parse_mesh.c) ------------------------------- */

/* The 'mesh' statement after its keyword kw. */
rt_status rt_parse_mesh(rt_lex *p, const rt_lex_token *kw, rt_scene *s,
                        const rt_parse_names names);

#endif /* RT_LEX_H */
