/* SPDX-License-Identifier: MIT */
/*
 * mesh.c: the page's mesh loader (mesh.h). Its messages are the command
 * line's (port/posix/mesh_obj.c, mesh_obj_load): a file that is not there
 * is "PATH: No such file or directory"; an OBJ error is reported at its
 * own line and column, then at the scene's statement.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "heap.h"
#include "mesh.h"
#include "mesh_obj.h"

/* The files JavaScript handed over, in a list on the heap. */
typedef struct file {
    struct file *next;
    char *name, *text;
    size_t len;
} file;

static file *files;

int wasm_file_add(const char *name, size_t name_len, const char *text,
                  size_t len)
{
    file *f = malloc(sizeof *f);
    char *n = malloc(name_len + 1), *t = malloc(len ? len : 1);
    if (!f || !n || !t)
        return -1;
    memcpy(n, name, name_len);
    n[name_len] = '\0';
    memcpy(t, text, len);
    f->name = n;
    f->text = t;
    f->len = len;
    f->next = files;
    files = f;
    return 0;
}

void wasm_files_clear(void)
{
    files = NULL;
}

rt_status wasm_mesh_load(void *ctx, const char *path, size_t path_len,
                         const rt_mesh_place *pl, const struct rt_mesh **out,
                         char *msg, size_t msg_cap)
{
    const char *scene = ctx;
    const char *slash = strrchr(scene, '/');
    const size_t bl = slash && path[0] != '/' ? (size_t)(slash - scene) + 1
                                              : 0;
    char *full = malloc(bl + path_len + 1);
    if (!full) {
        snprintf(msg, msg_cap, "out of memory");
        return RT_ERR_CAPACITY;
    }
    memcpy(full, scene, bl);
    memcpy(full + bl, path, path_len);
    full[bl + path_len] = '\0';
    const file *f = files;
    while (f && strcmp(f->name, full) != 0)
        f = f->next;
    if (!f) {
        snprintf(msg, msg_cap, "%s: %s", full, "No such file or directory");
        return RT_ERR_ARG;
    }
    rt_parse_error e;
    unsigned long ignored = 0;
    rt_mesh *m = mesh_obj_parse(f->text, f->len, pl, &e, &ignored);
    if (!m) {
        wasm_message_parse_error(full, f->text, f->len, &e);
        snprintf(msg, msg_cap, "%s:%lu:%lu: %s", full, (unsigned long)e.line,
                 (unsigned long)e.col, e.msg);
        return RT_ERR_PARSE;
    }
    *out = m;
    return RT_OK;
}
