#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The layout of core/ (docs/architecture.md), checked by tools/core_rules.py:
# includes and calls only downward through the layer folders, no include
# cycle, no CPU test outside core/fx, no issue numbers or measurements in
# comments, no function over 100 lines, and the architecture page naming
# every file. The calls are read from the host build's objects.
set -u
cd "$(dirname "$0")/.."
HOST_BUILD=${HOST_BUILD:-build/posix}
if ! command -v python3 >/dev/null; then
    echo "SKIPPED: core layout rules (python3 missing; install python3)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
if ! command -v nm >/dev/null || [ ! -d "$HOST_BUILD/core" ]; then
    exec python3 tools/core_rules.py
fi
exec python3 tools/core_rules.py --objects "$HOST_BUILD"
