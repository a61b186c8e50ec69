#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The PNG writer (port/posix/png.c) against real decoders: every PNG that
# fixtrace writes must decode to exactly the bytes of the PPM it writes for
# the same render. Two independent decoders:
#   - netpbm's pngtopnm (libpng), which checks every chunk CRC;
#   - a small Python decoder below (zlib for the inflate and the Adler-32,
#     its own chunk walk, CRC-32 check and scanline unfiltering).
# Sizes cover 1x1, a noisy image large enough for several Huffman blocks
# (300x300 with bumps), sizes that once filled stored blocks exactly
# (28x771, 28x772, 28x1542), the widest row (4096x3), in every row format.
# The PNG must also be compressed for real: the 640x480 seed scene must be
# no larger than 1.25 times what netpbm's pnmtopng (zlib) writes for it.
# With neither decoder present the suite prints SKIPPED and counts a skip.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
pass=0 fail=0 skip=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not found (build it with make)"
    echo "0 passed, 1 failed"
    exit 1
fi

decoders=""
command -v pngtopnm >/dev/null 2>&1 && decoders="$decoders pngtopnm"
if command -v python3 >/dev/null 2>&1 &&
    python3 -c 'import zlib' >/dev/null 2>&1; then
    decoders="$decoders python"
fi
if [ -z "$decoders" ]; then
    echo "SKIPPED: no PNG decoder (install netpbm for pngtopnm, or python3)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
for d in pngtopnm python; do
    case " $decoders " in *" $d "*) ;; *)
        echo "note: $d not available; checking with$decoders only";;
    esac
done

# Decodes PNG $1 to a binary PPM on stdout, "P6\n<w> <h>\n255\n" + RGB,
# the header fixtrace writes. Walks the chunks itself and refuses anything
# malformed, so a writer bug shows as an error, not as a lenient guess.
cat >"$tmp/png2ppm.py" <<'EOF'
import struct, sys, zlib

def fail(msg):
    sys.stderr.write("png2ppm: %s\n" % msg)
    sys.exit(1)

data = open(sys.argv[1], "rb").read()
if data[:8] != b"\x89PNG\r\n\x1a\n":
    fail("bad signature")
pos, chunks = 8, []
while pos < len(data):
    if pos + 12 > len(data):
        fail("truncated chunk at %d" % pos)
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    crc, = struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])
    if len(body) != n or zlib.crc32(kind + body) & 0xFFFFFFFF != crc:
        fail("bad length or CRC in %r chunk" % kind)
    chunks.append((kind, body))
    pos += 12 + n
    if kind == b"IEND":
        break
if pos != len(data):
    fail("%d bytes after IEND" % (len(data) - pos))
if not chunks or chunks[0][0] != b"IHDR" or chunks[-1][0] != b"IEND":
    fail("IHDR must come first and IEND last")
w, h, depth, ctype, comp, filt, lace = struct.unpack(">IIBBBBB",
                                                       chunks[0][1])
if (depth, ctype, comp, filt, lace) != (8, 2, 0, 0, 0) or w == 0 or h == 0:
    fail("unexpected IHDR %r" % ((w, h, depth, ctype, comp, filt, lace),))
raw = zlib.decompress(b"".join(b for k, b in chunks if k == b"IDAT"))
stride = 3 * w
if len(raw) != h * (stride + 1):
    fail("%d bytes of scanlines, want %d" % (len(raw), h * (stride + 1)))
out, prev = bytearray(), bytearray(stride)
for y in range(h):
    f = raw[y * (stride + 1)]
    line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - 3] if i >= 3 else 0
        b = prev[i]
        c = prev[i - 3] if i >= 3 else 0
        if f == 0:
            p = 0
        elif f == 1:
            p = a
        elif f == 2:
            p = b
        elif f == 3:
            p = (a + b) // 2
        elif f == 4:
            pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
            p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
        else:
            fail("filter type %d on row %d" % (f, y))
        line[i] = (line[i] + p) & 0xFF
    out += line
    prev = line
sys.stdout.buffer.write(b"P6\n%d %d\n255\n" % (w, h) + bytes(out))
EOF

