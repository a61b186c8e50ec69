#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every figure README.md, docs/*.md and port/baremetal/README.md quote from
# a measurement is the one the tool that measures it gives, or follows
# from it, so that none can go stale unnoticed:
# - measured again here (on the host, in seconds): the accuracy table
#   (tools/reference_table.sh), the adaptive table
#   (tools/adaptive_table.sh --check), --build-flags, --stats and error
#   output, make firmware's capacity refusal, and what the unit tests
#   print (test_vec's normalize error, test_cutoff's trials,
#   test_stability's mirror differences);
# - held to the table a slow (QEMU) tool wrote: docs/stack.md (make
#   stack; every stack quote, marked N<!-- stack BOARD KEY -->),
#   port/baremetal/README.md's boards table (tools/boards_table.sh) and
#   docs/bench.md, as README.md, docs/effects.md, docs/porting.md,
#   docs/accuracy.md and docs/embedding.md quote them; README.md's time
#   per frame (tools/frame_time.sh --check);
# - re-derived from a page's own measured cells: docs/accuracy.md and its
#   chart (tools/accuracy_report.sh --check) and docs/effects.md's pruning
#   table (tools/pruning_table.sh --check);
# - following from the sources: sizes from the headers (sizeof(rt_scene)
#   and its formula, on the host and on a Cortex-M0), the scenes (objects,
#   depth, text size), the board files and linker scripts, and the
#   defaults of core/fx/rt_config.h.
# Figures nothing can measure again cheaply (QEMU runs) are checked only
# against their table: regenerate the table with its tool, and this names
# every page that quotes it.
set -u
cd "$(dirname "$0")/.."
# -I for every layer folder of core/ (the Makefile exports the same).
CORE_INC=${CORE_INC:-$(for d in core/*/; do printf -- '-I%s ' "${d%/}"; done)}
FT=${FIXTRACE:-build/posix/fixtrace}
CC=${CC:-gcc}
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
numword() { # "eight" -> 8 (zero to twelve)
    echo " zero one two three four five six seven eight nine ten eleven twelve " |
        awk -v w="$1" '{ for (i = 1; i <= NF; i++) if ($i == w) print i - 1 }'
}
counts() { # scene -> "objects materials lights" as --emit-c gives them
    "$FT" --emit-c "$1" | awk '/^#define FW_SCENE_OBJECTS / { o = $3 }
        /^#define FW_SCENE_MATERIALS / { m = $3 } /^#define FW_SCENE_LIGHTS / { l = $3 }
        END { print o, m, l }'
}

if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not found (build it with make)"
    echo "0 passed, 1 failed"
    exit 1
fi

# --- Sizes from the headers, the board files and core/fx/rt_config.h -----------
# docs/embedding.md states sizeof(rt_scene) for the default capacities and
# the micro:bit build's (mk/boards/microbit.mk's FW_CAPS, read from there),
# the formula behind them and the bytes per capacity; all must match the
# headers. The sizes are kept for port/baremetal/README.md's checks below.
MICROBIT_CAPS=$(sed -e :a -e '/\\$/N; s/\\\n//; ta' mk/boards/microbit.mk |
    sed -n 's/^FW_CAPS :=//p' | tr ' ' '\n' | grep -E '^-DRT_MAX_' |
    paste -sd' ' -)
[ -n "$MICROBIT_CAPS" ] && ok ||
    bad "mk/boards/microbit.mk's FW_CAPS has no RT_MAX_* capacity"
cat >"$tmp/size.c" <<'EOF'
#include <stdio.h>
#include "rt_scene.h"
int main(void)
{
    printf("%u %d %d %d %d %d\n", (unsigned)sizeof(rt_scene),
           RT_MAX_MATERIALS, RT_MAX_LIGHTS, RT_MAX_OBJECTS, RT_MAX_WIDTH,
           RT_MAX_NAME);
    return 0;
}
EOF
probe() { # capacities... -> "sizeof materials lights objects width name"
    # shellcheck disable=SC2068
    $CC -std=c99 $CORE_INC $@ "$tmp/size.c" -o "$tmp/size" 2>"$tmp/err" &&
        "$tmp/size"
}
th() { echo "$1" | sed -E ':a; s/^([0-9]+)([0-9]{3})/\1,\2/; ta'; }
read -r scene_def mat_def lig_def obj_def width_def name_def <<<"$(probe)"
# shellcheck disable=SC2086
read -r scene_mb mat_mb lig_mb obj_mb _ <<<"$(probe $MICROBIT_CAPS)"
# The page gives the 32-bit targets' sizes (a Cortex-M0 compile; an
# object's mesh pointer takes 8 bytes on a 64-bit host, 4 there).
host_def=$scene_def host_mb=$scene_mb
sz32() { # capacities... -> sizeof(rt_scene) on a Cortex-M0, or nothing
    printf '#include "rt_scene.h"\nchar probe_m0[sizeof(rt_scene)];\n' >"$tmp/sz32.c"
    # shellcheck disable=SC2068
    arm-none-eabi-gcc -std=c99 -mcpu=cortex-m0 -mthumb $CORE_INC $@ \
        -c "$tmp/sz32.c" -o "$tmp/sz32.o" 2>>"$tmp/err" || return 0
    local hex
    hex=$(arm-none-eabi-nm -S "$tmp/sz32.o" | awk '$4 == "probe_m0" { print $2 }')
    [ -n "$hex" ] && echo $((16#$hex))
}
if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
    scene_def=$(sz32)
    # shellcheck disable=SC2086
    scene_mb=$(sz32 $MICROBIT_CAPS)
    probe() { echo "$(sz32 "$@")"; }
fi
if [ -z "${scene_def:-}" ] || [ -z "${scene_mb:-}" ]; then
    bad "cannot compile a sizeof(rt_scene) probe: $(head -c 300 "$tmp/err")"
else
    for spec in "default $mat_def $lig_def $obj_def $scene_def" \
        "micro:bit $mat_mb $lig_mb $obj_mb $scene_mb"; do
        # shellcheck disable=SC2086
        set -- $spec
        # As the page writes it: | default (...) | 32 | 4 | 128 | 19,628 bytes |
        grep -qE "^\| $1 [^|]*\| $2 \| $3 \| $4 \| $(th "$5") bytes \|$" docs/embedding.md && ok ||
            bad "docs/embedding.md's sizeof(rt_scene) row for the $1 build" \
                "should read $2 materials, $3 lights, $4 objects: $(th "$5") bytes"
    done
    # The formula: a + b * materials + c * lights + d * objects, each
    # coefficient measured by raising one capacity from 1 to 2.
    one="-DRT_MAX_MATERIALS=1 -DRT_MAX_LIGHTS=1 -DRT_MAX_OBJECTS=1"
    s1=$(probe $one | cut -d' ' -f1)
    c_mat=$(($(probe "$one -URT_MAX_MATERIALS -DRT_MAX_MATERIALS=2" | cut -d' ' -f1) - s1))
    c_lig=$(($(probe "$one -URT_MAX_LIGHTS -DRT_MAX_LIGHTS=2" | cut -d' ' -f1) - s1))
    c_obj=$(($(probe "$one -URT_MAX_OBJECTS -DRT_MAX_OBJECTS=2" | cut -d' ' -f1) - s1))
    c0=$((s1 - c_mat - c_lig - c_obj))
    want="sizeof(rt_scene) = $c0 + $c_mat * RT_MAX_MATERIALS + $c_lig * RT_MAX_LIGHTS + $c_obj * RT_MAX_OBJECTS"
    tr '\n' ' ' <docs/embedding.md | tr -s ' ' | grep -qF "$want" && ok ||
        bad "docs/embedding.md's formula should read '$want'"
    for spec in "OBJECTS $obj_def $c_obj" "MATERIALS $mat_def $c_mat" "LIGHTS $lig_def $c_lig"; do
        # shellcheck disable=SC2086
        set -- $spec
        grep -qE "^\| \`RT_MAX_$1\` \| $2 \| $3 bytes each in \`rt_scene\`" docs/embedding.md && ok ||
            bad "docs/embedding.md's configuration table: RT_MAX_$1 is $2, $3 bytes each in rt_scene"
    done
fi

# Defaults the pages give as `RT_NAME` (N), and the configuration table of
# docs/embedding.md (| `RT_NAME` | N | ...), are core/fx/rt_config.h's.
cfg_default() { sed -nE "s/^#define $1 ([0-9]+)\$/\\1/p" core/fx/rt_config.h | head -n 1; }
for md in README.md docs/*.md port/baremetal/README.md; do
    { tr '\n' ' ' <"$md" | tr -s ' ' | grep -oE '`RT_[A-Z_]+` \([0-9,]+\)' | sed -E 's/`(RT_[A-Z_]+)` \(([0-9,]+)\)/\1 \2/'
      [ "$md" = docs/embedding.md ] && sed -nE 's/^\| `(RT_[A-Z_]+)` \| ([0-9,]+) \|.*/\1 \2/p' "$md"; } |
        while read -r name v; do
            want=$(cfg_default "$name")
            [ -n "$want" ] || continue
            [ "$(echo "$v" | tr -d ,)" = "$want" ] && echo ok ||
                echo "FAILED: $md gives $name as $v, core/fx/rt_config.h's default is $want"
        done
done >"$tmp/cfgq"
grep -v '^ok$' "$tmp/cfgq"
pass=$((pass + $(grep -c '^ok$' "$tmp/cfgq")))
fail=$((fail + $(grep -c '^FAILED' "$tmp/cfgq")))
[ "$(wc -l <"$tmp/cfgq")" -ge 15 ] && ok ||
    bad "fewer than 15 quoted rt_config.h defaults found in the docs"
# docs/embedding.md: on a 64-bit host an object is the same 128 bytes,
# and the whole at most 7 bytes more, to align it.
if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
    d_def=$((host_def - scene_def))
    d_mb=$((host_mb - scene_mb))
    [ "$d_def" -ge 0 ] && [ "$d_def" -le 7 ] && [ "$d_mb" -ge 0 ] &&
        [ "$d_mb" -le 7 ] && ok ||
        bad "sizeof(rt_scene) on the host ($host_def, $host_mb) is not the" \
            "Cortex-M0's ($scene_def, $scene_mb) plus at most 7 bytes of" \
            "alignment, as docs/embedding.md says"
else
    echo "note: arm-none-eabi-gcc missing; sizeof(rt_scene) checked on the host only"
fi

# --- Measured figures: docs/stack.md and the frame-time table ---------------
# Every stack figure the docs quote (marked N<!-- stack BOARD KEY -->, the
# stack columns of the boards tables, README.md's example output) is the
# one in docs/stack.md's data block, which `make stack` measures; the data
# covers every scene and board; README.md's frame-time table follows the
# measured instructions per pixel (tools/frame_time.sh --check).
data=$(sed -n '/^```$/,/^```$/p' docs/stack.md 2>/dev/null |
    grep -E '^(stack|fit|example) ')
if [ -z "$data" ]; then
    bad "docs/stack.md has no data block (run make stack)"
else
    ok
    # One-core boards (a two-core board's stacks: docs/dual-core.md).
    for b in $(cd mk/boards && grep -L 'FW_CORES=2' *.mk | sed 's/\.mk$//'); do
        for sc in scenes/*.scene; do
            echo "$data" | grep -q "^stack $b $(basename "$sc" .scene) " && ok ||
                bad "docs/stack.md has no figure for $sc on $b (run make stack)"
        done
    done
    for f in README.md docs/*.md port/baremetal/README.md linker/template.ld; do
        echo "$data" | awk -v f="$f" '
            FNR == NR { if ($1 == "example") ex[$3] = $4; else v[$2 " " $3] = $4
                        if ($1 == "stack" && $3 == "seed") seed[$2] = $4; next }
            function num(x) { gsub(/[ ,]/, "", x); return x }
            function check(what, got, want) {
                if (want == "") printf "FAILED: %s:%d: %s has no figure in docs/stack.md\n", f, FNR, what
                else if (got != want) printf "FAILED: %s:%d: %s is %s, docs/stack.md says %s (run make stack)\n", f, FNR, what, got, want
                else print "ok" }
            { line = $0
              n = gsub(/<!-- stack /, "&", line)
              k = gsub(/[0-9]<!-- stack /, "&", line)
              if (n > k) printf "FAILED: %s:%d: a stack quote without a number (run make stack)\n", f, FNR
              while (match(line, /[0-9][0-9,]*<!-- stack [^ ]+ [^ ]+ -->/)) {
                  m = substr(line, RSTART, RLENGTH); split(m, p, "<!-- stack ")
                  split(p[2], q, " "); check(q[1] " " q[2], num(p[1]), v[q[1] " " q[2]])
                  line = substr(line, RSTART + RLENGTH) } }
            # The stack column of the seed tables (README.md: board, ipp,
            # flash, RAM, stack; port/baremetal/README.md: the tables rows).
            f == "README.md" && /^\| [a-z0-9]+ \(/ && NF >= 7 {
                split($0, c, "|"); split(c[2], bn, " "); check(bn[1] " seed stack", num(c[6]), seed[bn[1]]) }
            f == "port/baremetal/README.md" && /^\| [a-z0-9]+ \| tables \|/ {
                split($0, c, "|"); b = c[2]; gsub(/ /, "", b); check(b " seed stack", num(c[6]), seed[b]) }
            f == "README.md" && /^    make qemu BOARD=an385 SCENE=myscene.scene/ { inex = 1; next }
            f == "README.md" && inex && /^    wrote / { inex = 0 }
            f == "README.md" && inex && /^    [a-z_]+ [0-9.]+$/ { check("example " $1, $2, ex[$1]) }
            ' - "$f"
    done >"$tmp/stackq"
    grep -v '^ok$' "$tmp/stackq"
    pass=$((pass + $(grep -c '^ok$' "$tmp/stackq")))
    fail=$((fail + $(grep -c '^FAILED' "$tmp/stackq")))
    [ "$(grep -c '^ok$' "$tmp/stackq")" -ge 10 ] && ok ||
        bad "fewer than 10 quoted stack figures found in the docs"
fi
# docs/stack.md's tables and example are its data block, and the fit
# follows the depth columns the way tools/stack_table.sh computes it.
echo "$data" | awk '
    function num(x) { gsub(/[ ,]/, "", x); return x }
    function want(what, got, ex) {
        if (got == ex) print "ok"
        else printf "FAILED: docs/stack.md: %s reads '\''%s'\'', its data block gives '\''%s'\''\n", what, got, ex }
    FNR == NR { if ($1 == "example") ex[$3] = $4; else v[$2 " " $3] = $4; next }
    /^\| scene \(depth\) \|/ { n = split($0, hd, "|"); for (i = 3; i < n; i++) { b = hd[i]; gsub(/ /, "", b); col[i] = b }; sc = 1; next }
    /^## Per level of depth/ { sc = 0 }
    sc && /^\| [a-z]+ \([0-9]+\) \|/ { n = split($0, c, "|"); s = c[2]; sub(/^ /, "", s); sub(/ \(.*/, "", s)
        for (i = 3; i < n; i++) { x = num(c[i]); if (x == "overitscapacities") x = "-"
            want(s " on " col[i], x, v[col[i] " " s]) } }
    /^\| [a-z0-9]+ \| [0-9,]+ \| [0-9,]+ \|/ && !/^\| board / { n = split($0, c, "|"); b = c[2]; gsub(/ /, "", b)
        cnt = 0; sx = sy = sxx = sxy = 0
        for (d = 0; d <= 5; d++) { x = num(c[d + 3]); want(b " depth " d, x, v[b " seed_d" d]); y[d] = x }
        for (d = 1; d <= 5; d++) { cnt++; sx += d; sy += y[d]; sxx += d * d; sxy += d * y[d] }
        k = (cnt * sxy - sx * sy) / (cnt * sxx - sx * sx); q = (sy - k * sx) / cnt
        base = int(q + 0.5); per = int(k + 0.5); worst = 0
        for (d = 1; d <= 5; d++) { e = y[d] - (base + per * d); if (e < 0) e = -e; if (e > worst) worst = e }
        want(b " base", num(c[9]), base); want(b " per level", num(c[10]), per)
        want(b " worst misfit", num(c[11]), worst)
        want(b " fit_base (data)", base, v[b " fit_base"]); want(b " fit_per_level (data)", per, v[b " fit_per_level"]) }
    /^## The README.s example/ { exs = 1 } /^## Data/ { exs = 0 }
    exs && /^    [a-z_]+ [0-9.]+$/ { want("example " $1, $2, ex[$1]); nex++ }
    END { want("example lines", nex + 0, 5) }
