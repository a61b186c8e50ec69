/* SPDX-License-Identifier: MIT */
/*
 * fx_cpu_rv32: the back-end for RV32 without the Zbb extension (the rv32
 * board's RV32IMAC). mul and mulh give a full 64-bit product; there is no
 * count-leading-zeros instruction.
 */
#ifndef FX_CPU_RV32_H
#define FX_CPU_RV32_H

#define FX_CPU_NAME "rv32 without zbb"
#define FX_SOFT_MUL64 0
#define FX_SOFT_CLZ 1
#define FX_SOFT_DIV 0

#endif /* FX_CPU_RV32_H */
