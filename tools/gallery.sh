#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Renders every scene in scenes/ to a PNG with fixtrace itself, for the
# README's gallery:
#
#   tools/gallery.sh [-W WIDTH] [-H HEIGHT] [-s SPP] [OUTDIR]
#
# Defaults: 320x240 at 4 spp into docs/img/ (`make gallery` runs this).
# fixtrace writes stored (uncompressed) PNGs, about 230 KB at 320x240, so
# keep the size modest. The images are deterministic: the same tree gives
# the same bytes on every machine. FIXTRACE names the binary to use
# (default build/posix/fixtrace; run `make` first).
set -eu
cd "$(dirname "$0")/.."

width=320 height=240 spp=4
usage() {
    echo "usage: tools/gallery.sh [-W WIDTH] [-H HEIGHT] [-s SPP] [OUTDIR]" >&2
    exit 2
}
while getopts W:H:s:h opt; do
    case $opt in
    W) width=$OPTARG ;;
    H) height=$OPTARG ;;
    s) spp=$OPTARG ;;
    *) usage ;;
    esac
done
shift $((OPTIND - 1))
[ $# -le 1 ] || usage
out=${1:-docs/img}

ft=${FIXTRACE:-build/posix/fixtrace}
if [ ! -x "$ft" ]; then
    echo "gallery: $ft not found; build it first with 'make'" >&2
    exit 1
fi
jobs=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
[ "$jobs" -le 64 ] || jobs=64

mkdir -p "$out"
n=0
for scene in scenes/*.scene; do
    name=$(basename "$scene" .scene)
    # fixtrace renders to a temporary file and renames it into place, so
    # a failure never leaves a broken picture behind.
    "$ft" -q -j "$jobs" -W "$width" -H "$height" -s "$spp" \
        -o "$out/$name.png" "$scene"
    echo "  $out/$name.png"
    n=$((n + 1))
done
echo "gallery: $n scenes at ${width}x${height}, spp $spp, in $out/"
