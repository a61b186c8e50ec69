#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs every test part and adds up their "N passed, N failed[, N skipped]"
# lines (TEST_SUITES picks suites; see below). Parts: each unit-test binary
# build/<host>/tests/test_*, then each tests/suite_*.sh script. A part that
# exits non-zero or prints no summary counts as one failure. A part that
# needs a missing tool prints "SKIPPED: <why>" and counts a skip; under CI
# (CI=true) a skip is a failure, because CI installs every tool.
#
# TEST_JOBS parts (default: the machine's processors) run at once, each
# with its own log; the parts that took longest last time start first. It
# says at the start how many parts run, and prints each part's line (its
# counts and seconds) as soon as it ends. Parts
# that build share nothing but the host build, which test-build has made
# already; the firmware suites lock each board's build directory.
set -u
cd "$(dirname "$0")/.."
HOST_BUILD=${HOST_BUILD:-build/posix}
export HOST_BUILD
export FIXTRACE="$HOST_BUILD/fixtrace"
JOBS=${TEST_JOBS:-$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)}
pass=0 fail=0 skip=0 cpu_total=0
skipped_parts=""
log_dir="$HOST_BUILD/test-logs"
mkdir -p "$log_dir"

# Runs one part into its log; its exit status and seconds go to NAME.rc.
run_part() {
    local name=$1; shift
    local start=$SECONDS
    "$@" >"$log_dir/$name.log" 2>&1
    local rc=$?
    # This subshell's children's processor time (user + system): with a
    # part's seconds, what make test's time is made of.
    # (times itself in this shell: in a pipe or $(...) it would report a
    # subshell's.)
    local cpu
    times >"$log_dir/$name.times"
    cpu=$(tail -n 1 "$log_dir/$name.times" | awk '{ s = 0
        for (i = 1; i <= 2; i++) { split($i, t, /[ms]/); s += 60 * t[1] + t[2] }
        printf "%d", s + 0.5 }')
    # Renamed into place, so the report never reads half a line.
    echo "$rc $((SECONDS - start)) $cpu" >"$log_dir/$name.rc.tmp"
    mv -f "$log_dir/$name.rc.tmp" "$log_dir/$name.rc"
}

# Adds up one part that has ended, and prints its line.
report_part() {
    local name=$1
    local log="$log_dir/$name.log" rc=1 secs=0 cpu=0 line
    [ -f "$log_dir/$name.rc" ] && read -r rc secs cpu <"$log_dir/$name.rc"
    cpu_total=$((cpu_total + ${cpu:-0}))
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$log" | tail -n 1)
    local p=0 f=0 s=0
    if [ -n "$line" ]; then
        p=$(echo "$line" | sed -E 's/^([0-9]+) passed.*/\1/')
        f=$(echo "$line" | sed -E 's/^[0-9]+ passed, ([0-9]+) failed.*/\1/')
        s=$(echo "$line" | sed -nE 's/.*, ([0-9]+) skipped.*/\1/p')
        s=${s:-0}
    fi
    if [ -z "$line" ] || { [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; }; then
        f=$((f + 1))
        echo "  $name: exit status $rc$( [ -z "$line" ] && echo ', no summary line')"
    fi
    if [ "$s" -gt 0 ]; then
        skipped_parts="$skipped_parts
  $name: $(grep -E '^SKIPPED:' "$log" | sed 's/^SKIPPED: //' | paste -sd ';' -)"
        if [ "${CI:-}" = true ]; then
            f=$((f + s)); s=0
            echo "  $name: a skip counts as a failure under CI"
        fi
    fi
    pass=$((pass + p)); fail=$((fail + f)); skip=$((skip + s))
    reported=$((reported + 1))
    local total=${#parts[@]}
    printf '[%*d/%d] %-28s %6d passed %4d failed %3d skipped  (%ds, %ds CPU)\n' \
        "${#total}" "$reported" "$total" "$name" "$p" "$f" "$s" "$secs" \
        "${cpu:-0}"
    if [ "$f" -gt 0 ]; then
        grep -E 'FAILED|error|Error' "$log" | head -n 20 | sed 's/^/    /'
        echo "    (full log: $log)"
    fi
}

# The parts, in report order: "name command...", one a line.
parts=()
for bin in "$HOST_BUILD"/tests/test_*; do
    [ -x "$bin" ] || continue
    parts+=("$(basename "$bin") $bin")
done
# TEST_SUITES="cli png" runs only those suites (after every unit binary),
# for make test-quick.
for suite in tests/suite_*.sh; do
    [ -f "$suite" ] || continue
    if [ -n "${TEST_SUITES:-}" ]; then
        case " $TEST_SUITES " in
        *" $(basename "$suite" .sh | sed 's/^suite_//') "*) ;;
        *) continue ;;
        esac
    fi
    parts+=("$(basename "$suite" .sh) bash $suite")
done

# Start order: longest last time first (NAME.rc keeps the seconds).
order=$(for i in "${!parts[@]}"; do
    name=${parts[$i]%% *} secs=0
    [ -f "$log_dir/$name.rc" ] && read -r _ secs _ <"$log_dir/$name.rc"
    echo "$secs $i"
done | sort -k1,1nr -k2,2n | cut -d' ' -f2)
for i in "${!parts[@]}"; do
    rm -f "$log_dir/${parts[$i]%% *}.rc"
done

# Reports every part that has ended since the last call, in the order they
# ended (as far as one wait can tell).
declare -A done_parts=()
reported=0
report_ended() {
    local part name
    for part in "${parts[@]}"; do
        name=${part%% *}
        [ -z "${done_parts[$name]:-}" ] && [ -f "$log_dir/$name.rc" ] || continue
        done_parts[$name]=1
        report_part "$name"
    done
}

echo "Running ${#parts[@]} test parts, $JOBS at a time (logs in $log_dir/)"
running=0
for i in $order; do
    if [ "$running" -ge "$JOBS" ]; then
        wait -n
        running=$((running - 1))
        report_ended
    fi
    # shellcheck disable=SC2086
    run_part ${parts[$i]} &
    running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
    wait -n
    running=$((running - 1))
    report_ended
done
wait
report_ended
echo "Processor time of all parts: ${cpu_total}s, ${SECONDS}s here"
if [ -n "$skipped_parts" ]; then
    echo "Skipped parts (install the tool to run them):$skipped_parts"
fi
if [ "$skip" -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ "$fail" -eq 0 ]
