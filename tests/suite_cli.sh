#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The host command as a user meets it: every bad argument and bad scene gets
# a clear message and the right exit status, a failed or interrupted render
# leaves an existing output untouched and no temporary file behind, and
# good renders are byte-identical however they are made (-j, stdout, PNG).
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
pass=0 fail=0 skip=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
SEED=scenes/seed.scene

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

# expect STATUS PATTERN -- command...: exit status and a stderr match.
expect() {
    local want=$1 pat=$2; shift 3
    "$@" >"$tmp/out" 2>"$tmp/err"
    local rc=$?
    if [ "$rc" -ne "$want" ]; then
        bad "'$*' exited $rc, want $want; stderr: $(head -c 300 "$tmp/err")"
    elif [ -n "$pat" ] && ! grep -qE -- "$pat" "$tmp/err" "$tmp/out"; then
        bad "'$*' said: $(head -c 300 "$tmp/err"), want /$pat/"
    else
        ok
    fi
}

# --- usage ------------------------------------------------------------
expect 0 'SYNOPSIS' -- "$FT" --help
expect 0 'EXAMPLES' -- "$FT" -h
expect 0 '^fixtrace [0-9]' -- "$FT" --version
# The version is fixtrace_version.h's, and --help names every subcommand.
want=$(sed -nE 's/^#define FIXTRACE_VERSION_(MAJOR|MINOR|PATCH) +([0-9]+).*/\2/p' \
    core/fx/fixtrace_version.h | paste -sd. -)
expect 0 "^fixtrace ${want//./\\.} " -- "$FT" --version
expect 0 'fixtrace receive -o' -- "$FT" --help
expect 0 'fixtrace compare A' -- "$FT" --help

# -W or -H alone keeps the scene's aspect (seed: 320x240).
size_of() { sed -n 2p "$1"; }
"$FT" -q -W 64 -o "$tmp/w.ppm" "$SEED" && [ "$(size_of "$tmp/w.ppm")" = "64 48" ] &&
    ok || bad "-W 64 alone: $(size_of "$tmp/w.ppm"), want 64 48"
"$FT" -q -H 30 -o "$tmp/h.ppm" "$SEED" && [ "$(size_of "$tmp/h.ppm")" = "40 30" ] &&
    ok || bad "-H 30 alone: $(size_of "$tmp/h.ppm"), want 40 30"
"$FT" -q -W 33 -H 7 -o "$tmp/wh.ppm" "$SEED" && [ "$(size_of "$tmp/wh.ppm")" = "33 7" ] &&
    ok || bad "-W 33 -H 7: $(size_of "$tmp/wh.ppm"), want 33 7"
"$FT" -q -W 1 -o "$tmp/w1.ppm" "$SEED" && [ "$(size_of "$tmp/w1.ppm")" = "1 1" ] &&
    ok || bad "-W 1 alone: $(size_of "$tmp/w1.ppm"), want 1 1"

# Quoted mesh paths: an unclosed quote is reported at the quote, and a
# closed one may hold spaces and '#'.
mkdir -p "$tmp/my models"
cp scenes/models/torus.obj "$tmp/my models/ring #2.obj"
printf '%s\n' 'camera eye 0 2 -6 look 0 0 0' 'light 5 5 -5' \
    'material m color 1 1 1' 'mesh file "models/torus.obj material m' \
    >"$tmp/unclosed.scene"
expect 2 'unclosed.scene:4:11: error: unclosed quote' -- "$FT" -q -o "$tmp/u.ppm" "$tmp/unclosed.scene"
printf '%s\n' 'camera eye 0 2 -6 look 0 0 0' 'light 5 5 -5' \
    'material m color 1 1 1' 'mesh file "my models/ring #2.obj" material m # c' \
    >"$tmp/spaced.scene"
expect 0 '' -- "$FT" -q -W 16 -o "$tmp/spaced.ppm" "$tmp/spaced.scene"
[ -s "$tmp/spaced.ppm" ] && ok || bad "a quoted path with spaces rendered nothing"

# receive given no frame: a clear message, and no binary on the terminal.
"$FT" -q -W 16 -o "$tmp/bin.ppm" "$SEED"
"$FT" receive -o "$tmp/r.ppm" <"$tmp/bin.ppm" >"$tmp/out" 2>"$tmp/err"
rc=$?
if [ $rc -ne 1 ] || ! grep -q 'no image frame in stdin' "$tmp/err" ||
    ! grep -q 'not text' "$tmp/err"; then
    bad "receive of a PPM: status $rc, $(head -c 300 "$tmp/err")"
