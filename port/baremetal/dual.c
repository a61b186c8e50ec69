/* SPDX-License-Identifier: MIT */
/*
 * dual.c: one frame on both cores of a two-core board (FW_CORES=2;
 * dual.h). The core (rt_render_row_set()) stays single-threaded: each core
 * calls it with its own stack, work buffer and hand-out context, and the
 * core keeps no state of its own, so the two calls share nothing but the
 * scene and the options, both read-only. What the cores share is here:
 *
 *   the hand-out  FW_HANDOUT 0 (the default): a shared row counter, taken
 *                 with an exclusive load/store pair (LDREX/STREX), so each
 *                 core takes the next row whenever it is free; 1: a fixed
 *                 interleave, core 0 the even rows, core 1 the odd ones;
 *                 2: a deliberately unbalanced one, core 1 every fourth
 *                 row (for the test that the balance check catches it).
 *   the ring      core 1's finished rows, in the order it finished them
 *                 (which is row order: it takes rows in increasing
 *                 order), FW_RING_ROWS slots of one row. Core 1 waits for
 *                 a free slot before it takes a row, so it never holds a
 *                 row it cannot hand over.
 *
 * Core 0 alone talks to the output: after each of its rows it sends every
 * row whose turn has come, from the ring or from its own rows that finished
 * early (a private queue of FW_RING_ROWS rows), so the sink sees rows
 * 0, 1, 2, ... with exactly the bytes of a one-core render. Memory is a
 * few rows, not a frame: a scene that fits one core fits both.
 *
 * Waiting: a core that must wait for the other polls in a wait function
 * (in the .text.fw_wait section, which the linker script brackets with
 * _swait and _ewait, so the instruction counts show waiting apart from
 * work). Polling, not WFE: under QEMU a WFE ends the core's turn at once
 * (board_an521.c), so a wait would cost no instructions and a core's
 * count would hide the time it stood still; polled, a core's count is its
 * time. Core 1 is started with a bounded wait: if it gives no sign of
 * life within DUAL_START_POLLS polls, dual_render() says so and fails
 * instead of hanging.
 */
#include "port.h"
#include "fw_buffers.h"
#include "dual.h"

enum { DUAL_COUNTER = 0, DUAL_INTERLEAVE = 1, DUAL_SKEWED = 2 };

/* How rows are handed out (above). */
#ifndef FW_HANDOUT
#define FW_HANDOUT DUAL_COUNTER
#endif

/* Rows core 1 may have finished ahead of core 0's output, and core 0 ahead
 * of core 1's. */
#ifndef FW_RING_ROWS
#define FW_RING_ROWS 4
#endif

/* 0 leaves core 1 held, for the test that this is reported, not hung. */
#ifndef FW_CORE1_START
#define FW_CORE1_START 1
#endif

/* Polls of core 1's first sign of life before giving up: a count, not a
 * time, so the outcome does not depend on the host. Far more than the
 * few thousand instructions core 1 needs from its release to its first
 * store, and more than one of QEMU's round-robin turns. */
#define DUAL_START_POLLS 4000000u

/* Section of the wait functions, kept apart by the linker script. */
#define DUAL_WAIT __attribute__((noinline, section(".text.fw_wait")))

typedef struct {
    /* Set by core 0 before it releases core 1; read-only afterwards. */
    const rt_scene *scene;
    const rt_options *opt;
    /* The next row of the shared counter (FW_HANDOUT 0). */
    uint32_t next_row;
    /* The ring: core 1 fills slot head % FW_RING_ROWS and then advances
     * head; core 0 sends slot tail % FW_RING_ROWS and then advances tail.
     * Each index has one writer. */
    uint32_t head, tail;
    int32_t ring_y[FW_RING_ROWS];
    /* Core 1's news for core 0's waits: events counts its changes (its
     * start, each row, its end); done and status1 say it has ended, and
     * how. */
    uint32_t events;
    uint32_t done;
    int32_t status1;
    uint32_t rows1;
} dual_shared;

/* One core's hand-out state, on that core's stack. */
typedef struct {
    unsigned core;
    int last; /* the row it took last, -1 before the first */
} dual_core;

static dual_shared sh;
static uint8_t ring[FW_RING_ROWS][FW_ROW_BYTES];
static uint8_t core1_buf[FW_BUF_BYTES];

/* Core 0's own state: the output, the next row due there, and its rows
 * that finished before their turn. */
