#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Windows and panels from the command line:
# - `--window X0,Y0,X1,Y1` writes exactly the crop (netpbm's pnmcut) of the
#   full render, on several scenes at an odd size, at 1, 4 and 9 spp, with
#   adaptive anti-aliasing, drafts and both, dithered RGB565, with -j 2,
#   for windows touching each edge, single pixels and odd rectangles;
# - `--format mono|mono-page|grey4` with `--dither ordered|diffusion`:
#   the PBM/PGM picture and the .raw panel bytes hold the same pixels
#   (mono rows MSB-first with 1 lit, SSD1306 pages, grey nibbles), the
#   dithers differ, an ordered window is the crop of the full picture;
# - bad windows and format combinations are refused with a message.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

for t in pnmcut python3; do
    if ! command -v "$t" >/dev/null; then
        echo "SKIPPED: window and panel test ($t missing; install netpbm" \
            "python3)"
        echo "0 passed, 0 failed, 1 skipped"
        exit 0
    fi
done

# expect STATUS PATTERN -- command...: exit status and a stderr match.
expect() {
    local want=$1 pat=$2; shift 3
    "$@" >"$tmp/out" 2>"$tmp/err"
    local rc=$?
    if [ "$rc" -ne "$want" ]; then
        bad "'$*' exited $rc, want $want; stderr: $(head -c 300 "$tmp/err")"
    elif [ -n "$pat" ] && ! grep -qE -- "$pat" "$tmp/err"; then
        bad "'$*' said: $(head -c 300 "$tmp/err"), want /$pat/"
    else
        ok
    fi
}

W=77 H=45
WINDOWS="0,0,77,45 0,0,1,1 76,44,77,45 76,0,77,45 0,44,77,45 0,0,9,45
         38,22,39,23 5,3,31,17 50,30,77,45 0,20,77,27 13,0,14,8 1,1,76,44"

# window_check NAME OPTIONS...: every window of WINDOWS is the crop.
window_check() {
    local name=$1; shift
    local scene=$1; shift
    if ! "$FT" -q -W $W -H $H "$@" -o "$tmp/full.ppm" "$scene"; then
        bad "$name: full render failed"
        return
    fi
    for win in $WINDOWS; do
        IFS=, read -r x0 y0 x1 y1 <<<"$win"
        pnmcut -left "$x0" -top "$y0" -width $((x1 - x0)) \
            -height $((y1 - y0)) "$tmp/full.ppm" >"$tmp/crop.ppm"
        if ! "$FT" -q -W $W -H $H "$@" --window "$win" -o "$tmp/win.ppm" \
            "$scene"; then
            bad "$name: --window $win failed"
        elif ! cmp -s "$tmp/crop.ppm" "$tmp/win.ppm"; then
            bad "$name: --window $win differs from the crop"
        else
            ok
        fi
    done
}

for scene in scenes/seed.scene scenes/glass.scene scenes/textures.scene \
    scenes/meshes.scene; do
    n=$(basename "$scene" .scene)
    window_check "$n 1spp" "$scene" -s 1
    window_check "$n 9spp" "$scene" -s 9
    window_check "$n adaptive" "$scene" -s 4 --adaptive 8
    window_check "$n draft" "$scene" -s 1 --draft 32
    window_check "$n adaptive draft" "$scene" -s 4 --adaptive 8 --draft 32
done
window_check "seed 565 dither" scenes/seed.scene -s 1 --format rgb565be \
    --dither
window_check "seed -j 2 draft" scenes/seed.scene -j 2 -s 1 --draft 16

# --- panels ------------------------------------------------------------
S=scenes/seed.scene
for d in ordered diffusion; do
    "$FT" -q -W $W -H $H --format mono --dither $d -o "$tmp/m-$d.pbm" $S &&
        "$FT" -q -W $W -H $H --format mono --dither $d -o "$tmp/m-$d.raw" \
            $S &&
        "$FT" -q -W $W -H $H --format mono-page --dither $d \
            -o "$tmp/p-$d.raw" $S &&
        "$FT" -q -W $W -H $H --format mono-page --dither $d \
            -o "$tmp/p-$d.pbm" $S &&
        "$FT" -q -W $W -H $H --format grey4 --dither $d -o "$tmp/g-$d.pgm" \
            $S &&
        "$FT" -q -W $W -H $H --format grey4 --dither $d -o "$tmp/g-$d.raw" \
            $S || bad "panel renders with --dither $d failed"
    # The same pixels in each layout.
    if python3 - "$tmp" "$d" $W $H <<'EOF'; then ok; else bad "panel layouts differ ($d)"; fi
