#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The scene fuzzer as a test (tests/fuzz/README.md): build it (libFuzzer,
# ASan, UBSan), run every seed, example scene and saved regression input
# once (one check each), then fuzz briefly from them (one check: no crash).
# Without clang's libFuzzer the part is skipped.
#
# FUZZ_SUITE_SECONDS (default 15) and FUZZ_SUITE_JOBS (default 2) size the
# short run; it works in build/fuzz/suite/, and a crash leaves its input in
# build/fuzz/suite/crashes/.
set -u
cd "$(dirname "$0")/.." || exit 2
MK=${MAKE:-make}
SECS=${FUZZ_SUITE_SECONDS:-15}
JOBS=${FUZZ_SUITE_JOBS:-2}
BIN=build/fuzz/fuzz_scene
pass=0 fail=0

summary() {
    if [ "$1" -gt 0 ]; then
        echo "$pass passed, $fail failed, $1 skipped"
    else
        echo "$pass passed, $fail failed"
    fi
}

# libFuzzer ships with clang but not always (e.g. Apple's clang): try it.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%s\n' '#include <stddef.h>' '#include <stdint.h>' \
    'int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n);' \
    'int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n)' \
    '{ (void)d; (void)n; return 0; }' >"$tmp/probe.c"
if ! command -v "${FUZZ_CC:-clang}" >/dev/null; then
    echo "SKIPPED: fuzzing (clang not found; install clang)"
    summary 1
    exit 0
fi
if ! "${FUZZ_CC:-clang}" -fsanitize=fuzzer,address,undefined "$tmp/probe.c" \
        -o "$tmp/probe" >"$tmp/probe.log" 2>&1; then
    echo "SKIPPED: fuzzing (${FUZZ_CC:-clang} cannot link -fsanitize=fuzzer:" \
        "$(head -n 1 "$tmp/probe.log"))"
    summary 1
    exit 0
fi

if ! $MK --no-print-directory -s -j2 fuzz-build; then
    echo "FAILED: make fuzz-build"
    fail=1
    summary 0
    exit 1
fi

# 1. Every seed and regression input runs clean.
out=$(FUZZ_BIN=$BIN FUZZ_DIR=build/fuzz bash tests/fuzz/fuzz.sh repro)
echo "$out"
n=$(echo "$out" | sed -nE 's/^fuzz-repro: ([0-9]+) inputs, ([0-9]+) failed$/\1/p')
f=$(echo "$out" | sed -nE 's/^fuzz-repro: ([0-9]+) inputs, ([0-9]+) failed$/\2/p')
if [ -z "$n" ]; then
    echo "FAILED: fuzz.sh repro gave no count"
    fail=$((fail + 1))
else
    pass=$((pass + n - f))
    fail=$((fail + f))
fi

# 2. A short fuzz from them finds nothing.
mkdir -p build/fuzz/suite
out=$(FUZZ_BIN=$BIN FUZZ_DIR=build/fuzz/suite FUZZ_SECONDS=$SECS \
      FUZZ_JOBS=$JOBS bash tests/fuzz/fuzz.sh run)
rc=$?
echo "$out"
if [ $rc -eq 0 ]; then
    pass=$((pass + 1))
else
    echo "FAILED: the short fuzz run crashed (inputs in build/fuzz/suite/crashes/)"
    fail=$((fail + 1))
fi

summary 0
[ $fail -eq 0 ]
