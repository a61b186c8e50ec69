#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Firmware built for what the scene needs (docs/effects.md), on the M3
# (an385) at 48x36:
# - `make firmware` derives the RT_NO_* flags from the scene itself: the
#   generated build/.../fw_effects.h holds exactly `fixtrace --build-flags`,
#   and the scene's counts as its capacities;
# - the pruned (PRUNE=1) firmware carries the scene as tables: neither the
#   parser nor the scene text is linked; the full (PRUNE=0) one parses the
#   text on the device;
# - both render the host's bytes for the diffuse scene, and the pruned one
#   takes at most half the full one's flash (the ratio is printed);
# - switching the same build to the seed scene re-derives the flags, the
#   capacities and the tables (it renders the host's bytes too);
# - a scene with more objects than the build allows fails the build,
#   naming the limit;
# - a firmware with an effect removed by hand refuses the seed scene with
#   a message naming the effect and exit status 4, and sends no image;
# - a firmware built with DRAFT=0 (the default), pruned or full, links no
#   draft render code; one with DRAFT=64 does;
# - the host tool that parses the scene is built with the settings of
#   FW_DEFS and FW_CAPS that change the parsed scene (RT_MAX_DEPTH,
#   RT_UNIT_BITS) and with the light limit the depth must fit
#   (core/fx/rt_config.h's colour bound): 16 deep with 2 lights, and 16-bit
#   unit vectors, render the host's bytes for those settings; 16 deep with
#   the default 4 lights stops with rt_config.h's message before
#   anything is compiled; the micro:bit's light limit reaches its host
#   tool;
# - the minimal renderer (bench/minimal) still renders the host's bytes.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
MK=${MAKE:-make}
W=48 H=36
DIFFUSE=scenes/diffuse.scene SEED=scenes/seed.scene
B=build/pruning
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

missing=""
for t in arm-none-eabi-gcc qemu-system-arm; do
    command -v "$t" >/dev/null || missing="${missing:+$missing }$t"
done
if [ -n "$missing" ]; then
    echo "SKIPPED: firmware pruning ($missing missing; install" \
        "gcc-arm-none-eabi qemu-system-arm)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not built (run make first)"
    echo "0 passed, 1 failed"
    exit 1
fi

# Two runs of this suite in one tree would share build/pruning: take turns.
mkdir -p "$B"
if command -v flock >/dev/null; then
    exec 9>"$B/.suite.lock"
    flock 9
fi

# fw NAME TARGET ARGS...: make for the an385 in $B/NAME, log in $tmp/NAME.log.
fw() {
    local name=$1 target=$2
    shift 2
    "$MK" -s "$target" BOARD=an385 FW_BUILD="$B/$name" WIDTH=$W HEIGHT=$H \
        QEMU_TIMEOUT=60 "$@" >>"$tmp/$name.log" 2>&1
}

# flash NAME: text + rodata of the firmware in $B/NAME.
flash() {
    arm-none-eabi-size -A "$B/$1/fixtrace.elf" |
        awk '$1 == ".text" { t = $2 } $1 == ".rodata" { r = $2 }
             END { print t + r }'
}

for s in diffuse seed; do
    "$FT" -q -W $W -H $H -o "$tmp/$s.ppm" "scenes/$s.scene" ||
        { bad "host render of $s failed"; }
done

# The three firmware variants build and run side by side; the capacity
# limit fails before any compiling.
( fw pruned qemu SCENE=$DIFFUSE PRUNE=1; echo $? >"$tmp/pruned.rc" ) &
( fw full qemu SCENE=$DIFFUSE PRUNE=0; echo $? >"$tmp/full.rc" ) &
( fw refuse qemu SCENE=$SEED PRUNE=1 FW_DEFS=-DRT_NO_REFLECTION
  echo $? >"$tmp/refuse.rc" ) &
