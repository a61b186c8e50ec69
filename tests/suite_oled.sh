#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The LM3S6965 board's OLED, checked from the screen: for the seed scene
# and one more, the firmware (BOARD=lm3s6965) renders at the panel's
# 128x64 under QEMU, headless; tools/qemu_screen.py (make qemu) waits for
# the firmware's "display_done" line and takes the monitor's screendump
# (512x256, each panel pixel 4x4). That picture must equal, pixel for
# pixel, the host's render of the same scene mapped by the same converter,
# rt_panel.h's RT_PANEL_GREY4 with the ordered dither
# (tools/grey4.c -s 4, drawing level L as QEMU's ssd0323 model does:
# grey 17 * L). The image sent through semihosting must equal the host's
# as on every board, the run must report its figures, and the screen must
# differ from the other scene's picture (so the check can fail).
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
HOST_BUILD=${HOST_BUILD:-build/posix}
MK=${MAKE:-make}
SEED=${OLED_TEST_SEED:-scenes/seed.scene}
OTHER=${OLED_TEST_SCENE:-scenes/primitives.scene}
BUILD=build/oled-test
TIMEOUT=${OLED_TEST_TIMEOUT:-120}
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

missing=""
for t in arm-none-eabi-gcc qemu-system-arm python3; do
    command -v "$t" >/dev/null || missing="${missing:+$missing }$t"
done
if [ -n "$missing" ]; then
    echo "SKIPPED: OLED screen test ($missing missing; install" \
        "gcc-arm-none-eabi qemu-system-arm python3)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not built (run make first)"
    echo "0 passed, 1 failed"
    exit 1
fi
if ! "$MK" -s HOST_BUILD="$HOST_BUILD" grey4 >/dev/null; then
    echo "FAILED: make grey4"
    echo "0 passed, 1 failed"
    exit 1
fi
GREY4=$HOST_BUILD/grey4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Pixels (of 512x256) in which two P6 files differ, and grey levels in the
# first; "error" if either is not a 512x256 P6.
compare() {
    python3 - "$1" "$2" <<'PY'
import sys
def load(p):
    d = open(p, "rb").read()
    head = b"P6\n512 256\n255\n"
    if not d.startswith(head) or len(d) != len(head) + 512 * 256 * 3:
        return None
    return d[len(head):]
a, b = load(sys.argv[1]), load(sys.argv[2])
if a is None or b is None:
    print("error")
else:
    diff = sum(1 for i in range(0, len(a), 3) if a[i:i + 3] != b[i:i + 3])
    print(diff, len(set(a[0::3])))
PY
}

for scene in "$SEED" "$OTHER"; do
    name=$(basename "$scene" .scene)
    "$FT" -q -W 128 -H 64 -o "$tmp/$name.ppm" "$scene" &&
        "$GREY4" -s 4 "$tmp/$name.ppm" "$tmp/$name.expect.ppm" ||
        { bad "$name: host render or grey4 failed"; continue; }
    args=(BOARD=lm3s6965 FW_BUILD="$BUILD" SCENE="$scene" WIDTH=128 HEIGHT=64)
    if ! "$MK" -s firmware "${args[@]}" >"$tmp/build.log" 2>&1; then
        bad "$name: firmware build failed: $(head -c 600 "$tmp/build.log")"
        continue
    fi
    rc=0
    "$MK" -s qemu "${args[@]}" QEMU_TIMEOUT="$TIMEOUT" >"$tmp/run.log" 2>&1 ||
        rc=$?
    if [ $rc -ne 0 ] || [ ! -f "$BUILD/screen.ppm" ]; then
        bad "$name: run failed (status $rc) or no screendump:" \
            "$(grep -v '^  ' "$tmp/run.log" | head -c 600)"
        continue
    fi
    cp "$BUILD/screen.ppm" "$tmp/$name.screen.ppm"
    if grep -q '^display_done$' "$tmp/run.log" &&
        grep -q '^instructions [0-9]' "$tmp/run.log" &&
        grep -q '^stack_bytes [0-9]' "$tmp/run.log"; then
        ok
    else
        bad "$name: the run did not report its figures and display_done"
    fi
    # It says where the screen went, and QEMU's idle notes stay out.
    grep -q "^wrote $BUILD/screen.ppm" "$tmp/run.log" && ok ||
        bad "$name: the run does not say it wrote $BUILD/screen.ppm"
    if grep -qE 'Timer with period zero|icount sleep disabled' "$tmp/run.log"; then
        bad "$name: the run prints QEMU's timer warnings"
    else
        ok
    fi
    cmp -s "$BUILD/out.ppm" "$tmp/$name.ppm" && ok ||
        bad "$name: the image sent through semihosting differs from the" \
            "host's ($(cmp "$BUILD/out.ppm" "$tmp/$name.ppm" 2>&1 | head -n 1))"
    set -- $(compare "$tmp/$name.screen.ppm" "$tmp/$name.expect.ppm")
    if [ "${1:-error}" = error ]; then
        bad "$name: the screendump is not a 512x256 P6"
    elif [ "$1" -eq 0 ] && [ "$2" -ge 8 ]; then
        ok
        echo "$name: screen = host, 512x256, $2 grey levels;" \
            "$(grep -E '^(instructions|stack_bytes) ' "$tmp/run.log" |
                tr '\n' ' ')"
    else
        bad "$name: the screen differs from the host's picture in $1 of" \
            "131072 pixels ($2 grey levels shown)"
    fi
done

# The comparison can fail: one scene's screen is not the other's picture.
s=$(basename "$SEED" .scene) o=$(basename "$OTHER" .scene)
if [ -f "$tmp/$s.screen.ppm" ] && [ -f "$tmp/$o.expect.ppm" ]; then
    set -- $(compare "$tmp/$s.screen.ppm" "$tmp/$o.expect.ppm")
    [ "${1:-0}" != error ] && [ "${1:-0}" -gt 0 ] && ok ||
        bad "$s's screen equals $o's picture: the check cannot tell them apart"
fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
