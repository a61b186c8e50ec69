/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include "harness.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>

long th_passed, th_failed;

int th_check(int cond, const char *file, int line, const char *expr)
{
    if (cond) {
        th_passed++;
    } else {
        th_failed++;
        printf("%s:%d: FAILED: %s\n", file, line, expr);
    }
    return cond;
}

int th_summary(void)
{
    printf("%ld passed, %ld failed\n", th_passed, th_failed);
    fflush(stdout);
    return th_failed ? 1 : 0;
}

uint64_t th_rnd64(uint64_t *state)
{
    uint64_t x = *state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    *state = x;
    return x * 0x2545F4914F6CDD1DULL;
}

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

int th_scene_names(char *names[], int max)
{
    int count = 0;
    DIR *d = opendir("scenes");
    struct dirent *e;
    while (d && (e = readdir(d)) != NULL && count < max) {
        size_t n = strlen(e->d_name);
        if (n > 6 && strcmp(e->d_name + n - 6, ".scene") == 0)
            names[count++] = strdup(e->d_name);
    }
    if (d)
        closedir(d);
    qsort(names, (size_t)count, sizeof names[0], cmp_names);
    return count;
}

int th_to_image(void *ctx, int y, const uint8_t *row, size_t n)
{
    th_sink *s = ctx;
    memcpy(s->img + (size_t)y * s->stride, row, n);
    return 0;
}
