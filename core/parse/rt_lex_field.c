/* SPDX-License-Identifier: MIT */
/*
 * rt_lex_field: a statement's values and field names (rt_lex.h), read
 * with rt_lex.c's tokens. Each reader checks its value's range and, on a
 * problem, explains it in the words of the scene format: which field, how
 * many values, and what the token looks like instead.
 */
#include "rt_lex.h"

rt_status rt_lex_need(rt_lex *p, const rt_lex_token *tk, const char *what,
                      const char *labels, int n, const char *kind)
{
    rt_lex_fail(p, tk, RT_ERR_PARSE, "'");
    rt_lex_say(p, what);
    rt_lex_say(p, "' needs ");
    if (n > 1) {
        rt_lex_say_u32(p, (uint32_t)n);
        rt_lex_say(p, " ");
        rt_lex_say(p, kind);
        rt_lex_say(p, "s");
    } else {
        rt_lex_say(p, "a ");
        rt_lex_say(p, kind);
    }
    if (labels) {
        rt_lex_say(p, " (");
        rt_lex_say(p, labels);
        rt_lex_say(p, ")");
    }
    rt_lex_say_got(p, tk);
    return RT_ERR_PARSE;
}

/* Whether the token reads nan or inf(inity), any case, with a sign. */
static int is_nan_inf(const rt_lex *p, const rt_lex_token *tk)
{
    static const char *const words[] = {"nan", "inf", "infinity", NULL};
    const char *t = p->t + tk->off;
    size_t n = tk->len, skip = n > 0 && (t[0] == '+' || t[0] == '-');
    for (int w = 0; words[w]; w++) {
        size_t i = 0;
        for (; skip + i < n && words[w][i]; i++)
            if ((t[skip + i] | 0x20) != words[w][i])
                break;
        if (skip + i == n && words[w][i] == '\0')
            return 1;
    }
    return 0;
}

/* Converts a token to Q16.16, explaining any failure. */
static rt_status to_fx(rt_lex *p, const rt_lex_token *tk, const char *what,
                       const char *labels, int n, fx_t *v)
{
    const char *t = p->t + tk->off;
    size_t used;
    rt_lex_num ns = rt_lex_scan_fx(t, tk->len, v, &used);
    if (ns == RT_LEX_NUM_NONE) {
        if (tk->len && is_nan_inf(p, tk)) {
            rt_lex_fail(p, tk, RT_ERR_PARSE, "");
            rt_lex_say_tok(p, tk);
            rt_lex_say(p, " is not allowed: numbers must be finite decimals");
            return RT_ERR_PARSE;
        }
        return rt_lex_need(p, tk, what, labels, n, "number");
    }
    if (used < tk->len) {
        char c = t[used];
        const char *why = "malformed number ";
        if (c == 'e' || c == 'E')
            why = "exponents are not supported (write the number out): ";
        else if ((c == 'x' || c == 'X') && t[used - 1] == '0' &&
                 used <= 2 && (used == 1 || !rt_lex_is_digit(t[0])))
            why = "hexadecimal numbers are not supported: ";
        rt_lex_fail(p, tk, RT_ERR_PARSE, why);
        rt_lex_say_tok(p, tk);
        return RT_ERR_PARSE;
    }
    if (ns == RT_LEX_NUM_RANGE)
        return rt_lex_fail(p, tk, RT_ERR_PARSE,
                           "number out of Q16.16 range "
                           "(-32768 .. 32767.99998)");
    if (ns == RT_LEX_NUM_DIGITS)
        return rt_lex_fail(p, tk, RT_ERR_PARSE,
                           "number has more than 40 digits");
    return RT_OK;
}

rt_status rt_lex_get_fxs(rt_lex *p, const char *what, const char *labels,
                         int n, fx_t *out, fx_t lo, fx_t hi,
                         const char *rule)
{
    for (int i = 0; i < n; i++) {
        rt_lex_token tk;
        fx_t v = 0;
        TRY(rt_lex_next(p, &tk));
        TRY(to_fx(p, &tk, what, labels, n, &v));
        if (v < lo || v > hi) {
            rt_lex_fail(p, &tk, RT_ERR_PARSE, what);
            if (n == 1 && labels) {
                rt_lex_say(p, " ");
                rt_lex_say(p, labels);
            }
            rt_lex_say(p, " must be ");
            rt_lex_say(p, rule);
            return RT_ERR_PARSE;
        }
        out[i] = v;
    }
    return RT_OK;
}

rt_status rt_lex_get_vec(rt_lex *p, const char *what, fx_vec3 *v)
{
    fx_t c[3];
    TRY(rt_lex_get_fxs(p, what, "x y z", 3, c, FX_MIN, FX_MAX, ""));
    *v = fx_v3(c[0], c[1], c[2]);
    return RT_OK;
}

