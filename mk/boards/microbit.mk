# SPDX-License-Identifier: MIT
# BBC micro:bit (nRF51822, Cortex-M0, 16 KB of RAM for everything): small
# capacities keep rt_scene small, the row buffer holds 320 pixels, and -Os
# keeps the stack frames small (flash is no constraint). RT_MAX_WIDTH stays
# large so that any scene's `image` line parses; WIDTH must then be at most
# 320. Three direction grids (1.5 KB of stack) leave room for the parser's
# frames in text mode.
FW_PREFIX := $(ARM_PREFIX)
FW_CPU := -mcpu=cortex-m0 -mthumb
FW_OPT := -Os
FW_CAPS := -DRT_MAX_OBJECTS=16 -DRT_MAX_MATERIALS=12 -DRT_MAX_LIGHTS=2 \
    -DRT_MAX_NAME=15 -DFW_ROW_PIXELS=320 -DRT_DIR_MAX_GRIDS=3
FW_LD := linker/microbit.ld
FW_BOARD_SRC := port/baremetal/board_microbit.c \
    port/baremetal/startup_cortexm.c
FW_QEMU := $(FW_ARM_QEMU) -M microbit
FW_ICOUNT := 7