( "$MK" -s minimal BOARD=an385 WIDTH=$W HEIGHT=$H >"$tmp/minimal.log" 2>&1
  echo $? >"$tmp/minimal.rc" ) &
( fw draft firmware SCENE=$SEED DRAFT=64; echo $? >"$tmp/draft.rc" ) &
wait
fw caps firmware SCENE=$DIFFUSE PRUNE=1 FW_DEFS=-DRT_MAX_OBJECTS=3 &&
    bad "diffuse (4 objects) built with RT_MAX_OBJECTS=3 as its limit" ||
    { grep -q 'diffuse.scene has 4 objects.*at most 3 (RT_MAX_OBJECTS=3)' \
        "$tmp/caps.log" && ok ||
        bad "the capacity limit's message: $(tail -n 3 "$tmp/caps.log")"; }

for v in pruned full; do
    if [ "$(cat "$tmp/$v.rc")" = 0 ] && cmp -s "$B/$v/out.ppm" "$tmp/diffuse.ppm"
    then
        ok
    else
        bad "$v firmware for diffuse: status $(cat "$tmp/$v.rc"), image" \
            "$(cmp "$B/$v/out.ppm" "$tmp/diffuse.ppm" 2>&1 | head -n 1)" \
            "$(tail -n 5 "$tmp/$v.log")"
    fi
done

# The flags come from the scene, not from the user.
want=$("$FT" --build-flags -s 1 "$DIFFUSE" | tr ' ' '\n' | sed 's/^-D//' |
    sort | tr '\n' ' ')
got=$(sed -nE 's/^#define (RT_NO_[A-Z]+) 1$/\1/p' "$B/pruned/fw_effects.h" |
    sort | tr '\n' ' ')
[ -n "$want" ] && [ "$got" = "$want" ] && ok ||
    bad "fw_effects.h removes '$got', fixtrace --build-flags says '$want'"
[ -f "$B/full/fw_effects.h" ] && ! grep -q '^#define' "$B/full/fw_effects.h" &&
    ok ||
    bad "PRUNE=0 removed effects: $(cat "$B/full/fw_effects.h")"

# caps NAME: the capacities in $B/NAME/fw_effects.h, "objects materials
# lights"; want SCENE: the scene's counts, at least 1 each.
caps() {
    local c out=
    for c in OBJECTS MATERIALS LIGHTS; do
        out="$out $(sed -nE "s/^#define RT_MAX_$c ([0-9]+)$/\1/p" \
            "$B/$1/fw_effects.h")"
    done
    echo $out
}
want_caps() {
    awk '$1 ~ /^(sphere|quad|box|cylinder|cone|mesh)$/ { o++ }
         $1 == "material" { m++ } $1 == "light" { l++ }
         END { print (o ? o : 1), (m ? m : 1), (l ? l : 1) }' "$1"
}
[ "$(caps pruned)" = "$(want_caps $DIFFUSE)" ] && ok ||
    bad "capacities '$(caps pruned)', want the scene's '$(want_caps $DIFFUSE)'"

# syms NAME: the symbols of the firmware in $B/NAME.
syms() { arm-none-eabi-nm "$B/$1/fixtrace.elf" | awk '{ print $NF }'; }
if syms pruned | grep -qE '^rt_(parse|lex)|^fw_scene_text$'; then
    bad "the pruned firmware links the parser or the scene text:" \
        "$(syms pruned | grep -E '^rt_(parse|lex)|^fw_scene_text$' | tr '\n' ' ')"
elif syms pruned | grep -qx fw_scene; then
    ok
else
    bad "the pruned firmware has no fw_scene tables"
fi
# A scene without meshes: no mesh code in its firmware.
syms pruned | grep -qE '^rt_mesh_' &&
    bad "the pruned firmware links the mesh code:" \
        "$(syms pruned | grep -E '^rt_mesh_' | tr '\n' ' ')" || ok
