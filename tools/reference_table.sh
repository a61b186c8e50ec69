#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Prints the README's accuracy table: every scene at 320x240, 1 spp, the
# fixed-point core against the double reference (fixtrace compare).
set -eu
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| scene | PSNR (dB) | max error | pixels off by > 2/255 | outliers (> 64/255), away from edges |"
echo "|---|---|---|---|---|"
for scene in scenes/*.scene; do
    "$FT" -q -W 320 -H 240 -s 1 -o "$tmp/f.ppm" "$scene"
    "$FT" -q --reference -W 320 -H 240 -s 1 -o "$tmp/r.ppm" "$scene"
    "$FT" compare "$tmp/f.ppm" "$tmp/r.ppm" | awk -v n="$(basename "$scene" .scene)" '
        /^PSNR/ {p = $2} /^max error/ {m = $3}
        /^off by/ {b = $5 " %"} /^outliers/ {o = $4 ", " $6}
        END {printf "| %s | %s | %s | %s | %s |\n", n, p, m, b, o}'
done
