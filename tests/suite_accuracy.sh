#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# suite_accuracy: the quick form of `make accuracy` (docs/accuracy.md), so
# that the accuracy settings cannot rot. For each setting (RT_ACCURACY 0
# fast, 1 default, 2 precise) it builds the host renderer, renders the
# seed at 48x36 and checks its PSNR against the double reference is above
# that setting's floor; then, with the Arm tools, it counts each setting's
# Cortex-M3 instructions in QEMU and checks fast < default < precise and
# that the firmware's image is the host's, byte for byte. It also runs
# tests/test_fx.c and tests/test_vec.c built for the fast and the precise
# setting (`make test` runs them for the default).
# Ends with "N passed, N failed[, N skipped]".
set -u
cd "$(dirname "$0")/.."
MAKE=${MAKE:-make}
OUT=build/accuracy-test
W=48
H=36
SCENE=scenes/seed.scene
NAMES=(fast default precise)
# PSNR floors (dB) at 48x36. Measured: 52.8 for each setting. One pixel
# that flips at a silhouette costs about 13 dB at this size, so the floors
# leave room for that; a broken math path costs far more.
FLOORS=(33 35 35)
pass=0 fail=0 skip=0
mkdir -p "$OUT"

check() { # description, then a command that succeeds when it holds
    local what=$1
    shift
    if "$@"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAILED: $what"
    fi
}

ge() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a == "inf" || a + 0 >= b + 0) }'; }
lt() { [ "$1" -gt 0 ] && [ "$1" -lt "$2" ]; }

for acc in 0 1 2; do
    if ! $MAKE -s -j2 SANITIZE= HOST_BUILD=build/posix-acc$acc \
        RT_DEFS=-DRT_ACCURACY=$acc \
        build/posix-acc$acc/fixtrace >"$OUT/build-$acc.log" 2>&1; then
        echo "FAILED: host build, RT_ACCURACY=$acc"
        tail -n 20 "$OUT/build-$acc.log"
        fail=$((fail + 1))
    fi
done
REF=build/posix-acc1/fixtrace

# The math tests, held to each non-default setting's bounds.
for acc in 0 2; do
    for t in test_fx test_vec; do
        bin=build/posix-acc$acc/tests/$t
        if $MAKE -s SANITIZE= HOST_BUILD=build/posix-acc$acc \
            RT_DEFS=-DRT_ACCURACY=$acc "$bin" >"$OUT/$t-$acc.log" 2>&1 &&
            "$bin" >>"$OUT/$t-$acc.log" 2>&1; then
            pass=$((pass + 1))
        else
            fail=$((fail + 1))
            echo "FAILED: $t built with RT_ACCURACY=$acc"
            grep -E 'FAILED|error' "$OUT/$t-$acc.log" | head -n 10
        fi
        tail -n 1 "$OUT/$t-$acc.log" | sed "s/^/$t (${NAMES[$acc]}): /"
    done
done

psnr=()
if [ -x "$REF" ] && $REF -q --reference -W $W -H $H -o "$OUT/ref.ppm" "$SCENE"
then
    for acc in 0 1 2; do
        bin=build/posix-acc$acc/fixtrace
        p=none
        if [ -x "$bin" ] && $bin -q -W $W -H $H -o "$OUT/host-$acc.ppm" \
            "$SCENE"; then
            p=$($REF compare "$OUT/host-$acc.ppm" "$OUT/ref.ppm" |
                awk '/^PSNR:/ { print $2 }')
        fi
        psnr[acc]=$p
        echo "${NAMES[$acc]}: PSNR $p dB (floor ${FLOORS[$acc]})"
        check "${NAMES[$acc]}: PSNR $p >= ${FLOORS[$acc]} dB" \
            ge "$p" "${FLOORS[$acc]}"
    done
else
    echo "FAILED: reference render"
    fail=$((fail + 1))
fi

if ! command -v arm-none-eabi-gcc >/dev/null ||
    ! command -v qemu-system-arm >/dev/null; then
    echo "SKIPPED: instruction counts need arm-none-eabi-gcc and qemu-system-arm"
    skip=$((skip + 1))
else
    ins=()
    for acc in 0 1 2; do
        dir=$OUT/fw-an385-acc$acc
        ins[acc]=0
        if $MAKE -s qemu BOARD=an385 FW_BUILD="$dir" \
            FW_DEFS=-DRT_ACCURACY=$acc SCENE="$SCENE" WIDTH=$W HEIGHT=$H \
            SPP=1 >"$OUT/fw-$acc.log" 2>&1; then
            ins[acc]=$(awk '/^instructions /{ print $2 }' "$dir/qemu.log")
            echo "${NAMES[$acc]}: ${ins[acc]} M3 instructions"
            check "${NAMES[$acc]}: firmware image = host image" \
                cmp -s "$dir/out.ppm" "$OUT/host-$acc.ppm"
        else
            echo "FAILED: firmware RT_ACCURACY=$acc"
            tail -n 20 "$OUT/fw-$acc.log"
            fail=$((fail + 1))
        fi
    done
    check "M3 instructions: fast (${ins[0]}) < default (${ins[1]})" \
        lt "${ins[0]}" "${ins[1]}"
    check "M3 instructions: default (${ins[1]}) < precise (${ins[2]})" \
        lt "${ins[1]}" "${ins[2]}"
fi

if [ "$skip" -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ "$fail" -eq 0 ]
