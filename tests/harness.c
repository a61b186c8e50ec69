/* SPDX-License-Identifier: MIT */
#include "harness.h"

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