# check NAME FIXTRACE-ARGS...: renders to PPM and to PNG with the same
# arguments and compares each decoder's output with the PPM byte for byte.
check() {
    local name=$1; shift
    if ! "$FT" -q "$@" -o "$tmp/$name.ppm" ||
        ! "$FT" -q "$@" -o "$tmp/$name.png"; then
        bad "$name: fixtrace $* failed"
        return
    fi
    local d
    for d in $decoders; do
        rm -f "$tmp/$name.$d.ppm"
        if [ "$d" = pngtopnm ]; then
            pngtopnm "$tmp/$name.png" >"$tmp/$name.$d.ppm" 2>"$tmp/err"
        else
            python3 "$tmp/png2ppm.py" "$tmp/$name.png" \
                >"$tmp/$name.$d.ppm" 2>"$tmp/err"
        fi
        if [ $? -ne 0 ]; then
            bad "$name: $d could not decode the PNG: $(head -c 300 "$tmp/err")"
        elif cmp -s "$tmp/$name.ppm" "$tmp/$name.$d.ppm"; then
            ok
        else
            bad "$name: the PNG decoded by $d differs from the PPM" \
                "($(cmp "$tmp/$name.ppm" "$tmp/$name.$d.ppm" 2>&1 | head -n 1))"
        fi
    done
}

SEED=scenes/seed.scene
check 1x1 -W 1 -H 1 "$SEED"
check 2x1 -W 2 -H 1 "$SEED"
check 40x30 -W 40 -H 30 "$SEED"
check 300x300 -W 300 -H 300 "$SEED"
check 300x300-bumps -W 300 -H 300 scenes/textures.scene
check 28x771-one-full-block -W 28 -H 771 "$SEED"
check 28x772-one-byte-over -W 28 -H 772 "$SEED"
check 28x1542-two-full-blocks -W 28 -H 1542 "$SEED"
check 4096x3-widest -W 4096 -H 3 scenes/diffuse.scene
check 97x61-spp4 -W 97 -H 61 -s 4 scenes/glass.scene
check 64x48-rgb565le -W 64 -H 48 --format rgb565le "$SEED"
check 64x48-rgb565be-dither -W 64 -H 48 --format rgb565be --dither "$SEED"

# fixtrace compare reads PNG: its own, and zlib's (pnmtopng, stored and
# compressed); a damaged PNG is refused with the reason, exit 2.
"$FT" -q -W 64 -H 48 -o "$tmp/cmp.ppm" "$SEED" &&
    "$FT" -q -W 64 -H 48 -o "$tmp/cmp.png" "$SEED"
pngs="$tmp/cmp.png"
if command -v pnmtopng >/dev/null 2>&1; then
    for lvl in 0 1 9; do
        pnmtopng -compression $lvl "$tmp/cmp.ppm" >"$tmp/cmp$lvl.png" 2>/dev/null
        pngs="$pngs $tmp/cmp$lvl.png"
    done
fi
for p in $pngs; do
    if "$FT" compare "$p" "$tmp/cmp.ppm" >"$tmp/out" 2>"$tmp/err" &&
        grep -q 'inf (identical)' "$tmp/out"; then
        ok
    else
        bad "compare $(basename "$p") cmp.ppm: $(cat "$tmp/err" "$tmp/out" | head -c 300)"
    fi
done
cp "$tmp/cmp.png" "$tmp/broken.png"
printf '\377' | dd of="$tmp/broken.png" bs=1 seek=60 conv=notrunc 2>/dev/null
"$FT" compare "$tmp/broken.png" "$tmp/cmp.ppm" >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && grep -q 'broken.png: bad' "$tmp/err" && ok ||
    bad "compare of a damaged PNG: exit $rc, $(head -c 300 "$tmp/err")"

# Compression: against zlib as pnmtopng uses it, on the same pixels.
if command -v pnmtopng >/dev/null 2>&1; then
    "$FT" -q -W 640 -H 480 -o "$tmp/seed640.png" "$SEED" &&
        "$FT" -q -W 640 -H 480 -o "$tmp/seed640.ppm" "$SEED"
    ours=$(stat -c %s "$tmp/seed640.png")
    theirs=$(pnmtopng "$tmp/seed640.ppm" 2>/dev/null | wc -c)
    echo "seed 640x480: fixtrace PNG $ours bytes, pnmtopng $theirs bytes"
    if [ "$theirs" -gt 0 ] && [ $((ours * 4)) -le $((theirs * 5)) ]; then
        ok
    else
        bad "the 640x480 seed PNG is $ours bytes, over 1.25 x pnmtopng's $theirs"
    fi
else
    echo "note: pnmtopng missing; PNG size not compared"
fi

# A directory in place of the output: the write fails cleanly.
mkdir "$tmp/dir.png"
if "$FT" -q -W 4 -H 4 -o "$tmp/dir.png" "$SEED" 2>"$tmp/err"; then
    bad "writing a PNG over a directory succeeded"
else
    ok
fi

if [ "$skip" -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ "$fail" -eq 0 ]