' - docs/stack.md >"$tmp/stackt"
grep -v '^ok$' "$tmp/stackt"
pass=$((pass + $(grep -c '^ok$' "$tmp/stackt")))
fail=$((fail + $(grep -c '^FAILED' "$tmp/stackt")))
[ "$(wc -l <"$tmp/stackt")" -ge 80 ] && ok ||
    bad "docs/stack.md: fewer than 80 table figures found"

if bash tools/frame_time.sh --check 2>"$tmp/err"; then
    ok
else
    bad "README.md's frame-time table does not follow the measured" \
        "instructions per pixel (run tools/frame_time.sh --write):" \
        "$(head -c 400 "$tmp/err")"
fi

# --- Measured figures ----------------------------------------------------------
# Every figure the docs quote from a measurement is either printed by the
# tool that measures it (run here when it is quick) or checked against the
# table that tool wrote. The slow tools (QEMU) write the board tables of
# port/baremetal/README.md and docs/bench.md; every other page's copy of
# those figures is checked against them, so regenerating a table without
# the pages that quote it fails here, naming the page.
nocomma() { echo "$1" | tr -d ','; }
same_num() { # a b: equal as numbers (commas ignored)
    awk -v a="$(nocomma "$1")" -v b="$(nocomma "$2")" 'BEGIN { exit !(a + 0 == b + 0 && a != "") }'
}
# board_fig BOARD MODE FIELD: from the table tools/boards_table.sh writes
# (fields: instructions, ipp, stack, flash, ram, reserved).
board_fig() {
    awk -F'|' -v b="$1" -v m="$2" -v f="$3" '
        { gsub(/ /, "", $2); gsub(/ /, "", $3) }
        $2 == b && $3 == m {
            i = 8; if (f == "instructions") i = 4; if (f == "ipp") i = 5
            if (f == "stack") i = 6; if (f == "flash") i = 7
            if (f == "reserved") i = 9
            v = $i; gsub(/ /, "", v); print v; exit }' port/baremetal/README.md
}
check_fig() { # what, quoted, measured
    if [ -z "$3" ]; then
        bad "$1: no measured figure to check against"
    elif same_num "$2" "$3"; then
        ok
    else
        bad "$1 says '$2', the measurement says '$3'"
    fi
}

