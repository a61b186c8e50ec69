#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The firmware's UART output (OUTPUT=uart: port/baremetal/out_uart.c) and
# its receiver (`fixtrace receive`, port/posix/receive.c):
# - on an385 (CMSDK UART), microbit (nRF51 UART) and rv32 (16550), the
#   seed scene at 48x36 goes out on the UART, which QEMU writes to a file
#   chardev; `fixtrace receive` turns the capture into a PPM equal, byte
#   for byte, to the host's render, and python3's zlib checks the frame's
#   CRC-32 independently; the device's text (its figures) arrives on the
#   same line and is shown;
# - a frame with one flipped payload byte, a cut one, one whose header
#   lies about its size and a capture without a frame are all refused with
#   a message, exit 1, and neither create the output nor touch an existing
#   one;
# - an image too large for the build: the device's error text reaches the
#   host over the UART, and the exit status is the firmware's;
# - SEMIHOST=0 links no semihosting at all (a board without a debugger).
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
MK=${MAKE:-make}
W=48 H=36
SEED=scenes/seed.scene
TIMEOUT=${FW_TEST_TIMEOUT:-60}
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not built (run make first)"
    echo "0 passed, 1 failed"
    exit 1
fi
if ! "$FT" -q -W $W -H $H -o "$tmp/host.ppm" $SEED; then
    echo "FAILED: host render of $SEED"
    echo "0 passed, 1 failed"
    exit 1
fi

# check_crc FILE: the frame's CRC-32, recomputed by python3's zlib.
check_crc() {
    command -v python3 >/dev/null 2>&1 || { echo "note: no python3"; return 0; }
    python3 - "$1" <<'EOF'
import struct, sys, zlib
d = open(sys.argv[1], 'rb').read()
i = d.index(b'FXIM')
n = struct.unpack_from('<I', d, i + 12)[0]
body = d[i + 4:i + 16 + n]
sent = struct.unpack_from('<I', d, i + 16 + n)[0]
sys.exit(0 if zlib.crc32(body) == sent else 1)
EOF
}

boards=""
for b in an385 microbit rv32; do
    if [ "$b" = rv32 ]; then
        tools="riscv64-unknown-elf-gcc qemu-system-riscv32"
    else
        tools="arm-none-eabi-gcc qemu-system-arm"
    fi
    missing=""
    for t in $tools; do
        command -v "$t" >/dev/null || missing="${missing:+$missing }$t"
    done
    if [ -n "$missing" ]; then
        echo "SKIPPED: $b UART ($missing missing)"
        skipped=1
    else
        boards="$boards $b"
    fi
done

for b in $boards; do
    # suite_firmware.sh builds in the same directories: take turns.
    mkdir -p "build/$b"
    if command -v flock >/dev/null; then
        exec 9>"build/$b/.suite.lock"
        flock 9
    fi
    rc=0
    "$MK" -s qemu BOARD=$b OUTPUT=uart WIDTH=$W HEIGHT=$H \
        QEMU_TIMEOUT="$TIMEOUT" >"$tmp/$b.log" 2>&1 || rc=$?
    exec 9>&-
    if [ $rc -ne 0 ]; then
        bad "$b: make qemu OUTPUT=uart failed ($rc): $(head -c 600 "$tmp/$b.log")"
        continue
    fi
    cp "build/$b/uart.bin" "$tmp/$b.bin"
    cmp -s "build/$b/out.ppm" "$tmp/host.ppm" && ok ||
        bad "$b: the image received over the UART differs from the host's"
    check_crc "$tmp/$b.bin" && ok ||
        bad "$b: the frame's CRC-32 is not zlib's CRC-32 of header and payload"
    grep -q '^instructions [0-9]' "$tmp/$b.log" &&
        grep -q "fixtrace receive: wrote" "$tmp/$b.log" && ok ||
        bad "$b: the device's figures did not arrive over the UART: $(head -c 300 "$tmp/$b.log")"
    # The receiver by hand, from stdin, as from a serial port.
    if "$FT" receive -q -o "$tmp/$b.ppm" <"$tmp/$b.bin" 2>"$tmp/err" &&
        cmp -s "$tmp/$b.ppm" "$tmp/host.ppm"; then
        ok
    else
        bad "$b: fixtrace receive < uart.bin: $(head -c 300 "$tmp/err")"
    fi
    echo "$b: $(grep -E '^(instructions|stack_bytes) ' "$tmp/$b.log" | tr '\n' ' ')"
done

