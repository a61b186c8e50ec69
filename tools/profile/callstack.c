/* SPDX-License-Identifier: MIT */
/* callstack: a QEMU TCG plugin for `make profile PROFILE=--inclusive`
 * (mk/profile.mk). It keeps a shadow call stack of Thumb (Cortex-M)
 * firmware and counts, per call context and translated block, how often
 * the block ran; tools/profile/inclusive.py turns that into inclusive
 * counts.
 *
 * A call: the previous block ended in a BL and the new block starts at
 * its target, or in a BLX register; and the new block starts at a
 * function entry (entries=FILE). It pushes a frame: the callee, and the
 * return address (the call's address plus its size). A return: the
 * previous block ended in an instruction that can return (BX, POP or
 * LDM with the pc, LDR pc, MOV pc) and the new block starts at the
 * return address of a frame on the stack (searched from the top): that
 * frame and all above it are popped. A context is a node of the call
 * tree: its caller's context and its entry. A tail call (a plain branch
 * into a function) is no call: it runs in its caller's frame. An
 * exception handler runs in the frame it interrupted.
 *
 * Output, written at exit (to FILE.tmp, then renamed to FILE):
 *
 *   C id parent entry calls       a context (ids from 1, parent before
 *                                 child; 0 is the root, outside any call):
 *                                 entry in hex, calls decimal
 *   B ctx pc runs n pc1 ... pcn   a block that ran runs times in context
 *                                 ctx: its first pc and its n instruction
 *                                 addresses, in hex
 *
 * A block is counted whole, as in insncount.c. The stack is at most
 * MAX_DEPTH frames deep and there are at most MAX_CTX contexts; past
 * either (or out of memory) the plugin says so at exit and writes no
 * profile.
 *
 * Build: cc -O2 -shared -fPIC -o callstack.so callstack.c
 * Use:   qemu-system-arm ... -plugin ./callstack.so,entries=E,out=FILE
 *        E: function entry addresses, hex, one a line (bit 0, the Thumb
 *        bit, is ignored), e.g. from `nm` of the ELF
 *
 * The plugin API's declarations: qemu_plugin.h. */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <inttypes.h>

#include "qemu_plugin.h"

#ifndef MAX_DEPTH /* -D for a test of the bounds */
#define MAX_DEPTH 256
#endif
#ifndef MAX_CTX
#define MAX_CTX (1u << 20)
#endif
#define MAX_COUNTERS (1u << 22)

/* How a block ends. */
enum { END_OTHER, END_BL, END_BLX, END_RET };

/* One translation; a block translated again gets a record of its own. */
typedef struct block {
    uint64_t target; /* END_BL: the call's target */
    uint64_t ret;    /* END_BL, END_BLX: the return address */
    int end;
    int entry; /* pc[0] is a function entry */
    size_t n;
    uint64_t pc[];
} block;

typedef struct {
    uint32_t parent;
    uint64_t entry;
    uint64_t calls;
} context;

typedef struct {
    uint64_t ret;
    uint32_t ctx; /* the caller's */
} frame;

/* runs of one block in one context; b == NULL: a free slot */
typedef struct {
    const block *b;
    uint32_t ctx;
    uint64_t runs;
} counter;

static char *out_path;
static uint64_t *entries;
static size_t n_entries;

static context *ctxs; /* ctxs[0]: the root */
static uint32_t n_ctx = 1, cap_ctx;
static uint32_t *ctx_slot; /* hash of (parent, entry): id, 0 = free */
static size_t ctx_mask;

static counter *ctr;
static size_t n_ctr, ctr_mask;

static frame stack[MAX_DEPTH];
static int depth;
static uint32_t cur;
static const block *prev;
static const char *failed; /* why no profile will be written */

static size_t mix(uint64_t a, uint64_t b)
{
    uint64_t h = (a ^ (b * 0x9e3779b97f4a7c15u)) * 0xff51afd7ed558ccdu;
    return (size_t)(h ^ (h >> 29));
}

static int is_entry(uint64_t pc)
{
    size_t lo = 0, hi = n_entries;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (entries[mid] < pc)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < n_entries && entries[lo] == pc;
}

