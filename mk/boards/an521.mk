# SPDX-License-Identifier: MIT
# QEMU mps2-an521: two Cortex-M33 in an SSE-200 subsystem. Core 0 boots,
# releases core 1 through the subsystem's CPUWAIT register, and both
# render rows of the frame (port/baremetal/dual.c; docs/porting.md).
# Soft-float ABI, as on the an505: nothing touches the FPU. Without the DSP
# extension: the SSE-200 builds core 0 without it (and without an FPU),
# core 1 with, and both run the same code.
FW_PREFIX := $(ARM_PREFIX)
FW_CPU := -mcpu=cortex-m33+nodsp -mthumb -mfloat-abi=soft
FW_OPT := -O2
FW_CAPS := -DFW_CORES=2
FW_LD := linker/an521.ld
FW_BOARD_SRC := port/baremetal/board_an521.c port/baremetal/startup_cortexm.c \
    port/baremetal/dual.c
FW_QEMU := $(FW_ARM_QEMU) -M mps2-an521
FW_ICOUNT := 7
