#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The randomized differential test: renders random scenes (tests/randscene.c)
# with the fixed-point core and with the double reference and checks each.
#
#   tools/random_test.sh [FIRST [COUNT]]     scenes FIRST .. FIRST+COUNT-1
#
# A scene passes when the parser refuses it with a located message
# (file:line:col: error: ...), or when it renders, renders to the same
# bytes a second time, and its image has no speckle (tests/randjudge.c): no
# pixel off by more than 64/255 from the reference where the reference's
# 3x3 neighbourhood is smooth (`fixtrace compare`'s outliers away from
# edges) unless some reference ray near it sees what the core sees: the
# reference at three times the resolution (a third of a pixel around the
# pixel's centre) and with the eye moved by 8 ulps along each axis
# (randscene --jitter), the documented tolerance near a silhouette. A
# crash or a sanitizer report (SANITIZE=1 builds stop at the first) fails
# the scene. Failing scenes are kept in build/random-fail/ to reproduce.
# JOBS (default 2) scenes run at once. Ends with "N passed, N failed".
set -u
cd "$(dirname "$0")/.."
FIRST=${1:-1}
COUNT=${2:-300}
JOBS=${JOBS:-2}
HOST_BUILD=${HOST_BUILD:-build/posix}
FT=${FIXTRACE:-$HOST_BUILD/fixtrace}
GEN=${RANDSCENE:-$HOST_BUILD/tests/randscene}
JUDGE=${RANDJUDGE:-$HOST_BUILD/tests/randjudge}
for t in "$FT" "$GEN" "$JUDGE"; do
    [ -x "$t" ] || { echo "FAILED: $t not found (make test-build)"; echo "0 passed, 1 failed"; exit 1; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
keep=build/random-fail

# One scene: prints "pass", "refused" or "fail: why" as its last line.
one() {
    local s=$1 d="$tmp/$1" w h k
    mkdir -p "$d"
    "$GEN" "$s" >"$d/s.scene"
    # shellcheck disable=SC2046
    set -- $("$GEN" "$s" --size)
    w=$1 h=$2
    if ! "$FT" -q -W "$w" -H "$h" -o "$d/f.ppm" "$d/s.scene" 2>"$d/err"; then
        if grep -qE '^[^:]+:[0-9]+:[0-9]+: error: ' "$d/err" &&
            ! grep -qiE 'sanitizer|runtime error' "$d/err"; then
            echo refused
        else
            echo "fail: render failed without a located message: $(head -c 300 "$d/err")"
        fi
        return
    fi
    if ! "$FT" -q -W "$w" -H "$h" -o "$d/g.ppm" "$d/s.scene" 2>"$d/err" ||
        ! cmp -s "$d/f.ppm" "$d/g.ppm"; then
        echo "fail: a second render differs"
        return
    fi
    if ! "$FT" -q --reference -W "$w" -H "$h" -o "$d/r.ppm" "$d/s.scene" 2>"$d/err" ||
        ! "$FT" -q --reference -W $((3 * w)) -H $((3 * h)) -o "$d/r3.ppm" "$d/s.scene" 2>>"$d/err"; then
        echo "fail: the reference does not render: $(head -c 300 "$d/err")"
        return
    fi
    local near=()
    for k in 1 2 3 4 5 6; do
        "$GEN" "$s" --jitter "$k" >"$d/j.scene"
        "$FT" -q --reference -W "$w" -H "$h" -o "$d/j$k.ppm" "$d/j.scene" 2>/dev/null &&
            near+=("$d/j$k.ppm")
    done
    if "$JUDGE" "$d/f.ppm" "$d/r.ppm" "$d/r3.ppm" "${near[@]}" >"$d/judge" 2>&1; then
        echo pass
    else
        echo "fail: $(tail -n 1 "$d/judge") (${w}x${h}; $(head -n 1 "$d/judge"))"
    fi
}

pass=0 fail=0 refused=0
last=$((FIRST + COUNT - 1))
s=$FIRST
while [ "$s" -le "$last" ]; do
    pids=() seeds=()
    for _ in $(seq 1 "$JOBS"); do
        [ "$s" -le "$last" ] || break
        one "$s" >"$tmp/out.$s" 2>&1 &
        pids+=($!) seeds+=("$s")
        s=$((s + 1))
    done
    for i in "${!pids[@]}"; do
        wait "${pids[$i]}"
        n=${seeds[$i]}
        verdict=$(tail -n 1 "$tmp/out.$n")
        case $verdict in
        pass) pass=$((pass + 1)) ;;
        refused) pass=$((pass + 1)) refused=$((refused + 1)) ;;
        *)
            fail=$((fail + 1))
            echo "FAILED: random scene $n: ${verdict#fail: }"
            mkdir -p "$keep" && cp "$tmp/$n/s.scene" "$keep/random-$n.scene"
            ;;
        esac
        rm -rf "${tmp:?}/$n" "$tmp/out.$n"
    done
done
echo "scenes $FIRST..$last: $refused refused with a located message"
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
