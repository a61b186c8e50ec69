#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Prints the seed scene's figures on every board at 320x240, 1 spp, in both
# firmware modes (tables: PRUNE=1, the default; text: PRUNE=0), as the
# markdown table of port/baremetal/README.md. Instruction counts are exact
# (QEMU icount); flash is text + rodata (make size).
set -eu
cd "$(dirname "$0")/.."
MAKE=${MAKE:-make}
echo "| board | mode | instructions | per pixel | stack used | flash | RAM (data+bss) | stack reserved |"
echo "|---|---|---|---|---|---|---|---|"
for b in $(cd mk/boards && ls *.mk | sed 's/\.mk$//'); do
    for mode in tables text; do
        p=$([ $mode = tables ] && echo 1 || echo 0)
        dir=build/boards/$b-$mode
        run=$($MAKE -s qemu BOARD=$b WIDTH=320 HEIGHT=240 SPP=1 PRUNE=$p \
              FW_BUILD=$dir 2>&1 >/dev/null)
        size=$($MAKE -s size BOARD=$b WIDTH=320 HEIGHT=240 SPP=1 PRUNE=$p \
               FW_BUILD=$dir 2>&1)
        echo "$run" "$size" | tr '\n' ' ' | awk -v b=$b -v m=$mode '
            function th(n) { s = sprintf("%d", n); o = "";
                while (length(s) > 3) { o = "," substr(s, length(s) - 2) o;
                    s = substr(s, 1, length(s) - 3) } return s o }
            { for (i = 1; i <= NF; i++) {
                if ($i == "instructions") ins = $(i + 1);
                if ($i == "instructions_per_pixel") ipp = $(i + 1);
                if ($i == "stack_bytes") st = $(i + 1);
                if ($i == "stack_reserved") sr = $(i + 1);
                if ($i == "(text") t = $(i + 1);
                if ($i == "rodata") r = $(i + 1);
                if ($i == "ram") ram = $(i + 1) } }
            END { gsub(/,/, "", t); gsub(/,/, "", r);
                printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", b, m,
                    th(ins), ipp, th(st), th(t + r), th(ram), th(sr) }'
    done
done
