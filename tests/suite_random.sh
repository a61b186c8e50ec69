#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The randomized differential test in make test: random scenes 1 ..
# RANDOM_COUNT (500 by default, small images, two at a time) from
# tests/randscene.c, each rendered by the fixed-point core twice and by
# the reference, judged by tests/randjudge.c (tools/random_test.sh has the
# rules). A scene the parser refuses with a located message passes; a
# crash, a sanitizer report, two renders that differ or a speckle fails
# it. `make random-test` runs many more (RANDOM_FIRST, RANDOM_COUNT).
# Each scene counts once; ends with "N passed, N failed".
set -u
cd "$(dirname "$0")/.."
exec bash tools/random_test.sh 1 "${RANDOM_COUNT:-500}"