# DRAFT=0 (the default), pruned or not: no draft render code
# (core/frame/rt_draft.c, rt_thin.c; RT_NO_DRAFT). Their static functions
# are reached only through the rt_draft_ and rt_thin_ ones, so the names
# tell. A DRAFT=64 firmware links them.
draft_code() {
    arm-none-eabi-nm -S "$B/$1/fixtrace.elf" |
        awk '$NF ~ /^rt_(draft|thin)_/ { print $NF }' | tr '\n' ' '
}
for v in pruned full; do
    [ -f "$B/$v/fixtrace.elf" ] && [ -z "$(draft_code $v)" ] && ok ||
        bad "the $v firmware with DRAFT=0 links draft code: $(draft_code $v)"
done
[ "$(cat "$tmp/draft.rc")" = 0 ] &&
    draft_code draft | grep -q 'rt_draft_render .*rt_thin_' && ok ||
    bad "the DRAFT=64 firmware: status $(cat "$tmp/draft.rc"), draft code" \
        "'$(draft_code draft)' $(tail -n 3 "$tmp/draft.log")"
# rt_parse is linked as rt_parse_cfg_o<N>_m<N>_l<N> (core/scene/rt_scene.h).
syms full | grep -qE '^rt_parse(_cfg_[a-z0-9_]+)?$' &&
    syms full | grep -qx fw_scene_text && ok ||
    bad "the full firmware does not parse the scene text on the device"

# At most half: the scene as tables instead of the text and the parser.
fp=$(flash pruned) ff=$(flash full)
echo "flash (text+rodata) at ${W}x$H: pruned $fp, full $ff" \
    "($(awk -v a="$fp" -v b="$ff" 'BEGIN { printf "%.1f", 100 * a / b }')%)"
[ -n "$fp" ] && [ -n "$ff" ] && [ $((2 * fp)) -le "$ff" ] && ok ||
    bad "pruned flash '$fp' is more than half the full flash '$ff'"

# The same build directory, switched to the seed scene: the flags are
# derived again and the core rebuilt with them.
if fw pruned qemu SCENE=$SEED PRUNE=1 &&
    cmp -s "$B/pruned/out.ppm" "$tmp/seed.ppm"; then
    ok
else
    bad "the pruned build switched to seed renders wrong bytes:" \
        "$(tail -n 5 "$tmp/pruned.log")"
fi
grep -q RT_NO_REFLECTION "$B/pruned/fw_effects.h" &&
    bad "switching to seed kept RT_NO_REFLECTION" || ok
[ "$(caps pruned)" = "$(want_caps $SEED)" ] && ok ||
    bad "switching to seed: capacities '$(caps pruned)', want" \
        "'$(want_caps $SEED)'"

# Refusal: exit 4, the effect named on stderr, no image bytes.
rc=$(sed -nE 's/^qemu: firmware exit status ([0-9]+).*/\1/p' \
    "$tmp/refuse.log" | tail -n 1)
if [ "$rc" = 4 ] && grep -q 'needs reflection.*built without it' \
    "$tmp/refuse.log" && [ ! -s "$B/refuse/out.ppm" ]; then
    ok
else
    bad "seed on a firmware without reflection: exit '$rc'," \
        "$(grep -v '^qemu:' "$tmp/refuse.log" | head -c 300)"
fi

# Settings that change the parsed scene reach the host tool, with the
# light limit the depth must fit. The mirrors 16 deep (its two lights):
# the firmware renders the bytes of a host build with the same settings,
# and not those of depth 5.
sed 's/^image 640 480 depth 5$/image 640 480 depth 16/' scenes/mirrors.scene \
    >"$tmp/deep.scene"
