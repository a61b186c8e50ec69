/*
 * rt_parse: the scene text format (docs/scene-format.md) into an rt_scene.
 *
 * One pass, line by line. Each statement reads its tokens left to right and
 * the first problem ends the parse with its position. Every byte is looked
 * at a bounded number of times, so the time is linear in the input. Nothing
 * is allocated and nothing recurses: the stack holds the material name
 * table and a few hundred bytes more.
 */
#include "rt_libc.h"
#include "rt_parse.h"

/* The scene's field types bound the capacities in rt_config.h. */
#if RT_MAX_MATERIALS < 1 || RT_MAX_MATERIALS > 255
#error "RT_MAX_MATERIALS must be 1..255: rt_object.material is a uint8_t"
#endif
#if RT_MAX_LIGHTS < 1 || RT_MAX_LIGHTS > 255
#error "RT_MAX_LIGHTS must be 1..255: rt_scene.n_lights is a uint8_t"
#endif
#if RT_MAX_OBJECTS < 1 || RT_MAX_OBJECTS > 65535
#error "RT_MAX_OBJECTS must be 1..65535: rt_scene.n_objects is a uint16_t"
#endif
#if RT_MAX_WIDTH < 1 || RT_MAX_WIDTH > 65535 || RT_MAX_HEIGHT < 1 || \
    RT_MAX_HEIGHT > 65535
#error "RT_MAX_WIDTH and RT_MAX_HEIGHT must be 1..65535 (uint16_t sizes)"
#endif
#if RT_MAX_SPP_SIDE < 1 || RT_MAX_SPP_SIDE > 15
#error "RT_MAX_SPP_SIDE must be 1..15: rt_scene.spp is a uint8_t"
#endif
#if RT_MAX_DEPTH < 0 || RT_MAX_DEPTH > 255
#error "RT_MAX_DEPTH must be 0..255: rt_scene.depth is a uint8_t"
#endif
#if RT_MAX_NAME < 1
#error "RT_MAX_NAME must be at least 1"
#endif
#if RT_CAP_BOTTOM != 1 || RT_CAP_TOP != 2
#error "the 'caps' words are listed in RT_CAP_* bit order"
#endif

#define NUM_MAX_DIGITS 40

/* Value limits (raw Q16.16) and the defaults the format documents. */
#define LIGHT_MAX FX_INT(16) /* light and ambient colours */
#define IOR_MIN ((fx_t)655)  /* 0.01, as the parser rounds it */
#define IOR_MAX FX_INT(100)
#define BUMP_MAX FX_INT(4)
#define DEF_AMBIENT ((fx_t)6554)  /* 0.1 */
#define DEF_DIFFUSE ((fx_t)58982) /* 0.9 */
#define DEF_SPECULAR FX_HALF
#define DEF_SHININESS 10u

#define TRY(x)                                                                \
    do {                                                                      \
        rt_status try_st_ = (x);                                              \
        if (try_st_ != RT_OK)                                                 \
            return try_st_;                                                   \
    } while (0)

/* ---- Numbers ------------------------------------------------------------ */

typedef enum { NUM_OK, NUM_NONE, NUM_RANGE, NUM_DIGITS } num_status;

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* rt_parse_fx with a reason for failure. */
static num_status scan_fx(const char *t, size_t len, fx_t *out, size_t *used)
{
    uint8_t frac[NUM_MAX_DIGITS];
    size_t i = 0, nd = 0, nf = 0;
    uint32_t ip = 0, bits = 0;
    int neg = 0;

    if (len > 0 && (t[0] == '+' || t[0] == '-'))
        neg = t[i++] == '-';
    for (; i < len && is_digit(t[i]); i++, nd++)
        if (ip < 100000u) /* saturates: above 32768 is out of range anyway */
            ip = ip * 10u + (uint32_t)(t[i] - '0');
    if (i < len && t[i] == '.') {
        size_t dot = i++;
        for (; i < len && is_digit(t[i]); i++, nd++)
            if (nf < NUM_MAX_DIGITS)
                frac[nf++] = (uint8_t)(t[i] - '0');
        if (nd == 0)
            i = dot;
    }
    *used = nd ? i : 0;
    if (nd == 0)
        return NUM_NONE;
    if (nd > NUM_MAX_DIGITS)
        return NUM_DIGITS;
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
        return NUM_RANGE;
    *out = neg ? (fx_t)(0 - (int64_t)mag) : (fx_t)mag;
    return NUM_OK;
}

rt_status rt_parse_fx(const char *text, size_t len, fx_t *out, size_t *used)
{
    size_t n;
    fx_t v = 0;
    num_status ns = scan_fx(text, len, &v, &n);
    if (used)
        *used = n;
    if (ns != NUM_OK)
        return RT_ERR_PARSE;
    *out = v;
    return RT_OK;
}

/* ---- Lexer and messages ------------------------------------------------- */

