#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The firmware on every QEMU board (mk/boards/), in
# both scene modes (mk/firmware.mk): rendering on the device gives the same
# bytes as the host, for the seed scene as tables (PRUNE=1, the default: no
# parser linked) and for one other scene as text parsed on the device
# (PRUNE=0), for a draft render of the seed (DRAFT=64) and for the meshes
# as tables, at 48x36 (those three on the first board of each CPU; a
# two-core board's renders are tests/suite_dual.sh's);
# each board's instruction counter is exact (a loop of known length); a
# stack overflow ends the run with a fault code instead of hanging it; a
# bad scene fails a PRUNE=1 build on the host with its file:line:col, and
# a PRUNE=0 firmware exits 2 with a message; the M0 images use no
# soft-float helpers; and the micro:bit build, parser and
# rt_scene in RAM, fits in its 16 KB and renders the seed scene at 320x240.
#
# Boards run in parallel, each with its own build/<board>/ directory. A
# board whose cross compiler or QEMU is missing is skipped, with the
# package to install.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
MK=${MAKE:-make}
SEED=${FW_TEST_SEED:-scenes/seed.scene}
W=48 H=36
TIMEOUT=${FW_TEST_TIMEOUT:-60}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The other scene: FW_TEST_SCENE, else scenes/primitives.scene (every
# shape and cap variant; the seed has the effects), else the first scene
# that fits the micro:bit build's capacities (mk/firmware.mk).
pick_other() {
    local s
    for s in "${FW_TEST_SCENE:-}" scenes/primitives.scene scenes/*.scene; do
        [ -f "$s" ] && [ "$s" != "$SEED" ] || continue
        grep -q '^mesh ' "$s" && continue # text on the device: no meshes
        awk '$1 ~ /^(sphere|quad|box|cylinder|cone)$/ { o++ }
             $1 == "material" { m++ } $1 == "light" { l++ }
             END { exit !(o <= 16 && m <= 12 && l <= 2) }' "$s" &&
            { echo "$s"; return; }
    done
    echo "$SEED"
}
OTHER=$(pick_other)
# A scene with triangle meshes (tables in flash; refused as text).
MESHES=${FW_TEST_MESHES:-scenes/meshes.scene}

# Soft-float and soft-double helpers of libgcc (ARM EABI and generic names).
SOFT_FLOAT='__aeabi_([fd][a-z0-9]+|[a-z0-9]+2[fd]z?)$|__(add|sub|mul|div|neg|cmp|eq|ne|lt|le|gt|ge|unord|extend|trunc)[sdtx]f[0-9]*$|__(float|fix)[a-z]*[sdtx]f[a-z0-9]*$'

# Per-board results go to $tmp/<board>.res, one line per check: "ok" or
# "FAILED: ...", or a "SKIPPED: ..." line.
res() { echo "$*" >>"$tmp/$b.res"; }

# fw TARGET ARGS...: run make for this board, output to $tmp/$b.log.
fw() {
    "$MK" -s "$@" BOARD="$b" >"$tmp/$b.log" 2>&1
}

# run_qemu NAME TIMEOUT ARGS...: run the firmware; sets rc (124 = timeout).
run_qemu() {
    local name=$1 t=$2
    shift 2
    "$MK" -s qemu BOARD="$b" QEMU_TIMEOUT="$t" "$@" >"$tmp/$b.log" 2>&1
    rc=$(sed -nE 's/^qemu: firmware exit status ([0-9]+).*/\1/p' \
        "$tmp/$b.log" | tail -n 1)
    grep -q '^qemu: no exit after' "$tmp/$b.log" && rc=124
    rc=${rc:-0}
    if [ "$rc" = 124 ]; then
        res "FAILED: $b $name: QEMU did not exit within $t s (hang)"
    elif [ "$rc" != 0 ] && [ -z "${want_rc:-}" ]; then
        res "FAILED: $b $name: firmware exit status $rc (101-106: fault," \
            "2: parse error, 5: stack overflow): $(grep -v '^qemu:' \
            "$tmp/$b.log" | head -c 300)"
    fi
}

# render NAME SCENE W H REF [TIMEOUT [MAKE ARGS...]]: build, run, compare
# with the host render; then check the image's symbols (check_elf).
render() {
    local name=$1 scene=$2 w=$3 h=$4 ref=$5 t=${6:-$TIMEOUT}
    shift 5
    [ $# -gt 0 ] && shift
    if ! fw firmware SCENE="$scene" WIDTH="$w" HEIGHT="$h" "$@"; then
        res "FAILED: $b $name: build failed: $(head -c 600 "$tmp/$b.log")"
        return 1
    fi
    check_elf "$name" "$@"
    run_qemu "$name" "$t" SCENE="$scene" WIDTH="$w" HEIGHT="$h" "$@"
    [ "$rc" = 0 ] || return 1
    if cmp -s "build/$b/out.ppm" "$ref"; then
        res ok
        echo "$b $name: $(tr '\n' ' ' <"build/$b/qemu.log")" >>"$tmp/$b.info"
    else
        res "FAILED: $b $name: device image differs from the host's" \
            "($(cmp "build/$b/out.ppm" "$ref" 2>&1 | head -n 1))"
    fi
}

# check_elf NAME [MAKE ARGS...]: no soft-float helper is linked into the
# renderer, and the parser is linked exactly when the scene is text
# (PRUNE=0 among the arguments).
check_elf() {
    local name=$1 elf=build/$b/fixtrace.elf nm=arm-none-eabi-nm
    shift
    grep -q 'RISCV_PREFIX' "mk/boards/$b.mk" && nm=riscv64-unknown-elf-nm
    syms=$("$nm" "$elf" | awk '{print $NF}')
    sf=$(echo "$syms" | grep -E "$SOFT_FLOAT")
    if [ -z "$sf" ]; then
        res ok
    else
        res "FAILED: $b $name links soft-float helpers: $(echo $sf)"
    fi
    case " $* " in
    *" PRUNE=0 "*)
        # rt_parse is linked as rt_parse_cfg_o<N>_m<N>_l<N> (rt_scene.h).
        echo "$syms" | grep -qE '^rt_parse(_cfg_[a-z0-9_]+)?$' && res ok ||
            res "FAILED: $b $name: PRUNE=0 firmware without rt_parse" ;;
    *)
        if echo "$syms" | grep -qE '^rt_(parse|lex)|^fw_scene_text$'; then
            res "FAILED: $b $name: the tables firmware links the parser" \
                "or the text: $(echo "$syms" | grep -E '^rt_(parse|lex)|^fw_scene_text$')"
        else
            echo "$syms" | grep -qx fw_scene && res ok ||
                res "FAILED: $b $name: no fw_scene tables in the image"
        fi ;;
    esac
}

