#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The CMake package (CMakeLists.txt, cmake/): tests/cmake_consumer, a tiny
# project, is configured, built and run on the host with the core taken by
# add_subdirectory, by FetchContent and by find_package; each renders
# tests/cmake_consumer/tiny.scene to the bytes the CLI writes. The library
# is configured as a user would (no build type, the default prefix) and
# installed with --prefix into a temporary directory; outside the
# checkout, a copy of the consumer finds it with find_package, a Makefile
# project with pkg-config, `fixtrace --emit-c` tables of a scene with
# meshes compile against the installed headers alone, and the docs'
# examples (embed_example.c, scene_in_c.c) build against it, all
# rendering the CLI's bytes. The install holds only the public headers,
# under include/fixtrace/, a closed set, each compiling alone; its
# version is fixtrace_version.h's. The core is built with an -O level
# when no build type is given, at top level and inside another project.
# FIXTRACE_CONFIG_FILE, given with -D or set() before add_subdirectory,
# reaches the core and the consumer alike (the core's names carry its
# capacities). With cmake/arm-none-eabi.cmake the consumer builds as
# Cortex-M0 firmware, which renders the same bytes under QEMU.
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
    cmake -S "$CONSUMER" -B "$tmp/$name" -DFIXTRACE_DIR="$SRC" "$@" >"$tmp/$name.log" 2>&1 &&
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

# The library's own compile flags: optimised with no build type given.
# optimised DIR: the core's flags in that build have an -O level.
optimised() {
    grep -E '^C_FLAGS' "$1/CMakeFiles/fixtrace_core.dir/flags.make" 2>/dev/null |
        grep -qE '(^| )-O([1-3sz]|fast)?( |$)'
}

