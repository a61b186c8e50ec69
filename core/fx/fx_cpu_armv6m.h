/* SPDX-License-Identifier: MIT */
/*
 * fx_cpu_armv6m: the back-end for ARMv6-M (Cortex-M0, M0+, M1). Its
 * multiply gives the low 32 bits of a product only, and it has neither
 * CLZ nor a divide instruction: 64-bit products, leading-zero counts and
 * quotients come from 32-bit pieces.
 */
#ifndef FX_CPU_ARMV6M_H
#define FX_CPU_ARMV6M_H

#define FX_CPU_NAME "armv6-m"
#define FX_SOFT_MUL64 1
#define FX_SOFT_CLZ 1
#define FX_SOFT_DIV 1

#endif /* FX_CPU_ARMV6M_H */
