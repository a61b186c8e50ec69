# SPDX-License-Identifier: MIT
# QEMU mps2-an505: a Cortex-M33. Soft-float ABI: the core has no floating
# point, and nothing may touch the FPU (it stays disabled in CPACR).
FW_PREFIX := $(ARM_PREFIX)
FW_CPU := -mcpu=cortex-m33 -mthumb -mfloat-abi=soft
FW_OPT := -O2
FW_CAPS :=
FW_LD := linker/an505.ld
FW_BOARD_SRC := port/baremetal/board_an505.c port/baremetal/startup_cortexm.c
FW_QEMU := $(FW_ARM_QEMU) -M mps2-an505
FW_ICOUNT := 7