# Install as a user would: configure with the default prefix, install
# with --prefix elsewhere (the package must follow it), then build
# outside the checkout with find_package, a Makefile and pkg-config,
# --emit-c tables and the documentation's examples.
prefix=$tmp/prefix
if cmake -S "$SRC" -B "$tmp/lib" >"$tmp/lib.log" 2>&1 &&
    cmake --build "$tmp/lib" -j 2 >>"$tmp/lib.log" 2>&1 &&
    cmake --install "$tmp/lib" --prefix "$prefix" >>"$tmp/lib.log" 2>&1; then
    ok
    optimised "$tmp/lib" && ok ||
        bad "top level, no build type: the core is built without -O"
    missing=""
    for f in include/fixtrace/rt_render.h include/fixtrace/rt_parse.h \
        include/fixtrace/rt_scene.h include/fixtrace/rt_config.h \
        include/fixtrace/fx_math.h include/fixtrace/rt_mesh.h \
        include/fixtrace/rt_grey.h include/fixtrace/fixtrace_version.h \
        include/fixtrace/rt_panel.h \
        lib/libfixtrace.a \
        lib/cmake/fixtrace/fixtraceConfig.cmake \
        lib/cmake/fixtrace/fixtraceConfigVersion.cmake \
        lib/pkgconfig/fixtrace.pc; do
        [ -f "$prefix/$f" ] || missing="$missing $f"
    done
    [ -z "$missing" ] && ok || bad "the install lacks:$missing"
    extra=$(cd "$prefix" && ls include/fixtrace | grep -vxE \
        'fixtrace_version.h|fx_cpu.h|fx_cpu_armv6m.h|fx_cpu_mul64.h|fx_cpu_rv32.h|fx_dir.h|fx_dot.h|fx_math.h|fx_mul64_soft.h|fx_rsqrt.h|fx_vec.h|rt_config.h|rt_features.h|rt_grey.h|rt_mesh.h|rt_options.h|rt_panel.h|rt_parse.h|rt_ray.h|rt_render.h|rt_scene.h')
    [ -z "$extra" ] && ok || bad "the install has internal headers: $extra"
    [ ! -e "$prefix/include/rt_render.h" ] && ok ||
        bad "headers installed straight into include/"
    # Closed: every header an installed header includes is installed, and
    # each compiles on its own.
    for h in "$prefix"/include/fixtrace/*.h; do
        for inc in $(sed -nE 's/^#[ ]*include "([^"]+)".*/\1/p' "$h"); do
            [ "$inc" = fixtrace_conf.h ] && continue
            [ -f "$prefix/include/fixtrace/$inc" ] ||
                bad "$(basename "$h") includes $inc, which is not installed"
        done
        if printf '#include <fixtrace/%s>\n' "$(basename "$h")" |
            gcc -std=c99 -Wall -Werror -fsyntax-only -I"$prefix/include" \
                -x c - 2>"$tmp/hdr.err"; then
            ok
        else
            bad "<fixtrace/$(basename "$h")> alone: $(head -c 300 "$tmp/hdr.err")"
        fi
    done
    want=$(sed -nE 's/^#define FIXTRACE_VERSION_(MAJOR|MINOR|PATCH) +([0-9]+).*/\2/p' \
        core/fx/fixtrace_version.h | paste -sd. -)
    grep -q "PACKAGE_VERSION \"$want\"" \
        "$prefix/lib/cmake/fixtrace/fixtraceConfigVersion.cmake" && ok ||
        bad "the package's version is not fixtrace_version.h's $want"

    # find_package, from a copy of the consumer outside the checkout.
    mkdir -p "$tmp/outside"
    cp "$CONSUMER/CMakeLists.txt" "$CONSUMER/main.c" "$CONSUMER/tiny.scene" \
        "$tmp/outside/"
    CONSUMER=$tmp/outside host package -DFIXTRACE_VIA=package \
        -DCMAKE_PREFIX_PATH="$prefix"

    if command -v pkg-config >/dev/null 2>&1; then
        export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
        [ "$(pkg-config --modversion fixtrace)" = "$want" ] && ok ||
            bad "fixtrace.pc's version is not $want"
        # A Makefile project: nothing but pkg-config's flags.
        mkdir -p "$tmp/mk"
        cp "$CONSUMER/main.c" "$tmp/package/tiny_scene.h" "$tmp/mk/"
        printf '%s\n' '# SPDX-License-Identifier: MIT' \
            'CFLAGS += -std=c99 $(shell pkg-config --cflags fixtrace)' \
            'LDLIBS += $(shell pkg-config --libs fixtrace)' \
            'consumer: main.c tiny_scene.h' \
            '	$(CC) $(CFLAGS) -I. main.c -o $@ $(LDLIBS)' >"$tmp/mk/Makefile"
        if make -C "$tmp/mk" >"$tmp/mk.log" 2>&1 &&
            "$tmp/mk/consumer" >"$tmp/mk.ppm" &&
            cmp -s "$tmp/mk.ppm" "$tmp/host.ppm"; then
            ok
        else
            bad "Makefile with pkg-config: $(tail -c 600 "$tmp/mk.log")"
        fi
        unset PKG_CONFIG_PATH
    else
        bad "pkg-config missing (apt-get install pkgconf)"
    fi

    # `fixtrace --emit-c` tables with meshes, against the installed
    # headers alone, rendered to the CLI's bytes.
    mkdir -p "$tmp/emit"
    cat >"$tmp/emit/main.c" <<'EOF'