/* Classifies a block's last instruction (Thumb, little-endian). */
static void classify(block *b, const uint8_t *d, size_t size, uint64_t at)
{
    const unsigned hw = d[0] | d[1] << 8;
    b->end = END_OTHER;
    if (size == 4) {
        const unsigned hw2 = d[2] | d[3] << 8;
        const int rt_pc = (hw2 >> 12) == 15;
        if ((hw & 0xf800) == 0xf000 && (hw2 & 0xd000) == 0xd000) {
            /* BL: imm32 = S:I1:I2:imm10:imm11:0, In = !(Jn ^ S) */
            const uint32_t s = hw >> 10 & 1;
            const uint32_t i1 = !((hw2 >> 13 & 1) ^ s);
            const uint32_t i2 = !((hw2 >> 11 & 1) ^ s);
            uint32_t imm = s << 24 | i1 << 23 | i2 << 22 |
                           (hw & 0x3ff) << 12 | (hw2 & 0x7ff) << 1;
            if (s)
                imm |= 0xfe000000u;
            b->end = END_BL;
            b->target = (uint32_t)(at + 4 + imm);
        } else if (((hw & 0xffd0) == 0xe890 || (hw & 0xffd0) == 0xe910) &&
                   (hw2 & 0x8000)) {
            b->end = END_RET; /* LDMIA/LDMDB (POP.W) with the pc */
        } else if (((hw & 0xfff0) == 0xf8d0 || (hw & 0xfff0) == 0xf850) &&
                   rt_pc) {
            b->end = END_RET; /* LDR.W pc */
        }
        b->ret = at + 4;
    } else if (size == 2) {
        if ((hw & 0xff87) == 0x4780)
            b->end = END_BLX;
        else if ((hw & 0xff87) == 0x4700 || (hw & 0xff00) == 0xbd00 ||
                 (hw & 0xff87) == 0x4687)
            b->end = END_RET; /* BX, POP {..., pc}, MOV pc */
        b->ret = at + 2;
    }
}

/* Doubles a counter table, or makes the first one. */
static int grow_counters(void)
{
    const size_t cap = ctr ? 2 * (ctr_mask + 1) : 4096;
    counter *t = calloc(cap, sizeof *t);
    if (!t)
        return -1;
    for (size_t i = 0; ctr && i <= ctr_mask; i++) {
        if (!ctr[i].b)
            continue;
        size_t j = mix((uintptr_t)ctr[i].b, ctr[i].ctx) & (cap - 1);
        while (t[j].b)
            j = (j + 1) & (cap - 1);
        t[j] = ctr[i];
    }
    free(ctr);
    ctr = t;
    ctr_mask = cap - 1;
    return 0;
}

static void count(const block *b, uint32_t ctx)
{
    size_t i = mix((uintptr_t)b, ctx) & ctr_mask;
    while (ctr[i].b && (ctr[i].b != b || ctr[i].ctx != ctx))
        i = (i + 1) & ctr_mask;
    if (!ctr[i].b) {
        if (n_ctr >= MAX_COUNTERS) {
            failed = "too many (context, block) counters";
            return;
        }
        if (2 * (n_ctr + 1) > ctr_mask + 1) {
            if (grow_counters() != 0) {
                failed = "out of memory";
                return;
            }
            count(b, ctx); /* the slot moved */
            return;
        }
        ctr[i].b = b;
        ctr[i].ctx = ctx;
        n_ctr++;
    }
    ctr[i].runs++;
}

/* The context (parent, entry), made on its first call; 0 if none can be
 * made (failed says why). */
static uint32_t child(uint32_t parent, uint64_t entry)
{
    size_t i = mix(entry, parent) & ctx_mask;
    for (uint32_t id; (id = ctx_slot[i]) != 0; i = (i + 1) & ctx_mask)
        if (ctxs[id].parent == parent && ctxs[id].entry == entry)
            return id;
    if (n_ctx >= MAX_CTX) {
        failed = "more than MAX_CTX call contexts";
        return 0;
    }
    if (n_ctx == cap_ctx) {
        context *c = realloc(ctxs, 2 * cap_ctx * sizeof *c);
        if (!c) {
            failed = "out of memory";
            return 0;
        }
        ctxs = c;
        cap_ctx *= 2;
    }
    ctxs[n_ctx] = (context){parent, entry, 0};
    ctx_slot[i] = n_ctx;
    return n_ctx++;
}

