/* SPDX-License-Identifier: MIT */
/* vcpucount: a QEMU TCG plugin that counts the instructions each virtual
 * CPU retires in its frame, for the two-core board (port/baremetal/dual.c,
 * tools/dual_table.sh). Arguments, addresses in hex as nm prints them:
 *
 *   start=A  the function each core calls where its frame begins
 *   end=A    the function each core calls when its last row is done
 *   wait=A-B the code in which a core waits for the other ([A, B))
 *   out=FILE where the counts go (default vcpucount.txt)
 *
 * A vCPU's frame runs from its first call of start to its last call of
 * end. At exit it writes one line per vCPU that called start:
 *
 *   vcpu N frame F wait W all T
 *
 * F: instructions from its start to its end; W: of those, the ones in the
 * wait code; T: all it retired from reset to exit. Each translated block
 * is counted whole when it starts (a helper call per block), so the
 * markers, which are functions, begin blocks of their own; a block that an
 * exception leaves early overcounts its tail, as in insncount.c.
 *
 * Build: cc -O2 -shared -fPIC -o vcpucount.so vcpucount.c
 * Use:   qemu-system-arm ... -plugin ./vcpucount.so,start=...,end=...
 *
 * The plugin API's declarations: qemu_plugin.h. */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <inttypes.h>

#include "qemu_plugin.h"

#define MAX_VCPUS 8

/* What one translated block is: its size and which of the marked places
 * it starts at. Blocks are translated once and run many times. */
typedef struct {
    uint64_t n;
    int is_start, is_end, is_wait;
} block;

typedef struct {
    uint64_t all, start, end, wait_in, wait_at_end;
    int started, ended;
} vcpu;

static vcpu cpus[MAX_VCPUS];
static uint64_t mark_start, mark_end, wait_lo, wait_hi;
static char *out_path;
static int failed;

static void on_exec(unsigned int idx, void *userdata)
{
    const block *b = userdata;
    if (idx >= MAX_VCPUS) {
        failed = 1;
        return;
    }
    vcpu *c = &cpus[idx];
    if (b->is_start && !c->started) {
        c->started = 1;
        c->start = c->all;
    }
    if (b->is_end && c->started) {
        c->ended = 1;
        c->end = c->all;
        c->wait_at_end = c->wait_in;
    }
    if (b->is_wait && c->started)
        c->wait_in += b->n;
    c->all += b->n;
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    const size_t n = qemu_plugin_tb_n_insns(tb);
    if (n == 0)
        return;
    const uint64_t pc =
        qemu_plugin_insn_vaddr(qemu_plugin_tb_get_insn(tb, 0));
    block *b = calloc(1, sizeof *b); /* lives as long as QEMU */
    if (!b) {
        failed = 1;
        return;
    }
    b->n = n;
    b->is_start = pc == mark_start;
    b->is_end = pc == mark_end;
    b->is_wait = pc >= wait_lo && pc < wait_hi;
    qemu_plugin_register_vcpu_tb_exec_cb(tb, on_exec, QEMU_PLUGIN_CB_NO_REGS,
                                         b);
}

static void write_counts(FILE *f)
{
    for (unsigned i = 0; i < MAX_VCPUS; i++) {
        const vcpu *c = &cpus[i];
        if (!c->started)
            continue;
        if (!c->ended) {
            fprintf(f, "vcpu %u no-end all %" PRIu64 "\n", i, c->all);
            continue;
        }
        fprintf(f, "vcpu %u frame %" PRIu64 " wait %" PRIu64 " all %" PRIu64
                "\n", i, c->end - c->start, c->wait_at_end, c->all);
    }
}

static void on_exit(qemu_plugin_id_t id, void *userdata)
{
    (void)id, (void)userdata;
    if (failed) {
        fprintf(stderr, "vcpucount: out of memory or more than %d vCPUs; "
                "no counts written\n", MAX_VCPUS);
        return;
    }
    plugin_write("vcpucount", out_path, write_counts);
}

/* Reads the n hex digits at s into *v; 1 if they are all digits. */
static int parse_hex(const char *s, size_t n, uint64_t *v)
{
    uint64_t x = 0;
    if (n == 0 || n > 16)
        return 0;
    for (size_t i = 0; i < n; i++) {
        const char c = s[i];
        const int d = c >= '0' && c <= '9'   ? c - '0'
                      : c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                             : -1;
        if (d < 0)
            return 0;
        x = x << 4 | (uint64_t)d;
    }
    *v = x;
    return 1;
}

PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id,
                                      const qemu_info_t *info, int argc,
                                      char **argv)
{
    (void)info;
    int have = 0;
    out_path = "vcpucount.txt";
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        const char *dash = strchr(a, '-');
        int ok = 0;
        if (strncmp(a, "out=", 4) == 0 && a[4] != '\0') {
            out_path = strdup(a + 4); /* argv is QEMU's */
            if (!out_path)
                return -1;
            ok = 1;
        } else if (strncmp(a, "start=", 6) == 0) {
            ok = parse_hex(a + 6, strlen(a + 6), &mark_start);
            have |= ok;
        } else if (strncmp(a, "end=", 4) == 0) {
            ok = parse_hex(a + 4, strlen(a + 4), &mark_end);
            have |= ok << 1;
        } else if (strncmp(a, "wait=", 5) == 0 && dash) {
            ok = parse_hex(a + 5, (size_t)(dash - (a + 5)), &wait_lo) &&
                 parse_hex(dash + 1, strlen(dash + 1), &wait_hi);
            have |= ok << 2;
        }
        if (!ok) {
            fprintf(stderr, "vcpucount: bad argument '%s' (start=A end=A "
                    "wait=A-B out=FILE, addresses in hex)\n", a);
            return -1;
        }
    }
    if (have != 7) {
        fprintf(stderr, "vcpucount: start=, end= and wait= are needed\n");
        return -1;
    }
    /* Thumb: nm may give a function's address with bit 0 set. */
    mark_start &= ~(uint64_t)1;
    mark_end &= ~(uint64_t)1;
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit, NULL);
    return 0;
}
