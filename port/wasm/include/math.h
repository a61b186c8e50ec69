/* SPDX-License-Identifier: MIT */
/*
 * math.h of the WebAssembly port: what the host files the page reuses
 * call (the reference renderer, the OBJ reader), from port/wasm/libm.c.
 */
#ifndef FT_WASM_MATH_H
#define FT_WASM_MATH_H

#define HUGE_VAL ((double)__builtin_inf())

/* Correctly rounded square root (f64.sqrt). */
double sqrt(double x);

/* |x|. */
double fabs(double x);

/* |x| with the sign of y. */
double copysign(double x, double y);

/* The largest integer not above x. */
double floor(double x);

/* max(x, y); the other one if either is NaN. */
double fmax(double x, double y);

/* min(x, y); the other one if either is NaN. */
double fmin(double x, double y);

/* tan(x), from bench/softref/libm.c's series. */
double tan(double x);

/* x^y, from bench/softref/libm.c. */
double pow(double x, double y);

/* sin(x) and cos(x), within an ulp or two for |x| up to a few pi. */
double sin(double x);
double cos(double x);

/* x rounded to the nearest integer, halves away from zero. */
long lround(double x);
long long llround(double x);

#endif /* FT_WASM_MATH_H */
