/* SPDX-License-Identifier: MIT */
/*
 * mesh_obj: the OBJ reader and the mesh loader of the host (mesh_obj.h).
 * Numbers read as the scene's do (rt_parse_fx, correctly rounded to
 * Q16.16; an exponent form through strtod). The placement is integer
 * arithmetic on those values, so the mesh is the same on every host.
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "cli_util.h"
#include "mesh_obj.h"

/* Largest OBJ file read: 64 MiB. */
#define OBJ_MAX_BYTES (64u << 20)

typedef struct {
    const char *t;
    size_t len, line_off, line_end, pos;
    uint32_t line;
    rt_parse_error *err;
} obj_lex;

#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static int obj_fail(obj_lex *x, size_t off, size_t tok_len, const char *fmt,
                    ...)
{
    rt_parse_error *e = x->err;
    va_list ap;
    e->line = x->line;
    e->col = (uint32_t)(off - x->line_off + 1);
    e->line_off = x->line_off;
    e->line_len = x->line_end - x->line_off;
    e->tok_len = tok_len;
    va_start(ap, fmt);
    vsnprintf(e->msg, sizeof e->msg, fmt, ap);
    va_end(ap);
    return -1;
}

/* Where a statement is: its line, for errors found after parsing. */
typedef struct {
    uint32_t line;
    size_t line_off, line_end;
} obj_loc;

static obj_loc here(const obj_lex *x)
{
    obj_loc l = {x->line, x->line_off, x->line_end};
    return l;
}

/* An error at the start of the statement at l. */
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static int fail_at(obj_lex *x, const obj_loc *l, const char *fmt, ...)
{
    char m[sizeof x->err->msg];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(m, sizeof m, fmt, ap);
    va_end(ap);
    x->line = l->line;
    x->line_off = l->line_off;
    x->line_end = l->line_end;
    return obj_fail(x, l->line_off, l->line_end - l->line_off, "%s", m);
}

/* Sets x's line to the one holding byte pos (counting from the start). */
static void locate(obj_lex *x, size_t pos)
{
    x->line = 1;
    x->line_off = 0;
    for (size_t i = 0; i < pos; i++)
        if (x->t[i] == '\n') {
            x->line++;
            x->line_off = i + 1;
        }
    x->line_end = x->line_off;
    while (x->line_end < x->len && x->t[x->line_end] != '\n')
        x->line_end++;
}

/* A byte outside ASCII in the token at off, n: an error there, else 0. */
static int non_ascii(obj_lex *x, size_t off, size_t n, const char *where)
{
    for (size_t i = 0; i < n; i++) {
        const unsigned char c = (unsigned char)x->t[off + i];
        if (c >= 0x80) {
            /* By hand: the WebAssembly port's printf has no %X. */
            const char hex[] = {'0', 'x', "0123456789ABCDEF"[c >> 4],
                                "0123456789ABCDEF"[c & 15], '\0'};
            return obj_fail(x, off + i, 1, "a byte that is not ASCII (%s) "
                            "in %s", hex, where);
        }
    }
    return 0;
}

/* The next token on the line: *off and *n (0 at the line's end). */
static void next_tok(obj_lex *x, size_t *off, size_t *n)
{
    size_t i = x->pos;
    while (i < x->line_end && (x->t[i] == ' ' || x->t[i] == '\t'))
        i++;
    if (i < x->line_end && x->t[i] == '#')
        i = x->line_end;
    *off = i;
    while (i < x->line_end && x->t[i] != ' ' && x->t[i] != '\t' &&
           x->t[i] != '#')
        i++;
    *n = i - *off;
    x->pos = i;
}

static int number(obj_lex *x, const char *what, fx_t *out)
{
    size_t off, n, used = 0;
    next_tok(x, &off, &n);
    if (n == 0)
        return obj_fail(x, off, 0, "'%s' needs 3 numbers", what);
    if (rt_parse_fx(x->t + off, n, out, &used) == RT_OK && used == n)
        return 0;
    if (non_ascii(x, off, n, "a number"))
        return -1;
    /* 1e-3 and the like: strtod on a copy, then rounded as Q16.16. The
     * copy, cut at 24 bytes, names the token in messages. */
    char buf[64], name[28];
    const size_t nn = n < 24 ? n : 24;
    memcpy(name, x->t + off, nn);
    memcpy(name + nn, n > nn ? "..." : "", n > nn ? 4 : 1);
    if (n < sizeof buf) {
        memcpy(buf, x->t + off, n);
        buf[n] = '\0';
        char *end;
        errno = 0;
        const double v = strtod(buf, &end);
        if (end == buf + n && v == v) {
            /* An underflow (1e-400) is a number too: it rounds to 0. */
            if (errno == ERANGE && fabs(v) < 1.0) {
                *out = 0;
                return 0;
            }
            if (errno == 0 && fabs(v) < 32767.0) {
                *out = (fx_t)lround(v * 65536.0);
                return 0;
            }
            return obj_fail(x, off, n, "'%s' needs numbers within +-32767 "
                            "(Q16.16); %s is out of range", what, name);
        }
    }
    return obj_fail(x, off, n, "'%s' needs numbers; '%s' is not one", what,
                    name);
}

