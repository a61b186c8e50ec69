# Cortex-M0 code on the mps2-an385 machine (its board file and memory map):
# the instruction set of the smallest Cortex-M, without a 32x32->64
# multiply.
FW_PREFIX := $(ARM_PREFIX)
FW_CPU := -mcpu=cortex-m0 -mthumb
FW_OPT := -O2
FW_CAPS :=
FW_LD := linker/an385.ld
FW_BOARD_SRC := port/baremetal/board_an385.c port/baremetal/startup_cortexm.c
FW_QEMU := $(FW_ARM_QEMU) -M mps2-an385
FW_ICOUNT := 7
