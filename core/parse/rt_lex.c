/* SPDX-License-Identifier: MIT */
/*
 * rt_lex: scene text into lines, tokens and Q16.16 numbers, and the error
 * message of the first problem (rt_lex.h). The number reader is public
 * too, as rt_parse_fx() (rt_parse.h).
 *
 * Every byte is looked at a bounded number of times, so the time is linear
 * in the input; nothing is allocated and nothing recurses.
 */
#include "rt_libc.h"
#include "rt_lex.h"

/* More digits than any Q16.16 value needs to be written exactly. */
#define NUM_MAX_DIGITS 40

/* ---- Numbers ------------------------------------------------------------ */

rt_lex_num rt_lex_scan_fx(const char *t, size_t len, fx_t *out,
                          size_t *used)
{
    uint8_t frac[NUM_MAX_DIGITS];
    size_t i = 0, nd = 0, nf = 0;
    uint32_t ip = 0, bits = 0;
    int neg = 0;

    if (len > 0 && (t[0] == '+' || t[0] == '-'))
        neg = t[i++] == '-';
    for (; i < len && rt_lex_is_digit(t[i]); i++, nd++)
        if (ip < 100000u) /* saturates: above 32768 is out of range anyway */
            ip = ip * 10u + (uint32_t)(t[i] - '0');
    if (i < len && t[i] == '.') {
        size_t dot = i++;
        for (; i < len && rt_lex_is_digit(t[i]); i++, nd++)
            if (nf < NUM_MAX_DIGITS)
                frac[nf++] = (uint8_t)(t[i] - '0');
        if (nd == 0)
            i = dot;
    }
    *used = nd ? i : 0;
    if (nd == 0)
        return RT_LEX_NUM_NONE;
    if (nd > NUM_MAX_DIGITS)
        return RT_LEX_NUM_DIGITS;
    /* The fraction's first 17 bits, exactly: doubling the decimal digits
     * carries one bit at a time out past the point. Trailing zeros are
     * dropped as they appear, so short fractions cost little. */
    for (int k = 0; k < 17; k++) {
        unsigned carry = 0;
        while (nf > 0 && frac[nf - 1] == 0)
            nf--;
        for (size_t j = nf; j-- > 0;) {
            unsigned v = frac[j] * 2u + carry;
            carry = v >= 10u;
            frac[j] = (uint8_t)(v - 10u * carry);
        }
        bits = bits << 1 | carry;
    }
    /* Ties away from zero: round the magnitude up when bit 17 is set. */
    uint64_t mag = ((uint64_t)ip << 16) + ((bits + 1u) >> 1);
    if (mag > (neg ? 0x80000000u : 0x7FFFFFFFu))
        return RT_LEX_NUM_RANGE;
    *out = neg ? (fx_t)(0 - (int64_t)mag) : (fx_t)mag;
    return RT_LEX_NUM_OK;
}

rt_status rt_parse_fx(const char *text, size_t len, fx_t *out, size_t *used)
{
    size_t n;
    fx_t v = 0;
    rt_lex_num ns = rt_lex_scan_fx(text, len, &v, &n);
    if (used)
        *used = n;
    if (ns != RT_LEX_NUM_OK)
        return RT_ERR_PARSE;
    *out = v;
    return RT_OK;
}

/* ---- Lines, messages and tokens ----------------------------------------- */

void rt_lex_start_line(rt_lex *p)
{
    size_t i = p->next;
    p->line_off = p->pos = i;
    while (i < p->len && p->t[i] != '\n')
        i++;
    p->next = i < p->len ? i + 1 : i;
    if (i > p->line_off && p->t[i - 1] == '\r')
        i--;
    p->line_end = i;
    if (p->line < UINT32_MAX)
        p->line++;
}

void rt_lex_say(rt_lex *p, const char *s)
{
    char *m = p->err->msg;
    while (*s && p->mlen + 1 < sizeof p->err->msg)
        m[p->mlen++] = *s++;
    m[p->mlen] = '\0';
}

