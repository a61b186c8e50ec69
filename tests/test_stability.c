/* SPDX-License-Identifier: MIT */
/*
 * The numerical-stability suite: a table of named hard cases, each a tiny
 * scene or a direct call into the core, with its expected behaviour in the
 * comment above it, in tests/stability/ by topic (geometry.c, scenes.c,
 * effects.c, textures.c, views.c, optics.c; the helpers in helpers.c, the
 * list of cases in stability.h).
 * This file is the runner. Each case prints "PASS  name" or "FAIL  name";
 * a failed check also prints file:line. docs/stability-cases.md lists the
 * cases and the choices they document.
 *
 * Properties checked across the suite (helpers.c):
 * - speckles: isolated pixels that differ from all 8 neighbours and from the
 *   double reference (ref_render_rows) by more than 64/255, where the
 *   reference is locally smooth (see count_speckles2);
 * - acne: pixels darker than the reference by more than 64/255 where the
 *   reference is not at an edge (a wrongly shadowed lit surface);
 * - determinism: the same bytes twice, and the same bytes in row bands;
 * - no wrap-around: huge values saturate, colours never wrap to dark.
 *
 * Usage: test_stability [substring] runs only the cases whose name
 * contains the substring. STAB_VERBOSE=1 prints the metrics of every
 * render comparison; STAB_DUMP=dir writes the fixed and reference images;
 * STAB_NOFORK=1 runs the cases in-process (each normally runs in a child,
 * so that a crash fails only its own case).
 */
#include "stability/stability.h"

/* ==== The table ========================================================== */

typedef struct {
    const char *name;
    void (*run)(void);
} stab_case;

static const stab_case cases[] = {
#define CASE(n) { #n, case_##n },
    STAB_CASES(CASE)
#undef CASE
};

/* Runs one case in a child process, so that a crash (a core defect this
 * suite exists to find) fails that case and the others still run. The
 * child's check counts come back through a pipe. STAB_NOFORK=1 runs the
 * cases in-process (for a debugger). */
static int run_case(const stab_case *c, int nofork)
{
    long before = th_failed;
    if (nofork) {
        c->run();
        return th_failed == before;
    }
    int fd[2];
    long counts[2] = { 0, 0 };
    fflush(stdout);
    if (pipe(fd) != 0) {
        c->run();
        return th_failed == before;
    }
    pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        th_passed = th_failed = 0;
        c->run();
        fflush(stdout);
        counts[0] = th_passed;
        counts[1] = th_failed;
        ssize_t w = write(fd[1], counts, sizeof counts);
        _exit(w == (ssize_t)sizeof counts ? 0 : 3);
    }
    close(fd[1]);
    ssize_t got = pid > 0 ? read(fd[0], counts, sizeof counts) : -1;
    close(fd[0]);
    int status = 0;
    if (pid > 0)
        waitpid(pid, &status, 0);
    if (got != (ssize_t)sizeof counts || !WIFEXITED(status) ||
        WEXITSTATUS(status) != 0) {
        th_check(0, __FILE__, __LINE__, "the case ran to its end");
        if (WIFSIGNALED(status))
            printf("    crashed with signal %d (%s)\n", WTERMSIG(status),
                   strsignal(WTERMSIG(status)));
        else
            printf("    exit status %d\n", WEXITSTATUS(status));
        return 0;
    }
    th_passed += counts[0];
    th_failed += counts[1];
    return counts[1] == 0;
}

int main(int argc, char **argv)
{
    const char *only = argc > 1 ? argv[1] : NULL;
    int n_cases = (int)(sizeof cases / sizeof cases[0]), failed = 0, run = 0;
    int nofork = getenv("STAB_NOFORK") != NULL;
    struct timespec t_start, t0, t1;
    verbose = getenv("STAB_VERBOSE") != NULL;
    dump_dir = getenv("STAB_DUMP");
    clock_gettime(CLOCK_MONOTONIC, &t_start);
    for (int i = 0; i < n_cases; i++) {
        if (only && !strstr(cases[i].name, only))
            continue;
        case_name = cases[i].name;
        dump_seq = 0;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        int ok = run_case(&cases[i], nofork);
        clock_gettime(CLOCK_MONOTONIC, &t1);
        double ms = 1e3 * (double)(t1.tv_sec - t0.tv_sec) +
                    1e-6 * (double)(t1.tv_nsec - t0.tv_nsec);
        failed += !ok;
        run++;
        printf("%s  %-34s %8.1f ms\n", ok ? "PASS" : "FAIL", cases[i].name,
               ms);
        fflush(stdout);
    }
    double secs = (double)(t1.tv_sec - t_start.tv_sec) +
                  1e-9 * (double)(t1.tv_nsec - t_start.tv_nsec);
    printf("%d cases, %d failed, %.1f s\n", run, failed, run ? secs : 0.0);
    return th_summary();
}

