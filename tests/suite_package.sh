#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The packaging manifests (docs/packaging.md), each taken at its word: the
# sources, include folders, definitions and flags it declares, read from
# the manifest by tests/package/manifest.py (PlatformIO library.json and
# Arduino library.properties, in the flat package tools/package_library.sh
# makes) or by running its CMake code with the build system's functions
# recorded (tests/package/manifest.cmake: the Zephyr module with its
# Kconfig defaults and one capacity changed, the ESP-IDF component). Each
# set is compiled with arm-none-eabi-gcc for a Cortex-M3 and linked with
# tests/package/rows.c and the bare-metal port into a program that renders
# the first rows of tests/cmake_consumer/tiny.scene under QEMU (mps2-an385),
# which must be the host's bytes. The Arduino example sketch is built as
# the Arduino builder would (C++, after <Arduino.h>, here a stub whose
# Serial writes to the port) and must send the CLI's PPM. Every
# manifest's version is core/fx/fixtrace_version.h's.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

missing=""
for t in arm-none-eabi-gcc arm-none-eabi-g++ qemu-system-arm python3 cmake; do
    command -v "$t" >/dev/null 2>&1 || missing="$missing $t"
done
if [ -n "$missing" ]; then
    echo "SKIPPED: packaging manifests ($missing missing; install" \
        "gcc-arm-none-eabi qemu-system-arm python3 cmake)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not built (run make first)"
    echo "0 passed, 1 failed"
    exit 1
fi

want=$(sed -nE 's/^#define FIXTRACE_VERSION_(MAJOR|MINOR|PATCH) +([0-9]+).*/\2/p' \
    core/fx/fixtrace_version.h | paste -sd. -)
SCENE=tests/cmake_consumer/tiny.scene
ROWS=8
"$FT" -q -o "$tmp/host.ppm" "$SCENE" || { bad "host render"; exit 1; }
# The first ROWS rows of the host's image (tiny.scene is 32 wide).
tail -c +"$(($(head -n 3 "$tmp/host.ppm" | wc -c) + 1))" "$tmp/host.ppm" |
    head -c $((32 * 3 * ROWS)) >"$tmp/host.rows"
python3 - "$SCENE" >"$tmp/scene_text.h" <<'EOF'
import sys
data = open(sys.argv[1], "rb").read()
print("static const char scene_text[] = {%s};" % ",".join(str(b) for b in data))
EOF

CPU="-mcpu=cortex-m3 -mthumb"
PORT=port/baremetal
PORT_SRC="$PORT/startup_cortexm.c $PORT/board_an385.c $PORT/common.c
    $PORT/semihost.c $PORT/out_semihost.c"
LDFLAGS="$CPU -nostdlib -T linker/an385.ld -Wl,--gc-sections -Wl,--no-warn-rwx-segments"

# Reads a "KIND value" listing into SRCS, INCS (-I...), DEFS (-D...), OPTS.
load() {
    SRCS=$(sed -n 's/^SRC //p' "$1")
    INCS=$(sed -n 's/^INC /-I/p' "$1")
    DEFS=$(sed -n 's/^DEF /-D/p' "$1")
    OPTS=$(sed -n 's/^OPT //p' "$1")
}

# build NAME EXTRA_OPTS: compiles the loaded set and rows.c with the port,
# links NAME.elf; the port's libc.c is the application's, built apart.
build() {
    local name=$1 extra=$2 d=$tmp/$1 objs="" i=0
    mkdir -p "$d"
    # shellcheck disable=SC2086
    for src in $SRCS tests/package/rows.c $PORT_SRC; do
        i=$((i + 1))
        arm-none-eabi-gcc $CPU $extra $OPTS $DEFS $INCS -I"$PORT" -I"$tmp" \
            -DROWS=$ROWS -ffreestanding -c "$src" -o "$d/$i.o" \
            2>>"$d.log" || return 1
        objs="$objs $d/$i.o"
    done
    # shellcheck disable=SC2086
    arm-none-eabi-gcc $CPU -O2 -ffreestanding -fno-tree-loop-distribute-patterns \
        -I"$PORT" $INCS $DEFS -c "$PORT/libc.c" -o "$d/libc.o" 2>>"$d.log" &&
        arm-none-eabi-gcc $LDFLAGS $objs "$d/libc.o" -o "$d.elf" -lgcc \
            2>>"$d.log"
}

# run NAME: runs NAME.elf under QEMU; its output goes to NAME.out.
run() {
    timeout 120 qemu-system-arm -M mps2-an385 -display none -monitor none \
        -serial none -semihosting-config enable=on,target=native \
        -kernel "$tmp/$1.elf" </dev/null >"$tmp/$1.out" 2>"$tmp/$1.err"
}

# check NAME EXTRA_OPTS: builds and runs the loaded set against the host.
check() {
    local name=$1
    if [ -z "$SRCS" ] || [ -z "$INCS" ]; then
        bad "$name: the manifest declares no sources or no include folder"
        return
    fi
    if ! build "$name" "$2"; then
        bad "$name: does not build: $(head -c 600 "$tmp/$name.log")"
    elif ! run "$name"; then
        bad "$name: the program failed under QEMU: $(head -c 300 "$tmp/$name.err")"
    elif cmp -s "$tmp/$name.out" "$tmp/host.rows"; then
        ok
        echo "$name: $(echo "$SRCS" | wc -w) sources, first $ROWS rows = host"
    else
        bad "$name: its rows differ from the host's"
    fi
}

# --- PlatformIO and Arduino: the flat library package ----------------------
pkg=$tmp/package/fixtrace
if bash tools/package_library.sh "$pkg" >"$tmp/pkg.log" 2>&1; then
    ok
