#!/usr/bin/env bash
# The quick form of `make bench` (tools/bench.sh --quick), so the benchmark
# cannot rot: it must run and report the seed scene's instructions per
# pixel on the Cortex-M3, which must stay under a ceiling. Instruction
# counts are exact and repeatable, so this is a fair regression check (no
# wall-clock time is asserted).
set -u
cd "$(dirname "$0")/.."
# Seed at 48x36 measured 3,370 instructions/pixel; the ceiling leaves
# room for small changes and catches a large regression.
CEILING=4000
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
v=$(awk -F'|' '/^\| seed \|/{gsub(/ /, "", $3); print $3}' build/bench/quick.md 2>/dev/null)
echo "seed 48x36 on M3: ${v:-none} instructions/pixel (ceiling $CEILING)"
if [ -n "$v" ] && awk -v v="$v" -v c=$CEILING 'BEGIN{exit !(v > 0 && v <= c)}'; then
    pass=$((pass + 1))
else
    fail=$((fail + 1))
    echo "FAILED: seed costs ${v:-nothing} instructions/pixel on M3 (ceiling $CEILING)"
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
