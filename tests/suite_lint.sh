#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Static analysis as a test: `make lint` (mk/lint.mk, docs/static-analysis.md)
# runs cppcheck and clang-tidy over core/ and the ports; each clean run is a
# pass, each run with a finding a failure. Skipped when a tool is missing.
set -u
cd "$(dirname "$0")/.." || exit 2
MK=${MAKE:-make}
missing=""
for t in "${CPPCHECK:-cppcheck}" "${CLANG_TIDY:-clang-tidy}"; do
    command -v "$t" >/dev/null || missing="$missing $t"
done
if [ -n "$missing" ]; then
    echo "SKIPPED: static analysis (not found:$missing; install cppcheck" \
        "and clang-tidy)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi

out=$($MK --no-print-directory -s lint 2>&1)
rc=$?
echo "$out"
clean=$(echo "$out" | sed -nE 's/^lint: ([0-9]+) runs clean.*/\1/p')
bad=$(echo "$out" | sed -nE 's/^lint: ([0-9]+) of ([0-9]+) runs failed$/\1 \2/p')
if [ -n "$clean" ] && [ $rc -eq 0 ]; then
    echo "$clean passed, 0 failed"
elif [ -n "$bad" ]; then
    set -- $bad # two numbers
    echo "FAILED: static analysis findings in $1 of $2 runs (above)"
    echo "$(($2 - $1)) passed, $1 failed"
    exit 1
else
    echo "FAILED: make lint (exit status $rc) gave no summary"
    echo "0 passed, 1 failed"
    exit 1
fi