elif LC_ALL=C grep -q '[^[:print:][:space:]]' "$tmp/err" ||
    [ "$(grep -c . "$tmp/err")" -gt 4 ]; then
    bad "receive echoes the binary input: $(LC_ALL=C tr -c '[:print:]\n' '?' <"$tmp/err" | head -c 200)"
else
    ok
fi
[ ! -e "$tmp/r.ppm" ] && ok || bad "receive wrote an image without a frame"
expect 2 'no scene file given' -- "$FT"
expect 2 'unknown option' -- "$FT" --bogus "$SEED"
expect 2 'more than one scene' -- "$FT" "$SEED" "$SEED"
expect 2 'cannot open scene' -- "$FT" -o "$tmp/x.ppm" "$tmp/missing.scene"
expect 2 'given twice' -- "$FT" -o a.ppm -o b.ppm "$SEED"
expect 2 'needs a file name' -- "$FT" -o '' "$SEED"
expect 2 '--dither needs' -- "$FT" --dither -o "$tmp/x.ppm" "$SEED"
expect 2 'format must be' -- "$FT" --format rgb999 "$SEED"
expect 2 "write '-j 2'" -- "$FT" -j2 "$SEED"
expect 2 "write '--width 640'" -- "$FT" --width=640 "$SEED"
expect 2 'must end in .ppm or .png .or .raw, .bin or .h' -- "$FT" -q -o "$tmp/x.jpg" "$SEED"
[ ! -e "$tmp/x.jpg" ] && ok || bad "a .jpg output was written"
expect 2 'renders at 1 spp, so add -s' -- "$FT" -q --adaptive 8 -o "$tmp/x.ppm" "$SEED"
cp "$SEED" "$tmp/same.ppm"
expect 2 'is the scene file itself' -- "$FT" -q -o "$tmp/same.ppm" "$tmp/same.ppm"
cmp -s "$SEED" "$tmp/same.ppm" && ok || bad "the scene file was overwritten"
for opt in -W --width -H --height -s --spp -d --depth -j --jobs -o --output --format; do
    expect 2 "needs a value" -- "$FT" "$SEED" "$opt"
done
for opt in -W -H; do
    for v in 0 -1 4097 99999999999999999999 abc 1.5 '' ' 8'; do
        expect 2 "$opt (needs a whole number|must be from)" -- "$FT" "$opt" "$v" "$SEED"
    done
done
for v in 0 2 3 17 -4 x; do
    expect 2 '(-s must be|needs a whole number|must be from)' -- "$FT" -s "$v" "$SEED"
done
for v in -1 6 100 x; do
    expect 2 '(-d must be from|needs a whole number)' -- "$FT" -d "$v" "$SEED"
done
for v in 0 65 -2 y; do
    expect 2 '(-j must be from|needs a whole number)' -- "$FT" -j "$v" "$SEED"
done

# --- output safety ------------------------------------------------------
echo "precious" >"$tmp/keep.ppm"
expect 1 'does its directory exist' -- "$FT" -q -W 8 -H 8 -o "$tmp/nodir/x.ppm" "$SEED"
[ ! -e "$tmp/nodir" ] && ok || bad "a missing output directory was created"
mkdir "$tmp/ro" && chmod 555 "$tmp/ro"
if [ "$(id -u)" != 0 ]; then
    expect 1 'cannot write' -- "$FT" -q -W 8 -H 8 -o "$tmp/ro/x.ppm" "$SEED"
else
    ok # root writes anywhere; the missing-directory case covers the path
fi
printf 'camera eye 0 0 -5 look 0 0 0 up 0 1 0 fov 60\nsphere center 0 0 0 radius 1 material nope\n' >"$tmp/bad.scene"
expect 2 'bad.scene:2:[0-9]+: error: .*nope' -- "$FT" -q -o "$tmp/keep.ppm" "$tmp/bad.scene"
[ "$(cat "$tmp/keep.ppm")" = precious ] && ok || bad "a failed render changed the existing output"
ls -a "$tmp" | grep -q '^\.fixtrace-' && bad "a temporary file was left behind" || ok