# The boards table's per-pixel column is its instructions over 320x240.
awk -F'|' '$3 ~ /^ (tables|text) $/ {
        i = $4; gsub(/[ ,]/, "", i); p = $5; gsub(/ /, "", p); b = $2 $3; gsub(/ +/, " ", b); sub(/ $/, "", b)
        if (sprintf("%.1f", i / 76800) == p) print "ok"
        else printf "FAILED: port/baremetal/README.md:%s per pixel reads %s, its instructions give %.1f\n", b, p, i / 76800 }' \
    port/baremetal/README.md >"$tmp/ippq"
grep -v '^ok$' "$tmp/ippq"
pass=$((pass + $(grep -c '^ok$' "$tmp/ippq")))
fail=$((fail + $(grep -c '^FAILED' "$tmp/ippq")))
[ "$(wc -l <"$tmp/ippq")" -ge 12 ] && ok || bad "port/baremetal/README.md: fewer than 12 rows in the boards table"

# port/baremetal/README.md: its sample `make qemu` output is the an385
# tables row, and the sizes the boards section quotes follow from the
# scene, the headers, the board files and the table itself.
pb=port/baremetal/README.md
awk '/^`make qemu BOARD=an385 WIDTH=320 HEIGHT=240` prints/ { on = 1; next }
     on && /^    wrote / { exit }
     on && /^    [a-z_]+ [0-9.]+$/ { print $1, $2 }' "$pb" >"$tmp/pbex"
ex() { awk -v k="$1" '$1 == k { print $2 }' "$tmp/pbex"; }
check_fig "$pb sample output: instructions" "$(ex instructions)" "$(board_fig an385 tables instructions)"
check_fig "$pb sample output: pixels" "$(ex pixels)" $((320 * 240))
check_fig "$pb sample output: stack_bytes" "$(ex stack_bytes)" "$(board_fig an385 tables stack)"
check_fig "$pb sample output: stack_reserved" "$(ex stack_reserved)" "$(board_fig an385 tables reserved)"
check_fig "$pb sample output: instructions_per_pixel" "$(ex instructions_per_pixel)" "$(board_fig an385 tables ipp)"
pbtext=$(sed -n '/^<!-- begin boards /,/^<!-- end boards -->/p' "$pb" | tr '\n' ' ' | tr -s ' ')
pbq() { echo "$pbtext" | sed -nE "s/.*$1.*/\\1/p" | tr -d ,; }
seed_objs=$("$FT" --emit-c scenes/seed.scene | sed -nE 's/^#define FW_SCENE_OBJECTS ([0-9]+).*/\1/p')
seed_depth=$(awk '/^image /{for (i = 1; i < NF; i++) if ($i == "depth") print $(i + 1)}' scenes/seed.scene)
check_fig "$pb: the seed's objects" "$(pbq 'scenes\/seed\.scene`: ([0-9]+) objects')" "$seed_objs"
check_fig "$pb: the seed's depth" "$(pbq 'objects, depth ([0-9]+)\)')" "$seed_depth"
check_fig "$pb: the seed's text" "$(pbq "the seed's text \\(([0-9,]+) bytes")" "$(wc -c <scenes/seed.scene)"
check_fig "$pb: the default rt_scene" "$(pbq 'default-capacity `rt_scene` \(([0-9,]+) bytes')" "${scene_def:-}"
check_fig "$pb: the large boards' row (pixels)" "$(pbq 'a ([0-9]+)-pixel row')" "${width_def:-}"
check_fig "$pb: the large boards' row (bytes)" "$(pbq '-pixel row \(([0-9,]+) bytes')" "$((3 * ${width_def:-0}))"
mb_row=$(sed -e :a -e '/\\$/N; s/\\\n//; ta' mk/boards/microbit.mk |
    sed -nE 's/^FW_CAPS :=.*-DFW_ROW_PIXELS=([0-9]+).*/\1/p')