/* A growing array of fixed-size elements. */
typedef struct {
    void *p;
    size_t n, cap, size;
} vec;

static void *push(vec *v)
{
    if (v->n == v->cap) {
        size_t cap = v->cap ? 2 * v->cap : 256;
        void *q = realloc(v->p, cap * v->size);
        if (!q)
            return NULL;
        v->p = q;
        v->cap = cap;
    }
    return (char *)v->p + v->size * v->n++;
}

/* A face corner: vertex and normal index (0-based; -1: no normal). */
typedef struct {
    int32_t v, n;
} corner;

/* One index of a face corner, OBJ-style: 1-based, or negative from the
 * end; 0 is no index. */
static int index_of(obj_lex *x, size_t off, size_t n, const char *s, size_t k,
                    size_t count, const char *what, int32_t *out)
{
    if (k == 0) {
        *out = -1;
        return 0;
    }
    long v = 0;
    size_t i = 0;
    int neg = s[0] == '-';
    if (neg)
        i = 1;
    if (non_ascii(x, off, n, "a face"))
        return -1;
    if (i == k)
        return obj_fail(x, off, n, "bad %s index in a face", what);
    for (; i < k; i++) {
        if (s[i] < '0' || s[i] > '9' || v > 100000000L)
            return obj_fail(x, off, n, "bad %s index in a face", what);
        v = v * 10 + (s[i] - '0');
    }
    long idx = neg ? (long)count - v : v - 1;
    if (v == 0 || idx < 0 || idx >= (long)count)
        return obj_fail(x, off, n, "the face names %s %s%ld, but the file "
                        "has %lu so far", what, neg ? "-" : "", v,
                        (unsigned long)count);
    *out = (int32_t)idx;
    return 0;
}

/* Placement: scale, then rotations about x, y, z as one matrix (Q2.30,
 * exact at multiples of 90 degrees), then the translation. */
typedef struct {
    int64_t m[3][3];
} mat30;

static void sincos_deg(fx_t deg, double *s, double *c)
{
    const int64_t quarter = (int64_t)FX_INT(90);
    if (deg % quarter == 0) {
        static const double ss[4] = {0, 1, 0, -1}, cc[4] = {1, 0, -1, 0};
        const int q = (int)(((deg / quarter) % 4 + 4) % 4);
        *s = ss[q];
        *c = cc[q];
        return;
    }
    const double a = (double)deg / 65536.0 * 3.14159265358979323846 / 180.0;
    *s = sin(a);
    *c = cos(a);
}

static mat30 rotation(const fx_t rot[3])
{
    double r[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int ax = 0; ax < 3; ax++) {
        double s, c, q[3][3] = {{0}}, out[3][3];
        sincos_deg(rot[ax], &s, &c);
        const int i = (ax + 1) % 3, j = (ax + 2) % 3;
        q[ax][ax] = 1;
        q[i][i] = c;
        q[i][j] = -s;
        q[j][i] = s;
        q[j][j] = c;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                out[a][b] = q[a][0] * r[0][b] + q[a][1] * r[1][b] +
                            q[a][2] * r[2][b];
        memcpy(r, out, sizeof r);
    }
    mat30 m;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            m.m[a][b] = llround(r[a][b] * 1073741824.0);
    return m;
}

static void apply(const mat30 *m, const int64_t v[3], int64_t out[3])
{
    for (int a = 0; a < 3; a++) {
        const int64_t s = m->m[a][0] * v[0] + m->m[a][1] * v[1] +
                          m->m[a][2] * v[2];
        out[a] = (s + ((int64_t)1 << 29)) >> 30;
    }
}