# SIGINT during a long render: the old file stays, no temporary is left.
"$FT" -q -W 2000 -H 2000 -s 16 -o "$tmp/keep.ppm" "$SEED" 2>"$tmp/int.err" &
pid=$!
sleep 1
kill -INT $pid
wait $pid
rc=$?
[ $rc -eq 130 ] && ok || bad "SIGINT exit status $rc, want 130"
grep -q 'interrupted' "$tmp/int.err" && ok || bad "no 'interrupted' message: $(cat "$tmp/int.err")"
[ "$(cat "$tmp/keep.ppm")" = precious ] && ok || bad "SIGINT changed the existing output"
ls -a "$tmp" | grep -q '^\.fixtrace-' && bad "SIGINT left a temporary file" || ok

# --- good renders -------------------------------------------------------
expect 0 'wrote' -- "$FT" -W 40 -H 30 -o "$tmp/a.ppm" "$SEED"
head -c 2 "$tmp/a.ppm" | grep -q P6 && ok || bad "output is not a P6 PPM"
[ "$(stat -c %s "$tmp/a.ppm")" -eq $((40 * 30 * 3 + 13)) ] && ok || bad "PPM size wrong"
expect 0 '' -- "$FT" -q -j 2 -W 40 -H 30 -o "$tmp/b.ppm" "$SEED"
cmp -s "$tmp/a.ppm" "$tmp/b.ppm" && ok || bad "-j 2 differs from -j 1"
"$FT" -q -W 40 -H 30 -o - "$SEED" >"$tmp/c.ppm" && cmp -s "$tmp/a.ppm" "$tmp/c.ppm" && ok || bad "-o - differs"
# -o - on a terminal: refused before rendering, nothing binary shown.
if command -v script >/dev/null 2>&1; then
    script -qec "$FT -W 40 -H 30 -o - $SEED" /dev/null >"$tmp/tty.out" 2>&1
    rc=$?
    [ $rc -eq 2 ] && ok || bad "-o - on a terminal exited $rc, want 2"
    grep -q 'stdout, which is a terminal' "$tmp/tty.out" && ok ||
        bad "-o - on a terminal: no message ($(head -c 200 "$tmp/tty.out"))"
    grep -q 'P6' "$tmp/tty.out" && bad "-o - wrote the PPM to a terminal" || ok
else
    echo "note: script(1) missing; -o - on a terminal not checked"
fi
expect 0 '' -- "$FT" -q -W 40 -H 30 -o "$tmp/keep.ppm" "$SEED"
cmp -s "$tmp/a.ppm" "$tmp/keep.ppm" && ok || bad "a good render did not replace the old file"
expect 0 '^primary_rays 1200$' -- "$FT" -q --stats -W 40 -H 30 -o "$tmp/s.ppm" "$SEED"
for k in shadow_rays reflection_rays refraction_rays intersection_tests rays_cut render_seconds pixels; do
    grep -q "^$k " "$tmp/err" && ok || bad "--stats lacks $k"
done
# The seed's glass has rays too faint to trace; --trace-all traces them.
grep -qE '^rays_cut [1-9]' "$tmp/err" && ok || bad "the seed cut no rays"
expect 0 '^rays_cut 0$' -- "$FT" -q --stats --trace-all -W 40 -H 30 -o "$tmp/t.ppm" "$SEED"
cmp -s "$tmp/s.ppm" "$tmp/t.ppm" && bad "--trace-all rendered the same bytes" || ok
# Draft renders: --stats splits the pixels into traced and interpolated;
# threads give the same bytes; bad thresholds and the reference refuse.
expect 0 '^traced_pixels 1200$' -- "$FT" -q --stats -W 40 -H 30 -o "$tmp/s.ppm" "$SEED"
grep -q '^interpolated_pixels 0$' "$tmp/err" && ok || bad "a full render interpolated pixels"
expect 0 '^interpolated_pixels [1-9]' -- "$FT" -q --stats --draft 64 -W 80 -H 60 -o "$tmp/d1.ppm" "$SEED"
awk '/^traced_pixels/{t=$2} /^interpolated_pixels/{i=$2} END{exit !(t + i == 4800 && t > 0)}' \
    "$tmp/err" && ok || bad "--draft: traced and interpolated pixels do not add up to 4800"
