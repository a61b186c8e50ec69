/* SPDX-License-Identifier: MIT */
/*
 * math.h for the bench-only bare-metal build of the double reference
 * renderer (bench/softref): just what port/posix/ref_render.c calls, from
 * libm.c. There is no newlib for arm-none-eabi here. With -Ddouble=float
 * (the float32 build) every prototype becomes its float version.
 */
#ifndef SOFTREF_MATH_H
#define SOFTREF_MATH_H

#define HUGE_VAL ((double)__builtin_inf())

/* Correctly rounded square root; sqrt(-x) is NaN. */
double sqrt(double x);

/* |x|, by clearing the sign bit. */
double fabs(double x);

/* |x| with the sign of y. */
double copysign(double x, double y);

/* The largest integer not above x. */
double floor(double x);

/* max(x, y); the other one if either is NaN. */
double fmax(double x, double y);

/* tan(x) from Taylor series of sin and cos after reducing x by pi. */
double tan(double x);

/* x^y: by squaring for integer y, else exp(y log x) for x > 0. */
double pow(double x, double y);

#endif /* SOFTREF_MATH_H */