static int cmp_corner(const void *a, const void *b)
{
    const corner *x = a, *y = b;
    if (x->v != y->v)
        return x->v < y->v ? -1 : 1;
    return (x->n > y->n) - (x->n < y->n);
}

/* The mesh from the parsed lists: one vertex per distinct (v, vn) pair
 * when the normals are used, else per v. */
static rt_mesh *assemble(obj_lex *x, const vec *pos, const vec *nrm,
                         const vec *cor, const obj_loc *vloc,
                         const obj_loc *floc, const rt_mesh_place *pl)
{
    const fx_vec3 *P = pos->p;
    const fx_vec3 *N = nrm->p;
    corner *C = cor->p;
    const size_t nc = cor->n;
    int use_vn = pl->smooth && nc > 0;
    for (size_t k = 0; k < nc && use_vn; k++)
        use_vn = C[k].n >= 0;
    for (size_t k = 0; k < nc; k++)
        if (!use_vn)
            C[k].n = -1;
    /* Distinct corners, sorted; each corner's new vertex index. */
    corner *u = malloc((nc ? nc : 1) * sizeof *u);
    uint32_t *tri = malloc((nc ? nc : 1) * sizeof *tri);
    fx_vec3 *v = malloc((nc ? nc : 1) * sizeof *v);
    fx_dir3 *vn = malloc((nc ? nc : 1) * sizeof *vn);
    double (*acc)[3] = calloc(nc ? nc : 1, sizeof *acc);
    rt_mesh *m = NULL;
    if (!u || !tri || !v || !vn || !acc) {
        obj_fail(x, x->line_off, 0, "out of memory");
        goto done;
    }
    memcpy(u, C, nc * sizeof *u);
    qsort(u, nc, sizeof *u, cmp_corner);
    size_t nu = 0;
    for (size_t k = 0; k < nc; k++)
        if (nu == 0 || cmp_corner(&u[nu - 1], &u[k]) != 0)
            u[nu++] = u[k];
    if (nu > RT_MESH_MAX) {
        /* The face whose corner is the first one too many. */
        unsigned char *seen = calloc(nu, 1);
        size_t count = 0, k = 0;
        for (; seen && k < nc && count <= RT_MESH_MAX; k++) {
            const corner *f = bsearch(&C[k], u, nu, sizeof *u, cmp_corner);
            count += !seen[f - u];
            seen[f - u] = 1;
        }
        free(seen);
        if (count > RT_MESH_MAX)
            fail_at(x, &floc[(k - 1) / 3], "this face brings the mesh to "
                    "%u vertices; at most %u fit", RT_MESH_MAX + 1,
                    RT_MESH_MAX);
        else
            obj_fail(x, x->line_off, 0, "out of memory");
        goto done;
    }
    const mat30 rot = rotation(pl->rotate);
    for (size_t k = 0; k < nu; k++) {
        const fx_vec3 p = P[u[k].v];
        const fx_t pc[3] = {p.x, p.y, p.z};
        int64_t s[3], r[3];
        for (int i = 0; i < 3; i++) {
            /* fx_mul saturates; a vertex scaled beyond the range is an
             * error, not a vertex moved to its edge. */
            const int64_t wide = (int64_t)pc[i] * pl->scale / 65536;
            if (wide < FX_MIN || wide > FX_MAX) {
                fail_at(x, &vloc[u[k].v], "this vertex, scaled, leaves the "
                        "Q16.16 range (+-32767)");
                goto done;
            }
            s[i] = fx_mul(pc[i], pl->scale);
        }
        apply(&rot, s, r);
        r[0] += pl->translate.x;
        r[1] += pl->translate.y;
        r[2] += pl->translate.z;
        for (int i = 0; i < 3; i++)
            if (r[i] < FX_MIN || r[i] > FX_MAX) {
                fail_at(x, &vloc[u[k].v], "this vertex, scaled, rotated "
                        "and moved, leaves the Q16.16 range (+-32767)");
                goto done;
            }
        v[k] = fx_v3((fx_t)r[0], (fx_t)r[1], (fx_t)r[2]);
        if (use_vn) {
            const fx_vec3 q = N[u[k].n];
            const int64_t n3[3] = {q.x, q.y, q.z};
            int64_t rn[3];
            apply(&rot, n3, rn);
            vn[k] = fx_d3_normalize64(rn[0], rn[1], rn[2]);
        }
    }
    /* Triangles, dropping those with no area (they can never be hit). The
     * box of the vertices kept so far finds the one that makes the mesh
     * too large (mesh_build's limit, found here to name its line). */
    size_t nt = 0;
    int64_t lo[3] = {INT64_MAX, INT64_MAX, INT64_MAX};
    int64_t hi[3] = {INT64_MIN, INT64_MIN, INT64_MIN};
    for (size_t k = 0; k + 2 < nc; k += 3) {
        uint32_t ix[3];
        for (int j = 0; j < 3; j++) {
            const corner *f = bsearch(&C[k + j], u, nu, sizeof *u, cmp_corner);
            ix[j] = (uint32_t)(f - u);
        }
        const fx_vec3 a = v[ix[0]], b = v[ix[1]], c = v[ix[2]];
        const int64_t e1[3] = {(int64_t)b.x - a.x, (int64_t)b.y - a.y,
                               (int64_t)b.z - a.z};
        const int64_t e2[3] = {(int64_t)c.x - a.x, (int64_t)c.y - a.y,
                               (int64_t)c.z - a.z};
        const double cr[3] = {
            (double)e1[1] * (double)e2[2] - (double)e1[2] * (double)e2[1],
            (double)e1[2] * (double)e2[0] - (double)e1[0] * (double)e2[2],
            (double)e1[0] * (double)e2[1] - (double)e1[1] * (double)e2[0]};
        /* Exact (rt_mesh_normal's own test): edges within 2^31 here, as
         * a larger mesh fails in mesh_build anyway. */
        int fits = 1;
        for (int i = 0; i < 3; i++)
            fits &= e1[i] == (fx_t)e1[i] && e2[i] == (fx_t)e2[i];
        const fx_vec3 a1 = fx_v3((fx_t)e1[0], (fx_t)e1[1], (fx_t)e1[2]);
        const fx_vec3 a2 = fx_v3((fx_t)e2[0], (fx_t)e2[1], (fx_t)e2[2]);
        const fx_dir3 fn = fits ? fx_d3_cross_unit(a1, a2) : fx_d3(1, 0, 0);
        if (fn.x == 0 && fn.y == 0 && fn.z == 0)
            continue;
        if (nt == RT_MESH_MAX) {
            fail_at(x, &floc[k / 3], "this face brings the mesh to %u "
                    "triangles; at most %u fit", RT_MESH_MAX + 1,
                    RT_MESH_MAX);
            goto done;
        }
        for (int j = 0; j < 3; j++) {
            const fx_vec3 p = v[ix[j]];
            const int64_t c3[3] = {p.x, p.y, p.z};
            for (int i = 0; i < 3; i++) {
                lo[i] = c3[i] < lo[i] ? c3[i] : lo[i];
                hi[i] = c3[i] > hi[i] ? c3[i] : hi[i];
                if (hi[i] - lo[i] >= ((int64_t)1 << 30)) {
                    fail_at(x, &vloc[C[k + j].v], "this vertex makes the "
                            "mesh span more than 16384 units");
                    goto done;
                }
            }
        }
        for (int j = 0; j < 3; j++) {
            tri[3 * nt + j] = ix[j];
            for (int i = 0; i < 3; i++)
                acc[ix[j]][i] += cr[i]; /* area-weighted vertex normals */
        }
        nt++;
    }
    if (pl->smooth && !use_vn)
        for (size_t k = 0; k < nu; k++) {
            const double l = sqrt(acc[k][0] * acc[k][0] +
                                  acc[k][1] * acc[k][1] +
                                  acc[k][2] * acc[k][2]);
            const double s = l > 0 ? (double)FX_UONE / l : 0;
            vn[k] = fx_d3((int32_t)lround(acc[k][0] * s),
                          (int32_t)lround(acc[k][1] * s),
                          (int32_t)lround(acc[k][2] * s));
        }
    char why[160];
    m = mesh_build(v, (unsigned)nu, pl->smooth ? vn : NULL, tri,
                   (unsigned)nt, why, sizeof why);
    if (!m)
        obj_fail(x, x->line_off, 0, "%s", why);
done:
    free(u);
    free(tri);
    free(v);
    free(vn);
    free(acc);
    return m;
}