check_fig "$pb: the micro:bit's rt_scene" "$(pbq 'stack included \(`rt_scene` ([0-9,]+) bytes')" "${scene_mb:-}"
check_fig "$pb: the micro:bit's row" "$(pbq 'stack included \(`rt_scene` [0-9,]+ bytes, row ([0-9,]+) bytes')" "$((3 * ${mb_row:-0}))"
mb_ram=$(sed -nE 's/^ *ram .*LENGTH = ([0-9]+)K.*/\1/p' linker/microbit.ld)
check_fig "$pb: the micro:bit's RAM" "$(pbq 'The micro:bit uses [0-9,]+ of its ([0-9,]+) bytes')" "$((1024 * ${mb_ram:-0}))"
for mode in text tables; do
    used=$(($(board_fig microbit $mode ram | tr -d ,) + $(board_fig microbit $mode reserved | tr -d ,)))
    if [ $mode = text ]; then q=$(pbq 'The micro:bit uses ([0-9,]+) of its')
    else q=$(pbq 'bytes\), and ([0-9,]+) with the tables'); fi
    check_fig "$pb: the micro:bit's RAM in use, $mode build (RAM + stack reserved)" "$q" "$used"
done

# docs/porting.md's cost of the panel: the lm3s6965 and an385 tables rows
# of the boards table, and what follows from them.
ptext=$(tr '\n' ' ' <docs/porting.md | tr -s ' ')
pq() { echo "$ptext" | sed -nE "s/.*$1.*/\\$2/p" | tr -d ,; } # regex, group
lm_i=$(board_fig lm3s6965 tables instructions | tr -d ,)
an_i=$(board_fig an385 tables instructions | tr -d ,)
lm_f=$(board_fig lm3s6965 tables flash | tr -d ,)
an_f=$(board_fig an385 tables flash | tr -d ,)
panel=$((128 * 64))
re='the lm3s6965 takes ([0-9,]+) instructions against the an385.s ([0-9,]+), that is ([0-9,]+) more, or ([0-9.]+) for each of the ([0-9,]+) pixels'
check_fig "docs/porting.md: lm3s6965 instructions" "$(pq "$re" 1)" "$lm_i"
check_fig "docs/porting.md: an385 instructions" "$(pq "$re" 2)" "$an_i"
check_fig "docs/porting.md: the panel's instructions" "$(pq "$re" 3)" "$((lm_i - an_i))"
check_fig "docs/porting.md: the panel's instructions per pixel shown" "$(pq "$re" 4)" \
    "$(awk -v d=$((lm_i - an_i)) -v p=$panel 'BEGIN { printf "%.1f", d / p }')"
check_fig "docs/porting.md: the panel's pixels" "$(pq "$re" 5)" "$panel"
re='; ([0-9,]+) bytes of flash against ([0-9,]+), ([0-9,]+) more for the driver'
check_fig "docs/porting.md: lm3s6965 flash" "$(pq "$re" 1)" "$lm_f"
check_fig "docs/porting.md: an385 flash" "$(pq "$re" 2)" "$an_f"
check_fig "docs/porting.md: the driver's flash" "$(pq "$re" 3)" "$((lm_f - an_f))"

# README's board table: each row against its board's tables row (a
# two-core board has none: its figures are docs/dual-core.md's, below).
boards=$(cd mk/boards && grep -L 'FW_CORES=2' *.mk | sed 's/\.mk$//')
for b in $boards; do
    row=$(grep -E "^\| $b \(" README.md | head -n 1)
    if [ -z "$row" ]; then
        bad "README.md's board table has no row for $b"
        continue
    fi
    IFS='|' read -r _ _ ipp flash ram stack _ <<<"$row"
    check_fig "README.md $b instructions/pixel" "$ipp" "$(board_fig "$b" tables ipp)"
    check_fig "README.md $b flash" "$flash" "$(board_fig "$b" tables flash)"
    check_fig "README.md $b RAM" "$ram" "$(board_fig "$b" tables ram)"
    check_fig "README.md $b stack" "$stack" "$(board_fig "$b" tables stack)"
done
m3=$(board_fig an385 tables ipp)
m0=$(board_fig m0 tables ipp)
ratio=$(awk -v v="$(nocomma "$m3")" 'BEGIN { printf "%.1f", v / 1000 }')
if awk -v v="$(nocomma "$m3")" 'BEGIN { exit !(v > 1000) }'; then
    grep -q "seed scene is still ${ratio}x over the 1,000" README.md && ok ||
        bad "README.md should say the seed is ${ratio}x over the 1,000 instructions/pixel ($m3)"
fi
# The README's sample `make qemu` output is consistent in itself.
awk '/^    instructions [0-9]+$/ {i = $2} /^    pixels [0-9]+$/ {p = $2}
     /^    instructions_per_pixel / {q = $2}
     END { exit !(p > 0 && sprintf("%.1f", i / p) == q) }' README.md && ok ||
    bad "README.md's sample make qemu output: instructions / pixels is not its instructions_per_pixel"

# docs/bench.md (tools/bench.sh) measures the seed on the M3 and M0 again.
bench_seed=$(grep -E '^\| seed \|' docs/bench.md | head -n 1)
IFS='|' read -r _ _ b3 b0 _ <<<"$bench_seed"
check_fig "docs/bench.md seed an385" "$b3" "$m3"
check_fig "docs/bench.md seed m0" "$b0" "$m0"
fx=$(sed -nE 's/^\| fixed point, Cortex-M3 \| ([0-9.,]+) .*/\1/p' docs/bench.md)
check_fig "docs/bench.md fixed point, Cortex-M3" "$fx" "$m3"
t1=$(sed -nE 's/^\| seed <= 1,000 instructions\/pixel on the M3 \| ([0-9.,]+) .*/\1/p' docs/bench.md)
check_fig "docs/bench.md targets: seed" "$t1" "$m3"
sd=$(sed -nE 's/^\| reference, soft double, Cortex-M3 \| ([0-9.]+) .*/\1/p' docs/bench.md)
m4f=$(sed -nE 's/^\| reference, float32 on the FPU, Cortex-M4F \| ([0-9.]+) .*/\1/p' docs/bench.md)
x_sd=$(awk -v a="$sd" -v b="$(nocomma "$m3")" 'BEGIN { if (b > 0) printf "%.1f", a / b }')
grep -qE "^\| >= 10x fewer instructions than soft double \(M3\) \| ${x_sd}x " docs/bench.md && ok ||
    bad "docs/bench.md targets: soft double / fixed should read ${x_sd}x"
tr '\n' ' ' <docs/accuracy.md | tr -s ' ' | grep -q "soft double ${x_sd}x" && ok ||
    bad "docs/accuracy.md should give the soft-double ratio ${x_sd}x (docs/bench.md)"
