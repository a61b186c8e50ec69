# SPDX-License-Identifier: MIT
# Cortex-M0 code on the mps2-an385 machine (its board file, memory map and
# QEMU command): the instruction set of the smallest Cortex-M, without a
# 32x32->64 multiply.
include mk/boards/an385.mk
FW_CPU := -mcpu=cortex-m0 -mthumb