rt_mesh *mesh_obj_parse(const char *text, size_t len, const rt_mesh_place *pl,
                        rt_parse_error *err, unsigned long *ignored)
{
    obj_lex x;
    vec pos = {NULL, 0, 0, sizeof(fx_vec3)};
    vec nrm = {NULL, 0, 0, sizeof(fx_vec3)};
    vec cor = {NULL, 0, 0, sizeof(corner)};
    vec vl = {NULL, 0, 0, sizeof(obj_loc)}; /* each v's line */
    vec fl = {NULL, 0, 0, sizeof(obj_loc)}; /* each triangle's face line */
    rt_mesh *m = NULL;
    memset(&x, 0, sizeof x);
    memset(err, 0, sizeof *err);
    x.t = text;
    x.len = len;
    x.err = err;
    for (size_t i = 0; i < len; i++)
        if (text[i] == '\0') {
            locate(&x, i);
            obj_fail(&x, i, 1, "a NUL byte: this is not a text OBJ file");
            return NULL;
        }
    size_t next = 0;
    int failed = 0;
    while (next < len && !failed) {
        x.line_off = next;
        x.line++;
        size_t e = next;
        while (e < len && text[e] != '\n')
            e++;
        next = e < len ? e + 1 : e;
        if (e > x.line_off && text[e - 1] == '\r')
            e--;
        x.line_end = e;
        x.pos = x.line_off;
        size_t off, n;
        next_tok(&x, &off, &n);
        if (n == 0)
            continue;
        const char *k = text + off;
        if (n == 1 && k[0] == 'v') {
            fx_vec3 *p = push(&pos);
            obj_loc *l = push(&vl);
            if (l)
                *l = here(&x);
            failed = !p || !l || number(&x, "v", &p->x) ||
                     number(&x, "v", &p->y) || number(&x, "v", &p->z);
        } else if (n == 2 && k[0] == 'v' && k[1] == 'n') {
            fx_vec3 *p = push(&nrm);
            failed = !p || number(&x, "vn", &p->x) ||
                     number(&x, "vn", &p->y) || number(&x, "vn", &p->z);
        } else if (n == 1 && k[0] == 'f') {
            corner first = {0, 0}, prev = {0, 0};
            unsigned count = 0;
            for (;;) {
                size_t o2, n2;
                next_tok(&x, &o2, &n2);
                if (n2 == 0)
                    break;
                const char *s = text + o2;
                size_t a = 0;
                while (a < n2 && s[a] != '/')
                    a++;
                size_t b = a < n2 ? a + 1 : n2; /* texture index, unused */
                while (b < n2 && s[b] != '/')
                    b++;
                corner c;
                if (a == 0) {
                    failed = obj_fail(&x, o2, n2, "a face corner needs a "
                                      "vertex index");
                    break;
                }
                if (index_of(&x, o2, n2, s, a, pos.n, "vertex", &c.v) ||
                    index_of(&x, o2, n2, s + (b + 1 < n2 ? b + 1 : n2),
                             b + 1 < n2 ? n2 - b - 1 : 0, nrm.n, "normal",
                             &c.n)) {
                    failed = 1;
                    break;
                }
                if (count >= 2) { /* a fan: first, prev, c */
                    /* One at a time: a push may move the array. */
                    const corner fan[3] = {first, prev, c};
                    for (int j = 0; j < 3 && !failed; j++) {
                        corner *t = push(&cor);
                        if (!t)
                            failed = obj_fail(&x, o2, n2, "out of memory");
                        else
                            *t = fan[j];
                    }
                    obj_loc *l = failed ? NULL : push(&fl);
                    if (!failed && !l)
                        failed = obj_fail(&x, o2, n2, "out of memory");
                    if (failed)
                        break;
                    *l = here(&x);
                }
                if (count == 0)
                    first = c;
                prev = c;
                count++;
            }
            if (!failed && count < 3)
                failed = obj_fail(&x, x.pos, 0, "a face needs at least 3 "
                                  "corners");
        } else {
            (*ignored)++; /* vt, o, g, s, usemtl, mtllib, l, ... */
        }
        /* A bound on memory only: the limits of a mesh (faces with no
         * area are dropped first) are checked once the file is read. */
        if (!failed && (pos.n > 4u * RT_MESH_MAX || cor.n > 12u * RT_MESH_MAX))
            failed = obj_fail(&x, off, n, "more than %u vertices or %u "
                              "triangles in the file", 4u * RT_MESH_MAX,
                              4u * RT_MESH_MAX);
    }
    if (!failed) {
        if (cor.n == 0) {
            obj_fail(&x, x.line_off, 0, "the file has no faces");
        } else {
            m = assemble(&x, &pos, &nrm, &cor, vl.p, fl.p, pl);
        }
    }
    free(pos.p);
    free(nrm.p);
    free(cor.p);
    free(vl.p);
    free(fl.p);
    return m;
}

