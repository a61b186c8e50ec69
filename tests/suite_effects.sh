#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Simulate only what a scene calls for (docs/effects.md):
# - with --stats, a scene without an effect casts no rays of that kind;
# - for every scene, the host renderer built with the RT_NO_* flags that
#   `fixtrace --build-flags` derives renders the very same bytes as the full
#   build;
# - a pruned build refuses a scene that needs a removed effect, clearly;
# - a build without draft renders (-DRT_NO_DRAFT) renders the same bytes
#   and refuses --draft;
# - the core compiles warning-free in every configuration of the removal
#   flags a build can get (below) for the host, and in those a one-shape
#   firmware gets for the boards.
set -u
cd "$(dirname "$0")/.."
# -I for every layer folder of core/ (the Makefile exports the same).
CORE_INC=${CORE_INC:-$(for d in core/*/; do printf -- '-I%s ' "${d%/}"; done)}
FT=${FIXTRACE:-build/posix/fixtrace}
MAKE=${MAKE:-make}
pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

PRUNED_OPT="-O0 -g0"
stat_of() { grep "^$1 " "$2" | awk '{print $2}'; }

for scene in scenes/*.scene; do
    name=$(basename "$scene" .scene)
    flags=$("$FT" --build-flags "$scene")
    "$FT" -q --stats -W 64 -H 48 -o "$tmp/$name.ppm" "$scene" 2>"$tmp/$name.stats" ||
        { bad "$name: full render failed"; continue; }
    # Rays of a kind the scene does not need: none.
    case " $flags " in *" -DRT_NO_REFRACTION "*)
        [ "$(stat_of refraction_rays "$tmp/$name.stats")" = 0 ] && ok ||
            bad "$name has no glass but cast refraction rays"
        case " $flags " in *" -DRT_NO_REFLECTION "*)
            [ "$(stat_of reflection_rays "$tmp/$name.stats")" = 0 ] && ok ||
                bad "$name has no mirror or glass but cast reflection rays";;
        esac;;
    esac
    case " $flags " in *" -DRT_NO_SHADOWS "*)
        [ "$(stat_of shadow_rays "$tmp/$name.stats")" = 0 ] && ok ||
            bad "$name has no shadows but cast shadow rays";;
    esac
    # The pruned build gives the same bytes.
    # Unoptimised (HOST_OPT): compiled in half the time, and the bytes
    # must not depend on the optimisation either.
    build="build/pruned/$name"
    if $MAKE -s HOST_BUILD="$build" HOST_OPT="$PRUNED_OPT" RT_DEFS="$flags" \
            "$build/fixtrace" \
            >"$tmp/build.log" 2>&1; then
        ok
        "$build/fixtrace" -q -W 64 -H 48 -o "$tmp/$name.pruned.ppm" "$scene" &&
            cmp -s "$tmp/$name.ppm" "$tmp/$name.pruned.ppm" && ok ||
            bad "$name: the build with $flags renders different bytes"
    else
        bad "$name: pruned build failed: $(tail -5 "$tmp/build.log")"
    fi
done

# The same scene without shadows casts no shadow ray.
sed 's/^light /shadows off\nlight /' scenes/diffuse.scene | awk '!seen[$0]++' >"$tmp/noshadow.scene"
"$FT" -q --stats -W 32 -H 24 -o "$tmp/ns.ppm" "$tmp/noshadow.scene" 2>"$tmp/ns.stats"
[ "$(stat_of shadow_rays "$tmp/ns.stats")" = 0 ] && ok || bad "shadows off still cast shadow rays"
[ "$("$FT" --build-flags "$tmp/noshadow.scene" | grep -c RT_NO_SHADOWS)" = 1 ] && ok ||
    bad "shadows off does not allow RT_NO_SHADOWS"

# A pruned build refuses what it cannot draw, and names it.
if [ -x build/pruned/diffuse/fixtrace ]; then
    build/pruned/diffuse/fixtrace -q -W 8 -H 8 -o "$tmp/x.ppm" scenes/seed.scene 2>"$tmp/err"
    rc=$?
    [ $rc -ne 0 ] && grep -q "built without it" "$tmp/err" && [ ! -e "$tmp/x.ppm" ] && ok ||
        bad "a diffuse-only build rendered the seed scene (status $rc: $(cat "$tmp/err"))"
    build/pruned/diffuse/fixtrace -q -s 4 -W 8 -H 8 -o "$tmp/y.ppm" scenes/diffuse.scene 2>"$tmp/err"
    [ $? -ne 0 ] && grep -q "supersampling" "$tmp/err" && ok ||
        bad "a build without supersampling accepted -s 4: $(cat "$tmp/err")"
fi

# Without draft renders (-DRT_NO_DRAFT, as make firmware builds with
# DRAFT=0): the same bytes, and --draft refused.
build=build/pruned/nodraft
if $MAKE -s HOST_BUILD="$build" HOST_OPT="$PRUNED_OPT" RT_DEFS=-DRT_NO_DRAFT \
        "$build/fixtrace" \
        >"$tmp/build.log" 2>&1; then
    "$build/fixtrace" -q -W 64 -H 48 -o "$tmp/nd.ppm" scenes/seed.scene &&
        cmp -s "$tmp/seed.ppm" "$tmp/nd.ppm" && ok ||
        bad "the build with -DRT_NO_DRAFT renders the seed differently"
    "$build/fixtrace" -q --draft 64 -W 8 -H 8 -o "$tmp/d.ppm" \
        scenes/seed.scene 2>"$tmp/err"
    rc=$?
    [ $rc -ne 0 ] && [ ! -s "$tmp/d.ppm" ] && ok ||
        bad "a build without drafts drew a draft (status $rc: $(cat "$tmp/err"))"
else
    bad "the build with -DRT_NO_DRAFT failed: $(tail -5 "$tmp/build.log")"
fi

# The configurations compile with -Werror: nothing removed, everything
# removed, each flag alone, and each shape kept alone, with every effect
# and with none (a firmware for a scene of one shape). A static helper
# that only some shapes or effects use must not become unused: GCC reports
# that only when it compiles (-fsyntax-only does not), so the core is
# compiled for real, with the host's compiler and the core's warnings and
# for each board in SUBSET_BOARDS (default "microbit rv32": Cortex-M0 code
# at -Os with the smallest capacities, and RISC-V; "all" for every board)
# with the flags mk/firmware.mk gives the core. Compile only, JOBS (2) at
# a time. A file whose preprocessed text is the same in two
# configurations compiles the same, so each distinct text is compiled
# once. The flag names come from the one list, core/scene/rt_features.h; the
# shapes are the names rt_kind has too (core/scene/rt_scene.h).
names=$(sed -nE 's/^ *X\(([A-Z]+), .*/\1/p' core/scene/rt_features.h)
shapes="" effects=""
for n in $names; do
    if grep -qE "^ *RT_$n( = 0)?,$" core/scene/rt_scene.h; then
        shapes="$shapes $n"
    else
        effects="$effects $n"
    fi
done
no() { local n out=""; for n in "$@"; do out="$out -DRT_NO_$n"; done; echo $out; }
# DRAFT is no scene's effect but a render option (RT_NO_DRAFT, which make
# firmware gives with DRAFT=0): alone, and with everything removed.
configs=("" "$(no $names)" "$(no $names DRAFT)" "-DRT_NO_DRAFT")
for n in $names; do configs+=("-DRT_NO_$n"); done
shape_from=${#configs[@]}
for s in $shapes; do
    others=$(echo $shapes | tr ' ' '\n' | grep -vx "$s" | tr '\n' ' ')
    configs+=("$(no $others)" "$(no $others $effects DRAFT)")
done
[ "$(echo $shapes | wc -w)" -ge 5 ] && [ "$(echo $effects | wc -w)" -ge 8 ] &&
    ok || bad "feature list: shapes '$shapes', effects '$effects'"

# The compilers, as "name|command" (the command with its flags).
core_warn=$($MAKE -s --no-print-directory print-CORE_WARN | sed 's/^[^=]*=//')
compilers=("host|${CC:-gcc} -std=c99 -O2 $core_warn")
boards=${SUBSET_BOARDS:-microbit rv32}
[ "$boards" = all ] &&
    boards=$(ls mk/boards/*.mk | sed 's|.*/||; s|\.mk$||' | tr '\n' ' ')
for b in $boards; do
    cc=$($MAKE -s --no-print-directory print-FW_CC BOARD="$b" |
        sed 's/^[^=]*=//')
    if ! command -v "$cc" >/dev/null; then
        echo "SKIPPED: the configurations for BOARD=$b ($cc missing)"
        skip=$((skip + 1))
        continue
    fi
    # PRUNE=0: the board's capacities as -D options; the configuration
    # takes the place of the generated fw_effects.h. DRAFT=1: draft
    # renders kept (RT_NO_DRAFT comes with the configuration).
    fl=$($MAKE -s --no-print-directory print-FW_CFLAGS BOARD="$b" PRUNE=0 \
        DRAFT=1 |
        sed 's/^[^=]*=//; s/-include [^ ]*//; s/ -g / /')
    compilers+=("$b|$cc $fl $core_warn")
done

# The configurations each compiler takes (indices into configs): the host
# every one; a board the full core, everything removed, and each shape
# alone with every effect and with none. The CPU shows only in core/fx,
# whose choices are constants in conditions like the removal flags', so
# what the flags alone can break the host finds; the boards add the
# cores a one-shape firmware gets, with their own types and back-ends.
cfgs_of() {
    if [ "$1" = 0 ]; then
        echo "${!configs[@]}"
    else
        echo 0 1 2 3 $(seq "$shape_from" $((${#configs[@]} - 1)))
    fi
}

# throttle: waits while JOBS jobs run.
throttle() { while [ "$(jobs -rp | wc -l)" -ge "${JOBS:-2}" ]; do wait -n; done; }
# Preprocess: $tmp/cfg/C.K lists "file hash" for compiler C, configuration
# K. One preprocessor run takes every file of a configuration (starting a
# compiler per file cost more than the preprocessing); each file's text is
# its part of the output, from the line marker that opens it (no flags
# after the name) to the next file's.
split_hash() {
    awk -v dir="$1" '
        /^# [01] "core\/[^"]*\.c"$/ {
            name = $3; gsub(/"/, "", name)
            if (name != cur) {
                if (out != "") close(out)
                cur = name; out = name; gsub(/\//, "%", out)
                out = dir "/" out; printf "" >out
            }
        }
        out != "" { print >>out }'
    (cd "$1" && md5sum -- *) | awk '{ f = $2; gsub(/%/, "/", f); print f, $1 }'
}
mkdir -p "$tmp/cfg" "$tmp/cc" "$tmp/pp"
nfiles=$(ls core/*/*.c | wc -l)
for c in "${!compilers[@]}"; do
    for k in $(cfgs_of "$c"); do
        (
            d="$tmp/pp/$c.$k"
            mkdir -p "$d"
            # shellcheck disable=SC2086
            ${compilers[$c]#*|} ${configs[$k]} $CORE_INC -E core/*/*.c \
                2>"$d.err" | split_hash "$d" >"$tmp/cfg/$c.$k"
            # A preprocessing error (an #error) leaves no trace in the
            # text: then each file compiles with this configuration, which
            # reports it.
            if [ -s "$d.err" ]; then
                sed -i "s/\$/-$k/" "$tmp/cfg/$c.$k"
            fi
            rm -rf "$d" "$d.err"
        ) &
        throttle
    done
done
wait
# A file the split missed would go unchecked.
for f in "$tmp"/cfg/*; do
    [ "$(wc -l <"$f")" = "$nfiles" ] ||
        bad "preprocessing ${f##*/} gave $(wc -l <"$f") of $nfiles files"
done
# Compile each distinct text once, with the first configuration that has it.
declare -A seen=()
for c in "${!compilers[@]}"; do
    for k in $(cfgs_of "$c"); do
        while read -r f h; do
            [ -n "${seen[$c.$h]:-}" ] && continue
            seen[$c.$h]=1
            (
                # shellcheck disable=SC2086
                ${compilers[$c]#*|} ${configs[$k]} $CORE_INC -c "$f" \
                    -o "$tmp/cc/$c.$h.o" >"$tmp/cc/$c.$h.log" 2>&1
                echo $? >"$tmp/cc/$c.$h.rc"
            ) &
            throttle
        done <"$tmp/cfg/$c.$k"
    done
done
wait
for c in "${!compilers[@]}"; do
    for k in $(cfgs_of "$c"); do
        failed=""
        while read -r f h; do
            [ "$(cat "$tmp/cc/$c.$h.rc" 2>/dev/null)" = 0 ] ||
                failed="$failed $(grep -m 1 -E ': (error|warning):' \
                    "$tmp/cc/$c.$h.log" || echo "$f does not compile")"
        done <"$tmp/cfg/$c.$k"
        [ -z "$failed" ] && ok ||
            bad "${compilers[$c]%%|*}: the core does not compile with" \
                "[${configs[$k]:-nothing removed}]:$failed"
    done
done
echo "configurations: $(for c in "${!compilers[@]}"; do
    printf '%s %s, ' "${compilers[$c]%%|*}" "$(cfgs_of "$c" | wc -w)"; done)" \
    "$(ls "$tmp"/cc/*.rc | wc -l) distinct compilations"

if [ $skip -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ $fail -eq 0 ]
