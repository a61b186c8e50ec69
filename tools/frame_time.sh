#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Turns the measured instructions per pixel (the seed scene at 320x240,
# 1 spp, firmware built for the scene: the "tables" rows of the table in
# port/baremetal/README.md, written by tools/boards_table.sh) into
# estimated seconds per frame at common clocks, as the markdown section
# README.md holds between its frame-time markers.
#
#   tools/frame_time.sh           print the section
#   tools/frame_time.sh --write   put it into README.md
#   tools/frame_time.sh --check   exit 1 if README.md's section differs
#                                 (tests/suite_figures.sh)
set -eu
cd "$(dirname "$0")/.."
SRC=port/baremetal/README.md
BEGIN='<!-- begin frame-time (tools/frame_time.sh) -->'
END='<!-- end frame-time -->'
CLOCKS="48 72 133 240"
PIXELS=76800 # 320 x 240

section() {
    echo "$BEGIN"
    echo "| board | instructions/pixel | $(for c in $CLOCKS; do printf '%s MHz | ' $c; done | sed 's/ | $//') |"
    echo "|---|---|$(for c in $CLOCKS; do printf -- '---|'; done)"
    awk -F'|' -v clocks="$CLOCKS" -v px=$PIXELS '
        $3 ~ /^ *tables *$/ {
            b = $2; gsub(/ /, "", b); ipp = $5; gsub(/[ ,]/, "", ipp)
            n = split(clocks, c, " ")
            printf "| %s | %s |", b, $5 ~ /^ / ? substr($5, 2, length($5) - 2) : $5
            for (i = 1; i <= n; i++) printf " %.2f s |", ipp * px / (c[i] * 1e6)
            printf "\n"; rows++ }
        END { if (!rows) exit 1 }' "$SRC"
    echo "$END"
}

case "${1:-}" in
--write|--check)
    new=$(section) || { echo "frame_time: no tables rows in $SRC" >&2; exit 1; }
    awk -v b="$BEGIN" -v e="$END" -v new="$new" '
        $0 == b { print new; skip = 1; found = 1; next }
        $0 == e { skip = 0; next }
        !skip { print }
        END { if (!found) exit 1 }' README.md >README.md.tmp ||
        { rm -f README.md.tmp; echo "frame_time: README.md has no '$BEGIN' line" >&2; exit 1; }
    if [ "$1" = --check ]; then
        if cmp -s README.md.tmp README.md; then rm -f README.md.tmp; exit 0; fi
        diff README.md README.md.tmp | head -n 20 >&2
        rm -f README.md.tmp
        exit 1
    fi
    if cmp -s README.md.tmp README.md; then rm -f README.md.tmp
    else mv README.md.tmp README.md; echo "updated README.md"; fi ;;
"") section ;;
*) echo "usage: tools/frame_time.sh [--write|--check]" >&2; exit 2 ;;
esac
