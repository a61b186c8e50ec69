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
