#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The double reference checked from outside: POV-Ray 3.7 renders scenes of
# ours, translated by tests/scene2pov.c (which reads them with the core's
# own parser and states the mapping of the two models), and each image is
# compared with `fixtrace --reference` at 320x240: its PSNR must reach the
# scene's floor below, and it may have no more speckles (pixels off by more
# than 64/255 where the reference's 3x3 neighbourhood is smooth) than the
# floor allows. Scenes with bump noise, which POV-Ray does not have, are
# rendered without it. Needs povray (Debian's povray package).
set -u
cd "$(dirname "$0")/.."
HOST_BUILD=${HOST_BUILD:-build/posix}
FT=${FIXTRACE:-$HOST_BUILD/fixtrace}
S2P=$HOST_BUILD/tests/scene2pov
if ! command -v povray >/dev/null 2>&1; then
    echo "SKIPPED: POV-Ray cross-check (needs povray; apt-get install povray)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# scene                          PSNR floor (dB)  most speckles
while read -r scene floor speckles; do
    case $scene in '#'*|'') continue ;; esac
    name=$(basename "$scene" .scene)
    sed -E 's/ bump [0-9.]+ [0-9.]+//' "$scene" >"$tmp/$name.scene"
    if ! "$S2P" "$tmp/$name.scene" 320 240 >"$tmp/$name.pov" 2>"$tmp/err" ||
        ! povray "+I$tmp/$name.pov" "+O$tmp/$name.pov.ppm" +FP +W320 +H240 \
            -A -D File_Gamma=1.0 >"$tmp/pov.log" 2>&1 ||
        ! "$FT" -q --reference -W 320 -H 240 -o "$tmp/$name.ref.ppm" \
            "$tmp/$name.scene" 2>>"$tmp/err"; then
        fail=$((fail + 1))
        echo "FAILED: $name does not render: $(tail -c 400 "$tmp/err" "$tmp/pov.log")"
        continue
    fi
    "$FT" compare "$tmp/$name.pov.ppm" "$tmp/$name.ref.ppm" >"$tmp/out" 2>&1
    psnr=$(awk '/^PSNR/ {print $2}' "$tmp/out")
    sp=$(awk '/^outliers/ {print $6}' "$tmp/out")
    echo "$name: POV-Ray against the reference: PSNR $psnr dB, $sp speckles (floor $floor dB, at most $speckles)"
    if awk -v p="$psnr" -v f="$floor" -v s="$sp" -v m="$speckles" \
        'BEGIN {exit !(p >= f && s <= m)}'; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAILED: $name: POV-Ray and the reference disagree: $(tr '\n' ' ' <"$tmp/out")"
    fi
done <<'LIST'
scenes/diffuse.scene             51   0
scenes/primitives.scene          61   0
scenes/mirrors.scene             42.5 0
scenes/textures.scene            42.5 0
tests/pov/stripes_caps.scene     41.5 0
tests/pov/glass_spheres.scene    43   1
LIST
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
