#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The quick form of `make bench` (tools/bench.sh --quick), so the benchmark
# cannot rot: it must run and report every scene's instructions per pixel
# on the Cortex-M3, and each must stay under its ceiling in
# tests/bench_ceilings.txt. Instruction counts are exact and repeatable,
# so this is a fair regression check (no wall-clock time is asserted).
set -u
cd "$(dirname "$0")/.."
CEILINGS=tests/bench_ceilings.txt
if ! command -v arm-none-eabi-gcc >/dev/null || ! command -v qemu-system-arm >/dev/null; then
    echo "SKIPPED: benchmark (needs arm-none-eabi-gcc and qemu-system-arm; install gcc-arm-none-eabi qemu-system-arm)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
pass=0 fail=0
if MAKE=${MAKE:-make} bash tools/bench.sh --quick >build/bench-quick.log 2>&1; then
    pass=$((pass + 1))
else
    fail=$((fail + 1))
    echo "FAILED: tools/bench.sh --quick: $(tail -5 build/bench-quick.log)"
fi
for f in scenes/*.scene; do
    name=${f#scenes/}
    c=$(awk -v n="$name" '$1 == n {print $2}' $CEILINGS)
    v=$(awk -F'|' -v n="${name%.scene}" '{g = $2; gsub(/ /, "", g)} g == n {gsub(/ /, "", $3); print $3}' build/bench/quick.md 2>/dev/null)
    echo "$name 48x36 on M3: ${v:-none} instructions/pixel (ceiling ${c:-none})"
    if [ -n "$v" ] && [ -n "$c" ] && awk -v v="$v" -v c="$c" 'BEGIN{exit !(v > 0 && v <= c)}'; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAILED: $name costs ${v:-nothing} instructions/pixel on M3 (ceiling ${c:-missing from $CEILINGS})"
    fi
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