import sys
tmp, d, w, h = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
def read(p):
    return open(f"{tmp}/{p}", "rb").read()
def netpbm(data, magic):
    # header: magic, width, height (and maxval for P5), one byte of space
    fields, i = [], 0
    while len(fields) < (3 if magic == b"P4" else 4):
        while data[i:i + 1].isspace():
            i += 1
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        fields.append(data[i:j])
        i = j
    assert fields[0] == magic and int(fields[1]) == w and int(fields[2]) == h
    return data[i + 1:]
stride = (w + 7) // 8
rows = read(f"m-{d}.raw")
assert len(rows) == stride * h
lit = [[(rows[y * stride + x // 8] >> (7 - x % 8)) & 1 for x in range(w)]
       for y in range(h)]
pbm = netpbm(read(f"m-{d}.pbm"), b"P4")
assert len(pbm) == stride * h
for y in range(h):
    for x in range(w):
        assert (pbm[y * stride + x // 8] >> (7 - x % 8)) & 1 == 1 - lit[y][x]
    pad = pbm[y * stride + stride - 1] & (0xFF >> (w % 8) if w % 8 else 0)
    assert pad == 0
assert read(f"p-{d}.pbm") == read(f"m-{d}.pbm")
pages = read(f"p-{d}.raw")
assert len(pages) == w * ((h + 7) // 8)
for y in range(h):
    for x in range(w):
        assert (pages[(y // 8) * w + x] >> (y % 8)) & 1 == lit[y][x]
g = read(f"g-{d}.raw")
pgm = netpbm(read(f"g-{d}.pgm"), b"P5")
gs = (w + 1) // 2
assert len(g) == gs * h and len(pgm) == w * h
for y in range(h):
    for x in range(w):
        b = g[y * gs + x // 2]
        assert (b & 15 if x % 2 else b >> 4) == pgm[y * w + x] <= 15
    assert w % 2 == 0 or g[y * gs + gs - 1] & 15 == 0
some = sum(map(sum, lit))
assert 0 < some < w * h
EOF
done
cmp -s "$tmp/m-ordered.raw" "$tmp/m-diffusion.raw" &&
    bad "mono: ordered and diffusion gave the same bytes" || ok
cmp -s "$tmp/g-ordered.raw" "$tmp/g-diffusion.raw" &&
    bad "grey4: ordered and diffusion gave the same bytes" || ok
"$FT" -q -W $W -H $H --format mono -o "$tmp/m-none.raw" $S
cmp -s "$tmp/m-ordered.raw" "$tmp/m-none.raw" &&
    bad "mono: ordered and no dither gave the same bytes" || ok
# An ordered window is the crop of the full picture (the dither follows
# the frame's columns and rows).
for f in "mono m-ordered.pbm pbm" "grey4 g-ordered.pgm pgm"; do
    set -- $f
    "$FT" -q -W $W -H $H --format "$1" --dither ordered --window 5,3,31,17 \
        -o "$tmp/w.$3" $S
    pnmcut -left 5 -top 3 -width 26 -height 14 "$tmp/$2" >"$tmp/c.$3"
    cmp -s "$tmp/w.$3" "$tmp/c.$3" && ok ||
        bad "$1: an ordered window differs from the crop"
done

# --- refused -------------------------------------------------------------
expect 2 'reaches past' -- "$FT" -W 20 -H 10 --window 0,0,21,10 -o \
    "$tmp/x.ppm" $S
expect 2 'is empty' -- "$FT" --window 4,0,4,10 -o "$tmp/x.ppm" $S
expect 2 'X0,Y0,X1,Y1' -- "$FT" --window 1,2,3 -o "$tmp/x.ppm" $S
expect 2 'X0,Y0,X1,Y1' -- "$FT" --window 1,2,3,x -o "$tmp/x.ppm" $S
expect 2 'X0,Y0,X1,Y1' -- "$FT" --window -1,2,3,4 -o "$tmp/x.ppm" $S
expect 2 'reference' -- "$FT" --reference --window 0,0,2,2 -o \
    "$tmp/x.ppm" $S
expect 2 'diffusion needs' -- "$FT" --format rgb565le --dither diffusion \
    -o "$tmp/x.ppm" $S
expect 2 'not PNG' -- "$FT" --format mono -o "$tmp/x.png" $S
expect 2 'needs --format mono' -- "$FT" -o "$tmp/x.pbm" $S
expect 2 'must be rgb888' -- "$FT" --format mono1 -o "$tmp/x.pbm" $S
[ ! -e "$tmp/x.ppm" ] && [ ! -e "$tmp/x.png" ] && [ ! -e "$tmp/x.pbm" ] &&
    ok || bad "a refused command wrote a file"

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
