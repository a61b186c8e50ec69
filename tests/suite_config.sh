#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The configuration header and the capacity check (core/fx/rt_config.h,
# core/scene/rt_scene.h, docs/embedding.md "Configuration"):
# - an application compiled with other capacities than the core does not
#   link, and the linker names the application's capacities (the case of
#   the reported case: docs/examples/embed_example.c with -DRT_MAX_OBJECTS=16
#   -DRT_MAX_MATERIALS=12 -DRT_MAX_LIGHTS=2 against a default core, which
#   used to overflow a global under ASan);
# - the same program against a core with the same capacities links and
#   runs cleanly under ASan, the capacities given as -D options, as
#   -DRT_CONFIG_FILE, as fixtrace_conf.h found on the include path, or
#   with -DRT_USE_CONF_FILE; a fixtrace_conf.h that only the application
#   sees is caught too; and clang finds fixtrace_conf.h as GCC does;
# - the colour bound (core/fx/rt_config.h): the core compiles at the deepest
#   RT_MAX_DEPTH each light count allows and refuses one level more, with
#   a message that gives the limits; rt_config.h and docs/embedding.md
#   state the limits the compiler enforces.
set -u
cd "$(dirname "$0")/.."
# -I for every layer folder of core/ (the Makefile exports the same).
CORE_INC=${CORE_INC:-$(for d in core/*/; do printf -- '-I%s ' "${d%/}"; done)}
CC=${CC:-gcc}
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The example includes the package's names (<fixtrace/rt_parse.h>): every
# core header under $tmp/inc/fixtrace/, as in tests/suite_docs.sh.
mkdir -p "$tmp/inc/fixtrace"
ln -s "$PWD"/core/*/*.h "$tmp/inc/fixtrace/"

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

# ASan when the compiler has it (it does on Debian's GCC); the mismatch
# used to be a global-buffer-overflow there.
SAN="-fsanitize=address,undefined -fno-sanitize-recover=all"
echo 'int main(void) { return 0; }' >"$tmp/probe.c"
$CC $SAN "$tmp/probe.c" -o "$tmp/probe" 2>/dev/null && "$tmp/probe" ||
    { SAN=""; echo "note: no ASan with $CC; running without it"; }
CFLAGS="-std=c99 -O0 $SAN -Wall -Wextra -Werror -Wundef"

# The application: the embedding example with a fake display, which
# prints the size of the rt_scene it was compiled with.
cat >"$tmp/app.c" <<'EOF'
#include <stdio.h>
#include "embed_example.c"
void spi_write(const uint8_t *d, size_t n) { (void)d; (void)n; }
void lcd_command(uint8_t c) { (void)c; }
int main(void)
{
    rt_parse_error e;
    int rc = render_to_lcd(&e);
    printf("sizeof(rt_scene) %u status %d\n", (unsigned)sizeof(rt_scene), rc);
    return rc != 0;
}
EOF
SMALL="-DRT_MAX_OBJECTS=16 -DRT_MAX_MATERIALS=12 -DRT_MAX_LIGHTS=2"
mkdir -p "$tmp/conf" "$tmp/named"
printf '%s\n' '/* micro:bit capacities */' '#define RT_MAX_OBJECTS 16' \
    '#define RT_MAX_MATERIALS 12' '#define RT_MAX_LIGHTS 2' \
    >"$tmp/conf/fixtrace_conf.h"
cp "$tmp/conf/fixtrace_conf.h" "$tmp/named/small_conf.h"

# core NAME FLAGS...: compiles core/*/*.c into $tmp/NAME/ (an archive).
core() {
    local name=$1 f
    shift
    mkdir -p "$tmp/$name"
    for f in core/*/*.c; do
        # shellcheck disable=SC2086
        $CC ${CORE_CFLAGS:-$CFLAGS} "$@" $CORE_INC -c "$f" \
            -o "$tmp/$name/$(basename "$f" .c).o" \
            2>>"$tmp/$name.err" || return 1
    done
    ar rcs "$tmp/$name/libcore.a" "$tmp/$name"/*.o
}

# app CORE FLAGS...: compiles and links the application against that core,
# log in $tmp/link.log; returns the link status.
app() {
    local name=$1
    shift
    rm -f "$tmp/app"
    # shellcheck disable=SC2086
    $CC $CFLAGS "$@" $CORE_INC -I"$tmp/inc" -Idocs/examples "$tmp/app.c" \
        "$tmp/$name/libcore.a" -o "$tmp/app" >"$tmp/link.log" 2>&1
}

# runs WANT_SIZE: the linked application runs cleanly with that scene size.
runs() {
    local out
    if out=$("$tmp/app" 2>&1) && echo "$out" | grep -q "sizeof(rt_scene) $1 status 0"; then
        ok
    else
        bad "$2: the program failed or has the wrong rt_scene: $(echo "$out" | head -c 400)"
    fi
}

core default || bad "the default core does not compile: $(head -c 400 "$tmp/default.err")"
core small $SMALL || bad "the small core does not compile: $(head -c 400 "$tmp/small.err")"
core named '-DRT_CONFIG_FILE="small_conf.h"' -I"$tmp/named" ||
    bad "the core with RT_CONFIG_FILE does not compile: $(head -c 400 "$tmp/named.err")"
core found -I"$tmp/conf" ||
    bad "the core with fixtrace_conf.h does not compile: $(head -c 400 "$tmp/found.err")"

# The reported mismatch: a clear link error, and no program.
if app default $SMALL; then
    bad "an application with RT_MAX_OBJECTS=16 ... linked against a default core"
elif grep -q "undefined reference to .rt_parse_cfg_o16_m12_l2" "$tmp/link.log" &&
    grep -q "rt_render_rows_cfg_o16_m12_l2" "$tmp/link.log" && [ ! -e "$tmp/app" ]; then
    ok
    echo "mismatch, as the linker says it:"
    grep -m 2 'undefined reference' "$tmp/link.log" | sed 's/^/    /'
else
    bad "mismatched capacities: no clear link error: $(head -c 400 "$tmp/link.log")"
fi
# The other way round: a small core, a default application.
if app small; then
    bad "a default application linked against a small core"
else
    grep -q "rt_render_rows_cfg_o128_m32_l4" "$tmp/link.log" && ok ||
        bad "default application, small core: $(head -c 400 "$tmp/link.log")"
fi
# Only the application sees fixtrace_conf.h.
if app default -I"$tmp/conf"; then
    bad "an application with its own fixtrace_conf.h linked against a default core"
else
    grep -q "rt_parse_cfg_o16_m12_l2" "$tmp/link.log" && ok ||
        bad "fixtrace_conf.h in the application only: $(head -c 400 "$tmp/link.log")"
fi

# Matching configurations link and run cleanly.
app default && runs 19120 "default capacities" ||
    bad "default application, default core: $(head -c 400 "$tmp/link.log")"
app small $SMALL && runs 3136 "-D capacities" ||
    bad "-D capacities on both sides: $(head -c 400 "$tmp/link.log")"
app named '-DRT_CONFIG_FILE="small_conf.h"' -I"$tmp/named" &&
    runs 3136 "RT_CONFIG_FILE" ||
    bad "RT_CONFIG_FILE on both sides: $(head -c 400 "$tmp/link.log")"
app found -I"$tmp/conf" && runs 3136 "fixtrace_conf.h" ||
    bad "fixtrace_conf.h on both sides: $(head -c 400 "$tmp/link.log")"
app found -DRT_USE_CONF_FILE -I"$tmp/conf" && runs 3136 "RT_USE_CONF_FILE" ||
    bad "RT_USE_CONF_FILE: $(head -c 400 "$tmp/link.log")"
# The configuration file and -D options may not disagree.
if $CC $CFLAGS $CORE_INC -I"$tmp/conf" -DRT_MAX_OBJECTS=8 -c core/scene/rt_scene.c \
    -o "$tmp/x.o" 2>"$tmp/err"; then
    bad "-DRT_MAX_OBJECTS=8 and fixtrace_conf.h's 16 compiled without a word"
else
    grep -q 'RT_MAX_OBJECTS' "$tmp/err" && ok ||
        bad "a -D against fixtrace_conf.h: $(head -c 300 "$tmp/err")"
fi

# clang: the file is found, in C99, without warnings.
if command -v clang >/dev/null 2>&1; then
    printf '#include "rt_scene.h"\n#if RT_MAX_OBJECTS != 16\n#error not found\n#endif\nint x;\n' \
        >"$tmp/c.c"
    if clang -std=c99 -pedantic -Wall -Wextra -Werror -Wundef $CORE_INC \
        -I"$tmp/conf" -c "$tmp/c.c" -o "$tmp/c.o" 2>"$tmp/err"; then
        ok
    else
        bad "clang does not find fixtrace_conf.h: $(head -c 300 "$tmp/err")"
    fi
else
    echo "note: clang missing; fixtrace_conf.h checked with $CC only"
fi

# The colour bound: with L lights the deepest recursion is
# 2047 / (16 + 32 L) - 1, and at the default depth of 5 at most 10 lights.
# The core compiles at each limit; one more is refused by rt_config.h,
# whose message gives the limits, before any file of the core is compiled.
# Compiled only, so without the sanitizers (in half the time).
limits=""
for l in 4 3 2 1 10; do
    if [ "$l" = 10 ]; then d=5; else d=$((2047 / (16 + 32 * l) - 1)); fi
    [ "$l" = 10 ] || limits="$limits${limits:+, }$d with $l"
    if CORE_CFLAGS="-std=c99 -O0 -Wall -Wextra -Werror -Wundef" \
        core "l${l}d$d" -DRT_MAX_LIGHTS=$l -DRT_MAX_DEPTH=$d; then
        ok
    else
        bad "RT_MAX_LIGHTS=$l RT_MAX_DEPTH=$d does not compile:" \
            "$(head -c 300 "$tmp/l${l}d$d.err")"
    fi
    for more in "-DRT_MAX_LIGHTS=$l -DRT_MAX_DEPTH=$((d + 1))" \
                "-DRT_MAX_LIGHTS=$((l + 1)) -DRT_MAX_DEPTH=$d"; do
        # shellcheck disable=SC2086
        if echo '#include "rt_scene.h"' | $CC $CFLAGS $more $CORE_INC -x c - \
            -fsyntax-only 2>"$tmp/err"; then
            bad "$more compiled: beyond the colour bound"
        else
            grep -q "depth <= 13 with 4 lights, 17 with 3, 24 with 2, 41 with 1, and lights <= 10 at depth 5" \
                "$tmp/err" && ok || bad "$more: $(head -c 300 "$tmp/err")"
        fi
    done
done
# The same limits in the message, in rt_config.h's comment and in
# docs/embedding.md (the comment and the page wrap their lines).
[ "$limits" = "13 with 4, 17 with 3, 24 with 2, 41 with 1" ] && ok ||
    bad "the computed limits are '$limits'"
flat() { sed 's/^ *\* \{0,1\}//' "$1" | tr '\n' ' ' | tr -s ' '; }
flat core/fx/rt_config.h | grep -q "depth is at most 13 with 4 lights, 17 with 3, 24 with 2 and 41 with 1" &&
    ok || bad "core/fx/rt_config.h does not state the depth limits at RT_MAX_DEPTH"
flat docs/embedding.md | grep -q "at most 13 with 4 lights (the defaults), 17 with 3, 24 with 2 and 41 with 1, and at the default depth of 5 .RT_MAX_LIGHTS. is at most 10" &&
    ok || bad "docs/embedding.md does not state the depth and light limits"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