expect 0 '' -- "$FT" -q --draft 64 -j 3 -W 80 -H 60 -o "$tmp/d3.ppm" "$SEED"
cmp -s "$tmp/d1.ppm" "$tmp/d3.ppm" && ok || bad "--draft -j 3 differs from -j 1"
expect 0 '' -- "$FT" -q --draft 64 -s 4 --adaptive 8 -j 2 -W 80 -H 60 -o "$tmp/d4.ppm" "$SEED"
expect 0 '' -- "$FT" -q --draft 64 -s 4 --adaptive 8 -W 80 -H 60 -o "$tmp/d5.ppm" "$SEED"
cmp -s "$tmp/d4.ppm" "$tmp/d5.ppm" && ok || bad "--draft --adaptive -j 2 differs from -j 1"
for v in 0 256 -3 x ''; do
    expect 2 '(--draft must be from|needs a whole number)' -- "$FT" --draft "$v" "$SEED"
done
expect 2 'needs a value' -- "$FT" "$SEED" --draft
expect 2 '--draft is a fixed-point core mode' -- "$FT" -q --reference --draft 8 -o "$tmp/r.ppm" "$SEED"
expect 2 '--window is a fixed-point core mode' -- "$FT" -q --reference-float --window 0,0,8,8 -o "$tmp/r.ppm" "$SEED"
expect 0 'float32 reference' -- "$FT" -W 40 -H 30 --reference-float -o "$tmp/r32.ppm" "$SEED"
expect 0 '' -- "$FT" -q -W 40 -H 30 -o "$tmp/a.png" "$SEED"
head -c 8 "$tmp/a.png" | od -An -tx1 | grep -q '89 50 4e 47 0d 0a 1a 0a' && ok || bad "PNG signature"
# The extension picks the format in any letter case, as the name check
# accepts it.
for ext in Png pNG PNG; do
    expect 0 '' -- "$FT" -q -W 40 -H 30 -o "$tmp/case.$ext" "$SEED"
    cmp -s "$tmp/a.png" "$tmp/case.$ext" && ok || bad "-o x.$ext did not write the PNG"
done
for ext in PPM Pnm; do
    expect 0 '' -- "$FT" -q -W 40 -H 30 -o "$tmp/case.$ext" "$SEED"
    cmp -s "$tmp/a.ppm" "$tmp/case.$ext" && ok || bad "-o x.$ext did not write the PPM"
done
if command -v pngtopnm >/dev/null; then
    pngtopnm "$tmp/a.png" >"$tmp/a2.ppm" 2>/dev/null
    # netpbm writes "P6\n40 30\n255\n" as we do.
    cmp -s "$tmp/a.ppm" "$tmp/a2.ppm" && ok || bad "PNG decoded by pngtopnm differs from the PPM"
else
    echo "SKIPPED: PNG decode check (pngtopnm missing; install netpbm)"
    skip=$((skip + 1))
fi
expect 0 '' -- "$FT" -q --format rgb565le --dither -W 40 -H 30 -o "$tmp/d.ppm" "$SEED"

# --build-flags on a scene that needs every effect: an empty flags line on
# stdout (still a valid $(...) list) and a comment saying so.
cat >"$tmp/all.scene" <<'EOF2'
camera eye 0 2 -8 look 0 0 0
image 16 12 spp 4
light 5 10 -5
light -5 10 -5
material a color 1 1 1 reflect 0.5 stripes x 0 0 0 1 bump 0.2 1
material g color 1 1 1 transparency 0.9 ior 1.5
sphere center 0 0 0 radius 1 material a
quad corner -5 0 -5 edge1 0 0 10 edge2 10 0 0 material g
box min 1 0 0 max 2 1 1 material a
cylinder base -2 0 0 radius 0.5 height 1 material a
cone base 2 0 2 radius 0.5 height 1 material a
mesh file tri.obj material a
EOF2
printf 'v 0 0 3\nv 1 0 3\nv 0 1 3\nf 1 2 3\n' >"$tmp/tri.obj"
expect 0 '^# .*all.scene needs every effect at 4 spp' -- "$FT" --build-flags "$tmp/all.scene"
[ "$(cat "$tmp/out")" = "" ] && ok || bad "--build-flags printed '$(cat "$tmp/out")' for a scene that needs every effect"
expect 0 '' -- "$FT" --build-flags -s 1 "$tmp/all.scene"
grep -qx -- '-DRT_NO_SUPERSAMPLING' "$tmp/out" && ok || bad "--build-flags -s 1: '$(cat "$tmp/out")'"
grep -q 'every effect' "$tmp/err" && bad "--build-flags -s 1 said every effect" || ok