grep -q 'depth 16' "$tmp/deep.scene" || bad "no depth 16 in $tmp/deep.scene"
# The host builds unoptimised (HOST_OPT): compiled in half the time, and
# their bytes must not depend on the optimisation either.
for run in "deep|$tmp/deep.scene|-DRT_MAX_DEPTH=16 -DRT_MAX_LIGHTS=2" \
           "unit16|scenes/mirrors.scene|-DRT_UNIT_BITS=16"; do
    name=${run%%|*} defs=${run##*|} scene=${run#*|}
    scene=${scene%%|*} host=$B/host-$name
    if fw "$name" qemu SCENE="$scene" FW_DEFS="$defs" &&
        "$MK" -s HOST_BUILD="$host" HOST_OPT="-O0 -g0" RT_DEFS="$defs" \
            "$host/fixtrace" \
            >>"$tmp/$name.log" 2>&1 &&
        "$host/fixtrace" -q -W $W -H $H -o "$tmp/$name.ppm" "$scene" &&
        cmp -s "$B/$name/out.ppm" "$tmp/$name.ppm"; then
        ok
    else
        bad "FW_DEFS='$defs': $(grep -v '^  ' "$tmp/$name.log" | tail -n 4)"
    fi
done
"$B/host-deep/fixtrace" -q -W $W -H $H -d 5 -o "$tmp/depth5.ppm" \
    "$tmp/deep.scene" 2>/dev/null
cmp -s "$tmp/depth5.ppm" "$tmp/deep.ppm" &&
    bad "the mirrors at depth 16 look as at depth 5" || ok
# 16 deep with 4 lights does not fit: said once, nothing compiled.
if fw deep4 firmware SCENE="$tmp/deep.scene" FW_DEFS=-DRT_MAX_DEPTH=16; then
    bad "RT_MAX_DEPTH=16 with 4 lights built"
elif grep -q 'depth <= 13 with 4 lights, 17 with 3, 24 with 2, 41 with 1' \
        "$tmp/deep4.log" &&
    grep -q 'host tool cannot be built with -DRT_MAX_DEPTH=16' \
        "$tmp/deep4.log" && ! grep -q '^  CC ' "$tmp/deep4.log"; then
    ok
else
    bad "RT_MAX_DEPTH=16 with 4 lights: $(head -c 600 "$tmp/deep4.log")"
fi
# The micro:bit allows 2 lights (FW_CAPS): 16 deep fits, in its host tool
# as in its firmware.
if "$MK" -s firmware BOARD=microbit FW_BUILD="$B/microbit-deep" WIDTH=$W \
    HEIGHT=$H SCENE="$tmp/deep.scene" FW_DEFS=-DRT_MAX_DEPTH=16 \
    >"$tmp/mb.log" 2>&1; then
    ok
else
    bad "micro:bit with RT_MAX_DEPTH=16: $(grep -v '^  ' "$tmp/mb.log" | head -c 600)"
fi

# Every scene: the pruned firmware (its own flags and tables) renders the
# very bytes the full host build does, at a small size (many.scene needs
# more capacity than a small size matters for, but runs as it is).
for scene in scenes/*.scene; do
    n=$(basename "$scene" .scene)
    if "$MK" -s qemu BOARD=an385 FW_BUILD="$B/every-$n" SCENE="$scene" \
            WIDTH=24 HEIGHT=18 SPP=1 PRUNE=1 >"$tmp/every.log" 2>&1 &&
        "$FT" -q -W 24 -H 18 -s 1 -o "$tmp/every.ppm" "$scene" &&
        cmp -s "$B/every-$n/out.ppm" "$tmp/every.ppm"; then
        ok
    else
        bad "$n: pruned firmware differs from the full host render" \
            "($(grep -v '^  ' "$tmp/every.log" | tail -n 3 | tr '\n' ' '))"
    fi
done

# The minimal renderer's yardstick still holds.
if [ "$(cat "$tmp/minimal.rc")" = 0 ] &&
    grep -q '^image identical' "$tmp/minimal.log"; then
    ok
    grep -E '^(instructions_per_pixel|flash) ' "$tmp/minimal.log" |
        sed 's/^/minimal: /'
else
    bad "make minimal: $(tail -n 8 "$tmp/minimal.log")"
fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
