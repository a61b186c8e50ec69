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
# CORE_DIR measures another version of the core, laid out as core/ is (a
# folder a layer), e.g. the committed one:
#   mkdir -p /tmp/base && git archive HEAD core | tar -x -C /tmp/base
#   bench/fxbench/run.sh /tmp/base/core
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
# The arithmetic, the scene's prepare and the shapes' tests; the four
# small shapes' files are compiled inside their dispatch, rt_shape.c.
INC=$(for d in "$CORE"/*/; do printf -- '-I%s ' "${d%/}"; done)
SRC="$(ls "$CORE"/fx/*.c) $CORE/scene/rt_scene.c $(ls "$CORE"/shapes/*.c |
    grep -vE '/rt_(sphere|quad|box|upright)\.c$')"
for cpu in cortex-m3 cortex-m0; do
    elf=$OUT/fxbench-$cpu.elf
    # shellcheck disable=SC2086
    $CC -mcpu=$cpu -mthumb $CFLAGS $INC -Tbench/fxbench/link.ld \
        -Wl,--gc-sections -Wl,-Map="$elf.map" \
        bench/fxbench/startup.c bench/fxbench/bench.c $SRC -lgcc -o "$elf"
    echo "== $cpu ($CORE)"
    # QEMU prints semihosting SYS_WRITE0 text on stderr.
    qemu-system-arm -M mps2-an385 -display none -monitor none -serial none \
        -semihosting-config enable=on,target=native \
        -icount shift=7,align=off,sleep=off -kernel "$elf" </dev/null 2>&1
done
