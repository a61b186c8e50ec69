/* SPDX-License-Identifier: MIT */
/*
 * fx_cpu: the one place that knows the CPU. It picks one back-end header
 * for the class of CPU being compiled for, and each back-end says, as 0/1
 * constants, which instructions that class lacks:
 *
 *   back-end         CPUs                       SOFT_MUL64  SOFT_CLZ  SOFT_DIV
 *   fx_cpu_armv6m.h  Cortex-M0, M0+, M1         1           1         1
 *   fx_cpu_rv32.h    RV32 without Zbb           0           1         0
 *   fx_cpu_mul64.h   everything else (M3, M4,   0           0         0
 *                    M33, x86-64, RV32 + Zbb)
 *
 * FX_SOFT_MUL64: no 32x32->64 multiply, so every 64-bit product would be a
 * call of a 64x64 library multiply; fx_imul64 and the dot products are
 * built from four 16x16 products instead (fx_mul64_soft.h), giving the
 * same bits. FX_SOFT_CLZ: no count-leading-zeros instruction, so
 * __builtin_clz is a library call; fx_clz32 uses a de Bruijn table.
 * FX_SOFT_DIV: no 32-bit divide instruction, so a divide is a library
 * call; the long divisions and roots (fx_math.c, fx_sqrt.c) estimate each
 * quotient digit from a reciprocal instead.
 *
 * Only core/fx reads these constants: geometry and shading call the named
 * operations (fx_math.h, fx_dot.h), whose results are the same bits on
 * every CPU. tests/suite_lint.sh checks that no other layer asks.
 */
#ifndef FX_CPU_H
#define FX_CPU_H

#if defined(__ARM_ARCH_6M__)
#include "fx_cpu_armv6m.h"
#elif defined(__riscv) && !defined(__riscv_zbb)
#include "fx_cpu_rv32.h"
#else
#include "fx_cpu_mul64.h"
#endif

#endif /* FX_CPU_H */
