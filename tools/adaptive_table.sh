#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Prints the adaptive anti-aliasing table of docs/effects.md: the seed
# scene's primary rays (fixtrace --stats) and PSNR against the reference at
# 16 spp (fixtrace compare), at 640x480 and 320x240. With --rays, only the
# 320x240 rows' ray counts (what tests/suite_docs.sh checks; no reference
# renders).
set -eu
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
SEED=scenes/seed.scene
RAYS_ONLY=0
[ "${1:-}" = --rays ] && RAYS_ONLY=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
th() { echo "$1" | sed -E ':a; s/^([0-9]+)([0-9]{3})/\1,\2/; ta'; }
row() { # W H label args...
    local w=$1 h=$2 label=$3; shift 3
    "$FT" -q --stats -W "$w" -H "$h" "$@" -o "$tmp/f.ppm" "$SEED" 2>"$tmp/st"
    local rays full pct=""
    rays=$(sed -n 's/^primary_rays //p' "$tmp/st")
    full=$((w * h * 16))
    case " $* " in *" --adaptive 16 "*)
        pct=" ($(awk -v r="$rays" -v f="$full" 'BEGIN { printf "%.1f%%", 100 * r / f }'))";;
    esac
    if [ $RAYS_ONLY = 1 ]; then
        echo "| ${w}x$h | $label | $(th "$rays")$pct |"
        return
    fi
    [ -f "$tmp/ref$w.ppm" ] || "$FT" -q --reference -s 16 -W "$w" -H "$h" \
        -o "$tmp/ref$w.ppm" "$SEED"
    local p
    p=$("$FT" compare "$tmp/f.ppm" "$tmp/ref$w.ppm" | awk '/^PSNR/ {print $2}')
    echo "| ${w}x$h | $label | $(th "$rays")$pct | $p dB |"
}
if [ $RAYS_ONLY = 0 ]; then
    echo "| size | mode | primary rays | PSNR vs reference |"
    echo "|---|---|---|---|"
    row 640 480 "16 spp, every pixel" -s 16
    row 640 480 '`--adaptive 16`' -s 16 --adaptive 16
fi
row 320 240 "1 spp" -s 1
row 320 240 "16 spp, every pixel" -s 16
row 320 240 '`--adaptive 16`' -s 16 --adaptive 16
row 320 240 '`--adaptive 8`' -s 16 --adaptive 8
row 320 240 '`--adaptive 4`' -s 16 --adaptive 4
