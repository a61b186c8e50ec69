/* SPDX-License-Identifier: MIT */
/*
 * A small test harness: checks count instead of aborting, print
 * "file:line: expression" on failure, and th_summary() prints the one line
 * "N passed, N failed" that tests/run.sh adds up.
 */
#ifndef TEST_HARNESS_H
#define TEST_HARNESS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

extern long th_passed, th_failed;

/* Records one check; prints where it failed. Returns cond. */
int th_check(int cond, const char *file, int line, const char *expr);

/* Prints the summary line; returns the process exit status (0 if none
 * failed). */
int th_summary(void);

/* xorshift64*: deterministic test inputs from a caller-held state, so a
 * fixed seed checks the same inputs on every run. */
uint64_t th_rnd64(uint64_t *state);

/* The names of the files in scenes/ that end in .scene (run from the top),
 * sorted, at most max, each malloc'd; returns how many. */
int th_scene_names(char *names[], int max);

/* A render's rows into an image (rt_row_fn): row y at img + y stride. */
typedef struct {
    uint8_t *img;
    size_t stride;
} th_sink;
int th_to_image(void *ctx, int y, const uint8_t *row, size_t n);

#define CHECK(cond) th_check(!!(cond), __FILE__, __LINE__, #cond)

/* Integer equality; prints both values on failure. */
#define CHECK_EQ(a, b)                                                        \
    do {                                                                      \
        long long th_a_ = (long long)(a), th_b_ = (long long)(b);             \
        if (!th_check(th_a_ == th_b_, __FILE__, __LINE__, #a " == " #b))      \
            printf("    got %lld, want %lld\n", th_a_, th_b_);               \
    } while (0)

/* |a - b| <= tol for integers (ulps); prints both on failure. */
#define CHECK_NEAR(a, b, tol)                                                 \
    do {                                                                      \
        long long th_a_ = (long long)(a), th_b_ = (long long)(b);             \
        long long th_d_ = th_a_ > th_b_ ? th_a_ - th_b_ : th_b_ - th_a_;      \
        if (!th_check(th_d_ <= (long long)(tol), __FILE__, __LINE__,          \
                      #a " ~ " #b))                                           \
            printf("    got %lld, want %lld (tolerance %lld)\n", th_a_,      \
                   th_b_, (long long)(tol));                                  \
    } while (0)

#endif /* TEST_HARNESS_H */