void rt_lex_say_u32(rt_lex *p, uint32_t v)
{
    char buf[11];
    size_t i = sizeof buf - 1;
    buf[i] = '\0';
    do {
        buf[--i] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    rt_lex_say(p, buf + i);
}

void rt_lex_say_tok(rt_lex *p, const rt_lex_token *tk)
{
    char buf[32];
    size_t n = tk->len > 24 ? 24 : tk->len;
    buf[0] = '\'';
    memcpy(buf + 1, p->t + tk->off, n);
    memcpy(buf + 1 + n, tk->len > n ? "...'" : "'", tk->len > n ? 5 : 2);
    rt_lex_say(p, buf);
}

void rt_lex_say_got(rt_lex *p, const rt_lex_token *tk)
{
    rt_lex_say(p, "; got ");
    if (tk->len)
        rt_lex_say_tok(p, tk);
    else
        rt_lex_say(p, "end of line");
}

void rt_lex_say_list(rt_lex *p, const char *const *names)
{
    for (size_t i = 0; names[i]; i++) {
        if (i)
            rt_lex_say(p, " ");
        rt_lex_say(p, names[i]);
    }
}

rt_status rt_lex_fail(rt_lex *p, const rt_lex_token *at, rt_status st,
                      const char *msg)
{
    rt_parse_error *e = p->err;
    size_t end = at->line_off, col = at->off - at->line_off + 1;
    while (end < p->len && p->t[end] != '\n')
        end++;
    if (end > at->line_off && p->t[end - 1] == '\r')
        end--;
    e->line = at->line;
    e->col = col > UINT32_MAX ? UINT32_MAX : (uint32_t)col;
    e->line_off = at->line_off;
    e->line_len = end - at->line_off;
    e->tok_len = at->len;
    p->mlen = 0;
    rt_lex_say(p, msg);
    return st;
}

static rt_status bad_byte(rt_lex *p, size_t i)
{
    static const char hex[] = "0123456789abcdef";
    unsigned char c = (unsigned char)p->t[i];
    char buf[5] = {'0', 'x', hex[c >> 4], hex[c & 15u], '\0'};
    rt_lex_token tk = {i, 1, p->line_off, p->line};
    rt_lex_fail(p, &tk, RT_ERR_PARSE, "unexpected byte ");
    rt_lex_say(p, buf);
    if (c >= 0x80)
        rt_lex_say(p, " (non-ASCII text is allowed only in comments)");
    return RT_ERR_PARSE;
}

rt_status rt_lex_next(rt_lex *p, rt_lex_token *tk)
{
    const char *t = p->t;
    int cont = 0;
    rt_lex_token bs = {0, 0, 0, 0};
    for (;;) {
        size_t i = p->pos;
        while (i < p->line_end && (t[i] == ' ' || t[i] == '\t'))
            i++;
        if (i < p->line_end && t[i] != '#') {
            size_t s = i;
            if (t[i] == '"') {
                /* A quoted token (a path) may hold spaces and '#'; it
                 * ends at the next '"' on the same line. */
                for (i++; i < p->line_end && t[i] != '"'; i++)
                    if ((unsigned char)t[i] < 0x20 ||
                        (unsigned char)t[i] > 0x7e)
                        return bad_byte(p, i);
                if (i == p->line_end) {
                    rt_lex_token q = {s, 1, p->line_off, p->line};
                    return rt_lex_fail(p, &q, RT_ERR_PARSE,
                                       "unclosed quote: this '\"' has no "
                                       "closing '\"' on its line");
                }
                i++;
            }
            for (; i < p->line_end && t[i] != ' ' && t[i] != '\t' &&
                   t[i] != '#'; i++)
                if ((unsigned char)t[i] < 0x21 || (unsigned char)t[i] > 0x7e)
                    return bad_byte(p, i);
            if (cont)
                return rt_lex_fail(p, &bs, RT_ERR_PARSE,
                                   "'\\' continues a statement on the next "
                                   "line and must be the last token on its "
                                   "line");
            p->pos = i;
            tk->off = s;
            tk->len = i - s;
            tk->line_off = p->line_off;
            tk->line = p->line;
            if (tk->len != 1 || t[s] != '\\')
                return RT_OK;
            cont = 1;
            bs = *tk;
            continue;
        }
        /* A comment may hold any byte but NUL. */
        for (; i < p->line_end; i++)
            if (t[i] == '\0')
                return bad_byte(p, i);
        p->pos = i;
        if (!cont) {
            tk->off = i;
            tk->len = 0;
            tk->line_off = p->line_off;
            tk->line = p->line;
            return RT_OK;
        }
        if (p->next >= p->len)
            return rt_lex_fail(p, &bs, RT_ERR_PARSE,
                               "'\\' at the end of the input: no line to "
                               "continue");
        rt_lex_start_line(p);
        cont = 0;
    }
}

static int tok_is(const rt_lex *p, const rt_lex_token *tk, const char *s)
{
    size_t i;
    /* Token bytes are never NUL, so a mismatch stops at s's end. */
    for (i = 0; i < tk->len; i++)
        if (s[i] != p->t[tk->off + i])
            return 0;
    return s[i] == '\0';
}

int rt_lex_find(const rt_lex *p, const rt_lex_token *tk,
                const char *const *names)
{
    for (int i = 0; names[i]; i++)
        if (tok_is(p, tk, names[i]))
            return i;
    return -1;
}

rt_status rt_lex_too_many(rt_lex *p, const rt_lex_token *kw,
                          const char *what, const char *limit_name,
                          uint32_t limit)
{
    rt_lex_fail(p, kw, RT_ERR_CAPACITY, "too many ");
    rt_lex_say(p, what);
    rt_lex_say(p, " (");
    rt_lex_say(p, limit_name);
    rt_lex_say(p, " is ");
    rt_lex_say_u32(p, limit);
    rt_lex_say(p, ")");
    return RT_ERR_CAPACITY;
}
