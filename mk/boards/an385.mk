# SPDX-License-Identifier: MIT
# QEMU mps2-an385: a Cortex-M3 (port/baremetal/board_an385.c).
FW_PREFIX := $(ARM_PREFIX)
FW_CPU := -mcpu=cortex-m3 -mthumb
FW_OPT := -O2
FW_CAPS :=
FW_LD := linker/an385.ld
FW_BOARD_SRC := port/baremetal/board_an385.c port/baremetal/startup_cortexm.c
FW_QEMU := $(FW_ARM_QEMU) -M mps2-an385
FW_ICOUNT := 7
