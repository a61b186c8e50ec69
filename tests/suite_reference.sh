#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every scene, rendered by the fixed-point core and by the double
# reference at 320x240, 1 spp, is close to the reference
# (tests/reference_floors.txt); the seed scene meets the accuracy target:
# PSNR >= 45 dB, at least 99.5% of pixels within 2/255 and no outlier
# pixel away from a silhouette edge.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
floor_of() {
    awk -v n="$1" '$1 == n {print $2; f = 1} $1 == "default" {d = $2}
                   END {if (!f) print d}' tests/reference_floors.txt
}
for scene in scenes/*.scene; do
    name=$(basename "$scene" .scene)
    "$FT" -q -W 320 -H 240 -s 1 -o "$tmp/f.ppm" "$scene" &&
        "$FT" -q --reference -W 320 -H 240 -s 1 -o "$tmp/r.ppm" "$scene" ||
        { fail=$((fail + 1)); echo "FAILED: $name does not render"; continue; }
    floor=$(floor_of "$name")
    if "$FT" compare "$tmp/f.ppm" "$tmp/r.ppm" --min-psnr "$floor" \
            >"$tmp/out" 2>&1; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAILED: $name below ${floor} dB: $(tr '\n' ' ' <"$tmp/out")"
    fi
    grep PSNR "$tmp/out" | sed "s/^/$name: /"
done
"$FT" -q -W 320 -H 240 -o "$tmp/f.ppm" scenes/seed.scene
"$FT" -q --reference -W 320 -H 240 -o "$tmp/r.ppm" scenes/seed.scene
if "$FT" compare "$tmp/f.ppm" "$tmp/r.ppm" --min-psnr 70 --max-bad 0.01 \
        --max-interior-outliers 0 >"$tmp/out" 2>&1; then
    pass=$((pass + 1))
else
    fail=$((fail + 1))
    echo "FAILED: seed misses its target: $(tr '\n' ' ' <"$tmp/out")"
fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