x_m4=$(awk -v a="$m4f" -v b="$(nocomma "$m3")" 'BEGIN { if (b > 0) printf "%.2f", a / b }')
m4c=$(echo "$m4f" | sed -E ':a; s/^([0-9]+)([0-9]{3})/\1,\2/; ta')
acc_flat=$(tr '\n' ' ' <docs/accuracy.md | tr -s ' ')
echo "$acc_flat" | grep -q "$m4c instructions per pixel, ${x_m4}x the fixed-point default" && ok ||
    bad "docs/accuracy.md should give the M4F float32 cost $m4c, ${x_m4}x (docs/bench.md)"

# docs/bench.md's derived figures follow its measured ones, as
# tools/bench.sh computes them: the ratios of the float builds, the host
# ratios and every target row (measured value and met).
awk -F'|' '
    function c(i,   v) { v = $i; gsub(/^ +| +$/, "", v); return v }
    function want(what, got, ex) {
        if (got == ex) print "ok"
        else printf "FAILED: docs/bench.md: %s reads '\''%s'\'', its figures give '\''%s'\''\n", what, got, ex }
    /^== cortex-m3/ { m3 = 1; next } /^== / { m3 = 0 }
    m3 && $0 ~ /^sqrt / { split($0, w, " "); sqrt3 = w[2] }
    c(2) == "fixed point, Cortex-M3" { fx = c(3) }
    c(2) ~ /^reference, / { ref[c(2)] = c(3); rat[c(2)] = c(4) }
    c(2) == "fixed point" { tf = c(3) } c(2) == "double reference" { tr = c(3) }
    c(2) == "fixed / reference" { fr = c(3) }
    c(2) == "-j 1" { j1 = c(3) } c(2) == "-j 2" { j2 = c(3) }
    c(2) == "speed-up of -j 2" { su = c(3) }
    c(2) ~ /^seed <= 1,000/ { t1 = c(3) "|" c(4) }
    c(2) ~ /^correctly rounded sqrt/ { t2 = c(3) "|" c(4) }
    c(2) ~ /^>= 10x fewer/ { t3 = c(3) "|" c(4) }
    c(2) ~ /^<= 1.2x the float32/ { t4 = c(3) "|" c(4) }
    c(2) ~ /^host: fixed <= 1.5x/ { t5 = c(3) "|" c(4) }
    c(2) ~ /^-j 2 scales/ { t6 = c(3) "|" c(4) }
    END {
        for (k in ref) want(k " ratio", rat[k], sprintf("%.3f", fx / ref[k]))
        want("fixed / reference", fr, sprintf("%.2f", tf / tr))
        sub(/ \(.*/, "", su); want("speed-up of -j 2", su, sprintf("%.2fx", j1 / j2))
        want("target: seed", t1, fx "|" (fx <= 1000 ? "yes" : "no"))
        want("target: sqrt", t2, sqrt3 "|" (sqrt3 <= 50 ? "yes" : "no"))
        r = ref["reference, soft double, Cortex-M3"] / fx
        want("target: soft double", t3, sprintf("%.1fx", r) "|" (r >= 10 ? "yes" : "no"))
        r = fx / ref["reference, float32 on the FPU, Cortex-M4F"]
        want("target: M4F", t4, sprintf("%.2fx", r) "|" (r <= 1.2 ? "yes" : "no"))
        r = tf / tr
        want("target: host", t5, sprintf("%.2fx (noisy)", r) "|" (r <= 1.5 ? "yes" : "no"))
        r = j1 / j2
        want("target: -j 2", t6, sprintf("%.2fx (noisy)", r) "|" (r >= 1.8 ? "yes" : "no"))
    }' docs/bench.md >"$tmp/benchq"
grep -v '^ok$' "$tmp/benchq"
pass=$((pass + $(grep -c '^ok$' "$tmp/benchq")))
fail=$((fail + $(grep -c '^FAILED' "$tmp/benchq")))

# docs/effects.md's pruning section (tools/pruning_table.sh --check): its
# seed rows are the boards table's an385 and m0 rows, and its per-pixel
# figures, percentages, ratios, targets met and notes follow its measured
# cells. The pruned diffuse rows are measured by other tools too: their
# cost is docs/bench.md's, their stack docs/stack.md's.
if bash tools/pruning_table.sh --check 2>"$tmp/err"; then
    ok
else
    bad "docs/effects.md's pruning section does not follow its measured" \
        "cells and port/baremetal/README.md's table (run" \
        "tools/pruning_table.sh --write): $(head -c 600 "$tmp/err")"
fi
eff_row() { grep -E "^\| $1 \| $2 \| $3[ ,]" docs/effects.md | head -n 1; }
bench_diff=$(grep -E '^\| diffuse \|' docs/bench.md | head -n 1)
IFS='|' read -r _ _ d3 d0 _ <<<"$bench_diff"
for spec in "an385 M3 $d3" "m0 M0 $d0"; do
    set -- $spec
    IFS='|' read -r _ _ _ _ _ est _ eipp _ <<<"$(eff_row diffuse "$2 \($1\)" pruned)"
    check_fig "docs/effects.md diffuse $2 pruned per pixel (docs/bench.md)" "$eipp" "$3"
    check_fig "docs/effects.md diffuse $2 pruned stack (docs/stack.md)" "$est" \
        "$(echo "$data" | awk -v b="$1" '$1 == "stack" && $2 == b && $3 == "diffuse" { print $4 }')"
done

# docs/embedding.md quotes its stack figures from docs/stack.md, which
# the stack quotes' own check below holds to it.

# README's accuracy table: printed again by the tool that made it.
if FIXTRACE="$FT" bash tools/reference_table.sh >"$tmp/acc" 2>"$tmp/err"; then
    tail -n +3 "$tmp/acc" | while IFS= read -r line; do
        grep -qxF -- "$line" README.md && echo ok ||
            echo "FAILED: README.md's accuracy table lacks '$line' (tools/reference_table.sh)"
    done >"$tmp/accres"
    grep -v '^ok$' "$tmp/accres"
    pass=$((pass + $(grep -c '^ok$' "$tmp/accres")))
    fail=$((fail + $(grep -c '^FAILED' "$tmp/accres")))
else
    bad "tools/reference_table.sh failed: $(head -c 300 "$tmp/err")"
fi

# What README.md says of the accuracy table: the seed's targets are
# suite_reference's, and the lowest scene is the one it names.
rtext=$(tr '\n' ' ' <README.md | tr -s ' ')
low=$(awk -F'|' 'NR > 2 { p = $3; gsub(/ /, "", p); n = $2; gsub(/ /, "", n)
    if (m == "" || p + 0 < m + 0) { m = p; l = n } } END { print l " " m }' "$tmp/acc")
lq=$(echo "$rtext" | sed -nE 's/.*[Tt]he lowest is `([a-z]+)` at ([0-9.]+) dB.*/\1 \2/p')
[ "$lq" = "$low" ] && ok ||
    bad "README.md names '$lq' as the lowest scene (dB); tools/reference_table.sh measures '$low'"
min_psnr=$(sed -nE 's/.*--min-psnr ([0-9.]+).*/\1/p' tests/suite_reference.sh | head -n 1)
max_bad=$(sed -nE 's/.*--max-bad ([0-9.]+).*/\1/p' tests/suite_reference.sh | head -n 1)
tq=$(echo "$rtext" | sed -nE 's/.*the seed scene to its target of ([0-9.]+) dB, ([0-9.]+)% of pixels within 2\/255.*/\1 \2/p')
[ "$tq" = "$min_psnr $(awk -v b="$max_bad" 'BEGIN { print 100 - b }')" ] && ok ||
    bad "README.md gives the seed's targets as '$tq' (dB, %); tests/suite_reference.sh holds it to --min-psnr $min_psnr --max-bad $max_bad"

# README.md's gallery captions and make run: the scenes' own counts and
# image lines.
read -r many_o _ <<<"$(counts scenes/many.scene)"
many_q=$(echo "$rtext" | sed -nE 's/.*`many`: ([0-9]+) shapes on a floor.*/\1/p')
check_fig "README.md: many's shapes besides the floor" "$many_q" "$((many_o - 1))"
read -r seed_o _ <<<"$(counts scenes/seed.scene)"
seed_q=$(echo "$rtext" | sed -nE 's/.*`seed`: every effect in ([a-z]+) objects.*/\1/p')
check_fig "README.md: the seed's objects" "$(numword "$seed_q")" "$seed_o"
mir_d=$(awk '/^image /{for (i = 1; i < NF; i++) if ($i == "depth") print $(i + 1)}' scenes/mirrors.scene)
check_fig "README.md: mirrors' depth" "$(echo "$rtext" | sed -nE 's/.*`mirrors`: two facing mirrors, depth ([0-9]+).*/\1/p')" "$mir_d"
seed_size=$(awk '/^image / { print $2 "x" $3 }' scenes/seed.scene)
grep -qE "^    make run +# renders scenes/seed\.scene at $seed_size to seed\.ppm$" README.md && ok ||
    bad "README.md's make run should render scenes/seed.scene at its own $seed_size"

# README.md's sample scene error: what fixtrace prints for a my.scene
# whose third line uses the undefined material.
mkdir -p "$tmp/err-example"
printf 'camera eye 0 2 -6 look 0 1 0 fov 50\nlight 5 10 -5\nsphere center 0 0 0 radius 1 material steel\n' \
    >"$tmp/err-example/my.scene"
ft_abs=$(cd "$(dirname "$FT")" && pwd)/$(basename "$FT")
(cd "$tmp/err-example" && "$ft_abs" -q -o x.ppm my.scene 2>&1 | sed 's/^/    /') >"$tmp/err-got"
awk '/^    my\.scene:[0-9]+:[0-9]+: error:/ { on = 1 } on && !/^    / { exit } on' README.md >"$tmp/err-shown"
[ -s "$tmp/err-shown" ] && cmp -s "$tmp/err-got" "$tmp/err-shown" && ok ||
    bad "README.md's sample scene error is not what fixtrace prints:" \
        "$(diff "$tmp/err-shown" "$tmp/err-got" | head -n 6)"
# port/baremetal/README.md's reserved stack: the boards table's.
rs=$(tr '\n' ' ' <port/baremetal/README.md | tr -s ' ' |
    sed -nE 's/.*inside the ([0-9]+) KB \(([0-9]+) KB on the micro:bit\) the linker scripts reserve.*/\1 \2/p')
[ "$rs" = "$(($(board_fig an385 tables reserved | tr -d ,) / 1024)) $(($(board_fig microbit tables reserved | tr -d ,) / 1024))" ] && ok ||
    bad "port/baremetal/README.md gives the reserved stack as '$rs' KB (an385, micro:bit); its table says otherwise"

# docs/effects.md's adaptive table, every row and column, measured again.
if FIXTRACE="$FT" bash tools/adaptive_table.sh --check 2>"$tmp/err"; then
    ok
else
    bad "docs/effects.md's adaptive table is not what" \
        "tools/adaptive_table.sh measures (run it with --write):" \
        "$(head -c 400 "$tmp/err")"
fi

# docs/accuracy.md is written by tools/accuracy_report.sh (make accuracy).
# Its default rows are measurements other tools make too: the firmware
# costs are docs/bench.md's per-scene ones, the errors at 1 spp what
# tools/reference_table.sh measured above, and the seed at 16 spp the
# adaptive table's.
# Its text, tables and charts follow from the data it was written from.
if bash tools/accuracy_report.sh --check 2>"$tmp/err"; then
    ok
else
    bad "docs/accuracy.md or its charts do not follow docs/accuracy-data.tsv" \
        "(run make accuracy): $(head -c 600 "$tmp/err")"
fi
acc_row() { # scene -> the default's 1 spp row's cells, '|'-separated
    awk -F'|' -v s="$1" '
        { for (i = 2; i <= 11; i++) { c[i] = $i; gsub(/^ +| +$/, "", c[i]) } }
        c[2] == "**30 (default)**" && c[3] == s {
            for (i = 2; i <= 11; i++) printf "%s|", c[i]; print ""; exit }' docs/accuracy.md
}
n_def=0
for sc in $(awk -F'|' '$2 ~ /30 \(default\)/ { gsub(/ /, "", $3); print $3 }' docs/accuracy.md | sort -u); do
    n_def=$((n_def + 1))
    IFS='|' read -r _ _ a3 a0 _ _ apsnr amax abad _ <<<"$(acc_row "$sc")"
    IFS='|' read -r _ _ b3 b0 _ <<<"$(grep -E "^\| $sc \|" docs/bench.md | head -n 1)"
    check_fig "docs/accuracy.md default $sc M3" "$a3" "$b3"
    check_fig "docs/accuracy.md default $sc M0" "$a0" "$b0"
    IFS='|' read -r _ _ rpsnr rmax rbad _ <<<"$(grep -E "^\| $sc \|" "$tmp/acc" | head -n 1)"
    check_fig "docs/accuracy.md default $sc PSNR" "$apsnr" "$(echo "$rpsnr" | tr -d ' ')"
    check_fig "docs/accuracy.md default $sc max error" "$amax" "$(echo "$rmax" | sed 's/ //g; s#/255##')"
    check_fig "docs/accuracy.md default $sc > 2/255" "${abad%\%}" "$(echo "$rbad" | tr -d ' %')"
done
[ "$n_def" -ge 4 ] && ok || bad "docs/accuracy.md has $n_def default rows, want 4 scenes"
a16=$(awk -F'|' '{ for (i = 2; i <= 9; i++) { c[i] = $i; gsub(/^ +| +$/, "", c[i]) } }
    c[2] == "16" && c[3] == "–" && c[4] == "5" { print c[8]; exit }' docs/accuracy.md)
ad16=$(sed -nE 's/^\| 320x240 \| 16 spp, every pixel \| [0-9,]+ \| ([0-9.]+) dB \|$/\1/p' docs/effects.md)
check_fig "docs/accuracy.md default seed at 16 spp PSNR (docs/effects.md's adaptive table)" "$a16" "$ad16"

# docs/effects.md's --build-flags examples, as the tool prints them.
awk '/^    \$ build\/posix\/fixtrace --build-flags / { s = $NF; getline; print s "|" $0 }' \
    docs/effects.md >"$tmp/bf"
[ -s "$tmp/bf" ] && ok || bad "docs/effects.md shows no --build-flags example"
while IFS='|' read -r scene want; do
    got=$("$FT" --build-flags "$scene" 2>/dev/null)
    [ "$got" = "$(echo "$want" | sed 's/^ *//')" ] && ok ||
        bad "docs/effects.md: --build-flags $scene prints '$got', the page shows '$want'"
done <"$tmp/bf"

# Command output the pages quote, produced again: every `$ build/posix/
# fixtrace ... --stats ...` block prints what it shows (the lines it
# shows, in any order among the others).
for md in README.md docs/*.md port/baremetal/README.md; do
    awk '/^    \$ build\/posix\/fixtrace .*--stats/ { n++; sub(/^    \$ /, ""); print "cmd " n " " $0; on = 1; next }
         on && /^    [a-z_]+ [0-9.]+$/ { print "out " n " " $1 " " $2; next }
         { on = 0 }' "$md" >"$tmp/statq"
    while read -r kind n rest; do
        [ "$kind" = cmd ] || continue
        # shellcheck disable=SC2086
        set -- $rest
        shift
        args=()
        while [ $# -gt 0 ]; do
            if [ "$1" = -o ]; then args+=(-o "$tmp/stat.ppm"); shift
            else args+=("$1"); fi
            shift
        done
        "$FT" "${args[@]}" 2>"$tmp/statout" >/dev/null
        awk -v n="$n" '$1 == "out" && $2 == n { print $3, $4 }' "$tmp/statq" |
            while read -r k v; do
                got=$(awk -v k="$k" '$1 == k { print $2 }' "$tmp/statout")
                [ "$got" = "$v" ] && echo ok ||
                    echo "FAILED: $md shows '$k $v' from '$rest', it prints '$k $got'"
            done
    done <"$tmp/statq"
done >"$tmp/statres"
grep -v '^ok$' "$tmp/statres"
pass=$((pass + $(grep -c '^ok$' "$tmp/statres")))
fail=$((fail + $(grep -c '^FAILED' "$tmp/statres")))
[ "$(wc -l <"$tmp/statres")" -ge 5 ] && ok ||
    bad "fewer than 5 quoted --stats lines found in the docs"

# docs/effects.md's make firmware messages: the capacities the diffuse
# scene gets are its counts, and many.scene is refused on the micro:bit
# with its own count and the board's limit (mk/firmware.mk prints it).
read -r d_o d_m d_l <<<"$(counts scenes/diffuse.scene)"
grep -qE "^    EFFECTS scenes/diffuse\.scene: .* RT_MAX_OBJECTS=$d_o RT_MAX_MATERIALS=$d_m RT_MAX_LIGHTS=$d_l$" docs/effects.md && ok ||
    bad "docs/effects.md's EFFECTS line should end RT_MAX_OBJECTS=$d_o RT_MAX_MATERIALS=$d_m RT_MAX_LIGHTS=$d_l (the diffuse scene's counts)"
mb_cap() { echo "$MICROBIT_CAPS" | tr ' ' '\n' | sed -nE "s/^-DRT_MAX_$1=([0-9]+)$/\\1/p"; }
read -r many_o _ <<<"$(counts scenes/many.scene)"
want="firmware: scenes/many.scene has $many_o objects, but the build for BOARD=microbit allows at most $(mb_cap OBJECTS) (RT_MAX_OBJECTS=$(mb_cap OBJECTS))"
grep -qxF "        $want" docs/effects.md && ok ||
    bad "docs/effects.md should show '$want'"
if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
    got=$(${MAKE:-make} -s firmware BOARD=microbit SCENE=scenes/many.scene \
        FW_BUILD="$tmp/fw-many" 2>&1 | grep '^firmware: ')
    [ "$got" = "$want" ] && ok ||
        bad "make firmware BOARD=microbit SCENE=scenes/many.scene says '$got', docs/effects.md shows '$want'"
else
    echo "note: arm-none-eabi-gcc missing; make firmware's refusal of many.scene not run"
fi
# The micro:bit's limits as README.md and docs/effects.md give them.
mbq=$(tr '\n' ' ' <README.md | tr -s ' ' |
    sed -nE 's/.*`microbit` \(nRF51, ([0-9]+) KB of RAM: at most ([0-9]+) objects, ([0-9]+) materials, ([0-9]+) lights and ([0-9]+) pixels wide\).*/\1 \2 \3 \4 \5/p')
mb_px=$(sed -e :a -e '/\\$/N; s/\\\n//; ta' mk/boards/microbit.mk |
    sed -nE 's/^FW_CAPS :=.*-DFW_ROW_PIXELS=([0-9]+).*/\1/p')
want="$(sed -nE 's/^ *ram .*LENGTH = ([0-9]+)K.*/\1/p' linker/microbit.ld) $(mb_cap OBJECTS) $(mb_cap MATERIALS) $(mb_cap LIGHTS) $mb_px"
[ "$mbq" = "$want" ] && ok ||
    bad "README.md's micro:bit limits are '$mbq', mk/boards/microbit.mk and linker/microbit.ld say '$want' (KB, objects, materials, lights, pixels)"
tr '\n' ' ' <docs/effects.md | tr -s ' ' |
    grep -qF "the micro:bit's $(mb_cap OBJECTS) objects, $(mb_cap MATERIALS) materials and $(mb_cap LIGHTS) lights" && ok ||
    bad "docs/effects.md should give the micro:bit's capacities as mk/boards/microbit.mk does ($MICROBIT_CAPS)"

# Figures the unit tests measure and print: the largest normalize error
# (test_vec), the cut-off's trials (test_cutoff) and the mirror
# differences of the symmetric scene (test_stability). The binaries are
# make test's; built here when missing.
HOST_BUILD=${HOST_BUILD:-build/posix}
unit() { # name [args...] -> its output
    local b=$HOST_BUILD/tests/$1
    shift
    [ -x "$b" ] || ${MAKE:-make} -s HOST_BUILD="$HOST_BUILD" \
        SANITIZE="${SANITIZE:-}" "$b" >/dev/null 2>&1
    "$b" "$@" 2>&1
}
nerr=$(unit test_vec | sed -nE 's/^fx_v3_normalize max error ([0-9.]+) ulp.*/\1/p')
nq=$(awk -v e="$nerr" 'BEGIN { if (e != "") { c = int(e * 100); if (c < e * 100) c++; printf "%.2f", c / 100 } }')
for spec in "docs/numerics.md|each component within ([0-9.]+) ulp \(measured\)" \
    "docs/numerics.md|and each is within ([0-9.]+) ulp of the truth"; do
    md=${spec%%|*} re=${spec#*|}
    q=$(tr '\n' ' ' <"$md" | tr -s ' ' | sed -nE "s/.*$re.*/\\1/p")
    check_fig "$md: normalize within (test_vec's largest error $nerr, rounded up)" "$q" "$nq"
done
unit test_cutoff >"$tmp/cutoff"
rtext=$(tr '\n' ' ' <docs/render-model.md | tr -s ' ')
rm_q() { echo "$rtext" | sed -nE "s/.*$1.*/\\1/p" | tr -d ,; }
check_fig "docs/render-model.md: the cut-off's traced rays" \
    "$(rm_q 'tests\/test_cutoff\.c checks the bounds on ([0-9,]+) traced rays')" \
    "$(sed -nE 's/^colour bounds: ([0-9]+) rays.*/\1/p' "$tmp/cutoff")"
check_fig "docs/render-model.md: the cut-off's random renders" \
    "$(rm_q 'the one-level limit on ([0-9,]+) random renders')" \
    "$(sed -nE 's/^cut-off: [0-9]+ rays cut in ([0-9]+) renders.*/\1/p' "$tmp/cutoff")"
sym=$(unit test_stability symmetric_scene_mirrors |
    sed -nE 's/.*mirror differences: core ([0-9]+) of ([0-9]+) pixel pairs \(max ([0-9]+) levels.*/\1 \2 \3/p')
sq=$(tr '\n' ' ' <docs/stability-cases.md | tr -s ' ' |
    sed -nE 's/.*at 320x240, ([0-9,]+) of the ([0-9,]+) pixel pairs differ \(the largest difference ([0-9]+) levels\).*/\1 \2 \3/p' | tr -d ,)
[ -n "$sym" ] && [ "$sq" = "$sym" ] && ok ||
    bad "docs/stability-cases.md's mirror differences are '$sq'; test_stability prints '$sym' (pairs differing, pairs, largest)"
# The seed at 16 spp, 640x480, from docs/effects.md's adaptive table (which
# its own check measures): its RMS error in levels, rounded up.
ad640=$(sed -nE 's/^\| 640x480 \| 16 spp, every pixel \| [0-9,]+ \| ([0-9.]+) dB \|$/\1/p' docs/effects.md)
rms=$(awk -v p="$ad640" 'BEGIN { if (p != "") { r = 255 / 10 ^ (p / 20); c = int(r * 10); if (c < r * 10) c++; printf "%.1f", c / 10 } }')
check_fig "docs/render-model.md: the seed's RMS error at 16 spp (levels, from the adaptive table's $ad640 dB)" \
    "$(rm_q 'at 16 spp the seed is within ([0-9.]+) levels RMS')" "$rms"
# docs/numerics.md's square root cost: docs/bench.md's (bench/fxbench).
sq3=$(awk '/^== cortex-m3/ { m = 1; next } /^== / { m = 0 } m && $1 == "sqrt" { printf "%.0f", $2 }' docs/bench.md)
check_fig "docs/numerics.md: instructions per sqrt on the M3 (docs/bench.md, rounded)" \
    "$(tr '\n' ' ' <docs/numerics.md | tr -s ' ' | sed -nE 's/.*rounding is decided on integers\. ([0-9]+) instructions on Cortex-M3.*/\1/p')" "$sq3"
# Sizes in KB that docs/embedding.md rounds: to the decimals it shows.
kb() { # bytes decimals -> KB
    awk -v b="$1" -v d="$2" 'BEGIN { printf "%." d "f", b / 1024 }'
}
etext=$(tr '\n' ' ' <docs/embedding.md | tr -s ' ')
ek=$(echo "$etext" | sed -nE 's/.*the seed scene is ([0-9.]+) KB of text, against ([0-9.]+) KB of `rt_scene`.*/\1 \2/p')
read -r ek1 ek2 <<<"$ek"
check_fig "docs/embedding.md: the seed's text in KB" "${ek1:-}" "$(kb "$(wc -c <scenes/seed.scene)" "$(echo "${ek1:-}" | awk -F. '{ print length($2) }')")"
check_fig "docs/embedding.md: rt_scene in KB" "${ek2:-}" "$(kb "${scene_def:-0}" 0)"
for f in docs/embedding.md docs/examples/embed_example.c; do
    check_fig "$f: rt_scene in KB, by default" \
        "$(sed -nE 's/.*static rt_scene scene; +\/\* ([0-9]+) KB by default.*/\1/p' "$f" | head -n 1)" "$(kb "${scene_def:-0}" 0)"
done
for f in docs/embedding.md docs/scene-format.md; do
    check_fig "$f: the parser's name table by default" \
        "$(tr '\n' ' ' <"$f" | tr -s ' ' | sed -nE 's/.*\(RT_MAX_NAME \+ 1\)`? bytes \(([0-9,]+) by default\).*/\1/p')" \
        "$((${mat_def:-0} * (${name_def:-0} + 1)))"
done

# docs/render-model.md's POV-Ray check: how many scenes tests/suite_povray.sh
# renders, and which may keep a speckle.
pov=$(awk '/^# scene +PSNR floor/ { on = 1; next } on && /^(scenes|tests)\// { print }' tests/suite_povray.sh)
npov=$(echo "$pov" | grep -c .)
pq_n=$(tr '\n' ' ' <docs/render-model.md | tr -s ' ' |
    sed -nE 's/.*`tests\/suite_povray\.sh` renders ([a-z]+) scenes with POV-Ray.*/\1/p')
check_fig "docs/render-model.md: the scenes suite_povray renders" \
    "$(numword "$pq_n")" "$npov"
spk=$(echo "$pov" | awk '$3 > 0 { printf "%s %s;", $1, $3 }')
[ "$spk" = "tests/pov/glass_spheres.scene 1;" ] &&
    tr '\n' ' ' <docs/render-model.md | tr -s ' ' | grep -qF 'with no speckle (one allowed in the glass scene)' && ok ||
    bad "docs/render-model.md allows one speckle in the glass scene; tests/suite_povray.sh allows '$spk'"

# docs/dual-core.md (make dual-table): each ratio follows the figures in
# its row, the targets hold (the busier core at most 0.6 of the an505 on
# every scene and 0.55 on the seed, the same bytes, flash within 4 KB of
# the an505), the counter's busier core below the interleave's as
# docs/porting.md says, and porting.md's poll bound is dual.c's.
if [ -f docs/dual-core.md ]; then
    awk -F'|' '
        function n(i,   v) { v = $i; sub(/\(.*/, "", v); gsub(/[ ,*]/, "", v); return v }
        /^\| [a-z]+ \| .*\*\*[0-9.]+\*\*/ {
            rows++; one = n(3); c0 = n(4); c1 = n(6); r = n(9)
            b = c0 > c1 ? c0 : c1
            want = sprintf("%.3f", b / one)
            if (r != want) printf "FAILED: docs/dual-core.md: %s reads %s, its figures give %s\n", n(2), r, want
            else if (r + 0 > (n(2) == "seed" ? 0.55 : 0.6)) printf "FAILED: docs/dual-core.md: %s at %s misses its target\n", n(2), r
            else if (n(NF - 1) != "yes") printf "FAILED: docs/dual-core.md: %s is not the same bytes\n", n(2)
            else if (NF == 12 && b >= (o = n(10)) + 0) printf "FAILED: docs/dual-core.md: %s: the interleave (%s) balances as well as the counter (%d); docs/porting.md says it does not\n", n(2), o, b
            else print "ok" }
        /^\| [0-9,]+ \| [0-9,]+ \| [0-9,]+ \|/ {
            flash++; d = n(3) - n(2)
            if (d != n(4)) printf "FAILED: docs/dual-core.md: flash difference %s, its figures give %d\n", n(4), d
            else if (d > 4096) printf "FAILED: docs/dual-core.md: the an521 is %d bytes over the an505, more than 4 KB\n", d
            else print "ok" }
        END { if (rows != '"$(ls scenes/*.scene | wc -l)"' || flash != 1)
                  printf "FAILED: docs/dual-core.md: %d scene rows, %d flash rows (make dual-table)\n", rows, flash }
    ' docs/dual-core.md >"$tmp/dual" 2>&1
    while IFS= read -r line; do
        case $line in ok) ok ;; *) fail=$((fail + 1)); echo "$line" ;; esac
    done <"$tmp/dual"
    polls=$(sed -nE 's/^#define DUAL_START_POLLS ([0-9]+)u?$/\1/p' port/baremetal/dual.c)
    check_fig "docs/porting.md: the polls before core 1 counts as not started" \
        "$(tr '\n' ' ' <docs/porting.md | tr -s ' ' | sed -nE 's/.*within ([0-9,]+) polls \(a count.*/\1/p')" \
        "$polls"
else
    bad "docs/dual-core.md is missing (make dual-table)"
fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