rt_status rt_lex_get_rgb(rt_lex *p, const char *what, rt_rgb *c, fx_t hi)
{
    fx_t v[3];
    TRY(rt_lex_get_fxs(p, what, "r g b", 3, v, 0, hi,
                       hi == FX_ONE ? "in [0, 1]" : "in [0, 16]"));
    c->r = v[0];
    c->g = v[1];
    c->b = v[2];
    return RT_OK;
}

rt_status rt_lex_get_uint(rt_lex *p, const char *what, const char *label,
                          uint32_t lo, uint32_t hi, const char *note,
                          uint32_t *out, rt_lex_token *where)
{
    rt_lex_token tk;
    uint32_t v = 0;
    size_t i = 0;
    TRY(rt_lex_next(p, &tk));
    *where = tk;
    for (; i < tk.len && rt_lex_is_digit(p->t[tk.off + i]); i++)
        v = v > 99999999u ? 1000000000u
                          : v * 10u + (uint32_t)(p->t[tk.off + i] - '0');
    int bad = tk.len == 0 || i < tk.len;
    if (bad) {
        /* Some other number ("-1", "2.5") gets the range message. */
        fx_t x;
        size_t used;
        if (tk.len == 0 ||
            rt_lex_scan_fx(p->t + tk.off, tk.len, &x, &used) ==
                RT_LEX_NUM_NONE ||
            used < tk.len)
            return rt_lex_need(p, &tk, what, label, 1, "whole number");
    }
    if (!bad && v >= lo && v <= hi) {
        *out = v;
        return RT_OK;
    }
    rt_lex_fail(p, &tk, RT_ERR_PARSE, label ? label : what);
    rt_lex_say(p, " must be a whole number in ");
    rt_lex_say_u32(p, lo);
    rt_lex_say(p, " .. ");
    rt_lex_say_u32(p, hi);
    rt_lex_say(p, note);
    if (bad)
        rt_lex_say_got(p, &tk);
    return RT_ERR_PARSE;
}

rt_status rt_lex_end_stmt(rt_lex *p, const char *stmt)
{
    rt_lex_token tk;
    TRY(rt_lex_next(p, &tk));
    if (tk.len == 0)
        return RT_OK;
    rt_lex_fail(p, &tk, RT_ERR_PARSE, "unexpected ");
    rt_lex_say_tok(p, &tk);
    rt_lex_say(p, " at the end of ");
    rt_lex_say(p, stmt);
    return RT_ERR_PARSE;
}

rt_status rt_lex_next_key(rt_lex *p, const char *stmt,
                          const char *const *keys, rt_lex_token *at,
                          uint32_t *seen, int *k)
{
    rt_lex_token tk;
    fx_t x;
    size_t used;
    *k = -1;
    TRY(rt_lex_next(p, &tk));
    if (tk.len == 0)
        return RT_OK;
    int i = rt_lex_find(p, &tk, keys);
    if (i < 0) {
        int num = rt_lex_scan_fx(p->t + tk.off, tk.len, &x, &used) !=
                  RT_LEX_NUM_NONE;
        rt_lex_fail(p, &tk, RT_ERR_PARSE, num ? "unexpected number " :
                                                "unknown field ");
        rt_lex_say_tok(p, &tk);
        rt_lex_say(p, " in ");
        rt_lex_say(p, stmt);
        rt_lex_say(p, num ? " (expected a field name: "
                          : " (expected one of: ");
        rt_lex_say_list(p, keys);
        rt_lex_say(p, ")");
        return RT_ERR_PARSE;
    }
    if (*seen & (1u << i)) {
        rt_lex_fail(p, &tk, RT_ERR_PARSE, "");
        rt_lex_say_tok(p, &tk);
        rt_lex_say(p, " given twice in ");
        rt_lex_say(p, stmt);
        return RT_ERR_PARSE;
    }
    *seen |= 1u << i;
    at[i] = tk;
    *k = i;
    return RT_OK;
}

rt_status rt_lex_require(rt_lex *p, const rt_lex_token *kw, const char *stmt,
                         const char *const *keys, uint32_t seen,
                         uint32_t required)
{
    for (int i = 0; keys[i]; i++) {
        if ((required & ~seen) & (1u << i)) {
            rt_lex_fail(p, kw, RT_ERR_PARSE, "missing '");
            rt_lex_say(p, keys[i]);
            rt_lex_say(p, "' in ");
            rt_lex_say(p, stmt);
            return RT_ERR_PARSE;
        }
    }
    return RT_OK;
}
