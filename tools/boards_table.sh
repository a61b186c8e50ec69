#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The seed scene's figures on every board at 320x240, 1 spp, in both
# firmware modes (tables: PRUNE=1, the default; text: PRUNE=0): the
# "Measured figures" section of port/baremetal/README.md, its table and
# the sizes its text quotes (the parser, the scene text and tables, RAM).
# Instruction counts are exact (QEMU icount); flash is text + rodata
# (make size); the parser and table sizes come from the link maps.
#
#   tools/boards_table.sh           print the section
#   tools/boards_table.sh --write   put it into port/baremetal/README.md
#
# Every firmware image must equal the host's, or nothing is written.
# tests/suite_figures.sh checks what it can without QEMU: the quotes of this
# table in the other pages, and the sizes that follow from the scene and
# the headers.
set -eu
cd "$(dirname "$0")/.."
MAKE=${MAKE:-make}
FT=build/posix/fixtrace
DOC=port/baremetal/README.md
BEGIN='<!-- begin boards (tools/boards_table.sh) -->'
END='<!-- end boards -->'
SEED=scenes/seed.scene
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
$MAKE -s "$FT" >/dev/null
"$FT" -q -W 320 -H 240 -o "$tmp/host.ppm" "$SEED"

th() { echo "$1" | sed -E ':a; s/^([0-9]+)([0-9]{3})/\1,\2/; ta'; }
# Bytes of .text and .rodata input sections from the objects (paths
# matching $2) in the link map $1.
mapsum() {
    awk -v pat="$2" '
        function hex(s,   i, v) { v = 0; s = tolower(s); sub(/^0x/, "", s)
            for (i = 1; i <= length(s); i++)
                v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
            return v }
        /^ \.[^ ]+$/ { sec = $1; getline; $0 = " " sec " " $0 }
        /^ \.(text|rodata)/ && $2 ~ /^0x/ && $3 ~ /^0x/ && $4 ~ pat { t += hex($3) }
        END { print t + 0 }' "$1"
}
symsize() { # elf nm symbol -> its size in bytes
    "$2" -S "$1" | awk -v s="$3" '$4 == s { print $2; exit }' |
        while read -r h; do printf '%d\n' "0x$h"; done
}

rows() {
    # One-core boards: a two-core board's figures, per core, are in
    # docs/dual-core.md (make dual-table).
    for b in $(cd mk/boards && grep -L 'FW_CORES=2' *.mk | sed 's/\.mk$//'); do
        for mode in tables text; do
            p=$([ $mode = tables ] && echo 1 || echo 0)
            dir=build/boards/$b-$mode
            run=$($MAKE -s qemu BOARD=$b WIDTH=320 HEIGHT=240 SPP=1 PRUNE=$p \
                  FW_BUILD=$dir 2>&1 >/dev/null)
            size=$($MAKE -s size BOARD=$b WIDTH=320 HEIGHT=240 SPP=1 PRUNE=$p \
                   FW_BUILD=$dir 2>&1)
            cmp -s "$dir/out.ppm" "$tmp/host.ppm" ||
                echo "$b $mode" >>"$tmp/differ"
            echo "$run" "$size" | tr '\n' ' ' | awk -v b=$b -v m=$mode -v x="$tmp/extra" '
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
                    if ($i == "exidx") e = $(i + 1);
                    if ($i == "(data") d = $(i + 1);
                    if ($i == "ram") ram = $(i + 1);
                    if ($i == "total") tot = $(i + 1) } }
                END { gsub(/,/, "", t); gsub(/,/, "", r); gsub(/,/, "", e)
                    if (ins == "" || t == "") exit 1
                    printf "%s %s %d %d\n", b, m, tot, e + d >> x
                    printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", b, m,
                        th(ins), ipp, th(st), th(t + r), th(ram), th(sr) }' ||
                { echo "boards_table: no figures from $b ($mode): $run $size" >&2
                  exit 1; }
        done
    done
}

