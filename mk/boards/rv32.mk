# SPDX-License-Identifier: MIT
# QEMU's RISC-V virt machine as an RV32IMAC microcontroller.
FW_PREFIX := $(RISCV_PREFIX)
FW_CPU := -march=rv32imac -misa-spec=2.2 -mabi=ilp32 -mcmodel=medany
FW_OPT := -O2
FW_CAPS :=
FW_LD := linker/rv32.ld
FW_BOARD_SRC := port/baremetal/board_rv32.c port/baremetal/startup_rv32.c
FW_QEMU := qemu-system-riscv32 -M virt -bios none -display none \
    -monitor none -serial none -semihosting-config enable=on,target=native
FW_ICOUNT := 0
