#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The randomized differential test: renders random scenes (tests/randscene.c)
# with the fixed-point core and with the double reference and checks each.
#
#   tools/random_test.sh [FIRST [COUNT]]     scenes FIRST .. FIRST+COUNT-1
#
# A scene passes when the parser refuses it with a located message
# (file:line:col: error: ...), or when it renders, renders to the same
# bytes a second time, and its image has no speckle: no pixel off by more
# than 64/255 from the reference where the reference's 3x3 neighbourhood
# is smooth (`fixtrace compare`, "away from edges"). A crash or a sanitizer
# report (SANITIZE=1 builds stop at the first) fails the scene. Failing
# scenes are kept in build/random-fail/ to reproduce. Ends with
# "N passed, N failed".
set -u
cd "$(dirname "$0")/.."
FIRST=${1:-1}
COUNT=${2:-300}
HOST_BUILD=${HOST_BUILD:-build/posix}
FT=${FIXTRACE:-$HOST_BUILD/fixtrace}
GEN=${RANDSCENE:-$HOST_BUILD/tests/randscene}
for t in "$FT" "$GEN"; do
    [ -x "$t" ] || { echo "FAILED: $t not found (make test-build)"; echo "0 passed, 1 failed"; exit 1; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
keep=build/random-fail
pass=0 fail=0 refused=0
fail_scene() {
    fail=$((fail + 1))
    echo "FAILED: random scene $1: $2"
    mkdir -p "$keep" && cp "$tmp/s.scene" "$keep/random-$1.scene"
}
for s in $(seq "$FIRST" $((FIRST + COUNT - 1))); do
    "$GEN" "$s" >"$tmp/s.scene"
    # shellcheck disable=SC2046
    set -- $("$GEN" "$s" --size)
    w=$1 h=$2
    if ! "$FT" -q -W "$w" -H "$h" -o "$tmp/f.ppm" "$tmp/s.scene" 2>"$tmp/err"; then
        if grep -qE '^[^:]+:[0-9]+:[0-9]+: error: ' "$tmp/err" &&
            ! grep -qiE 'sanitizer|runtime error' "$tmp/err"; then
            refused=$((refused + 1))
            pass=$((pass + 1))
        else
            fail_scene "$s" "render failed without a located message: $(head -c 300 "$tmp/err")"
        fi
        continue
    fi
    if ! "$FT" -q -W "$w" -H "$h" -o "$tmp/g.ppm" "$tmp/s.scene" 2>"$tmp/err" ||
        ! cmp -s "$tmp/f.ppm" "$tmp/g.ppm"; then
        fail_scene "$s" "a second render differs"
        continue
    fi
    if ! "$FT" -q --reference -W "$w" -H "$h" -o "$tmp/r.ppm" "$tmp/s.scene" 2>"$tmp/err"; then
        fail_scene "$s" "the reference does not render: $(head -c 300 "$tmp/err")"
        continue
    fi
    sp=$("$FT" compare "$tmp/f.ppm" "$tmp/r.ppm" | awk '/^outliers/ {print $6}')
    if [ "$sp" = 0 ]; then
        pass=$((pass + 1))
    else
        fail_scene "$s" "${sp:-?} speckles (${w}x${h}; fixtrace compare)"
    fi
done
echo "scenes $FIRST..$((FIRST + COUNT - 1)): $refused refused with a located message"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