section() {
    local table nobj depth parser tables text row scene mb_row mb_scene
    local mb_ram mb_text mb_tab more
    table=$(rows)
    if [ -s "$tmp/differ" ]; then
        echo "boards_table: these images differ from the host's:" \
            "$(paste -sd, "$tmp/differ")" >&2
        exit 1
    fi
    nobj=$("$FT" --emit-c "$SEED" | sed -nE 's/^#define FW_SCENE_OBJECTS ([0-9]+).*/\1/p')
    depth=$(awk '/^image /{for (i = 1; i < NF; i++) if ($i == "depth") print $(i + 1)}' "$SEED")
    parser=$(mapsum build/boards/an385-text/fixtrace.map 'core/parse/rt_(parse|lex)[a-z_]*\.o$')
    tables=$(mapsum build/boards/an385-tables/fixtrace.map 'scene_tables\.o$')
    text=$(wc -c <"$SEED" | tr -d ' ')
    row=$(symsize build/boards/an385-text/fixtrace.elf arm-none-eabi-nm row_buf)
    scene=$(symsize build/boards/an385-text/fixtrace.elf arm-none-eabi-nm scene)
    mb_row=$(symsize build/boards/microbit-text/fixtrace.elf arm-none-eabi-nm row_buf)
    mb_scene=$(symsize build/boards/microbit-text/fixtrace.elf arm-none-eabi-nm scene)
    mb_ram=$(sed -nE 's/^ *ram .*LENGTH = ([0-9]+)K.*/\1/p' linker/microbit.ld)
    mb_ram=$((mb_ram * 1024))
    mb_text=$(awk '$1 == "microbit" && $2 == "text" { print $3 }' "$tmp/extra")
    mb_tab=$(awk '$1 == "microbit" && $2 == "tables" { print $3 }' "$tmp/extra")
    more=$(awk '$4 > m { m = $4 } END { print m + 0 }' "$tmp/extra")
    for v in "$nobj" "$depth" "$parser" "$tables" "$row" "$scene" "$mb_row" \
        "$mb_scene" "$mb_text" "$mb_tab"; do
        case $v in ''|0) echo "boards_table: a size is missing" >&2; exit 1 ;; esac
    done
    echo "$BEGIN"
    cat <<EOT
Seed scene (\`$SEED\`: $nobj objects, depth $depth) at 320x240, 1 spp,
in both scene modes, measured by \`tools/boards_table.sh --write\` with
$(arm-none-eabi-gcc --version | head -n 1 | sed 's/ (.*)//'),
$(riscv64-unknown-elf-gcc --version | head -n 1 | sed 's/ (.*)//') and
$(qemu-system-arm --version | head -n 1 | sed 's/ (.*)//; s/ emulator version//').
Every board's image, in both modes, is byte-identical to
\`build/posix/fixtrace -W 320 -H 240 $SEED\`:

    make qemu BOARD=<board> WIDTH=320 HEIGHT=240 SPP=1 [PRUNE=0]
    make size BOARD=<board> WIDTH=320 HEIGHT=240 SPP=1 [PRUNE=0]

| board | mode | instructions | per pixel | stack used | flash | RAM (data+bss) | stack reserved |
|---|---|---|---|---|---|---|---|
$table

Flash here is \`.text + .rodata\`, as \`make size\` prints them (it also
prints \`.ARM.exidx\` and the initial \`.data\`, which flash holds too: at
most $more bytes more here; on rv32 the whole image sits in RAM). On the
M3 the text build carries the parser
($(th "$parser") bytes of \`core/parse/\` in the link map)
and the seed's text ($(th "$text") bytes); the tables build carries neither,
but $(th "$tables") bytes of tables, and leaves out multiple lights and
supersampling, which the seed does not use. RAM on the large boards is a
$((row / 3))-pixel row ($(th "$row") bytes), plus, for the text build, the
default-capacity \`rt_scene\` ($(th "$scene") bytes). The micro:bit uses
$(th "$mb_text") of its $(th "$mb_ram") bytes of RAM with the text build, stack
included (\`rt_scene\` $(th "$mb_scene") bytes, row $(th "$mb_row") bytes), and
$(th "$mb_tab") with the tables. The stack figures include the parser's in the
text build. The figures move as the core changes;
\`tools/boards_table.sh --write\` measures them again.
EOT
    echo "$END"
}

case "${1:-}" in
--write)
    section >"$tmp/new"
    awk -v b="$BEGIN" -v e="$END" -v new="$tmp/new" '
        $0 == b { while ((getline l < new) > 0) print l; skip = 1; found = 1; next }
        $0 == e { skip = 0; next }
        !skip { print }
        END { if (!found) exit 1 }' "$DOC" >"$tmp/doc" ||
        { echo "boards_table: $DOC has no '$BEGIN' line" >&2; exit 1; }
    if cmp -s "$tmp/doc" "$DOC"; then echo "$DOC unchanged"
    else cp "$tmp/doc" "$DOC"; echo "updated $DOC"; fi ;;
"") section | sed '1d;$d' ;;
*) echo "usage: tools/boards_table.sh [--write]" >&2; exit 2 ;;
esac