# --- compare ------------------------------------------------------------
"$FT" -q -W 40 -H 30 --reference -o "$tmp/r.ppm" "$SEED"
cp "$tmp/a.ppm" "$tmp/a.keep"
expect 1 'PSNR' -- "$FT" compare "$tmp/a.ppm" "$tmp/r.ppm" --min-psnr 99
expect 0 'PSNR' -- "$FT" compare "$tmp/a.ppm" "$tmp/r.ppm" --diff "$tmp/d1.ppm"
head -c 2 "$tmp/d1.ppm" | grep -q P6 && ok || bad "compare --diff x.ppm is not a PPM"
# The diff never overwrites an input, by name or by another path to it.
for d in "$tmp/a.ppm" "$tmp/r.ppm" "$tmp/./a.ppm"; do
    expect 2 'is the input' -- "$FT" compare "$tmp/a.ppm" "$tmp/r.ppm" --diff "$d"
done
cmp -s "$tmp/a.ppm" "$tmp/a.keep" && ok || bad "compare --diff overwrote its input"
# Names the render command refuses are refused here too.
expect 2 'must end in .ppm or .png' -- "$FT" compare "$tmp/a.ppm" "$tmp/r.ppm" --diff "$tmp/d.jpg"
[ ! -e "$tmp/d.jpg" ] && ok || bad "compare wrote a .jpg diff"
expect 2 'must end in .ppm or .png' -- "$FT" compare "$tmp/a.ppm" "$tmp/r.ppm" --diff -
expect 0 '' -- "$FT" compare "$tmp/a.ppm" "$tmp/r.ppm" --diff "$tmp/d1.PNG"
head -c 4 "$tmp/d1.PNG" | od -An -c | grep -q 'P   N   G' && ok || bad "compare --diff x.PNG is not a PNG"

# --- raw rows for displays (.raw, .bin, .h) -----------------------------
R="-q -W 40 -H 30"
# shellcheck disable=SC2086
"$FT" $R --format rgb565le -o "$tmp/le.raw" "$SEED" &&
    "$FT" $R --format rgb565be -o "$tmp/be.BIN" "$SEED" &&
    "$FT" $R --format rgb565le -o "$tmp/le.ppm" "$SEED" &&
    "$FT" $R --format rgb565be -o "$tmp/be.ppm" "$SEED" &&
    "$FT" $R -o "$tmp/888.raw" "$SEED" &&
    "$FT" $R --format rgb565be -o "$tmp/lcd_img.h" "$SEED" && ok ||
    bad "a raw render failed"
[ "$(stat -c %s "$tmp/le.raw")" -eq $((40 * 30 * 2)) ] && ok || bad ".raw 565 size"
# The two byte orders differ exactly by swapping each pair of bytes.
cmp -s "$tmp/le.raw" "$tmp/be.BIN" && bad "rgb565le and rgb565be raw files are equal" || ok
dd if="$tmp/le.raw" conv=swab 2>/dev/null | cmp -s - "$tmp/be.BIN" && ok ||
    bad "rgb565be raw is not rgb565le with its bytes swapped"
# In a PPM both orders give the same picture: the documented expansion.
cmp -s "$tmp/le.ppm" "$tmp/be.ppm" && ok || bad "565 PPMs differ by byte order"
python3 - "$tmp/le.raw" "$tmp/le.ppm" <<'EOF2' && ok || bad ".raw 565 does not expand to the PPM"
import sys
raw, ppm = open(sys.argv[1], "rb").read(), open(sys.argv[2], "rb").read()
px = ppm[len(b"P6\n40 30\n255\n"):]
out = bytearray()
for i in range(0, len(raw), 2):
    v = raw[i] | raw[i + 1] << 8
    r, g, b = v >> 11, (v >> 5) & 63, v & 31
    out += bytes((r << 3 | r >> 2, g << 2 | g >> 4, b << 3 | b >> 2))
sys.exit(0 if bytes(out) == px else 1)
EOF2
# rgb888 .raw is the PPM without its header.
tail -c $((40 * 30 * 3)) "$tmp/a.ppm" | cmp -s - "$tmp/888.raw" && ok ||
    bad "rgb888 .raw differs from the PPM's pixels"
