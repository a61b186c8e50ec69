#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Both cores of the two-core board (an521, port/baremetal/dual.c), under
# QEMU with the per-core counting plugin (make dual-count):
# - every scene in scenes/, at 32x24, 1 spp, gives exactly the host's
#   bytes (the scenes as text parsed on the device, PRUNE=0, one build;
#   scenes with meshes, which need tables, built for the scene);
# - the rows are shared evenly: the busier core does at most BALANCE_MAX
#   of the two cores' work (instructions outside the wait functions);
#   a deliberately unbalanced hand-out (FW_HANDOUT=2, core 1 every fourth
#   row) is caught by that same check;
# - a second core that never starts (FW_CORE1_START=0) ends the run with
#   exit status 6 and a message naming core 1, not a hang.
# Skipped without arm-none-eabi-gcc or a qemu-system-arm with mps2-an521.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
MK=${MAKE:-make}
W=32 H=24
# Work is even when each core does half; the start-up of each core (its
# tracer's tables) weighs more at this small size than at 320x240.
BALANCE_MAX=0.6
B=build/dual-test
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

for t in arm-none-eabi-gcc qemu-system-arm; do
    command -v $t >/dev/null || {
        echo "SKIPPED: $t missing (apt-get install --no-install-recommends" \
            "gcc-arm-none-eabi qemu-system-arm)"
        echo "0 passed, 0 failed, 1 skipped"; exit 0; }
done
if ! qemu-system-arm -M help 2>/dev/null | grep -q '^mps2-an521 '; then
    echo "SKIPPED: this qemu-system-arm has no mps2-an521 machine"
    echo "0 passed, 0 failed, 1 skipped"; exit 0
fi
[ -x "$FT" ] || { echo "FAILED: $FT not built (run make first)"
    echo "0 passed, 1 failed"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p $B

# count NAME MAKE-ARGS...: make dual-count into $B/NAME, log in
# $tmp/NAME.log; its exit status.
count() {
    local name=$1
    shift
    "$MK" -s dual-count BOARD=an521 WIDTH=$W HEIGHT=$H SPP=1 \
        FW_BUILD="$B/$name" QEMU_TIMEOUT=60 "$@" >"$tmp/$name.log" 2>&1
}
fig() { awk -v n="$2" '$1 == n { v = $2 } END { print v }' "$1"; }
# share LOG: the busier core's share of the two cores' work.
share() {
    awk '$1 ~ /^core[01]_frame$/ { f[$1] = $2 } $1 ~ /^core[01]_wait$/ { w[$1] = $2 }
        END { b0 = f["core0_frame"] - w["core0_wait"]
              b1 = f["core1_frame"] - w["core1_wait"]
              if (b0 + b1 <= 0) { print "none"; exit }
              m = f["core0_frame"]; if (f["core1_frame"] > m) m = f["core1_frame"]
              printf "%.3f", m / (b0 + b1) }' "$1"
}
over() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'; }

for s in scenes/*.scene; do
    n=$(basename "$s" .scene)
    if ! "$FT" -q -W $W -H $H -s 1 -o "$tmp/$n.ppm" "$s" 2>"$tmp/host.err"; then
        bad "host render of $s: $(cat "$tmp/host.err")"; continue
    fi
    if grep -q '^mesh ' "$s"; then
        count "$n" SCENE="$s"
    else
        count "$n" SCENE="$s" PRUNE=0 FW_BUILD="$B/text"
    fi
    rc=$?
    log=$tmp/$n.log
    if [ $rc -ne 0 ]; then
        bad "$n: make dual-count exit status $rc: $(grep -v '^  ' "$log" |
            head -c 400)"; continue
    fi
    dir=$B/$n; grep -q '^mesh ' "$s" || dir=$B/text
    cmp -s "$dir/out.ppm" "$tmp/$n.ppm" && ok ||
        bad "$n: the two-core image differs from the host's" \
            "($(cmp "$dir/out.ppm" "$tmp/$n.ppm" 2>&1 | head -n 1))"
    r=$(share "$log")
    if [ "$r" = none ] || over "$r" $BALANCE_MAX; then
        bad "$n: the busier core does $r of the work (at most $BALANCE_MAX)"
    else
        ok
    fi
    rows1=$(fig "$log" core1_rows)
    [ "${rows1:-0}" -gt 0 ] && ok || bad "$n: core 1 rendered no row"
    echo "$n: share $r, core 1 rows $rows1, core 1 stack" \
        "$(fig "$log" stack_bytes_core1)"
done

# The unbalanced hand-out: same bytes, and the balance check fails.
s=scenes/seed.scene
"$FT" -q -W $W -H $H -s 1 -o "$tmp/seed.ppm" $s 2>/dev/null
if count skew SCENE=$s PRUNE=0 FW_DEFS=-DFW_HANDOUT=2; then
    cmp -s "$B/skew/out.ppm" "$tmp/seed.ppm" && ok ||
        bad "skewed hand-out: the image differs from the host's"
    r=$(share "$tmp/skew.log")
    if [ "$r" != none ] && over "$r" $BALANCE_MAX; then
        ok; echo "skewed hand-out: share $r, caught"
    else
        bad "skewed hand-out: share $r passes the balance check" \
            "(at most $BALANCE_MAX), which cannot then tell"
    fi
else
    bad "skewed hand-out: $(grep -v '^  ' "$tmp/skew.log" | head -c 400)"
fi

# A second core that never starts: exit status 6 and a message, promptly
# (QEMU_TIMEOUT bounds it; a hang shows as status 124).
count nostart SCENE=$s PRUNE=0 FW_DEFS=-DFW_CORE1_START=0
rc=$(sed -nE 's/^qemu: firmware exit status ([0-9]+).*/\1/p' \
    "$tmp/nostart.log")
if [ "$rc" = 6 ] && grep -q 'core 1 gave no sign of life' "$tmp/nostart.log"
then
    ok
else
    bad "core 1 held: exit status $rc, want 6 with a message:" \
        "$(grep -v '^  ' "$tmp/nostart.log" | head -c 400)"
fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
