/* SPDX-License-Identifier: MIT */
/*
 * fxbench: instructions per call of the fx_math / fx_vec operations on a
 * Cortex-M, counted by QEMU with -icount shift=7 (see run.sh). Each op runs
 * over N pseudo-random inputs in the ranges a ray tracer sees; the cost of
 * an identical loop without the op is subtracted, so a figure includes the
 * call itself (argument set-up, bl, return) for out-of-line functions.
 */
#include <stdint.h>
#include "fx_math.h"
#include "fx_vec.h"
#include "rt_shape.h"

#define N 10000

void sh_exit(int code);

/* FPGAIO COUNTER: 25 MHz of virtual time; 3.2 ticks per instruction at
 * icount shift=7 (PLATFORM.md). */
#define COUNTER (*(volatile uint32_t *)0x40028018u)

static uintptr_t sh_call(uintptr_t op, const void *arg)
{
    register uintptr_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void sh_exit(int code)
{
    uint32_t blk[2] = {0x20026u, (uint32_t)code};
    sh_call(0x20, blk); /* SYS_EXIT_EXTENDED */
    for (;;)
        ;
}

static void puts_(const char *s)
{
    sh_call(0x04, s); /* SYS_WRITE0 */
}

static void putu(uint32_t v, int width)
{
    char b[12];
    int n = 0;
    do {
        b[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    char o[24];
    int k = 0;
    while (width-- > n)
        o[k++] = ' ';
    while (n)
        o[k++] = b[--n];
    o[k] = 0;
    puts_(o);
}

static uint32_t rng = 0x9E3779B9u;
static uint32_t rnd(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

/* Magnitude in [2^lo, 2^hi) raw units, log-uniform, as a uint32. */
static uint32_t logu(int lo, int hi)
{
    int e = lo + (int)(rnd() % (uint32_t)(hi - lo));
    return (rnd() | 0x80000000u) >> (31 - e);
}

static fx_t sgn(uint32_t m)
{
    return (rnd() & 1) ? -(fx_t)m : (fx_t)m;
}

static fx_t A[N], B[N];
static uint64_t Q[N];
static fx_vec3 V[N];
static fx_dir3 D[N];
static volatile uint32_t sink;

/* The second operand of the two-vector ops: a rotated copy. */
#define ROT(v) fx_v3((v).y, (v).z, (v).x)

/* Prints "name  ticks -> instructions per call (2 decimals)". */
static void report(const char *name, uint32_t ticks, uint32_t base)
{
    /* instructions = ticks * 5 / 16, rounded. */
    uint32_t ins = (uint32_t)(((uint64_t)ticks * 5 + 8) / 16);
    uint32_t bins = (uint32_t)(((uint64_t)base * 5 + 8) / 16);
    uint32_t per100 = (ins - bins) * 100u / N;
    puts_(name);
    putu(per100 / 100, 12 - (int)0);
    puts_(".");
    putu(per100 % 100 / 10, 1);
    putu(per100 % 10, 1);
    /* XOR of all results: must match across CPUs (bit-identical output). */
    char hex[12] = "   ";
    for (int d = 0; d < 8; d++)
        hex[3 + d] = "0123456789abcdef"[(sink >> (28 - 4 * d)) & 0xF];
    hex[11] = 0;
    puts_(hex);
    puts_("\n");
}

#define LOOP(expr)                                                            \
    ({                                                                        \
        uint32_t t0_ = COUNTER, s_ = 0;                                       \
        for (int i = 0; i < N; i++)                                           \
            s_ ^= (uint32_t)(expr);                                           \
        uint32_t t1_ = COUNTER;                                               \
        sink = s_;                                                            \
        t1_ - t0_;                                                            \
    })

static rt_ray R[N];

/* One object of each kind but meshes (tools/mesh_bench.sh measures
 * those, which need tables), seed-scene sized, and rays from about 20
 * units away aimed within 1.5 bounding radii of its centre: roughly half
 * hit. The figure is rt_intersect per call, bounding-sphere test
 * included. */
static void shapes(uint32_t bv)
{
    static const char *const names[RT_MESH] = {
        "sphere    ", "quad      ", "box       ", "cylinder  ", "cone      "
    };
    for (int kind = 0; kind < RT_MESH; kind++) {
        rt_object o;
        uint8_t *z = (uint8_t *)&o;
        for (unsigned k = 0; k < sizeof o; k++)
            z[k] = 0;
        o.kind = (uint8_t)kind;
        o.u.origin = fx_v3(FX_INT(1), 0, FX_INT(2)); /* any kind's first */
        if (kind == RT_SPHERE) {
            o.u.sphere.radius = FX_INT(3) / 2;
        } else if (kind == RT_QUAD) {
            o.u.quad.edge1 = fx_v3(FX_INT(4), 0, 0);
            o.u.quad.edge2 = fx_v3(0, FX_INT(3), FX_INT(1));
        } else if (kind == RT_BOX) {
            o.u.box.max = fx_v3(FX_INT(3), FX_INT(2), FX_INT(4));
        } else if (kind == RT_CYLINDER || kind == RT_CONE) {
            o.u.upright.radius = FX_INT(3) / 2;
            o.u.upright.height = FX_INT(3);
        }
        o.caps = RT_CAP_BOTTOM | RT_CAP_TOP;
        rt_object_prepare(&o);
        for (int i = 0; i < N; i++) {
            fx_vec3 org = fx_v3(sgn(logu(16, 19)), FX_INT(6), -FX_INT(18));
            fx_t reach = o.br + o.br / 2;
            fx_vec3 aim = fx_v3(o.bc.x + (fx_t)(rnd() % (uint32_t)(2 * reach)) - reach,
                                o.bc.y + (fx_t)(rnd() % (uint32_t)(2 * reach)) - reach,
                                o.bc.z);
            R[i].o = org;
            R[i].d = fx_d3_normalize(fx_v3_sub(aim, org));
            R[i].e = fx_d3_unit_err(R[i].d);
            R[i].small = (uint8_t)fx_v3_small(org);
        }
        fx_t t;
        uint16_t part;
        report(names[kind],
               LOOP(rt_intersect(&o, &R[i], 128, FX_MAX, &t, &part) ? t : 0),
               bv);
    }
}

int main(void)
{
    uint32_t b2, b1, b64, bv;
    int i;

    b2 = LOOP(A[i] ^ B[i]);
    b1 = LOOP(A[i]);
    b64 = LOOP(Q[i] >> 7);
    bv = LOOP(V[i].x ^ V[i].y ^ V[i].z);

    puts_("op             instr/call   xor of results\n");
    /* mul: |a|, |b| in [2^-8, 2^8). */
    for (i = 0; i < N; i++) {
        A[i] = sgn(logu(8, 24));
        B[i] = sgn(logu(8, 24));
    }
    report("mul       ", LOOP(fx_mul(A[i], B[i])), b2);

    /* div: |a| in [2^-8, 2^10), |b| in [2^-4, 2^8). */
    for (i = 0; i < N; i++) {
        A[i] = sgn(logu(8, 26));
        B[i] = sgn(logu(12, 24));
    }
    report("div       ", LOOP(fx_div(A[i], B[i])), b2);

    /* recip: |a| in [2^-4, 2^8). */
    report("recip     ", LOOP(fx_recip(B[i])), b1);

    /* sqrt: a in [2^-16, 2^15), log-uniform. */
    for (i = 0; i < N; i++)
        A[i] = (fx_t)logu(0, 31);
    report("sqrt      ", LOOP(fx_sqrt(A[i])), b1);

    /* sqrt_q32 / isqrt64: Q32.32 in [2^-12, 2^28), log-uniform. */
    for (i = 0; i < N; i++)
        Q[i] = (uint64_t)logu(0, 32) << (rnd() % 29);
    report("sqrt_q32  ", LOOP(fx_sqrt_q32(Q[i])), b64);
    report("isqrt64   ", LOOP(fx_isqrt64(Q[i])), b64);

    /* Vectors: components with |c| in [2^-4, 2^8), random signs. */
    for (i = 0; i < N; i++)
        V[i] = fx_v3(sgn(logu(12, 24)), sgn(logu(12, 24)), sgn(logu(12, 24)));
    report("length    ", LOOP(fx_v3_length(V[i])), bv);
    report("dot       ", LOOP(fx_v3_dot(V[i], ROT(V[i]))), bv);
    report("dotn      ", LOOP(fx_v3_dotn(V[i], ROT(V[i]))), bv);
    {
        fx_vec3 c;
        report("cross     ",
               LOOP((c = fx_v3_cross(V[i], ROT(V[i])), c.x ^ c.y ^ c.z)),
               bv);
    }
    {
        fx_vec3 u;
        report("normalize ", LOOP((u = fx_v3_normalize(V[i]), u.x ^ u.y ^ u.z)),
               bv);
    }
    {
        fx_dir3 u;
        report("d3_norm   ", LOOP((u = fx_d3_normalize(V[i]), u.x ^ u.y ^ u.z)),
               bv);
        /* A unit vector a few ulps off unit length, renormalised. */
        for (i = 0; i < N; i++) {
            fx_dir3 w = fx_d3_normalize(V[i]);
            D[i] = fx_d3(w.x + (int32_t)(rnd() % 7) - 3, w.y, w.z);
        }
        report("d3_renorm ", LOOP((u = fx_d3_renorm(D[i]), u.x ^ u.y ^ u.z)),
               bv);
    }
    shapes(bv);
    return 0;
}
