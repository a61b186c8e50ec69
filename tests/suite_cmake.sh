#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The CMake package (CMakeLists.txt, cmake/): tests/cmake_consumer, a tiny
# project, is configured, built and run on the host with the core taken by
# add_subdirectory, by FetchContent and by find_package after
# `cmake --install` (and once more through the installed pkg-config
# file); each renders tests/cmake_consumer/tiny.scene to the bytes the
# CLI writes. The install holds only the public headers, under
# include/fixtrace/. FIXTRACE_CONFIG_FILE reaches the core and the
# consumer alike (the core's names carry its capacities). With
# cmake/arm-none-eabi.cmake the consumer builds as Cortex-M0 firmware,
# which renders the same bytes under QEMU.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

if ! command -v cmake >/dev/null 2>&1; then
    echo "SKIPPED: cmake missing (apt-get install --no-install-recommends cmake)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not built (run make first)"
    echo "0 passed, 1 failed"
    exit 1
fi
SRC=$PWD
CONSUMER=$SRC/tests/cmake_consumer
"$FT" -q -o "$tmp/host.ppm" "$CONSUMER/tiny.scene" ||
    { echo "FAILED: host render"; echo "0 passed, 1 failed"; exit 1; }

# build NAME ARGS...: configures and builds the consumer in $tmp/NAME.
build() {
    local name=$1
    shift
    cmake -S "$CONSUMER" -B "$tmp/$name" "$@" >"$tmp/$name.log" 2>&1 &&
        cmake --build "$tmp/$name" -j 2 >>"$tmp/$name.log" 2>&1
}

# host NAME ARGS...: builds the consumer for the host and checks its image.
host() {
    local name=$1
    if ! build "$@"; then
        bad "$name: the consumer does not build: $(tail -c 600 "$tmp/$name.log")"
    elif "$tmp/$name/consumer" >"$tmp/$name.ppm" &&
        cmp -s "$tmp/$name.ppm" "$tmp/host.ppm"; then
        ok
    else
        bad "$name: the consumer's image differs from the CLI's"
    fi
}

host subdir -DFIXTRACE_VIA=subdir
host fetch -DFIXTRACE_VIA=fetch

# Install, then find_package and pkg-config.
prefix=$tmp/prefix
if cmake -S "$SRC" -B "$tmp/lib" -DCMAKE_INSTALL_PREFIX="$prefix" \
    >"$tmp/lib.log" 2>&1 && cmake --build "$tmp/lib" -j 2 >>"$tmp/lib.log" 2>&1 &&
    cmake --install "$tmp/lib" >>"$tmp/lib.log" 2>&1; then
    ok
    missing=""
    for f in include/fixtrace/rt_render.h include/fixtrace/rt_parse.h \
        include/fixtrace/rt_scene.h include/fixtrace/rt_config.h \
        include/fixtrace/fx_math.h include/fixtrace/rt_panel.h \
        lib/libfixtrace.a \
        lib/cmake/fixtrace/fixtraceConfig.cmake \
        lib/cmake/fixtrace/fixtraceConfigVersion.cmake \
        lib/pkgconfig/fixtrace.pc; do
        [ -f "$prefix/$f" ] || missing="$missing $f"
    done
    [ -z "$missing" ] && ok || bad "the install lacks:$missing"
    extra=$(cd "$prefix" && ls include/fixtrace | grep -vxE \
        'fx_dir.h|fx_math.h|fx_vec.h|rt_config.h|rt_features.h|rt_options.h|rt_panel.h|rt_parse.h|rt_render.h|rt_scene.h')
    [ -z "$extra" ] && ok || bad "the install has internal headers: $extra"
    [ ! -e "$prefix/include/rt_render.h" ] && ok ||
        bad "headers installed straight into include/"
    host package -DFIXTRACE_VIA=package -DCMAKE_PREFIX_PATH="$prefix"
    if command -v pkg-config >/dev/null 2>&1; then
        mkdir -p "$tmp/pc"
        (cd "$tmp/package" && cp tiny_scene.h "$tmp/pc/")
        # shellcheck disable=SC2046
        if gcc -std=c99 -I"$tmp/pc" "$CONSUMER/main.c" $(PKG_CONFIG_PATH=$prefix/lib/pkgconfig \
            pkg-config --cflags --libs fixtrace) -o "$tmp/pc/consumer" \
            2>"$tmp/pc.log" && "$tmp/pc/consumer" >"$tmp/pc.ppm" &&
            cmp -s "$tmp/pc.ppm" "$tmp/host.ppm"; then
            ok
        else
            bad "pkg-config: $(head -c 600 "$tmp/pc.log")"
        fi
    else
        echo "note: pkg-config missing; fixtrace.pc not tried"
    fi
else
    bad "the library does not build or install: $(tail -c 600 "$tmp/lib.log")"
fi

# FIXTRACE_CONFIG_FILE: the core and its user see the same capacities.
printf '%s\n' '#define RT_MAX_OBJECTS 16' '#define RT_MAX_MATERIALS 12' \
    '#define RT_MAX_LIGHTS 2' >"$tmp/my_conf.h"
host conf -DFIXTRACE_VIA=subdir -DFIXTRACE_CONFIG_FILE="$tmp/my_conf.h"
if [ -f "$tmp/conf/fixtrace/libfixtrace.a" ] &&
    nm "$tmp/conf/fixtrace/libfixtrace.a" | grep -q ' T rt_render_rows_cfg_o16_m12_l2$'; then
    ok
else
    bad "FIXTRACE_CONFIG_FILE did not reach the core's capacities"
fi

# Cortex-M0 with the example toolchain file, run under QEMU.
if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
    if build m0 -DFIXTRACE_VIA=subdir -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_TOOLCHAIN_FILE="$SRC/cmake/arm-none-eabi.cmake" \
        -DFIXTRACE_CPU="-mcpu=cortex-m0 -mthumb"; then
        ok
        arch=$(arm-none-eabi-readelf -A "$tmp/m0/consumer.elf" |
            sed -nE 's/.*Tag_CPU_arch: (.*)/\1/p')
        [ "$arch" = v6S-M ] || [ "$arch" = v6-M ] && ok ||
            bad "the M0 consumer is built for '$arch', not ARMv6-M"
        if command -v qemu-system-arm >/dev/null 2>&1; then
            if timeout 60 qemu-system-arm -M mps2-an385 -display none \
                -monitor none -serial none \
                -semihosting-config enable=on,target=native \
                -kernel "$tmp/m0/consumer.elf" </dev/null >"$tmp/m0.ppm" \
                2>"$tmp/m0.err" && cmp -s "$tmp/m0.ppm" "$tmp/host.ppm"; then
                ok
            else
                bad "the M0 consumer's image under QEMU differs: $(head -c 300 "$tmp/m0.err")"
            fi
        else
            echo "note: qemu-system-arm missing; the M0 consumer is only built"
        fi
    else
        bad "the consumer does not build for Cortex-M0: $(tail -c 600 "$tmp/m0.log")"
    fi
else
    echo "SKIPPED: Cortex-M0 consumer (arm-none-eabi-gcc missing; install gcc-arm-none-eabi)"
    m0_skip=1
fi

echo "$pass passed, $fail failed${m0_skip:+, 1 skipped}"
[ "$fail" -eq 0 ]