/* A token: text[off .. off + len), on line `line` starting at line_off. A
 * token of length 0 marks the end of a statement. */
typedef struct {
    size_t off, len, line_off;
    uint32_t line;
} token;

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
} parser;

static void start_line(parser *p)
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

static void say(parser *p, const char *s)
{
    char *m = p->err->msg;
    while (*s && p->mlen + 1 < sizeof p->err->msg)
        m[p->mlen++] = *s++;
    m[p->mlen] = '\0';
}

static void say_u32(parser *p, uint32_t v)
{
    char buf[11];
    size_t i = sizeof buf - 1;
    buf[i] = '\0';
    do {
        buf[--i] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    say(p, buf + i);
}

/* The token in quotes, shortened to 24 bytes. */
static void say_tok(parser *p, const token *tk)
{
    char buf[32];
    size_t n = tk->len > 24 ? 24 : tk->len;
    buf[0] = '\'';
    memcpy(buf + 1, p->t + tk->off, n);
    memcpy(buf + 1 + n, tk->len > n ? "...'" : "'", tk->len > n ? 5 : 2);
    say(p, buf);
}

/* The token, or "end of line" for the end marker. */
static void say_got(parser *p, const token *tk)
{
    say(p, "; got ");
    if (tk->len)
        say_tok(p, tk);
    else
        say(p, "end of line");
}

static void say_list(parser *p, const char *const *names)
{
    for (size_t i = 0; names[i]; i++) {
        if (i)
            say(p, " ");
        say(p, names[i]);
    }
}

/* Records the position of the problem at *at and starts the message. */
static rt_status fail(parser *p, const token *at, rt_status st,
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
    say(p, msg);
    return st;
}

static rt_status bad_byte(parser *p, size_t i)
{
    static const char hex[] = "0123456789abcdef";
    unsigned char c = (unsigned char)p->t[i];
    char buf[5] = {'0', 'x', hex[c >> 4], hex[c & 15u], '\0'};
    token tk = {i, 1, p->line_off, p->line};
    fail(p, &tk, RT_ERR_PARSE, "unexpected byte ");
    say(p, buf);
    if (c >= 0x80)
        say(p, " (non-ASCII text is allowed only in comments)");
    return RT_ERR_PARSE;
}

/* Reads the statement's next token into *tk; tk->len == 0 at its end. A
 * "\" token as the last on a line continues the statement on the next. */
static rt_status next_token(parser *p, token *tk)
{
    const char *t = p->t;
    int cont = 0;
    token bs = {0, 0, 0, 0};
    for (;;) {
        size_t i = p->pos;
        while (i < p->line_end && (t[i] == ' ' || t[i] == '\t'))
            i++;
        if (i < p->line_end && t[i] != '#') {
            size_t s = i;
            for (; i < p->line_end && t[i] != ' ' && t[i] != '\t' &&
                   t[i] != '#'; i++)
                if ((unsigned char)t[i] < 0x21 || (unsigned char)t[i] > 0x7e)
                    return bad_byte(p, i);
            if (cont)
                return fail(p, &bs, RT_ERR_PARSE,
                            "'\\' continues a statement on the next line "
                            "and must be the last token on its line");
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
            return fail(p, &bs, RT_ERR_PARSE,
                        "'\\' at the end of the input: no line to continue");
        start_line(p);
        cont = 0;
    }
}

static int tok_is(const parser *p, const token *tk, const char *s)
{
    size_t i;
    /* Token bytes are never NUL, so a mismatch stops at s's end. */
    for (i = 0; i < tk->len; i++)
        if (s[i] != p->t[tk->off + i])
            return 0;
    return s[i] == '\0';
}

static int find(const parser *p, const token *tk, const char *const *names)
{
    for (int i = 0; names[i]; i++)
        if (tok_is(p, tk, names[i]))
            return i;
    return -1;
}

/* ---- Values ------------------------------------------------------------- */

/* "'what' needs 3 numbers (x y z); got 'tok'". */
static rt_status need(parser *p, const token *tk, const char *what,
                      const char *labels, int n, const char *kind)
{
    fail(p, tk, RT_ERR_PARSE, "'");
    say(p, what);
    say(p, "' needs ");
    if (n > 1) {
        say_u32(p, (uint32_t)n);
        say(p, " ");
        say(p, kind);
        say(p, "s");
    } else {
        say(p, "a ");
        say(p, kind);
    }
    if (labels) {
        say(p, " (");
        say(p, labels);
        say(p, ")");
    }
    say_got(p, tk);
    return RT_ERR_PARSE;
}

/* Whether the token reads nan or inf(inity), any case, with a sign. */
static int is_nan_inf(const parser *p, const token *tk)
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
static rt_status to_fx(parser *p, const token *tk, const char *what,
                       const char *labels, int n, fx_t *v)
{
    const char *t = p->t + tk->off;
    size_t used;
    num_status ns = scan_fx(t, tk->len, v, &used);
    if (ns == NUM_NONE) {
        if (tk->len && is_nan_inf(p, tk)) {
            fail(p, tk, RT_ERR_PARSE, "");
            say_tok(p, tk);
            say(p, " is not allowed: numbers must be finite decimals");
            return RT_ERR_PARSE;
        }
        return need(p, tk, what, labels, n, "number");
    }
    if (used < tk->len) {
        char c = t[used];
        const char *why = "malformed number ";
        if (c == 'e' || c == 'E')
            why = "exponents are not supported (write the number out): ";
        else if ((c == 'x' || c == 'X') && t[used - 1] == '0' &&
                 used <= 2 && (used == 1 || !is_digit(t[0])))
            why = "hexadecimal numbers are not supported: ";
        fail(p, tk, RT_ERR_PARSE, why);
        say_tok(p, tk);
        return RT_ERR_PARSE;
    }
    if (ns == NUM_RANGE)
        return fail(p, tk, RT_ERR_PARSE,
                    "number out of Q16.16 range (-32768 .. 32767.99998)");
    if (ns == NUM_DIGITS)
        return fail(p, tk, RT_ERR_PARSE, "number has more than 40 digits");
    return RT_OK;
}

/* Reads n numbers for field `what` (labels names them for messages, as
 * "x y z") and checks each lies in [lo, hi]; else "what must be rule". */
static rt_status get_fxs(parser *p, const char *what, const char *labels,
                         int n, fx_t *out, fx_t lo, fx_t hi, const char *rule)
{
    for (int i = 0; i < n; i++) {
        token tk;
        fx_t v = 0;
        TRY(next_token(p, &tk));
        TRY(to_fx(p, &tk, what, labels, n, &v));
        if (v < lo || v > hi) {
            fail(p, &tk, RT_ERR_PARSE, what);
            if (n == 1 && labels) {
                say(p, " ");
                say(p, labels);
            }
            say(p, " must be ");
            say(p, rule);
            return RT_ERR_PARSE;
        }
        out[i] = v;
    }
    return RT_OK;
}

static rt_status get_vec(parser *p, const char *what, fx_vec3 *v)
{
    fx_t c[3];
    TRY(get_fxs(p, what, "x y z", 3, c, FX_MIN, FX_MAX, ""));
    *v = fx_v3(c[0], c[1], c[2]);
    return RT_OK;
}

static rt_status get_rgb(parser *p, const char *what, rt_rgb *c, fx_t hi)
{
    fx_t v[3];
    TRY(get_fxs(p, what, "r g b", 3, v, 0, hi,
                hi == FX_ONE ? "in [0, 1]" : "in [0, 16]"));
    c->r = v[0];
    c->g = v[1];
    c->b = v[2];
    return RT_OK;
}

/* Reads a whole number in [lo, hi]; `label` names a positional value. */
static rt_status get_uint(parser *p, const char *what, const char *label,
                          uint32_t lo, uint32_t hi, const char *note,
                          uint32_t *out, token *where)
{
    token tk;
    uint32_t v = 0;
    size_t i = 0;
    TRY(next_token(p, &tk));
    *where = tk;
    for (; i < tk.len && is_digit(p->t[tk.off + i]); i++)
        v = v > 99999999u ? 1000000000u
                          : v * 10u + (uint32_t)(p->t[tk.off + i] - '0');
    int bad = tk.len == 0 || i < tk.len;
    if (bad) {
        /* Some other number ("-1", "2.5") gets the range message. */
        fx_t x;
        size_t used;
        if (tk.len == 0 ||
            scan_fx(p->t + tk.off, tk.len, &x, &used) == NUM_NONE ||
            used < tk.len)
            return need(p, &tk, what, label, 1, "whole number");
    }
    if (!bad && v >= lo && v <= hi) {
        *out = v;
        return RT_OK;
    }
    fail(p, &tk, RT_ERR_PARSE, label ? label : what);
    say(p, " must be a whole number in ");
    say_u32(p, lo);
    say(p, " .. ");
    say_u32(p, hi);
    say(p, note);
    if (bad)
        say_got(p, &tk);
    return RT_ERR_PARSE;
}

/* Requires the statement to end here. */
static rt_status end_stmt(parser *p, const char *stmt)
{
    token tk;
    TRY(next_token(p, &tk));
    if (tk.len == 0)
        return RT_OK;
    fail(p, &tk, RT_ERR_PARSE, "unexpected ");
    say_tok(p, &tk);
    say(p, " at the end of ");
    say(p, stmt);
    return RT_ERR_PARSE;
}

/* Reads the next field name of a statement into keys index *k (-1 at the
 * statement's end), noting it in *seen and at[*k]; repeats are errors. */
static rt_status next_key(parser *p, const char *stmt,
                          const char *const *keys, token *at, uint32_t *seen,
                          int *k)
{
    token tk;
    fx_t x;
    size_t used;
    *k = -1;
    TRY(next_token(p, &tk));
    if (tk.len == 0)
        return RT_OK;
    int i = find(p, &tk, keys);
    if (i < 0) {
        int num = scan_fx(p->t + tk.off, tk.len, &x, &used) != NUM_NONE;
        fail(p, &tk, RT_ERR_PARSE, num ? "unexpected number " :
                                         "unknown field ");
        say_tok(p, &tk);
        say(p, " in ");
        say(p, stmt);
        say(p, num ? " (expected a field name: " : " (expected one of: ");
        say_list(p, keys);
        say(p, ")");
        return RT_ERR_PARSE;
    }
    if (*seen & (1u << i)) {
        fail(p, &tk, RT_ERR_PARSE, "");
        say_tok(p, &tk);
        say(p, " given twice in ");
        say(p, stmt);
        return RT_ERR_PARSE;
    }
    *seen |= 1u << i;
    at[i] = tk;
    *k = i;
    return RT_OK;
}

/* Fails at the statement keyword for the first required field not seen. */
static rt_status require(parser *p, const token *kw, const char *stmt,
                         const char *const *keys, uint32_t seen,
                         uint32_t required)
{
    for (int i = 0; keys[i]; i++) {
        if ((required & ~seen) & (1u << i)) {
            fail(p, kw, RT_ERR_PARSE, "missing '");
            say(p, keys[i]);
            say(p, "' in ");
            say(p, stmt);
            return RT_ERR_PARSE;
        }
    }
    return RT_OK;
}

/* ---- Statements --------------------------------------------------------- */

typedef char name_table[RT_MAX_MATERIALS][RT_MAX_NAME + 1];

static const char *const image_keys[] = {"spp", "depth", NULL};

static rt_status st_image(parser *p, rt_scene *s)
{
    token at[2], tk;
    uint32_t w, h, v, seen = 0;
    int k;
    TRY(get_uint(p, "image", "width", 1, RT_MAX_WIDTH, " (RT_MAX_WIDTH)", &w,
                 &tk));
    TRY(get_uint(p, "image", "height", 1, RT_MAX_HEIGHT, " (RT_MAX_HEIGHT)",
                 &h, &tk));
    s->width = (uint16_t)w;
    s->height = (uint16_t)h;
    for (;;) {
        TRY(next_key(p, "image", image_keys, at, &seen, &k));
        if (k < 0)
            return RT_OK;
        if (k == 1) {
            TRY(get_uint(p, "depth", NULL, 0, RT_MAX_DEPTH, " (RT_MAX_DEPTH)",
                         &v, &tk));
            s->depth = (uint8_t)v;
            continue;
        }
        TRY(get_uint(p, "spp", NULL, 1, RT_MAX_SPP_SIDE * RT_MAX_SPP_SIDE,
                     " (RT_MAX_SPP_SIDE squared)", &v, &tk));
        uint32_t n = 1;
        while (n < RT_MAX_SPP_SIDE && n * n < v)
            n++;
        if (n * n != v) {
            fail(p, &tk, RT_ERR_PARSE, "spp must be a square n*n with "
                                       "n <= RT_MAX_SPP_SIDE: ");
            for (n = 1; n <= RT_MAX_SPP_SIDE; n++) {
                if (n > 1)
                    say(p, n == RT_MAX_SPP_SIDE ? " or " : ", ");
                say_u32(p, n * n);
            }
            return RT_ERR_PARSE;
        }
        s->spp = (uint8_t)v;
    }
}

static const char *const cam_keys[] = {"eye", "look", "up", "fov", NULL};

static rt_status st_camera(parser *p, const token *kw, rt_scene *s)
{
    token at[4];
    uint32_t seen = 0;
    int k;
    rt_camera *c = &s->cam;
    for (;;) {
        TRY(next_key(p, "camera", cam_keys, at, &seen, &k));
        if (k < 0)
            break;
        if (k == 0)
            TRY(get_vec(p, "eye", &c->eye));
        else if (k == 1)
            TRY(get_vec(p, "look", &c->look));
        else if (k == 2)
            TRY(get_vec(p, "up", &c->up));
        else
            TRY(get_fxs(p, "fov", NULL, 1, &c->fov, 1, FX_INT(180) - 1,
                        "in (0, 180) degrees"));
    }
    TRY(require(p, kw, "camera", cam_keys, seen, 3u));
    /* Exact tests: |w| < 2^32 and |up| <= 2^31 raw, so each product below
     * fits int64 and the cross product is zero exactly when they match. */
    int64_t wx = (int64_t)c->look.x - c->eye.x;
    int64_t wy = (int64_t)c->look.y - c->eye.y;
    int64_t wz = (int64_t)c->look.z - c->eye.z;
    int64_t ux = c->up.x, uy = c->up.y, uz = c->up.z;
    if (wx == 0 && wy == 0 && wz == 0)
        return fail(p, &at[1], RT_ERR_PARSE,
                    "camera look must differ from eye");
    if (ux == 0 && uy == 0 && uz == 0)
        return fail(p, &at[2], RT_ERR_PARSE, "camera up must not be zero");
    if (wy * uz == wz * uy && wz * ux == wx * uz && wx * uy == wy * ux) {
        if (seen & 4u)
            return fail(p, &at[2], RT_ERR_PARSE,
                        "camera up is parallel to the view direction "
                        "(look - eye)");
        return fail(p, kw, RT_ERR_PARSE,
                    "camera looks straight along the default up (0 1 0); "
                    "give another 'up'");
    }
    return RT_OK;
}

static const char *const light_keys[] = {"color", NULL};

static rt_status st_light(parser *p, const token *kw, rt_scene *s)
{
    token at[1];
    uint32_t seen = 0;
    int k;
    rt_light *l;
    if (s->n_lights >= RT_MAX_LIGHTS) {
        fail(p, kw, RT_ERR_CAPACITY, "too many lights (RT_MAX_LIGHTS is ");
        say_u32(p, RT_MAX_LIGHTS);
        say(p, ")");
        return RT_ERR_CAPACITY;
    }
    l = &s->light[s->n_lights];
    l->color.r = l->color.g = l->color.b = FX_ONE;
    TRY(get_vec(p, "light", &l->pos));
    for (;;) {
        TRY(next_key(p, "light", light_keys, at, &seen, &k));
        if (k < 0)
            break;
        TRY(get_rgb(p, "color", &l->color, LIGHT_MAX));
    }
    s->n_lights++;
    return RT_OK;
}

static int lookup(const parser *p, const token *tk, const rt_scene *s,
                  const name_table names)
{
    for (int i = 0; i < s->n_materials; i++) {
        const char *n = names[i];
        size_t j = 0;
        while (j < tk->len && n[j] == p->t[tk->off + j])
            j++;
        if (j == tk->len && n[j] == '\0')
            return i;
    }
    return -1;
}

enum {
    M_COLOR, M_AMBIENT, M_DIFFUSE, M_SPECULAR, M_SHININESS, M_REFLECT,
    M_TRANSPARENCY, M_IOR, M_STRIPES, M_CHECKER, M_CHECKER3D, M_BUMP, M_COUNT
};
static const char *const mat_keys[] = {
    "color", "ambient", "diffuse", "specular", "shininess", "reflect",
    "transparency", "ior", "stripes", "checker", "checker3d", "bump", NULL};
#define M_TEXTURES ((1u << M_STRIPES) | (1u << M_CHECKER) | (1u << M_CHECKER3D))

static rt_status mat_field(parser *p, int k, rt_material *m)
{
    const fx_t one = FX_ONE;
    const char *const k01 = "in [0, 1]";
    switch (k) {
    case M_COLOR:
        return get_rgb(p, "color", &m->color, one);
    case M_AMBIENT:
        return get_fxs(p, "ambient", NULL, 1, &m->ambient, 0, one, k01);
    case M_DIFFUSE:
        return get_fxs(p, "diffuse", NULL, 1, &m->diffuse, 0, one, k01);
    case M_SPECULAR:
        return get_fxs(p, "specular", NULL, 1, &m->specular, 0, one, k01);
    case M_REFLECT:
        return get_fxs(p, "reflect", NULL, 1, &m->reflect, 0, one, k01);
    case M_TRANSPARENCY:
        return get_fxs(p, "transparency", NULL, 1, &m->transparency, 0, one,
                       k01);
    case M_IOR:
        return get_fxs(p, "ior", NULL, 1, &m->ior, IOR_MIN, IOR_MAX,
                       "in [0.01, 100]");
    case M_SHININESS: {
        uint32_t v;
        token tk;
        TRY(get_uint(p, "shininess", NULL, 1, 1024, "", &v, &tk));
        m->shininess = (uint16_t)v;
        return RT_OK;
    }
    case M_BUMP:
        TRY(get_fxs(p, "bump", "amplitude", 1, &m->bump, 0, BUMP_MAX,
                    "in [0, 4]"));
        return get_fxs(p, "bump", "size", 1, &m->bump_scale, 1, FX_MAX,
                       "> 0");
    case M_STRIPES: {
        static const char *const axes[] = {"x", "y", "z", NULL};
        token tk;
        int a;
        TRY(next_token(p, &tk));
        a = find(p, &tk, axes);
        if (a < 0) {
            fail(p, &tk, RT_ERR_PARSE, "'stripes' needs an axis (x, y or z)");
            say_got(p, &tk);
            return RT_ERR_PARSE;
        }
        m->texture = RT_TEX_STRIPES;
        m->axis = (uint8_t)a;
        TRY(get_rgb(p, "stripes", &m->color2, one));
        return get_fxs(p, "stripes", "width", 1, &m->tex_scale, 1, FX_MAX,
                       "> 0");
    }
    default: { /* M_CHECKER, M_CHECKER3D */
        const char *w = k == M_CHECKER ? "checker" : "checker3d";
        m->texture = k == M_CHECKER ? RT_TEX_CHECKER : RT_TEX_CHECKER3D;
        TRY(get_rgb(p, w, &m->color2, one));
        return get_fxs(p, w, "size", 1, &m->tex_scale, 1, FX_MAX, "> 0");
    }
    }
}

static rt_status st_material(parser *p, const token *kw, rt_scene *s,
                             name_table names)
{
    token name, at[M_COUNT];
    uint32_t seen = 0;
    int k;
    rt_material *m;
    if (s->n_materials >= RT_MAX_MATERIALS) {
        fail(p, kw, RT_ERR_CAPACITY,
             "too many materials (RT_MAX_MATERIALS is ");
        say_u32(p, RT_MAX_MATERIALS);
        say(p, ")");
        return RT_ERR_CAPACITY;
    }
    TRY(next_token(p, &name));
    const char *n = p->t + name.off;
    int ok = name.len > 0 &&
             (n[0] == '_' || ((n[0] | 0x20) >= 'a' && (n[0] | 0x20) <= 'z'));
    for (size_t i = 0; ok && i < name.len; i++)
        ok = n[i] == '_' || n[i] == '-' || is_digit(n[i]) ||
             ((n[i] | 0x20) >= 'a' && (n[i] | 0x20) <= 'z');
    if (!ok) {
        fail(p, &name, RT_ERR_PARSE, "'material' needs a name (a letter or "
                                     "'_', then letters, digits, '_', '-')");
        say_got(p, &name);
        return RT_ERR_PARSE;
    }
    if (name.len > RT_MAX_NAME) {
        fail(p, &name, RT_ERR_CAPACITY, "material name longer than "
                                        "RT_MAX_NAME (");
        say_u32(p, RT_MAX_NAME);
        say(p, " bytes)");
        return RT_ERR_CAPACITY;
    }
    if (lookup(p, &name, s, names) >= 0) {
        fail(p, &name, RT_ERR_PARSE, "material ");
        say_tok(p, &name);
        say(p, " is already defined");
        return RT_ERR_PARSE;
    }
    m = &s->mat[s->n_materials];
    memset(m, 0, sizeof *m);
    m->ambient = DEF_AMBIENT;
    m->diffuse = DEF_DIFFUSE;
    m->specular = DEF_SPECULAR;
    m->shininess = DEF_SHININESS;
    m->ior = FX_ONE;
    for (;;) {
        TRY(next_key(p, "material", mat_keys, at, &seen, &k));
        if (k < 0)
            break;
        if ((1u << k) & M_TEXTURES && (seen & M_TEXTURES) != (1u << k)) {
            fail(p, &at[k], RT_ERR_PARSE,
                 "a material has at most one texture (stripes, checker or "
                 "checker3d)");
            return RT_ERR_PARSE;
        }
        TRY(mat_field(p, k, m));
    }
    TRY(require(p, kw, "material", mat_keys, seen, 1u << M_COLOR));
    if ((int64_t)m->reflect + m->transparency > FX_ONE) {
        int later = (seen & (1u << M_REFLECT)) &&
                    at[M_REFLECT].off > at[M_TRANSPARENCY].off;
        return fail(p, &at[later ? M_REFLECT : M_TRANSPARENCY], RT_ERR_PARSE,
                    "reflect + transparency must be <= 1");
    }
    if (rt_material_prepare(m) != RT_OK)
        return fail(p, kw, RT_ERR_PARSE,
                    "invalid material: a texture or bump size is not > 0");
    memcpy(names[s->n_materials], n, name.len);
    names[s->n_materials][name.len] = '\0';
    s->n_materials++;
    return RT_OK;
}

/* What each object field sets. */
enum { F_A, F_B, F_C, F_R, F_H, F_MAT, F_OPEN, F_CAPS };

typedef struct {
    const char *name;
    const char *const *keys;
    uint8_t field[6];
    uint8_t n_required; /* the first n keys are required */
} shape_spec;

static const char *const sphere_keys[] = {"center", "radius", "material",
                                          NULL};
static const char *const quad_keys[] = {"corner", "edge1", "edge2",
                                        "material", NULL};
static const char *const box_keys[] = {"min", "max", "material", NULL};
static const char *const cyl_keys[] = {"base", "radius", "height", "material",
                                       "open", "caps", NULL};
static const char *const cone_keys[] = {"base", "radius", "height",
                                        "material", "open", NULL};

/* Indexed by rt_kind. */
static const shape_spec shapes[RT_KIND_COUNT] = {
    {"sphere", sphere_keys, {F_A, F_R, F_MAT}, 3},
    {"quad", quad_keys, {F_A, F_B, F_C, F_MAT}, 4},
    {"box", box_keys, {F_A, F_B, F_MAT}, 3},
    {"cylinder", cyl_keys, {F_A, F_R, F_H, F_MAT, F_OPEN, F_CAPS}, 4},
    {"cone", cone_keys, {F_A, F_R, F_H, F_MAT, F_OPEN}, 4},
};

static int key_of(const shape_spec *sp, int field)
{
    int i = 0;
    while (sp->field[i] != field)
        i++;
    return i;
}

static rt_status degenerate(parser *p, const token *at, const char *shape,
                            const char *why)
{
    fail(p, at, RT_ERR_DEGENERATE, "degenerate ");
    say(p, shape);
    say(p, ": ");
    say(p, why);
    return RT_ERR_DEGENERATE;
}

/* Shape checks with specific messages; rt_object_prepare() has the last
 * word. */
static rt_status check_shape(parser *p, const token *kw, const shape_spec *sp,
                             const token *at, rt_object *o)
{
    const char *nm = sp->name;
    if (o->kind == RT_QUAD) {
        const fx_vec3 a = o->b, b = o->c;
        if (a.x == 0 && a.y == 0 && a.z == 0)
            return degenerate(p, &at[1], nm, "edge1 must not be zero");
        if (b.x == 0 && b.y == 0 && b.z == 0)
            return degenerate(p, &at[2], nm, "edge2 must not be zero");
        /* Exact: each product is below 2^62. */
        if ((int64_t)a.y * b.z == (int64_t)a.z * b.y &&
            (int64_t)a.z * b.x == (int64_t)a.x * b.z &&
            (int64_t)a.x * b.y == (int64_t)a.y * b.x)
            return degenerate(p, &at[2], nm,
                              "edge1 and edge2 are parallel");
    } else if (o->kind == RT_BOX) {
        if (o->b.x <= o->a.x)
            return degenerate(p, &at[1], nm, "max x must be > min x");
        if (o->b.y <= o->a.y)
            return degenerate(p, &at[1], nm, "max y must be > min y");
        if (o->b.z <= o->a.z)
            return degenerate(p, &at[1], nm, "max z must be > min z");
    } else {
        if (o->r <= 0)
            return degenerate(p, &at[key_of(sp, F_R)], nm,
                              "radius must be > 0");
        if (o->kind != RT_SPHERE && o->h <= 0)
            return degenerate(p, &at[key_of(sp, F_H)], nm,
                              "height must be > 0");
    }
    if (rt_object_prepare(o) != RT_OK)
        return degenerate(p, kw, nm, o->kind == RT_QUAD
                                         ? "edges too short for Q16.16"
                                         : "too thin or too flat for Q16.16");
    return RT_OK;
}

static rt_status st_object(parser *p, const token *kw, int kind, rt_scene *s,
                           const name_table names)
{
    static const char *const caps[] = {"none", "bottom", "top", "both", NULL};
    const shape_spec *sp = &shapes[kind];
    const char *const *keys = sp->keys;
    token at[6];
    uint32_t seen = 0;
    int k, caps_given = 0;
    rt_object *o;
    if (s->n_objects >= RT_MAX_OBJECTS) {
        fail(p, kw, RT_ERR_CAPACITY, "too many objects (RT_MAX_OBJECTS is ");
        say_u32(p, RT_MAX_OBJECTS);
        say(p, ")");
        return RT_ERR_CAPACITY;
    }
    o = &s->obj[s->n_objects];
    memset(o, 0, sizeof *o);
    o->kind = (uint8_t)kind;
    o->caps = kind == RT_CYLINDER ? (RT_CAP_BOTTOM | RT_CAP_TOP)
              : kind == RT_CONE   ? RT_CAP_BOTTOM
                                  : 0;
    for (;;) {
        TRY(next_key(p, sp->name, keys, at, &seen, &k));
        if (k < 0)
            break;
        const char *key = keys[k];
        switch (sp->field[k]) {
        case F_A:
            TRY(get_vec(p, key, &o->a));
            break;
        case F_B:
            TRY(get_vec(p, key, &o->b));
            break;
        case F_C:
            TRY(get_vec(p, key, &o->c));
            break;
        case F_R:
            TRY(get_fxs(p, key, NULL, 1, &o->r, FX_MIN, FX_MAX, ""));
            break;
        case F_H:
            TRY(get_fxs(p, key, NULL, 1, &o->h, FX_MIN, FX_MAX, ""));
            break;
        case F_MAT: {
            token tk;
            TRY(next_token(p, &tk));
            if (tk.len == 0)
                return need(p, &tk, "material", NULL, 1, "name");
            int m = lookup(p, &tk, s, names);
            if (m < 0) {
                fail(p, &tk, RT_ERR_PARSE, "material ");
                say_tok(p, &tk);
                say(p, " is not defined (materials must be defined before "
                       "use)");
                return RT_ERR_PARSE;
            }
            o->material = (uint8_t)m;
            break;
        }
        case F_OPEN:
            o->caps = 0;
            break;
        default: { /* F_CAPS */
            token tk;
            TRY(next_token(p, &tk));
            int c = find(p, &tk, caps);
            if (c < 0) {
                fail(p, &tk, RT_ERR_PARSE,
                     "'caps' needs one of: both top bottom none");
                say_got(p, &tk);
                return RT_ERR_PARSE;
            }
            o->caps = (uint8_t)c; /* the list is in RT_CAP_* bit order */
            break;
        }
        }
        if (sp->field[k] >= F_OPEN && caps_given++ > 0)
            return fail(p, &at[k], RT_ERR_PARSE,
                        "give either 'open' or 'caps', not both");
    }
    TRY(require(p, kw, sp->name, keys, seen, (1u << sp->n_required) - 1u));
    TRY(check_shape(p, kw, sp, at, o));
    s->n_objects++;
    return RT_OK;
}

/* ---- The file ----------------------------------------------------------- */

enum {
    S_IMAGE, S_CAMERA, S_BACKGROUND, S_AMBIENT, S_SHADOWS, S_LIGHT,
    S_MATERIAL, S_SPHERE, S_QUAD, S_BOX, S_CYLINDER, S_CONE
};
static const char *const stmt_keys[] = {
    "image", "light", "camera", "background", "ambient", "shadows",
    "material", "sphere", "quad", "box", "cylinder", "cone", NULL};
/* stmt_keys order, so the message lists them as a file usually has them. */
static const uint8_t stmt_ids[] = {S_IMAGE, S_LIGHT, S_CAMERA, S_BACKGROUND,
                                   S_AMBIENT, S_SHADOWS, S_MATERIAL,
                                   S_SPHERE, S_QUAD, S_BOX, S_CYLINDER,
                                   S_CONE};

static rt_status statement(parser *p, const token *kw, rt_scene *s,
                           name_table names, uint32_t once[5])
{
    int i = find(p, kw, stmt_keys);
    if (i < 0) {
        fail(p, kw, RT_ERR_PARSE, "unknown keyword ");
        say_tok(p, kw);
        say(p, " (expected one of: ");
        say_list(p, stmt_keys);
        say(p, ")");
        return RT_ERR_PARSE;
    }
    int id = stmt_ids[i];
    if (id <= S_SHADOWS) {
        if (once[id]) {
            fail(p, kw, RT_ERR_PARSE, "second '");
            say(p, stmt_keys[i]);
            say(p, "' statement (the first is on line ");
            say_u32(p, once[id]);
            say(p, ")");
            return RT_ERR_PARSE;
        }
        once[id] = kw->line;
    }
    switch (id) {
    case S_IMAGE:
        return st_image(p, s);
    case S_CAMERA:
        return st_camera(p, kw, s);
    case S_BACKGROUND:
        TRY(get_rgb(p, "background", &s->background, FX_ONE));
        return end_stmt(p, "background");
    case S_AMBIENT:
        TRY(get_rgb(p, "ambient", &s->ambient, LIGHT_MAX));
        return end_stmt(p, "ambient");
    case S_SHADOWS: {
        static const char *const onoff[] = {"off", "on", NULL};
        token tk;
        TRY(next_token(p, &tk));
        int v = find(p, &tk, onoff);
        if (v < 0) {
            fail(p, &tk, RT_ERR_PARSE, "'shadows' needs 'on' or 'off'");
            say_got(p, &tk);
            return RT_ERR_PARSE;
        }
        s->shadows = (uint8_t)v;
        return end_stmt(p, "shadows");
    }
    case S_LIGHT:
        return st_light(p, kw, s);
    case S_MATERIAL:
        return st_material(p, kw, s, names);
    default:
        return st_object(p, kw, RT_SPHERE + (id - S_SPHERE), s, names);
    }
}

rt_status rt_parse(const char *text, size_t len, rt_scene *s,
                   rt_parse_error *err)
{
    name_table names;
    uint32_t once[5] = {0, 0, 0, 0, 0};
    parser p;
    token kw;

    memset(&p, 0, sizeof p);
    memset(err, 0, sizeof *err);
    p.t = text;
    p.len = len;
    p.err = err;
    /* A UTF-8 byte order mark, as some editors write, is skipped. */
    if (len >= 3 && (unsigned char)text[0] == 0xEF &&
        (unsigned char)text[1] == 0xBB && (unsigned char)text[2] == 0xBF)
        p.next = p.line_off = p.line_end = 3;
    rt_scene_init(s);
    s->features = 0;
    while (p.next < len) {
        start_line(&p);
        TRY(next_token(&p, &kw));
        if (kw.len)
            TRY(statement(&p, &kw, s, names, once));
    }
    if (!once[S_CAMERA]) {
        /* Point just past the last line's text. */
        kw.off = p.line_end;
        kw.len = 0;
        kw.line_off = p.line_off;
        kw.line = p.line ? p.line : 1;
        return fail(&p, &kw, RT_ERR_PARSE,
                    "no camera statement (every scene needs one)");
    }
    return RT_OK;
}
