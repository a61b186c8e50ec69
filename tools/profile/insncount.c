/* SPDX-License-Identifier: MIT */
/* insncount: a QEMU TCG plugin for `make profile` (mk/profile.mk). It
 * counts how often each translated block starts, with one inline counter
 * a block (no helper call, so the run stays fast), and at exit writes
 * "pc count" lines, one for every guest instruction of every block that
 * ran: hex address, decimal count. A block is counted whole; one that an
 * exception leaves early (a semihosting call, a fault) overcounts its
 * tail, which tests/suite_profile.sh bounds against the firmware's own
 * instruction count.
 *
 * Build: cc -O2 -shared -fPIC -o insncount.so insncount.c
 * Use:   qemu-system-arm ... -plugin ./insncount.so,out=FILE
 *
 * The plugin API's declarations: qemu_plugin.h. */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <inttypes.h>

#include "qemu_plugin.h"

/* One translation: its start counter and the addresses of its
 * instructions. A block translated again (QEMU flushes and retranslates)
 * gets a record of its own; the report adds them up. */
typedef struct block {
    struct block *next;
    uint64_t runs;
    size_t n;
    uint64_t pc[];
} block;

static block *blocks;
static char *out_path;
static int failed;

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    const size_t n = qemu_plugin_tb_n_insns(tb);
    block *b = calloc(1, sizeof *b + n * sizeof b->pc[0]);
    if (!b) {
        failed = 1; /* reported at exit: no partial profile */
        return;
    }
    b->n = n;
    for (size_t i = 0; i < n; i++)
        b->pc[i] = qemu_plugin_insn_vaddr(qemu_plugin_tb_get_insn(tb, i));
    b->next = blocks;
    blocks = b;
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64,
                                             &b->runs, 1);
}

static void write_counts(FILE *f)
{
    for (const block *b = blocks; b; b = b->next)
        for (size_t i = 0; b->runs && i < b->n; i++)
            fprintf(f, "%" PRIx64 " %" PRIu64 "\n", b->pc[i], b->runs);
}

static void on_exit(qemu_plugin_id_t id, void *userdata)
{
    (void)id, (void)userdata;
    if (failed) {
        fprintf(stderr, "insncount: out of memory; no profile written\n");
        return;
    }
    plugin_write("insncount", out_path, write_counts);
}

PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id,
                                      const qemu_info_t *info, int argc,
                                      char **argv)
{
    (void)info;
    out_path = "insncount.txt";
    for (int i = 0; i < argc; i++) {
        if (strncmp(argv[i], "out=", 4) == 0 && argv[i][4] != '\0') {
            out_path = strdup(argv[i] + 4); /* argv is QEMU's */
            if (!out_path)
                return -1;
        } else {
            fprintf(stderr, "insncount: unknown argument '%s' (out=FILE)\n",
                    argv[i]);
            return -1;
        }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_exit, NULL);
    return 0;
}
