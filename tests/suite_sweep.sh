#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# suite_sweep: the short form of `make accuracy-sweep` (docs/accuracy.md,
# "Over many sizes"). Every scene at three odd sizes, 1 spp, rendered by
# the fixed-point core, the float32 reference and the double reference;
# a scene whose fixed render has more flips (pixels off by more than
# 64/255 against the double) than tests/accuracy_ceilings.txt records, or
# whose worst PSNR falls more than 1 dB below it, fails. The sweep writes
# that file; after a change that removes flips, run it again to lower the
# ceilings. The float32 reference's own flips print beside, for scale.
# Ends with "N passed, N failed".
set -u
cd "$(dirname "$0")/.."
if ! command -v python3 >/dev/null; then
    echo "SKIPPED: the sweep needs python3"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
FIXTRACE=${FIXTRACE:-build/posix/fixtrace} exec python3 tools/accuracy_sweep.py check