else
    bad "tools/package_library.sh: $(cat "$tmp/pkg.log")"
fi
for kind in platformio arduino; do
    if python3 tests/package/manifest.py "$kind" "$pkg" >"$tmp/$kind.txt" \
        2>"$tmp/$kind.err"; then
        ok
    else
        bad "$kind manifest: $(cat "$tmp/$kind.err")"
        continue
    fi
    [ "$(sed -n 's/^VERSION //p' "$tmp/$kind.txt")" = "$want" ] && ok ||
        bad "$kind manifest's version is not $want"
    load "$tmp/$kind.txt"
    # Arduino declares no flags: its platforms build libraries with -Os.
    check "$kind" "$([ "$kind" = arduino ] && echo -Os)"
done

# The example sketch, as the Arduino builder makes it, sends the CLI's PPM.
load "$tmp/arduino.txt"
sketch=$pkg/examples/RenderScene/RenderScene.ino
d=$tmp/sketch
mkdir -p "$d"
{ echo '#include <Arduino.h>'; echo "#line 1 \"$sketch\""; cat "$sketch"; } \
    >"$d/sketch.cpp"
CXXFLAGS="$CPU -Os -ffreestanding -fno-exceptions -fno-rtti -Wall -Werror"
objs=""
i=0
ok_build=1
# shellcheck disable=SC2086
for src in $SRCS $PORT_SRC; do
    i=$((i + 1))
    arm-none-eabi-gcc $CPU -Os -ffreestanding $INCS -I"$PORT" -c "$src" \
        -o "$d/$i.o" 2>>"$d.log" || ok_build=0
    objs="$objs $d/$i.o"
done
# shellcheck disable=SC2086
if [ $ok_build -eq 1 ] &&
    arm-none-eabi-g++ $CXXFLAGS $INCS -Itests/package -I"$PORT" \
        -c "$d/sketch.cpp" -o "$d/sketch.o" 2>>"$d.log" &&
    arm-none-eabi-g++ $CXXFLAGS $INCS -Itests/package -I"$PORT" \
        -c tests/package/sketch_main.cpp -o "$d/main.o" 2>>"$d.log" &&
    arm-none-eabi-gcc $CPU -O2 -ffreestanding -fno-tree-loop-distribute-patterns \
        -I"$PORT" $INCS -c "$PORT/libc.c" -o "$d/libc.o" 2>>"$d.log" &&
    arm-none-eabi-g++ $LDFLAGS $objs "$d/sketch.o" "$d/main.o" "$d/libc.o" \
        -o "$tmp/sketch.elf" -lgcc 2>>"$d.log"; then
    ok
    "$FT" -q -o "$tmp/sketch_host.ppm" "$SCENE"
    if run sketch && cmp -s "$tmp/sketch.out" "$tmp/sketch_host.ppm"; then
        ok
    else
        bad "the example sketch's PPM differs from the CLI's: $(head -c 300 "$tmp/sketch.err")"
    fi
    # The sketch renders the scene this suite checks.
    grep -F "$(sed -n 1p "$SCENE")" "$sketch" >/dev/null && ok ||
        bad "RenderScene.ino's scene is not $SCENE"
else
    bad "the example sketch does not build: $(head -c 600 "$d.log")"
fi

# --- Zephyr: the module's CMake code with its Kconfig defaults -------------
[ -f zephyr/module.yml ] && grep -q '^ *cmake: zephyr$' zephyr/module.yml &&
    grep -q '^ *kconfig: zephyr/Kconfig$' zephyr/module.yml && ok ||
    bad "zephyr/module.yml does not name zephyr/ for CMake and Kconfig"
# shellcheck disable=SC2046
if cmake -DKIND=zephyr -DROOT="$PWD" -DOUT="$tmp/zephyr.txt" \
    $(python3 tests/package/manifest.py kconfig zephyr/Kconfig |
        sed 's/^-DCONFIG_FIXTRACE_MAX_OBJECTS=.*/-DCONFIG_FIXTRACE_MAX_OBJECTS=16/') \
    -DCONFIG_FIXTRACE=y -P tests/package/manifest.cmake >"$tmp/zephyr.log" 2>&1; then
    ok
    load "$tmp/zephyr.txt"
    check zephyr ""
    # The Kconfig capacity reached the core (its entry points carry it).
    arm-none-eabi-nm "$tmp/zephyr.elf" | grep -q ' rt_parse_cfg_o16_m32_l4$' && ok ||
        bad "zephyr: CONFIG_FIXTRACE_MAX_OBJECTS did not reach the core"
else
    bad "zephyr/CMakeLists.txt: $(head -c 600 "$tmp/zephyr.log")"
fi

# --- ESP-IDF: the component the top-level CMakeLists.txt registers ---------
grep -q "^version: \"$want\"$" idf_component.yml && ok ||
    bad "idf_component.yml's version is not $want"
if cmake -DKIND=idf -DROOT="$PWD" -DOUT="$tmp/idf.txt" \
    -P tests/package/manifest.cmake >"$tmp/idf.log" 2>&1; then
    ok
    load "$tmp/idf.txt"
    check esp-idf ""
else
    bad "ESP-IDF component: $(head -c 600 "$tmp/idf.log")"
fi

# Every manifest builds every core source.
n_core=$(ls core/*/*.c | wc -l)
for f in platformio arduino zephyr idf; do
    [ -f "$tmp/$f.txt" ] || continue
    n=$(grep -c '^SRC .*\.c$' "$tmp/$f.txt")
    [ "$n" -eq "$n_core" ] && ok || bad "$f builds $n of the $n_core core sources"
done

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