run_board() {
    b=$1
    : >"$tmp/$b.res"
    # Another run of this suite (or of make test) in the same tree would
    # rebuild build/<board>/ under our feet: take turns per board.
    mkdir -p "build/$b"
    if command -v flock >/dev/null; then
        exec 9>"build/$b/.suite.lock"
        flock 9
    fi
    render "$(basename "$SEED" .scene) ${W}x$H tables" "$SEED" $W $H \
        "$tmp/seed.ppm"
    # The other renders exercise the core's code for a CPU, the same on
    # every board built for it: only the first board of each CPU (its
    # FW_CPU) renders them. A two-core board renders every scene in
    # tests/suite_dual.sh.
    case " $(first_of_cpu) " in
    *" $b "*) ;;
    *) echo "$b: the seed only (an earlier board has its CPU)" >>"$tmp/$b.info"
       render_rest=0 ;;
    esac
    if [ "${render_rest:-1}" = 1 ]; then
        render "$(basename "$OTHER" .scene) ${W}x$H text" "$OTHER" $W $H \
            "$tmp/other.ppm" "$TIMEOUT" PRUNE=0
        # A draft render (rt_options.draft) takes the same decisions on
        # every board: the same bytes as the host's draft.
        render "$(basename "$SEED" .scene) ${W}x$H draft 64" "$SEED" $W $H \
            "$tmp/seed-draft.ppm" "$TIMEOUT" DRAFT=64
        # The meshes as tables in flash, on every board they fit.
        if fw firmware SCENE="$MESHES" WIDTH=$W HEIGHT=$H ||
            ! grep -q "overflowed" "$tmp/$b.log"; then
            render "$(basename "$MESHES" .scene) ${W}x$H tables" "$MESHES" $W $H \
                "$tmp/meshes.ppm"
        else
            res "SKIPPED: $b $MESHES: its meshes do not fit the flash"
        fi
    fi

    case $b in
    an385)
        # A scene that does not parse. PRUNE=1: the host refuses to build
        # it and says where. PRUNE=0: the device exits 2 and says where.
        printf 'camera eye 0 0 -5 look 0 0 0 up 0 1 0 fov 60\nsphere center 0 0 0 radius 1 material nope\n' >"$tmp/bad.scene"
        if fw firmware SCENE="$tmp/bad.scene"; then
            res "FAILED: $b bad scene: the PRUNE=1 build succeeded"
        elif grep -q "bad.scene:2:[0-9]*: error: material 'nope'" \
            "$tmp/$b.log"; then
            res ok
        else
            res "FAILED: $b bad scene: the PRUNE=1 build failed without" \
                "the parser's message: $(head -c 300 "$tmp/$b.log")"
        fi
        # A scene that does not exist: said so, before anything is built.
        if fw qemu SCENE="$tmp/nosuch.scene"; then
            res "FAILED: $b missing scene: the build succeeded"
        elif grep -q "SCENE=$tmp/nosuch.scene: no such file" "$tmp/$b.log" &&
            ! grep -qE 'does not parse|^  CC ' "$tmp/$b.log"; then
            res ok
        else
            res "FAILED: $b missing scene: $(head -c 300 "$tmp/$b.log")"
        fi
        # A mesh in a scene parsed on the device: refused, with the way
        # out (PRUNE=1 carries meshes as tables).
        if fw firmware SCENE="$MESHES" PRUNE=0; then
            want_rc=2 run_qemu "mesh as text" "$TIMEOUT" SCENE="$MESHES" \
                PRUNE=0
            if [ "$rc" = 2 ] && grep -q "PRUNE=1" "$tmp/$b.log"; then
                res ok
            else
                res "FAILED: $b mesh as text: exit $rc, want 2 naming" \
                    "PRUNE=1: $(head -c 300 "$tmp/$b.log")"
            fi
        else
            res "FAILED: $b mesh as text: PRUNE=0 build failed:" \
                "$(head -c 300 "$tmp/$b.log")"
        fi
        if fw firmware SCENE="$tmp/bad.scene" PRUNE=0; then
            want_rc=2 run_qemu "bad scene" "$TIMEOUT" \
                SCENE="$tmp/bad.scene" PRUNE=0
            if [ "$rc" = 2 ] && grep -q 'scene line 2 col' "$tmp/$b.log"; then
                res ok
            else
                res "FAILED: $b bad scene: exit $rc, want 2 with a line" \
                    "number: $(head -c 300 "$tmp/$b.log")"
            fi
        else
            res "FAILED: $b bad scene: PRUNE=0 build failed:" \
                "$(head -c 300 "$tmp/$b.log")"
        fi
        ;;
    microbit)
        # A row wider than the board's buffer is refused by make, before
        # anything is built, whether WIDTH says it or the scene does.
        printf 'image 400 30\ncamera eye 0 0 -5 look 0 0 0\n' >"$tmp/wide.scene"
        for args in "WIDTH=400 HEIGHT=10" "SCENE=$tmp/wide.scene"; do
            # shellcheck disable=SC2086
            if fw firmware $args; then
                res "FAILED: $b $args: the build succeeded"
            elif grep -q 'renders rows of at most 320 pixels' "$tmp/$b.log" &&
                ! grep -q '^  CC ' "$tmp/$b.log"; then
                res ok
            else
                res "FAILED: $b $args: $(head -c 300 "$tmp/$b.log")"
            fi
        done
        # Everything, stack included, in 16 KB of RAM, in the mode that
        # needs the most: the text parsed on the device into an rt_scene in
        # RAM. The seed scene at 320x240 (which also checks the stack
        # high-water mark on exit).
        if render "$(basename "$SEED" .scene) 320x240 text" "$SEED" 320 240 \
            "$tmp/seed320.ppm" 120 PRUNE=0; then
            fw size SCENE="$SEED" WIDTH=320 HEIGHT=240 PRUNE=0
            total=$(sed -nE 's/.*, total ([0-9]+)$/\1/p' "$tmp/$b.log")
            if [ -n "$total" ] && [ "$total" -le 16384 ]; then
                res ok
            else
                res "FAILED: microbit RAM: '$total' bytes, want <= 16384:" \
                    "$(cat "$tmp/$b.log")"
            fi
        fi
        ;;
    esac

    # The counter: a two-instruction loop of 10^6 turns (bringup.c).
    if fw firmware FW_APP=bringup FW_BRINGUP=0; then
        run_qemu "counter check" "$TIMEOUT" FW_APP=bringup FW_BRINGUP=0
        got=$(sed -nE 's/^loop_instructions ([0-9]+)$/\1/p' "$tmp/$b.log")
        if [ "$rc" = 0 ] && [ "$got" = 2000000 ]; then
            res ok
        elif [ "$rc" = 0 ]; then
            res "FAILED: $b counter: a 2000000-instruction loop measured" \
                "'$got'"
        fi
    else
        res "FAILED: $b bringup build: $(head -c 600 "$tmp/$b.log")"
    fi

    # Unbounded recursion must end in a fault exit, not a hang or exit 0.
    if fw firmware FW_APP=bringup FW_BRINGUP=2; then
        want_rc=fault run_qemu "stack overflow" "$TIMEOUT" FW_APP=bringup \
            FW_BRINGUP=2
        case $rc in
        10[1-6]) res ok ;;
        124) ;;
        *) res "FAILED: $b stack overflow: exit status $rc, want 101-106" ;;
        esac
    else
        res "FAILED: $b bringup build: $(head -c 600 "$tmp/$b.log")"
    fi
}

