#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The numerical-stability suite and the shape tests under UndefinedBehavior
# and Address sanitizers with recovery off, as part of every `make test`
# (make SANITIZE=1 test runs everything that way): signed overflow, shifts
# of negative values and out-of-bounds reads in the core fail here.
set -u
cd "$(dirname "$0")/.."
MAKE=${MAKE:-make}
SAN=build/posix-san
pass=0 fail=0
if [ "${SANITIZE:-}" = 1 ]; then
    echo "SANITIZE=1: the whole suite already runs sanitized"
    echo "1 passed, 0 failed"
    exit 0
fi
if ! $MAKE -s SANITIZE=1 HOST_BUILD=$SAN $SAN/tests/test_stability \
        $SAN/tests/test_shapes >build/ubsan-build.log 2>&1; then
    echo "FAILED: cannot build the sanitized tests: $(tail -5 build/ubsan-build.log)"
    echo "0 passed, 1 failed"
    exit 1
fi
for t in test_stability test_shapes; do
    if UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 "$SAN/tests/$t" \
            >"build/ubsan-$t.log" 2>&1; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAILED: $t under UBSan/ASan: $(grep -m3 -E 'runtime error|ERROR|FAILED' "build/ubsan-$t.log")"
    fi
    tail -1 "build/ubsan-$t.log" | sed "s/^/$t (sanitized): /"
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