# refused NAME WANT_MESSAGE FILE: receive refuses FILE, says why, exit 1,
# and leaves the existing output as it was.
refused() {
    local name=$1 want=$2 in=$3 rc=0
    echo keep >"$tmp/out.ppm"
    "$FT" receive -o "$tmp/out.ppm" <"$in" >"$tmp/rout" 2>"$tmp/rerr" || rc=$?
    if [ $rc -ne 1 ]; then
        bad "$name: exit status $rc, want 1: $(head -c 300 "$tmp/rerr")"
    elif ! grep -q "$want" "$tmp/rerr"; then
        bad "$name: no '$want' in: $(head -c 300 "$tmp/rerr")"
    elif [ "$(cat "$tmp/out.ppm")" != keep ] ||
        ls -a "$tmp" | grep -q '^\.fixtrace-'; then
        bad "$name: the output was touched or a temporary file was left"
    else
        ok
    fi
    rm -f "$tmp/out.ppm"
    "$FT" receive -o "$tmp/new.ppm" <"$in" 2>/dev/null
    [ ! -e "$tmp/new.ppm" ] && ok || bad "$name: an output file was created"
}

if [ -f "$tmp/an385.bin" ] && command -v python3 >/dev/null 2>&1; then
    f=$tmp/an385.bin
    python3 - "$f" "$tmp" <<'EOF'
import struct, sys
d = bytearray(open(sys.argv[1], 'rb').read())
t = sys.argv[2]
i = d.index(b'FXIM')
n = struct.unpack_from('<I', d, i + 12)[0]
flip = bytearray(d); flip[i + 16 + n // 2] ^= 0x10
open(t + '/flip.bin', 'wb').write(flip)
open(t + '/cut.bin', 'wb').write(d[:i + 16 + n - 100])
size = bytearray(d); struct.pack_into('<I', size, i + 12, n + 3)
open(t + '/size.bin', 'wb').write(size)
open(t + '/text.bin', 'wb').write(d[:i] + b'fixtrace: render failed\n\x04')
EOF
    refused "one flipped payload byte" "checksum mismatch" "$tmp/flip.bin"
    refused "a cut frame" "cut short" "$tmp/cut.bin"
    refused "a header with the wrong size" "payload bytes, but 48x36" "$tmp/size.bin"
    refused "no frame" "no image frame" "$tmp/text.bin"
    grep -q 'render failed' "$tmp/rerr" && ok ||
        bad "receive does not show the device's text: $(head -c 300 "$tmp/rerr")"
    rc=0
    "$FT" receive <"$f" 2>"$tmp/rerr" || rc=$?
    [ $rc = 2 ] && ok || bad "receive without -o: exit $rc, want 2"
elif [ -f "$tmp/an385.bin" ]; then
    echo "note: python3 missing; corrupted frames not tested"
fi

# The device's own error, over the UART: an image the build cannot hold.
case " $boards " in
*" an385 "*)
    exec 9>"build/an385/.suite.lock"
    command -v flock >/dev/null && flock 9
    rc=0
    "$MK" -s qemu BOARD=an385 OUTPUT=uart WIDTH=5000 HEIGHT=10 \
        QEMU_TIMEOUT="$TIMEOUT" >"$tmp/big.log" 2>&1 || rc=$?
    if grep -q 'firmware exit status 3' "$tmp/big.log" &&
        grep -q 'is larger than this build allows' "$tmp/big.log" &&
        grep -q 'no image frame' "$tmp/big.log"; then
        ok
    else
        bad "an385 too large over the UART: $(head -c 400 "$tmp/big.log")"
    fi
    # SEMIHOST=0: nothing of semihosting is linked.
    if "$MK" -s firmware BOARD=an385 OUTPUT=uart SEMIHOST=0 WIDTH=$W \
        HEIGHT=$H >"$tmp/sh0.log" 2>&1; then
        syms=$(arm-none-eabi-nm build/an385/fixtrace-uart.elf)
        if echo "$syms" | grep -qE 'port_semihost|sh_call'; then
            bad "SEMIHOST=0 still links semihosting: $(echo "$syms" | grep -E 'port_semihost|sh_call')"
        else
            ok
        fi
    else
        bad "SEMIHOST=0 build: $(head -c 400 "$tmp/sh0.log")"
    fi
    # Leave the directory as a default build would find it.
    "$MK" -s firmware BOARD=an385 OUTPUT=uart WIDTH=$W HEIGHT=$H \
        >/dev/null 2>&1
    exec 9>&-
    ;;
esac

echo "$pass passed, $fail failed${skipped:+, 1 skipped}"
[ "$fail" -eq 0 ]
