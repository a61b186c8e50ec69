#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the scene fuzzer (mk/fuzz.mk builds it; see tests/fuzz/README.md).
#
#   fuzz.sh run     fuzz for FUZZ_SECONDS with FUZZ_JOBS processes on the
#                   working corpus FUZZ_DIR/corpus, then print
#                   "fuzz: N executions in S s, C crashes"
#   fuzz.sh repro   run every seed and regression input once and print
#                   "fuzz-repro: N inputs, F failed"
#
# Environment: FUZZ_BIN (the harness), FUZZ_DIR (its build directory, which
# holds corpus/, crashes/ and the logs), FUZZ_SECONDS, FUZZ_JOBS,
# FUZZ_MAX_LEN, FUZZ_TIMEOUT (seconds one input may take). Exits 1 when an
# input crashes; the input stays in FUZZ_DIR/crashes/. Every process it
# starts has ended when it returns, interrupted or not.
set -u
cd "$(dirname "$0")/../.." || exit 2
BIN=${FUZZ_BIN:-build/fuzz/fuzz_scene}
DIR=${FUZZ_DIR:-build/fuzz}
SECS=${FUZZ_SECONDS:-60}
JOBS=${FUZZ_JOBS:-1}
MAX_LEN=${FUZZ_MAX_LEN:-6144}
TIMEOUT=${FUZZ_TIMEOUT:-10}
DICT=tests/fuzz/scene.dict
# UBSan findings with their stack, like ASan's.
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}

# The inputs every run starts from: the hand-written seeds, the example
# scenes and the saved regressions (files only: libFuzzer fuzzes a
# directory it is given instead of running it).
seeds() {
    local f
    for f in tests/fuzz/corpus/* scenes/*.scene tests/fuzz/regressions/*; do
        [ -f "$f" ] && printf '%s\n' "$f"
    done
}

repro() {
    local list n fails=0 f
    mapfile -t list < <(seeds)
    n=${#list[@]}
    if [ "$n" -eq 0 ]; then
        echo "fuzz-repro: no inputs"
        return 1
    fi
    if ! "$BIN" -rss_limit_mb=2048 -timeout="$TIMEOUT" "${list[@]}" \
            >"$DIR/repro.log" 2>&1; then
        # Something failed: run them one by one to name each culprit.
        for f in "${list[@]}"; do
            if ! "$BIN" -timeout="$TIMEOUT" "$f" >"$DIR/repro-one.log" 2>&1
            then
                fails=$((fails + 1))
                echo "FAILED: $f"
                grep -E 'ERROR|runtime error|broken promise|#[0-9]+ ' \
                    "$DIR/repro-one.log" | head -n 12 | sed 's/^/    /'
            fi
        done
        [ "$fails" -gt 0 ] || { fails=1; echo "FAILED: the inputs together" \
            "(see $DIR/repro.log)"; }
    fi
    echo "fuzz-repro: $n inputs, $fails failed"
    [ "$fails" -eq 0 ]
}

pids=()
stop() {
    local p
    for p in "${pids[@]}"; do
        kill "$p" 2>/dev/null
    done
    wait
    echo "fuzz: interrupted (logs in $DIR/)"
    exit 130
}

run() {
    local corpus="$DIR/corpus" crashes="$DIR/crashes" i f rc crashed=0
    local total=0 start end n
    mkdir -p "$corpus" "$crashes"
    # Merge the seeds in (as seed-<name>, refreshed each run); what earlier
    # runs discovered (named by content hash) stays.
    seeds | while read -r f; do
        cp -- "$f" "$corpus/seed-$(basename "$f")"
    done
    trap stop INT TERM
    start=$(date +%s.%N)
    for ((i = 0; i < JOBS; i++)); do
        "$BIN" "$corpus" -dict="$DICT" -max_len="$MAX_LEN" \
            -max_total_time="$SECS" -timeout="$TIMEOUT" \
            -rss_limit_mb=2048 -print_final_stats=1 \
            -artifact_prefix="$crashes/" >"$DIR/fuzz-$i.log" 2>&1 &
        pids+=($!)
    done
    for i in "${!pids[@]}"; do
        wait "${pids[$i]}"
        rc=$?
        n=$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+).*/\1/p' \
            "$DIR/fuzz-$i.log" | tail -n 1)
        total=$((total + ${n:-0}))
        if [ "$rc" -ne 0 ]; then
            crashed=$((crashed + 1))
            echo "fuzz job $i: exit status $rc (log: $DIR/fuzz-$i.log)"
            grep -E 'ERROR|runtime error|broken promise|Test unit written' \
                "$DIR/fuzz-$i.log" | head -n 8 | sed 's/^/    /'
        fi
    done
    pids=()
    trap - INT TERM
    end=$(date +%s.%N)
    printf 'fuzz: %d executions in %s s, %d crashes\n' "$total" \
        "$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.0f", b - a }')" \
        "$crashed"
    [ "$crashed" -eq 0 ]
}

if [ ! -x "$BIN" ]; then
    echo "$BIN not built (make fuzz-build)" >&2
    exit 2
fi
case "${1:-run}" in
repro) repro ;;
run) run ;;
*) echo "usage: $0 run|repro" >&2; exit 2 ;;
esac
