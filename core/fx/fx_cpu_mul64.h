/* SPDX-License-Identifier: MIT */
/*
 * fx_cpu_mul64: the back-end for CPUs with a 32x32->64 multiply and a
 * count-leading-zeros instruction (Cortex-M3, M4, M33, x86-64, RV32 with
 * Zbb): every operation is the plain C expression.
 */
#ifndef FX_CPU_MUL64_H
#define FX_CPU_MUL64_H

#define FX_CPU_NAME "64-bit multiply"
#define FX_SOFT_MUL64 0
#define FX_SOFT_CLZ 0
#define FX_SOFT_DIV 0

#endif /* FX_CPU_MUL64_H */
