#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# `make profile` (mk/profile.mk, tools/profile/): the seed scene at 48x36
# on the an385 under the instruction-count plugin:
# - the image is byte-identical to the host's (the plugin only counts);
# - the plugin's count covers the firmware's own (the render) and exceeds
#   it by no more than start-up and reporting take (2 %);
# - the report's rows add up to that count, and name the tracer's
#   functions; --inline and --lines give their tables;
# - a malformed count file is refused with file:line:col and exit 1;
# - PROFILE=--inclusive (tools/profile/callstack.c): the image is still
#   the host's, the render entry's inclusive count is the firmware's own
#   (2 %), the self column and the depth table add up to the count,
#   the tracer's functions are named, a malformed profile is refused and
#   a plugin past its bounds writes none.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
MK=${MAKE:-make}
W=48 H=36
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

missing=""
for t in arm-none-eabi-gcc qemu-system-arm python3; do
    command -v "$t" >/dev/null || missing="${missing:+$missing }$t"
done
if [ -n "$missing" ]; then
    echo "SKIPPED: make profile ($missing missing)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi

fw=$tmp/fw
"$FT" -q -W $W -H $H -o "$tmp/host.ppm" scenes/seed.scene || bad "host render"
if ! "$MK" -s profile BOARD=an385 WIDTH=$W HEIGHT=$H FW_BUILD="$fw" \
    PROFILE="--inline --lines 5" >"$tmp/make.log" 2>&1; then
    bad "make profile failed: $(head -c 600 "$tmp/make.log")"
    echo "$pass passed, $fail failed"
    exit 1
fi
cmp -s "$fw/profile.ppm" "$tmp/host.ppm" && ok ||
    bad "the image under the profiler differs from the host's"

counted=$(awk '{s += $2} END {print s + 0}' "$fw/profile.txt")
render=$(awk '$1 == "instructions" {print $2}' "$fw/profile.log")
pixels=$(awk '$1 == "pixels" {print $2}' "$fw/profile.log")
if [ -n "$render" ] && [ "$counted" -ge "$render" ] &&
    [ "$counted" -le $((render + render / 50)) ]; then
    ok
else
    bad "plugin count $counted against the firmware's ${render:-none}"
fi

