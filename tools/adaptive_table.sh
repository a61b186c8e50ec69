#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The adaptive anti-aliasing table of docs/effects.md: the seed scene's
# primary rays (fixtrace --stats) and PSNR against the reference at 16 spp
# (fixtrace compare), at 640x480 and 320x240. Everything is measured on
# the host, in a few seconds.
#
#   tools/adaptive_table.sh           print the table
#   tools/adaptive_table.sh --write   put it into docs/effects.md
#   tools/adaptive_table.sh --check   exit 1 if docs/effects.md's table
#                                     differs (tests/suite_figures.sh)
set -eu
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
SEED=scenes/seed.scene
DOC=docs/effects.md
BEGIN='<!-- begin adaptive (tools/adaptive_table.sh) -->'
END='<!-- end adaptive -->'
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
th() { echo "$1" | sed -E ':a; s/^([0-9]+)([0-9]{3})/\1,\2/; ta'; }
row() { # W H label args...
    local w=$1 h=$2 label=$3; shift 3
    "$FT" -q --stats -W "$w" -H "$h" "$@" -o "$tmp/f.ppm" "$SEED" 2>"$tmp/st"
    local rays full pct="" p
    rays=$(sed -n 's/^primary_rays //p' "$tmp/st")
    full=$((w * h * 16))
    case " $* " in *" --adaptive 16 "*)
        pct=" ($(awk -v r="$rays" -v f="$full" 'BEGIN { printf "%.1f%%", 100 * r / f }'))";;
    esac
    [ -f "$tmp/ref$w.ppm" ] || "$FT" -q --reference -s 16 -W "$w" -H "$h" \
        -o "$tmp/ref$w.ppm" "$SEED"
    p=$("$FT" compare "$tmp/f.ppm" "$tmp/ref$w.ppm" | awk '/^PSNR/ {print $2}')
    echo "| ${w}x$h | $label | $(th "$rays")$pct | $p dB |"
}
section() {
    echo "$BEGIN"
    echo "| size | mode | primary rays | PSNR vs reference |"
    echo "|---|---|---|---|"
    row 640 480 "16 spp, every pixel" -s 16
    row 640 480 '`--adaptive 16`' -s 16 --adaptive 16
    row 320 240 "1 spp" -s 1
    row 320 240 "16 spp, every pixel" -s 16
    row 320 240 '`--adaptive 16`' -s 16 --adaptive 16
    row 320 240 '`--adaptive 8`' -s 16 --adaptive 8
    row 320 240 '`--adaptive 4`' -s 16 --adaptive 4
    echo "$END"
}

case "${1:-}" in
--write|--check)
    section >"$tmp/new"
    awk -v b="$BEGIN" -v e="$END" -v new="$tmp/new" '
        $0 == b { while ((getline l < new) > 0) print l; skip = 1; found = 1; next }
        $0 == e { skip = 0; next }
        !skip { print }
        END { if (!found) exit 1 }' "$DOC" >"$tmp/doc" ||
        { echo "adaptive_table: $DOC has no '$BEGIN' line" >&2; exit 1; }
    if cmp -s "$tmp/doc" "$DOC"; then exit 0; fi
    if [ "$1" = --check ]; then
        diff "$DOC" "$tmp/doc" | head -n 20 >&2
        exit 1
    fi
    cp "$tmp/doc" "$DOC"
    echo "updated $DOC" ;;
"") section | sed '1d;$d' ;;
*) echo "usage: tools/adaptive_table.sh [--write|--check]" >&2; exit 2 ;;
esac