/* Mesh paths are relative to the scene's directory. */
static void set_base(mesh_obj_ctx *c, const char *scene_path)
{
    const char *slash = scene_path ? strrchr(scene_path, '/') : NULL;
    const size_t n = slash ? (size_t)(slash - scene_path) + 1 : 0;
    free(c->base_dir);
    c->base_dir = malloc(n + 1);
    if (c->base_dir) {
        if (n > 0)
            memcpy(c->base_dir, scene_path, n);
        c->base_dir[n] = '\0';
    }
}

void mesh_obj_init(mesh_obj_ctx *c, const char *scene_path, FILE *diag,
                   int quiet)
{
    memset(c, 0, sizeof *c);
    c->diag = diag;
    c->quiet = quiet;
    set_base(c, scene_path);
}

void mesh_obj_free(mesh_obj_ctx *c)
{
    for (unsigned i = 0; i < c->n_mesh; i++)
        mesh_free(c->mesh[i].m);
    free(c->mesh);
    free(c->base_dir);
    memset(c, 0, sizeof *c);
}

static char *read_all(const char *path, size_t *len, char *msg, size_t cap)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(msg, cap, "%s: %s", path, strerror(errno));
        return NULL;
    }
    size_t n = 0, sz = 1 << 16;
    char *buf = malloc(sz);
    while (buf) {
        n += fread(buf + n, 1, sz - n, f);
        if (n < sz)
            break;
        char *nb = sz < OBJ_MAX_BYTES ? realloc(buf, 2 * sz) : NULL;
        if (!nb) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = nb;
        sz *= 2;
    }
    if (!buf || ferror(f)) {
        snprintf(msg, cap, "%s: %s", path,
                 buf ? strerror(errno) : "too large or out of memory");
        free(buf);
        buf = NULL;
    }
    fclose(f);
    *len = n;
    return buf;
}