/* SPDX-License-Identifier: MIT */
#include <stdio.h>
#include <fixtrace/rt_render.h>
extern const rt_scene fw_scene;
static uint8_t row[4096 * 3];
static int send_row(void *ctx, int y, const uint8_t *px, size_t n)
{
    (void)ctx;
    (void)y;
    return fwrite(px, 1, n, stdout) != n;
}
int main(void)
{
    rt_options opt;
    rt_options_from_scene(&opt, &fw_scene);
    opt.width = 48;
    opt.height = 36;
    printf("P6\n48 36\n255\n");
    return rt_render_rows(&fw_scene, &opt, 0, 36, row, send_row, 0, 0) != RT_OK;
}
EOF
    if "$FT" --emit-c scenes/meshes.scene >"$tmp/emit/scene.c" 2>"$tmp/emit.log" &&
        grep -q 'RT_MESH' "$tmp/emit/scene.c" &&
        "$FT" -q -W 48 -H 36 -o "$tmp/emit_cli.ppm" scenes/meshes.scene &&
        (cd "$tmp/emit" && gcc -std=c99 -Wall -Werror -O2 -I"$prefix/include" \
            scene.c main.c -L"$prefix/lib" -lfixtrace -o emit) \
            >>"$tmp/emit.log" 2>&1 &&
        "$tmp/emit/emit" >"$tmp/emit.ppm" &&
        cmp -s "$tmp/emit.ppm" "$tmp/emit_cli.ppm"; then
        ok
    else
        bad "--emit-c meshes.scene against the package: $(tail -c 600 "$tmp/emit.log")"
    fi

    # The documentation's examples, against the package: embed_example.c
    # compiles; scene_in_c.c builds the scene its comment shows, to the
    # bytes the CLI renders of that text.
    STRICT="-std=c99 -Wall -Wextra -Werror -Wshadow -Wundef
        -Wdouble-promotion -Wstrict-prototypes -Wmissing-prototypes
        -Wconversion -Wno-sign-conversion"
    # shellcheck disable=SC2086
    if gcc $STRICT -I"$prefix/include" -c docs/examples/embed_example.c \
        -o "$tmp/embed.o" 2>"$tmp/ex.err"; then
        ok
    else
        bad "embed_example.c against the package: $(head -c 600 "$tmp/ex.err")"
    fi
    mkdir -p "$tmp/sic"
    sed -nE '/^ \*   camera/,/^ \*   sphere/s/^ \*   //p' \
        docs/examples/scene_in_c.c >"$tmp/sic/scene.scene"
    sed -e 's/^extern const rt_scene fw_scene;/rt_status build_scene(rt_scene *s);\nstatic rt_scene fw_scene;/' \
        -e 's/^    rt_options opt;/    rt_options opt;\n    if (build_scene(\&fw_scene) != RT_OK)\n        return 2;/' \
        "$tmp/emit/main.c" >"$tmp/sic/main.c"
    # shellcheck disable=SC2086
    if [ "$(wc -l <"$tmp/sic/scene.scene")" -eq 7 ] &&
        "$FT" -q -W 48 -H 36 -o "$tmp/sic_cli.ppm" "$tmp/sic/scene.scene" &&
        gcc $STRICT -O2 -I"$prefix/include" docs/examples/scene_in_c.c \
            "$tmp/sic/main.c" -L"$prefix/lib" -lfixtrace -o "$tmp/sic/sic" \
            2>"$tmp/sic.err" &&
        "$tmp/sic/sic" >"$tmp/sic.ppm" && cmp -s "$tmp/sic.ppm" "$tmp/sic_cli.ppm"; then
        ok
    else
        bad "scene_in_c.c does not render its scene's bytes: $(head -c 600 "$tmp/sic.err")"
    fi
else
    bad "the library does not build or install: $(tail -c 600 "$tmp/lib.log")"
fi

# FIXTRACE_CONFIG_FILE: the core and its user see the same capacities,
# given with -D, and with set() in the project before add_subdirectory
# (whose own cmake_minimum_required predates CMP0126). With no build type
# the core is optimised inside another project too.
printf '%s\n' '#define RT_MAX_OBJECTS 16' '#define RT_MAX_MATERIALS 12' \
    '#define RT_MAX_LIGHTS 2' >"$tmp/my_conf.h"
host conf -DFIXTRACE_VIA=subdir -DFIXTRACE_CONFIG_FILE="$tmp/my_conf.h"
host confset -DFIXTRACE_VIA=subdir -DCONSUMER_CONFIG="$tmp/my_conf.h"
for b in conf confset; do
    if [ -f "$tmp/$b/fixtrace/libfixtrace.a" ] &&
        nm "$tmp/$b/fixtrace/libfixtrace.a" |
        grep -q ' T rt_render_rows_cfg_o16_m12_l2$'; then
        ok
    else
        bad "$b: FIXTRACE_CONFIG_FILE did not reach the core's capacities"
    fi
done
optimised "$tmp/confset/fixtrace" && ok ||
    bad "add_subdirectory, no build type: the core is built without -O"

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
