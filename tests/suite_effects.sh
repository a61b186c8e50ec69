#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Simulate only what a scene calls for (docs/effects.md):
# - with --stats, a scene without an effect casts no rays of that kind;
# - for every scene, the host renderer built with the RT_NO_* flags that
#   `fixtrace --build-flags` derives renders the very same bytes as the full
#   build;
# - a pruned build refuses a scene that needs a removed effect, clearly.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
MAKE=${MAKE:-make}
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

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
    build="build/pruned/$name"
    if $MAKE -s HOST_BUILD="$build" RT_DEFS="$flags" "$build/fixtrace" \
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

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
