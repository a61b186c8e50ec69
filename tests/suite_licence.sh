#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The licence is in place: LICENSE holds the MIT licence, and every source
# file git tracks (C, C++, assembler, linker scripts, shell, Python, make,
# CMake and Kconfig files, YAML manifests, Arduino sketches) names it in an SPDX-License-Identifier line within its
# first five lines.
set -u
cd "$(dirname "$0")/.."
pass=0 fail=0
if grep -q '^MIT License$' LICENSE 2>/dev/null; then
    pass=$((pass + 1))
else
    fail=$((fail + 1))
    echo "FAILED: LICENSE is missing or is not the MIT licence"
fi
if ! command -v git >/dev/null 2>&1 || ! git rev-parse --git-dir >/dev/null 2>&1; then
    echo "SKIPPED: the SPDX check needs git and a checkout"
    echo "$pass passed, $fail failed, 1 skipped"
    exit 0
fi
missing=$(git ls-files '*.c' '*.h' '*.S' '*.ld' '*.sh' '*.py' '*.mk' \
    '*.cmake' '*.cmake.in' '*.pc.in' 'Makefile' '*/CMakeLists.txt' \
    'CMakeLists.txt' '.ci/run' '*.cpp' '*.ino' '*.yml' '*Kconfig' | while read -r f; do
    [ -f "$f" ] || continue
    head -n 5 "$f" | grep -q 'SPDX-License-Identifier: MIT' || echo "$f"
done)
if [ -z "$missing" ]; then
    pass=$((pass + 1))
else
    fail=$((fail + 1))
    echo "FAILED: sources without 'SPDX-License-Identifier: MIT':" $missing
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