rt_status mesh_obj_load(void *ctx, const char *path, size_t path_len,
                        const rt_mesh_place *pl, const struct rt_mesh **out,
                        char *msg, size_t msg_cap)
{
    mesh_obj_ctx *c = ctx;
    const char *base = c->base_dir && path[0] != '/' ? c->base_dir : "";
    const size_t bl = strlen(base);
    char *full = malloc(bl + path_len + 1);
    if (!full) {
        snprintf(msg, msg_cap, "out of memory");
        return RT_ERR_CAPACITY;
    }
    memcpy(full, base, bl);
    memcpy(full + bl, path, path_len);
    full[bl + path_len] = '\0';
    size_t len;
    char *text = read_all(full, &len, msg, msg_cap);
    if (!text) {
        free(full);
        return RT_ERR_ARG;
    }
    rt_parse_error e;
    unsigned long ign = 0;
    rt_mesh *m = mesh_obj_parse(text, len, pl, &e, &ign);
    struct mesh_obj_made *list =
        m ? realloc(c->mesh, (c->n_mesh + 1) * sizeof *list) : NULL;
    if (!m || !list) {
        if (m) {
            mesh_free(m);
            snprintf(e.msg, sizeof e.msg, "out of memory");
        }
        if (c->diag)
            cli_print_parse_error(c->diag, full, text, len, &e);
        snprintf(msg, msg_cap, "%s:%lu:%lu: %s", full, (unsigned long)e.line,
                 (unsigned long)e.col, e.msg);
        free(text);
        free(full);
        return RT_ERR_PARSE;
    }
    c->mesh = list;
    c->mesh[c->n_mesh++].m = m;
    c->ignored += ign;
    c->triangles += m->n_tris;
    if (ign && c->diag && !c->quiet)
        fprintf(c->diag, "%s: note: %lu statement%s other than v, vn and f "
                "ignored\n", full, ign, ign == 1 ? "" : "s");
    free(text);
    free(full);
    *out = m;
    return RT_OK;
}

rt_status mesh_obj_parse_scene(const char *text, size_t len,
                               const char *scene_path, rt_scene *s,
                               rt_parse_error *err, mesh_obj_ctx *c)
{
    if (scene_path)
        set_base(c, scene_path);
    return rt_parse_with_meshes(text, len, s, err, mesh_obj_load, c);
}
