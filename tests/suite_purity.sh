#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# core/ is freestanding: it must build with -ffreestanding -nostdlib and no
# floating-point registers, contain no float/double/malloc/stdio, and its
# objects may reference no symbol beyond memcpy, memset and memmove (plus
# its own). A check that cannot run is reported as skipped, not passed.
set -u
cd "$(dirname "$0")/.."
# -I for every layer folder of core/ (the Makefile exports the same).
CORE_INC=${CORE_INC:-$(for d in core/*/; do printf -- '-I%s ' "${d%/}"; done)}
pass=0 fail=0 skip=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. Source: no floating-point types, allocation, libm or stdio in core/.
hits=$(grep -nE '\b(float|double)\b|\b(malloc|calloc|realloc|free)\s*\(|<(math|stdio|stdlib)\.h>' \
       core/*/*.c core/*/*.h | grep -vE ':\s*(/\*|\*)' || true)
[ -z "$hits" ] && ok || bad "core sources use float/double/malloc/libm/stdio:
$hits"

# 2. Host build without FP registers; undefined symbols limited.
# Undefined symbols of all objects linked together (-r), less the allowed.
undefined() { # $1 = tool prefix, $2 = object dir, $3 = allowed regex
    "${1}ld" -r -o "$2/all.r" "$2"/*.o &&
    "${1}nm" -u "$2/all.r" | awk '{print $NF}' | sort -u | grep -vxE "$3" || true
}
mkdir -p "$tmp/x86"
okb=1
for f in core/*/*.c; do
    gcc -std=c99 -ffreestanding -nostdlib -mgeneral-regs-only -O2 -Wall \
        -Wextra -Werror $CORE_INC -c "$f" -o "$tmp/x86/$(basename "$f" .c).o" \
        || { bad "$f does not build freestanding with -mgeneral-regs-only"; okb=0; }
done
[ $okb = 1 ] && ok
undef=$(undefined "" "$tmp/x86" 'memcpy|memset|memmove')
[ -z "$undef" ] && ok || bad "core references symbols beyond memcpy/memset/memmove: $(echo $undef)"

# 2b. The configurations of the RT_NO_* flags compiling warning-free is
# tests/suite_effects.sh's check: it compiles them (a syntax check does
# not see an unused static function) for the host and the boards.

# 3. Cortex-M0: no soft-float helpers may appear (libgcc integer helpers such
# as __aeabi_lmul / __aeabi_uldivmod are fine).
if command -v arm-none-eabi-gcc >/dev/null; then
    mkdir -p "$tmp/m0"
    for f in core/*/*.c; do
        arm-none-eabi-gcc -std=c99 -mcpu=cortex-m0 -mthumb -ffreestanding \
            -nostdlib -O2 $CORE_INC -c "$f" -o "$tmp/m0/$(basename "$f" .c).o" ||
            bad "$f does not build for Cortex-M0"
    done
    refs=$(undefined arm-none-eabi- "$tmp/m0" 'memcpy|memset|memmove')
    fp=$(echo "$refs" | grep -E '^__aeabi_[fd]|^__(add|sub|mul|div|fix|float|extend|trunc|cmp|eq|ne|lt|le|gt|ge|un)[sdt]f' || true)
    [ -z "$fp" ] && ok || bad "M0 core objects call soft-float helpers: $(echo $fp)"
    # Integer helpers from libgcc (64-bit multiply/divide, clz) are fine.
    other=$(echo "$refs" | grep -vE '^$|^__aeabi_(l|ui|i|uldiv|ldiv)|^__(clz|ctz|ffs|popcount)[sd]i2$|^__gnu_' || true)
    [ -z "$other" ] && ok || bad "M0 core references: $(echo $other)"
else
    echo "SKIPPED: Cortex-M0 purity check (arm-none-eabi-gcc missing; install gcc-arm-none-eabi)"
    skip=$((skip + 1))
fi

if [ $skip -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ $fail -eq 0 ]
