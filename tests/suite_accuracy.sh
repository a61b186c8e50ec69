#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# suite_accuracy: the quick form of `make accuracy` (docs/accuracy.md), so
# that the precision setting cannot rot. For unit vectors of 16 and of 30
# (the default) fraction bits (RT_UNIT_BITS) it builds the host renderer,
# renders the seed at 48x36 and checks its PSNR against the double
# reference is above that setting's floor, and that 30 bits beat 16; then,
# with the Arm tools, it counts each setting's Cortex-M3 instructions in
# QEMU and checks that the firmware's image is the host's, byte for byte.
# It also runs tests/test_fx.c and tests/test_vec.c built for 16 and 20
# bits (`make test` runs them for the default).
# Ends with "N passed, N failed[, N skipped]".
set -u
cd "$(dirname "$0")/.."
MAKE=${MAKE:-make}
OUT=build/accuracy-test
W=48
H=36
SCENE=scenes/seed.scene
BITS="16 30"
# PSNR floors (dB) at 48x36, measured: 16 bits 53.57, 30 bits 72.72. One
# pixel that flips at a silhouette costs about 13 dB at this size: the
# floors leave room for one such flip, a broken path costs far more.
declare -A FLOOR=([16]=35 [30]=55)
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
gt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a == "inf" || a + 0 > b + 0) }'; }

# The host builds unoptimised (HOST_OPT, here and below): compiled in half
# the time, and no figure here depends on the optimisation.
for u in $BITS 20; do
    if ! $MAKE -s -j2 SANITIZE= HOST_OPT="-O0 -g0" HOST_BUILD=build/posix-u$u \
        RT_DEFS=-DRT_UNIT_BITS=$u \
        build/posix-u$u/fixtrace >"$OUT/build-$u.log" 2>&1; then
        echo "FAILED: host build, RT_UNIT_BITS=$u"
        tail -n 20 "$OUT/build-$u.log"
        fail=$((fail + 1))
    fi
done
REF=build/posix-u30/fixtrace

# The math tests hold for any precision of unit vectors.
for u in 16 20; do
    for t in test_fx test_vec; do
        bin=build/posix-u$u/tests/$t
        if $MAKE -s SANITIZE= HOST_OPT="-O0 -g0" HOST_BUILD=build/posix-u$u \
            RT_DEFS=-DRT_UNIT_BITS=$u "$bin" >"$OUT/$t-$u.log" 2>&1 &&
            "$bin" >>"$OUT/$t-$u.log" 2>&1; then
            pass=$((pass + 1))
        else
            fail=$((fail + 1))
            echo "FAILED: $t built with RT_UNIT_BITS=$u"
            grep -E 'FAILED|error' "$OUT/$t-$u.log" | head -n 10
        fi
        tail -n 1 "$OUT/$t-$u.log" | sed "s/^/$t ($u bits): /"
    done
done

declare -A psnr
if [ -x "$REF" ] && $REF -q --reference -W $W -H $H -o "$OUT/ref.ppm" "$SCENE"
then
    for u in $BITS; do
        bin=build/posix-u$u/fixtrace
        p=none
        if [ -x "$bin" ] && $bin -q -W $W -H $H -o "$OUT/host-$u.ppm" \
            "$SCENE"; then
            p=$($REF compare "$OUT/host-$u.ppm" "$OUT/ref.ppm" |
                awk '/^PSNR:/ { print $2 }')
        fi
        psnr[$u]=$p
        echo "$u unit bits: PSNR $p dB (floor ${FLOOR[$u]})"
        check "$u unit bits: PSNR $p >= ${FLOOR[$u]} dB" ge "$p" "${FLOOR[$u]}"
    done
    check "30 unit bits (${psnr[30]} dB) beat 16 (${psnr[16]} dB)" \
        gt "${psnr[30]}" "${psnr[16]}"
else
    echo "FAILED: reference render"
    fail=$((fail + 1))
fi

if ! command -v arm-none-eabi-gcc >/dev/null ||
    ! command -v qemu-system-arm >/dev/null; then
    echo "SKIPPED: instruction counts need arm-none-eabi-gcc and qemu-system-arm"
    skip=$((skip + 1))
else
    for u in $BITS; do
        dir=$OUT/fw-an385-u$u
        if $MAKE -s qemu BOARD=an385 FW_BUILD="$dir" \
            FW_DEFS=-DRT_UNIT_BITS=$u SCENE="$SCENE" WIDTH=$W HEIGHT=$H \
            SPP=1 >"$OUT/fw-$u.log" 2>&1; then
            echo "$u unit bits: $(awk '/^instructions /{ print $2 }' \
                "$dir/qemu.log") M3 instructions"
            check "$u unit bits: firmware image = host image" \
                cmp -s "$dir/out.ppm" "$OUT/host-$u.ppm"
        else
            echo "FAILED: firmware RT_UNIT_BITS=$u"
            tail -n 20 "$OUT/fw-$u.log"
            fail=$((fail + 1))
        fi
    done
fi

if [ "$skip" -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ "$fail" -eq 0 ]