static void on_exec(unsigned int vcpu, void *userdata)
{
    (void)vcpu;
    const block *b = userdata, *p = prev;
    prev = b;
    if (failed)
        return;
    if (p && b->entry &&
        ((p->end == END_BL && p->target == b->pc[0]) || p->end == END_BLX)) {
        if (depth == MAX_DEPTH) {
            failed = "a call stack deeper than MAX_DEPTH frames";
            return;
        }
        const uint32_t c = child(cur, b->pc[0]);
        if (!c)
            return;
        stack[depth++] = (frame){p->ret, cur};
        ctxs[c].calls++;
        cur = c;
    } else if (p && p->end == END_RET) {
        for (int i = depth - 1; i >= 0; i--)
            if (stack[i].ret == b->pc[0]) {
                cur = stack[i].ctx;
                depth = i;
                break;
            }
    }
    count(b, cur);
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    const size_t n = qemu_plugin_tb_n_insns(tb);
    block *b = n ? calloc(1, sizeof *b + n * sizeof b->pc[0]) : NULL;
    if (!b) {
        if (n)
            failed = "out of memory";
        return;
    }
    b->n = n;
    for (size_t i = 0; i < n; i++)
        b->pc[i] = qemu_plugin_insn_vaddr(qemu_plugin_tb_get_insn(tb, i));
    const struct qemu_plugin_insn *last = qemu_plugin_tb_get_insn(tb, n - 1);
    classify(b, qemu_plugin_insn_data(last), qemu_plugin_insn_size(last),
             b->pc[n - 1]);
    b->entry = is_entry(b->pc[0]);
    /* never freed: QEMU may run the block until the end */
    qemu_plugin_register_vcpu_tb_exec_cb(tb, on_exec, QEMU_PLUGIN_CB_NO_REGS,
                                         b);
}

static void write_profile(FILE *f)
{
    for (uint32_t i = 1; i < n_ctx; i++)
        fprintf(f, "C %" PRIu32 " %" PRIu32 " %" PRIx64 " %" PRIu64 "\n", i,
                ctxs[i].parent, ctxs[i].entry, ctxs[i].calls);
    for (size_t i = 0; i <= ctr_mask; i++) {
        const counter *c = &ctr[i];
        if (!c->b)
            continue;
        fprintf(f, "B %" PRIu32 " %" PRIx64 " %" PRIu64 " %zu", c->ctx,
                c->b->pc[0], c->runs, c->b->n);
        for (size_t k = 0; k < c->b->n; k++)
            fprintf(f, " %" PRIx64, c->b->pc[k]);
        fputc('\n', f);
    }
}

static void on_exit(qemu_plugin_id_t id, void *userdata)
{
    (void)id, (void)userdata;
    if (failed) {
        fprintf(stderr, "callstack: %s (MAX_DEPTH %d, MAX_CTX %u); "
                        "no profile written\n",
                failed, MAX_DEPTH, MAX_CTX);
        return;
    }
    plugin_write("callstack", out_path, write_profile);
}

static int cmp_u64(const void *a, const void *b)
{
    const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* Reads the entry addresses: hex, one a line. */
static int read_entries(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "callstack: cannot read %s\n", path);
        return -1;
    }
    char line[128];
    size_t cap = 0;
    for (unsigned no = 1; fgets(line, sizeof line, f); no++) {
        char *end;
        const uint64_t a = strtoull(line, &end, 16);
        if (end == line || (*end != '\n' && *end != '\0')) {
            fprintf(stderr, "callstack: %s:%u:1: expected a hex address\n",
                    path, no);
            fclose(f);
            return -1;
        }
        if (n_entries == cap) {
            cap = cap ? 2 * cap : 256;
            uint64_t *e = realloc(entries, cap * sizeof *e);
            if (!e) {
                fclose(f);
                return -1;
            }
            entries = e;
        }
        entries[n_entries++] = a & ~(uint64_t)1;
    }
    fclose(f);
    if (n_entries == 0) {
        fprintf(stderr, "callstack: %s: no entry addresses\n", path);
        return -1;
    }
    qsort(entries, n_entries, sizeof entries[0], cmp_u64);
    return 0;
}

PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id,
                                      const qemu_info_t *info, int argc,
                                      char **argv)
{
    (void)info;
    const char *entries_path = NULL;
    out_path = "callstack.txt";
    for (int i = 0; i < argc; i++) {
        if (strncmp(argv[i], "out=", 4) == 0 && argv[i][4] != '\0') {
            out_path = strdup(argv[i] + 4); /* argv is QEMU's */
            if (!out_path)
                return -1;
        } else if (strncmp(argv[i], "entries=", 8) == 0 &&
                   argv[i][8] != '\0') {
            entries_path = argv[i] + 8;
        } else {
            fprintf(stderr, "callstack: unknown argument '%s' "
                            "(entries=FILE, out=FILE)\n",
                    argv[i]);
            return -1;
        }
    }
    if (!entries_path) {
        fprintf(stderr, "callstack: no entries=FILE (function entry "
                        "addresses, hex, one a line)\n");
        return -1;
    }
    if (read_entries(entries_path) != 0)
        return -1;
    cap_ctx = 1024;
    ctx_mask = 2 * MAX_CTX - 1;
    ctxs = calloc(cap_ctx, sizeof *ctxs);
    ctx_slot = calloc(ctx_mask + 1, sizeof *ctx_slot);
    if (!ctxs || !ctx_slot || grow_counters() != 0) {
        fprintf(stderr, "callstack: out of memory\n");
        return -1;
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit, NULL);
    return 0;
}