# The C array compiles and holds the .raw bytes.
printf '#include <stdio.h>\n#include "lcd_img.h"\nint main(void) { fwrite(lcd_img, 1, sizeof lcd_img, stdout); return lcd_img_WIDTH != 40 || lcd_img_HEIGHT != 30; }\n' >"$tmp/use_h.c"
if ${CC:-gcc} -std=c99 -Wall -Werror -I"$tmp" "$tmp/use_h.c" -o "$tmp/use_h" 2>"$tmp/err" &&
    "$tmp/use_h" | cmp -s - "$tmp/be.BIN"; then
    ok
else
    bad ".h array does not compile or differs from .raw: $(head -c 300 "$tmp/err")"
fi

# --- bad scenes (file:line:col and the line) -----------------------------
scene_case() { # name, expected message regex, scene text
    printf '%b' "$3" >"$tmp/$1.scene"
    expect 2 "$1.scene:[0-9]+:[0-9]+: error: .*$2" -- "$FT" -q -o "$tmp/$1.ppm" "$tmp/$1.scene"
    [ ! -e "$tmp/$1.ppm" ] && ok || bad "$1: an output file was written"
}
CAM='camera eye 0 0 -5 look 0 0 0 up 0 1 0 fov 60\n'
MAT='material m color 1 1 1\n'
scene_case unknown_kw 'unknown' "${CAM}sphre center 0 0 0 radius 1\n"
scene_case undefined_mat 'not defined' "${CAM}sphere center 0 0 0 radius 1 material m\n"
scene_case dup_mat 'm' "${CAM}${MAT}${MAT}"
scene_case big_number 'range' "${CAM}${MAT}sphere center 40000 0 0 radius 1 material m\n"
scene_case nan_number '' "${CAM}${MAT}sphere center nan 0 0 radius 1 material m\n"
scene_case inf_number '' "${CAM}${MAT}sphere center 0 inf 0 radius 1 material m\n"
scene_case many_digits 'digits' "${CAM}${MAT}sphere center 0.1234567890123456789012345678901234567890123 0 0 radius 1 material m\n"
scene_case missing_radius 'radius' "${CAM}${MAT}sphere center 0 0 0 material m\n"
scene_case nul_byte '' "${CAM}${MAT}sphere center 0 0\0 0 radius 1 material m\n"
scene_case zero_radius '' "${CAM}${MAT}sphere center 0 0 0 radius 0 material m\n"
# Shape errors point at the field at fault and state the limit.
shape_case() { # name, expected line:col, message regex, object line
    printf '%b' "${CAM}${MAT}$4\n" >"$tmp/$1.scene"
    expect 2 "$1.scene:$2: error: $3" -- "$FT" -q -o "$tmp/$1.ppm" "$tmp/$1.scene"
}
shape_case flat_cone 3:17 'degenerate cone: radius / height must be at most 64' \
    'cone base 0 0 0 radius 10 height 0.1 material m'
shape_case thin_cylinder 3:21 'degenerate cylinder: too thin or too flat for Q16.16 .the radius and half the height' \
    'cylinder base 0 0 0 radius 0.00002 height 30000 material m'
head -c 3000 /dev/urandom | tr -d '\n' >"$tmp/garbage.scene"
expect 2 'garbage.scene:1:[0-9]+: error' -- "$FT" -q -o "$tmp/g.ppm" "$tmp/garbage.scene"
: >"$tmp/empty.scene"
"$FT" -q -W 8 -H 8 -o "$tmp/e.ppm" "$tmp/empty.scene" 2>"$tmp/err"
rc=$?
{ [ $rc -eq 0 ] || grep -q 'empty.scene:' "$tmp/err"; } && ok || bad "empty scene: status $rc, $(cat "$tmp/err")"
objs=""
for i in $(seq 1 300); do objs="${objs}sphere center $i 0 0 radius 0.5 material m\n"; done
scene_case too_many 'RT_MAX_OBJECTS' "${CAM}${MAT}${objs}"
lights=""
for i in $(seq 1 10); do lights="${lights}light $i 5 0\n"; done
scene_case too_many_lights 'RT_MAX_LIGHTS' "${CAM}${lights}"
# A 100 MB file is refused by size before it is parsed.
truncate -s 100M "$tmp/huge.scene"
expect 2 'larger than' -- "$FT" -q -o "$tmp/h.ppm" "$tmp/huge.scene"
rm -f "$tmp/huge.scene"

if [ $skip -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ $fail -eq 0 ]