# The inline table's rows, times the pixels, give back the count (each
# row is rounded to 0.05 a pixel).
sum=$(awk -F'|' '/^\| inlined function/ {t = 1; next}
    t && /^\|[^-]/ {s += $3} t && /^$/ {exit} END {printf "%.0f", s * 1000}' \
    "$fw/profile.md")
want=$(awk -v c="$counted" -v p="$pixels" \
    'BEGIN {printf "%.0f", c / p * 1000}')
rows=$(awk '/^\| inlined function/ {t = 1; next} t && /^\|[^-]/ {n++}
    t && /^$/ {exit} END {print n + 0}' "$fw/profile.md")
if [ $((sum > want ? sum - want : want - sum)) -le $((rows * 50 + 1)) ]; then
    ok
else
    bad "the inline table adds up to $sum/1000 a pixel, not $want/1000"
fi
grep -q '^| rt_intersect>' "$fw/profile.md" && grep -q '^| shade' \
    "$fw/profile.md" && ok || bad "the tracer's functions are not in the table"
n=$(awk '/^\| source line/ {t = 1; next} t && /^\| [a-z_]+\.[ch]:[0-9]+ /' \
    "$fw/profile.md" | wc -l)
[ "$n" -eq 5 ] && ok || bad "--lines 5 gave $n source lines"

# Per function, from the same counts.
python3 tools/profile/report.py --tools arm-none-eabi- "$fw/fixtrace.elf" \
    "$fw/profile.txt" "$fw/profile.log" >"$tmp/fn.md" &&
    grep -q '^| rt_intersect |' "$tmp/fn.md" && ok ||
    bad "the per-function report: $(head -c 300 "$tmp/fn.md")"

printf '1000 5\nnot a line\n' >"$tmp/bad.txt"
if python3 tools/profile/report.py "$fw/fixtrace.elf" "$tmp/bad.txt" \
    "$fw/profile.log" >"$tmp/out" 2>"$tmp/err"; then
    bad "a malformed count file was accepted"
else
    grep -q "bad.txt:2:1: " "$tmp/err" && [ ! -s "$tmp/out" ] && ok ||
        bad "malformed counts: $(cat "$tmp/err")"
fi

# --inclusive: counts per call context (tools/profile/callstack.c).
fi=$tmp/fi
if "$MK" -s profile BOARD=an385 WIDTH=$W HEIGHT=$H FW_BUILD="$fi" \
    PROFILE=--inclusive >"$tmp/incl.log" 2>&1; then
    ok
else
    bad "make profile PROFILE=--inclusive: $(head -c 600 "$tmp/incl.log")"
fi
cmp -s "$fi/profile.ppm" "$tmp/host.ppm" && ok ||
    bad "the image under the call-stack plugin differs from the host's"
md=$fi/profile.md
counted=$(awk '$1 == "B" {s += $4 * $5} END {print s + 0}' "$fi/profile.txt")
render=$(awk '$1 == "instructions" {print $2}' "$fi/profile.log")
# the render entry's inclusive row (the first table's), times the pixels
entry=$(awk -F'|' -v p="$pixels" '/^$/ && n++ == 1 {exit}
    $2 ~ /^ rt_render_rows/ {r = $3} $2 == " main " {m = $3}
    END {printf "%.0f", (r != "" ? r : m) * p}' "$md")
if [ -n "$render" ] && [ "$entry" -ge $((render - render / 50)) ] &&
    [ "$entry" -le $((render + render / 50)) ]; then
    ok
else
    bad "the render entry's inclusive ${entry:-none} against ${render:-none}"
fi
# A table's column (field f of the rows after the header h) in
# thousandths of a pixel, its rows, and the count in thousandths.
col() {
    awk -F'|' -v h="$1" -v f="$2" 'index($0, h) == 1 {t = 1; next}
        t && /^\|[^-]/ {s += $f; n++} t && /^$/ {exit}
        END {printf "%.0f %d", s * 1000, n}' "$md"
}
want=$(awk -v c="$counted" -v p="$pixels" \
    'BEGIN {printf "%.0f", c / p * 1000}')
for t in "| function | inclusive/pixel:5:self column" \
    "| depth | instr/pixel:3:depth table"; do
    IFS=: read -r h f what <<<"$t"
    read -r sum rows <<<"$(col "$h" "$f")"
    if [ "$rows" -gt 0 ] &&
        [ $((sum > want ? sum - want : want - sum)) -le $((rows * 50 + 1)) ]
    then
        ok
    else
        bad "the $what adds up to $sum/1000 a pixel, not $want/1000"
    fi
done
grep -q '^| shade | ' "$md" && grep -q '^| rt_intersect | ' "$md" && ok ||
    bad "shade or rt_intersect missing from the inclusive table"

printf 'C 1 0 100 1\nB 1 100 5 2 100 10x\n' >"$tmp/bad.cs"
if python3 tools/profile/report.py --inclusive "$fi/fixtrace.elf" \
    "$tmp/bad.cs" "$fi/profile.log" >"$tmp/out" 2>"$tmp/err"; then
    bad "a malformed call-context profile was accepted"
else
    grep -q "bad.cs:2:17: " "$tmp/err" && [ ! -s "$tmp/out" ] && ok ||
        bad "malformed call-context profile: $(cat "$tmp/err")"
fi

# Past its stack bound the plugin writes nothing, and make says why.
if ${CC:-cc} -O2 -shared -fPIC -DMAX_DEPTH=3 -o "$tmp/cs3.so" \
    tools/profile/callstack.c; then
    if "$MK" -s profile BOARD=an385 WIDTH=$W HEIGHT=$H FW_BUILD="$fi" \
        PROFILE=--inclusive PROF_PLUGIN="$tmp/cs3.so" >"$tmp/deep.log" 2>&1
    then
        bad "make profile passed with a 3-frame call stack"
    else
        grep -q 'no profile written' "$tmp/deep.log" &&
            [ ! -e "$fi/profile.txt" ] && [ ! -e "$fi/profile.md" ] && ok ||
            bad "a call stack past its bound: $(head -c 300 "$tmp/deep.log")"
    fi
else
    bad "callstack.c does not build with -DMAX_DEPTH=3"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
