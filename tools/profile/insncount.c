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
 * Debian's QEMU (7.2) runs plugins but ships no plugin header: the few
 * API calls used are declared here, as that version defines them. */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <inttypes.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PLUGIN_EXPORT __attribute__((visibility("default")))

typedef uint64_t qemu_plugin_id_t;
struct qemu_plugin_tb;
struct qemu_plugin_insn;
typedef struct qemu_info_t qemu_info_t;
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };

void qemu_plugin_register_vcpu_tb_trans_cb(
    qemu_plugin_id_t id,
    void (*cb)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb));
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id,
                                    void (*cb)(qemu_plugin_id_t id,
                                               void *userdata),
                                    void *userdata);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb,
                                              enum qemu_plugin_op op,
                                              void *ptr, uint64_t imm);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(
    const struct qemu_plugin_tb *tb, size_t idx);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);

PLUGIN_EXPORT int qemu_plugin_version = 1;

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

static void on_exit(qemu_plugin_id_t id, void *userdata)
{
    (void)id, (void)userdata;
    if (failed) {
        fprintf(stderr, "insncount: out of memory; no profile written\n");
        return;
    }
    /* Written beside the target and renamed: no half-written profile. */
    const size_t len = strlen(out_path);
    char *tmp = malloc(len + 5);
    if (!tmp)
        return;
    memcpy(tmp, out_path, len);
    memcpy(tmp + len, ".tmp", 5);
    FILE *f = fopen(tmp, "w");
    if (!f) {
        fprintf(stderr, "insncount: cannot write %s\n", tmp);
        free(tmp);
        return;
    }
    for (const block *b = blocks; b; b = b->next)
        for (size_t i = 0; b->runs && i < b->n; i++)
            fprintf(f, "%" PRIx64 " %" PRIu64 "\n", b->pc[i], b->runs);
    if (fclose(f) != 0 || rename(tmp, out_path) != 0) {
        fprintf(stderr, "insncount: cannot write %s\n", out_path);
        remove(tmp);
    }
    free(tmp);
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