static rt_row_fn emit_fn;
static void *emit_ctx;
static int next_emit;
static int emit_failed;
static unsigned park_head, park_tail;
static int32_t park_y[FW_RING_ROWS];
static uint8_t park[FW_RING_ROWS][FW_ROW_BYTES];

extern uint32_t _sstack1[], _estack1[];
#define STACK1_PAINT 0xA55AC33Cu
/* The lowest words of the stack, left out of the scan as common.c does. */
#define STACK1_SKIP_WORDS 8

/* Where each core's frame begins and where its last row is done: empty
 * functions that tools/profile/vcpucount.c finds by name in the ELF, to
 * count each core's instructions between them. noipa keeps each a
 * function of its own. */
void dual_mark_start(void);
void dual_mark_end(void);

__attribute__((noipa)) void dual_mark_start(void)
{
    __asm__ volatile("" ::: "memory");
}

__attribute__((noipa)) void dual_mark_end(void)
{
    __asm__ volatile("" ::: "memory");
}

/* Waits until *p differs from v, for at most `polls` polls (0: no
 * bound), and returns the last value read. */
DUAL_WAIT static uint32_t wait_change(const uint32_t *p, uint32_t v,
                                      uint32_t polls)
{
    uint32_t now = __atomic_load_n(p, __ATOMIC_ACQUIRE);
    for (uint32_t i = 0; now == v && (polls == 0 || i < polls); i++)
        now = __atomic_load_n(p, __ATOMIC_ACQUIRE);
    return now;
}

static void copy_row(uint8_t *dst, const uint8_t *src, size_t n)
{
    for (size_t i = 0; i < n; i++)
        dst[i] = src[i];
}

/* The next row for core c, or -1 when it has none left. */
static int take_row(dual_core *c)
{
    int y;
    switch (FW_HANDOUT) {
    case DUAL_COUNTER: /* LDREX/STREX on ARMv8-M Mainline */
        y = (int)__atomic_fetch_add(&sh.next_row, 1u, __ATOMIC_RELAXED);
        break;
    case DUAL_INTERLEAVE:
        y = c->last < 0 ? (int)c->core : c->last + 2;
        break;
    default: /* DUAL_SKEWED */
        y = c->last + 1;
        while (((y & 3) == 3) != (c->core == 1))
            y++;
        break;
    }
    if (y >= (int)sh.opt->height)
        return -1;
    c->last = y;
    return y;
}

/* ---- Core 1 --------------------------------------------------------- */

static int core1_next(void *ctx)
{
    uint32_t t;
    while (sh.head - (t = __atomic_load_n(&sh.tail, __ATOMIC_ACQUIRE)) >=
           FW_RING_ROWS)
        wait_change(&sh.tail, t, 0);
    return take_row(ctx);
}

static int core1_row(void *ctx, int y, const uint8_t *row, size_t nbytes)
{
    (void)ctx;
    const uint32_t h = sh.head;
    copy_row(ring[h % FW_RING_ROWS], row, nbytes);
    sh.ring_y[h % FW_RING_ROWS] = y;
    sh.rows1++;
    __atomic_store_n(&sh.head, h + 1, __ATOMIC_RELEASE);
    __atomic_store_n(&sh.events, sh.events + 1, __ATOMIC_RELEASE);
    return 0;
}

void port_core1_main(void)
{
    __atomic_store_n(&sh.events, 1u, __ATOMIC_RELEASE);
    dual_mark_start();
    dual_core me = { 1, -1 };
    rt_status st = rt_render_row_set(sh.scene, sh.opt, core1_next, core1_buf,
                                     core1_row, &me, 0);
    dual_mark_end();
    sh.status1 = st;
    __atomic_store_n(&sh.done, 1u, __ATOMIC_RELEASE);
    __atomic_store_n(&sh.events, sh.events + 1, __ATOMIC_RELEASE);
}

/* ---- Core 0 --------------------------------------------------------- */

static void send(const uint8_t *row, size_t nbytes)
{
    if (!emit_failed &&
        emit_fn(emit_ctx, next_emit, row, nbytes) != 0)
        emit_failed = 1;
    next_emit++;
}

/* Sends every row whose turn has come, from the ring or from core 0's own
 * early rows. Returns how many it sent. */