# Host references (the same core on the host).
if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not built (run make first)"
    echo "0 passed, 1 failed"
    exit 1
fi
for r in "seed $SEED $W $H" "other $OTHER $W $H" "seed320 $SEED 320 240" \
    "seed-draft $SEED $W $H --draft 64" "meshes $MESHES $W $H"; do
    set -- $r
    if ! "$FT" -q -W "$3" -H "$4" -o "$tmp/$1.ppm" "${@:5}" "$2" \
        2>"$tmp/host.err"
    then
        echo "FAILED: host render of $2: $(cat "$tmp/host.err")"
        echo "0 passed, 1 failed"
        exit 1
    fi
done
echo "scenes: $SEED, $OTHER and $MESHES"

# Every board that has a mk/boards/<board>.mk, with the tools its
# architecture needs.
all_boards=$(cd mk/boards && ls *.mk | sed 's/\.mk$//')
boards=""
for b in $all_boards; do
    if grep -q 'RISCV_PREFIX' "mk/boards/$b.mk"; then
        tools="riscv64-unknown-elf-gcc qemu-system-riscv32"
        pkgs="gcc-riscv64-unknown-elf qemu-system-misc"
    else
        tools="arm-none-eabi-gcc qemu-system-arm"
        pkgs="gcc-arm-none-eabi qemu-system-arm"
    fi
    missing=""
    for t in $tools; do
        command -v "$t" >/dev/null || missing="${missing:+$missing }$t"
    done
    if [ -n "$missing" ]; then
        echo "SKIPPED: $b firmware ($missing missing; install $pkgs)" \
            >"$tmp/$b.res"
    else
        boards="$boards $b"
    fi
done

# The first board (in $boards' order) of each CPU, and not a two-core one.
first_of_cpu() {
    local b cpu seen=" "
    for b in $boards; do
        grep -q 'FW_CORES=2' "mk/boards/$b.mk" && continue
        cpu=$(sed -nE 's/^FW_CPU := //p' "mk/boards/$b.mk" | tr -d ' ')
        case $seen in *" $cpu "*) continue ;; esac
        seen="$seen$cpu "
        echo "$b"
    done
}

start=$SECONDS
for b in $boards; do
    run_board "$b" &
done
wait

pass=0 fail=0 skip=0
for b in $all_boards; do
    [ -f "$tmp/$b.info" ] && cat "$tmp/$b.info"
    while IFS= read -r line; do
        case $line in
        ok) pass=$((pass + 1)) ;;
        SKIPPED:*) skip=$((skip + 1)); echo "$line" ;;
        *) fail=$((fail + 1)); echo "$line" ;;
        esac
    done <"$tmp/$b.res"
done
echo "boards took $((SECONDS - start)) s"
if [ "$skip" -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ "$fail" -eq 0 ]
