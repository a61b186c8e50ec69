#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# fxbench: instructions per call of the fx_math / fx_vec operations and of
# each intersection routine (rt_intersect per shape kind), on
# Cortex-M3 and Cortex-M0 code, run on QEMU's mps2-an385 with
# -icount shift=7 (deterministic: same binary, same count). Not part of
# the main build.
#
#   bench/fxbench/run.sh [CORE_DIR]     (default: core)
#
# CORE_DIR measures another version of the three math sources, e.g. the
# committed one:
#   mkdir -p /tmp/base && for f in fx_math.h fx_math.c fx_sqrt.c fx_vec.h \
#     fx_vec.c; do git show HEAD:core/$f > /tmp/base/$f; done
#   bench/fxbench/run.sh /tmp/base
# Output goes to build/fxbench/<basename of CORE_DIR>/.
set -eu
cd "$(dirname "$0")/../.."
CORE=${1:-core}
OUT=build/fxbench/$(basename "$CORE")
mkdir -p "$OUT"
CC=${CC:-arm-none-eabi-gcc}
CFLAGS="-std=gnu99 -O2 -ffreestanding -nostdlib -mgeneral-regs-only
        -Wall -Wextra -Werror -fno-tree-loop-distribute-patterns
        -ffunction-sections -fdata-sections"
for cpu in cortex-m3 cortex-m0; do
    elf=$OUT/fxbench-$cpu.elf
    $CC -mcpu=$cpu -mthumb $CFLAGS -I"$CORE" -Tbench/fxbench/link.ld \
        -Wl,--gc-sections -Wl,-Map="$elf.map" \
        bench/fxbench/startup.c bench/fxbench/bench.c \
        "$CORE"/fx_math.c "$CORE"/fx_sqrt.c "$CORE"/fx_vec.c \
        "$CORE"/fx_dir.c "$CORE"/fx_rsqrt.c \
        "$CORE"/rt_intersect.c "$CORE"/rt_scene.c "$CORE"/rt_mesh.c \
        "$CORE"/rt_mesh_check.c "$CORE"/rt_normal.c "$CORE"/rt_mesh_normal.c \
        -lgcc -o "$elf"
    echo "== $cpu ($CORE)"
    # QEMU prints semihosting SYS_WRITE0 text on stderr.
    qemu-system-arm -M mps2-an385 -display none -monitor none -serial none \
        -semihosting-config enable=on,target=native \
        -icount shift=7,align=off,sleep=off -kernel "$elf" </dev/null 2>&1
done