static int pump(void)
{
    const size_t nbytes = rt_row_bytes(sh.opt);
    int sent = 0;
    for (;;) {
        const uint32_t t = sh.tail;
        if (t != __atomic_load_n(&sh.head, __ATOMIC_ACQUIRE) &&
            sh.ring_y[t % FW_RING_ROWS] == next_emit) {
            send(ring[t % FW_RING_ROWS], nbytes);
            __atomic_store_n(&sh.tail, t + 1, __ATOMIC_RELEASE);
                } else if (park_tail != park_head &&
                   park_y[park_tail % FW_RING_ROWS] == next_emit) {
            send(park[park_tail % FW_RING_ROWS], nbytes);
            park_tail++;
        } else {
            return sent;
        }
        sent++;
    }
}

/* Sends what it can, and waits for core 1 when nothing could be sent.
 * Returns RT_OK, or why the frame cannot be finished: core 1 ended with
 * an error, or ended while a row core 0 waits for never came. */
static rt_status pump_or_wait(void)
{
    const uint32_t e = __atomic_load_n(&sh.events, __ATOMIC_ACQUIRE);
    const uint32_t done = __atomic_load_n(&sh.done, __ATOMIC_ACQUIRE);
    if (pump() > 0)
        return RT_OK;
    if (done)
        return sh.status1 != RT_OK ? (rt_status)sh.status1 : RT_ERR_ABORTED;
    wait_change(&sh.events, e, 0);
    return RT_OK;
}

static int core0_next(void *ctx)
{
    return emit_failed ? -1 : take_row(ctx);
}

static int core0_row(void *ctx, int y, const uint8_t *row, size_t nbytes)
{
    (void)ctx;
    pump();
    if (y == next_emit) {
        send(row, nbytes);
        pump();
        return emit_failed;
    }
    while (park_head - park_tail >= FW_RING_ROWS)
        if (pump_or_wait() != RT_OK)
            return 1;
    copy_row(park[park_head % FW_RING_ROWS], row, nbytes);
    park_y[park_head % FW_RING_ROWS] = y;
    park_head++;
    return 0;
}

int dual_render(const rt_scene *s, const rt_options *o, uint8_t *row_buf,
                rt_row_fn emit, void *ctx)
{
    dual_mark_start();
    if (!s || !o || rt_row_bytes(o) > FW_ROW_BYTES ||
        rt_buffer_bytes(o) > sizeof core1_buf)
        return RT_ERR_ARG;
    sh.scene = s;
    sh.opt = o;
    emit_fn = emit;
    emit_ctx = ctx;
    /* Addresses as integers: the symbols are distinct C objects. */
    for (uintptr_t p = (uintptr_t)_sstack1; p < (uintptr_t)_estack1; p += 4)
        *(volatile uint32_t *)p = STACK1_PAINT;
    __asm__ volatile("dsb" ::: "memory");
    if (FW_CORE1_START)
        port_core1_start();
    if (wait_change(&sh.events, 0, DUAL_START_POLLS) == 0) {
        port_log("fixtrace: core 1 gave no sign of life within ");
        port_log_u64(DUAL_START_POLLS);
        port_log(" polls after its release (port_core1_start)\n");
        return DUAL_NO_CORE1;
    }

    dual_core me = { 0, -1 };
    rt_status st = rt_render_row_set(s, o, core0_next, row_buf, core0_row,
                                     &me, 0);
    while (st == RT_OK && next_emit < (int)o->height && !emit_failed)
        st = pump_or_wait();
    dual_mark_end();
    if (st == RT_OK && emit_failed)
        st = RT_ERR_ABORTED;
    if (st == RT_OK)
        wait_change(&sh.done, 0, 0);
    return st;
}

int dual_report(size_t guard)
{
    const uintptr_t top = (uintptr_t)_estack1;
    uintptr_t p = (uintptr_t)(_sstack1 + STACK1_SKIP_WORDS);
    while (p < top && *(const volatile uint32_t *)p == STACK1_PAINT)
        p += 4;
    const size_t used = (size_t)(top - p);
    const size_t size = (size_t)((uintptr_t)_estack1 - (uintptr_t)_sstack1);
    port_log_value("core1_rows", sh.rows1);
    port_log_value("stack_bytes_core1", used);
    port_log_value("stack_reserved_core1", size);
    if (used + guard > size) {
        port_log("fixtrace: core 1's stack overflowed (raise STACK1_SIZE "
                 "in the linker script)\n");
        return -1;
    }
    return 0;
}
