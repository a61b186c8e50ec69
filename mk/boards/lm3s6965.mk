# SPDX-License-Identifier: MIT
# Stellaris LM3S6965 EVB (QEMU lm3s6965evb): a Cortex-M3 with 256 KB of
# flash, 64 KB of RAM and a 128x64 4-bit OLED (SSD0323 on SSI0). Every row
# also goes to the panel (port/baremetal/board_lm3s6965.c, oled_ssd0323.c).
# QEMU runs under tools/qemu_screen.py, which takes the monitor's
# screendump when the firmware says it is done: build/lm3s6965/screen.ppm.
FW_PREFIX := $(ARM_PREFIX)
FW_CPU := -mcpu=cortex-m3 -mthumb
FW_OPT := -O2
FW_CAPS := -DFW_DISPLAY=1
FW_LD := linker/lm3s6965.ld
FW_BOARD_SRC := port/baremetal/board_lm3s6965.c \
    port/baremetal/oled_ssd0323.c port/baremetal/startup_cortexm.c
# Recursive (=): FW_BUILD is set after the board file is read.
FW_QEMU = python3 tools/qemu_screen.py $(FW_BUILD)/screen.ppm -- \
    qemu-system-arm -M lm3s6965evb -display none -serial none \
    -semihosting-config enable=on,target=native
FW_ICOUNT := 7
# The image goes to the panel and out through semihosting; the firmware
# then holds the picture for the screen capture, so a UART run would never
# end: OUTPUT=uart is refused here (the UART boards are an385, m0, an505,
# microbit and rv32).
ifeq ($(OUTPUT),uart)
$(error BOARD=lm3s6965 does not support OUTPUT=uart: its image goes to the OLED and through semihosting)
endif
