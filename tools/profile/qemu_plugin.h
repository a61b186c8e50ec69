/* SPDX-License-Identifier: MIT */
/* qemu_plugin.h: what `make profile`'s TCG plugins (insncount.c,
 * callstack.c) share: the few QEMU plugin API calls they use, declared
 * as QEMU 7.2 defines them (Debian's QEMU runs plugins but ships no
 * plugin header), and the writing of a plugin's output file. Each plugin
 * is one shared object built from one .c file that includes this once. */
#ifndef QEMU_PLUGIN_H
#define QEMU_PLUGIN_H

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
enum qemu_plugin_cb_flags { QEMU_PLUGIN_CB_NO_REGS };

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
void qemu_plugin_register_vcpu_tb_exec_cb(
    struct qemu_plugin_tb *tb,
    void (*cb)(unsigned int vcpu_index, void *userdata),
    enum qemu_plugin_cb_flags flags, void *userdata);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(
    const struct qemu_plugin_tb *tb, size_t idx);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);
const void *qemu_plugin_insn_data(const struct qemu_plugin_insn *insn);
size_t qemu_plugin_insn_size(const struct qemu_plugin_insn *insn);

PLUGIN_EXPORT int qemu_plugin_version = 1;

/* Writes path by write(f), through path.tmp renamed into place: no
 * half-written output. Failures go to stderr, prefixed by name. */
static inline void plugin_write(const char *name, const char *path,
                                void (*write)(FILE *f))
{
    const size_t len = strlen(path);
    char *tmp = malloc(len + 5);
    if (!tmp) {
        fprintf(stderr, "%s: out of memory; no profile written\n", name);
        return;
    }
    memcpy(tmp, path, len);
    memcpy(tmp + len, ".tmp", 5);
    FILE *f = fopen(tmp, "w");
    if (!f) {
        fprintf(stderr, "%s: cannot write %s\n", name, tmp);
        free(tmp);
        return;
    }
    write(f);
    if (fclose(f) != 0 || rename(tmp, path) != 0) {
        fprintf(stderr, "%s: cannot write %s\n", name, path);
        remove(tmp);
    }
    free(tmp);
}

#endif /* QEMU_PLUGIN_H */
