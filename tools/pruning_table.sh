#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# "What pruning buys" in docs/effects.md: flash, stack and instructions of
# scenes/diffuse.scene at 320x240, 1 spp, on the M3 (an385) and the M0
# (m0), built three ways: full (PRUNE=0), pruned (PRUNE=1, the default)
# and the minimal renderer written for that scene (make minimal); and the
# seed's full and pruned rows, taken from port/baremetal/README.md's
# table (tools/boards_table.sh). Then the ratios and the targets.
#
#   tools/pruning_table.sh           measure, print the section
#   tools/pruning_table.sh --write   measure, put it into docs/effects.md
#   tools/pruning_table.sh --check   no QEMU: read the measured cells back
#                                    from the page, write the section again
#                                    from them and the boards table, exit 1
#                                    if it differs (tests/suite_figures.sh)
set -eu
cd "$(dirname "$0")/.."
MAKE=${MAKE:-make}
FT=build/posix/fixtrace
DOC=docs/effects.md
BOARDS=port/baremetal/README.md
BEGIN='<!-- begin pruning (tools/pruning_table.sh) -->'
END='<!-- end pruning -->'
W=320 H=240
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# ---- Measuring: "scene board build flash stack instructions" lines, and
# "differ board bytes max-error" for the minimal renderer ----------------------

measure() {
    $MAKE -s "$FT" >/dev/null
    "$FT" -q -W $W -H $H -o "$tmp/host.ppm" scenes/diffuse.scene
    local b p build dir run size
    for b in an385 m0; do
        for build in full pruned; do
            p=$([ $build = pruned ] && echo 1 || echo 0)
            dir=build/pruning/$b-$build
            run=$($MAKE -s qemu BOARD=$b SCENE=scenes/diffuse.scene WIDTH=$W \
                  HEIGHT=$H SPP=1 PRUNE=$p FW_BUILD=$dir 2>&1 >/dev/null)
            size=$($MAKE -s size BOARD=$b SCENE=scenes/diffuse.scene WIDTH=$W \
                   HEIGHT=$H SPP=1 PRUNE=$p FW_BUILD=$dir 2>&1)
            cmp -s "$dir/out.ppm" "$tmp/host.ppm" || {
                echo "pruning_table: $b $build: the image differs from the host's" >&2
                exit 1; }
            echo "$run $size" | tr '\n' ' ' | awk -v b=$b -v m=$build '
                { for (i = 1; i <= NF; i++) {
                    if ($i == "instructions") ins = $(i + 1)
                    if ($i == "stack_bytes") st = $(i + 1)
                    if ($i == "(text") t = $(i + 1)
                    if ($i == "rodata") r = $(i + 1) } }
                END { gsub(/,/, "", t); gsub(/,/, "", r)
                    if (ins == "" || t == "") exit 1
                    print "diffuse", b, m, t + r, st, ins }' ||
                { echo "pruning_table: no figures from $b $build: $run" >&2; exit 1; }
        done
        run=$($MAKE -s minimal BOARD=$b WIDTH=$W HEIGHT=$H 2>&1)
        echo "$run" | awk -v b=$b '
            $1 == "instructions" { ins = $2 } $1 == "stack_bytes" { st = $2 }
            $1 == "flash" { f = $2 }
            END { if (ins == "" || f == "") exit 1
                  print "diffuse", b, "minimal", f, st, ins }' ||
            { echo "pruning_table: no figures from make minimal BOARD=$b: $run" >&2; exit 1; }
        echo "differ $b $(cmp -l build/minimal/$b/out.ppm build/minimal/$b/host.ppm |
            awk 'function oct(s,   v, i) { v = 0   # cmp -l prints octal bytes
                     for (i = 1; i <= length(s); i++) v = v * 8 + substr(s, i, 1)
                     return v }
                 { a = oct($2); c = oct($3); d = a > c ? a - c : c - a
                   if (d > m) m = d; n++ }
                 END { print n + 0, m + 0 }')"
    done
}

# ---- Reading the measured cells back from the page ------------------------------

from_page() {
    awk -F'|' '
        function cell(i,   c) { c = $i; gsub(/^ +| +$/, "", c); return c }
        function num(c) { sub(/ .*/, "", c); gsub(/,/, "", c); return c }
        cell(2) == "diffuse" {
            b = cell(3); sub(/.*\(/, "", b); sub(/\).*/, "", b)
            m = cell(4); sub(/,.*/, "", m)
            print "diffuse", b, m, num(cell(5)), num(cell(6)), num(cell(7)) }' "$DOC"
    tr '\n' ' ' <"$DOC" | tr -s ' ' |
        grep -oE 'in [0-9]+ bytes \(at most [0-9]+/255\) on the (an385|m0)' |
        awk '{ m = $6; sub(/\/.*/, "", m); print "differ", $NF, $2, m }'
}

# ---- Writing the section from the data ---------------------------------------------

section() { # data file
    local data=$1
    # The seed rows: the boards table's an385 and m0, text (full) and
    # tables (pruned).
    awk -F'|' '
        function cell(i,   c) { c = $i; gsub(/^ +| +$/, "", c); gsub(/,/, "", c); return c }
        (cell(2) == "an385" || cell(2) == "m0") && (cell(3) == "tables" || cell(3) == "text") {
            print "seed", cell(2), cell(3) == "text" ? "full" : "pruned",
                cell(7), cell(6), cell(4) }' "$BOARDS" >>"$data"
    [ "$(grep -c '^seed ' "$data")" = 4 ] ||
        { echo "pruning_table: no seed rows in $BOARDS" >&2; return 1; }
    [ "$(grep -c '^diffuse ' "$data")" = 6 ] ||
        { echo "pruning_table: not six diffuse rows" >&2; return 1; }
    echo "$BEGIN"
    cat <<EOT
Flash is \`.text + .rodata\` (\`make size\` also counts \`.ARM.exidx\` and
\`.data\`, which flash holds too); stack is \`stack_bytes\`, the painted
high-water mark. Full is \`PRUNE=0\` (every effect, the scene text parsed
on the device), pruned is \`PRUNE=1\` (the scene's effects and capacities,
the scene as tables). Measured by \`tools/pruning_table.sh --write\` with
$GCC_V -O2 and
$QEMU_V; the seed rows are port/baremetal/README.md's.
Every fixtrace image is byte-identical to the host's.

EOT
    awk -v px=$((W * H)) '
        function th(x,   s, r, d) { s = x; d = ""
            if (s ~ /\./) { d = substr(s, index(s, ".")); s = substr(s, 1, index(s, ".") - 1) }
            r = ""; while (length(s) > 3) { r = "," substr(s, length(s) - 2) r
                s = substr(s, 1, length(s) - 3) } return s r d }
        function pname(b) { return b == "an385" ? "M3 (an385)" : "M0 (m0)" }
        $1 == "differ" { nd[$2] = $3; md[$2] = $4; next }
        { k = $1 " " $2 " " $3; fl[k] = $4; st[k] = $5; ins[k] = $6
          ipp[k] = sprintf("%.1f", $6 / px) }
        END {
            print "| scene, 320x240, 1 spp | board | build | flash | stack | instructions | per pixel |"
            print "|---|---|---|---|---|---|---|"
            ns = split("diffuse seed", sc, " ")
            for (i = 1; i <= ns; i++) for (j = 1; j <= 2; j++) {
                b = (j == 1) ? "an385" : "m0"
                nb = split(sc[i] == "diffuse" ? "full pruned minimal" : "full pruned", bl, " ")
                for (l = 1; l <= nb; l++) {
                    k = sc[i] " " b " " bl[l]; full = sc[i] " " b " full"
                    lab = bl[l]
                    if (b == "an385" && sc[i] == "diffuse" && lab != "minimal")
                        lab = lab (lab == "full" ? ", `PRUNE=0`" : ", `PRUNE=1`")
                    f = th(fl[k])
                    if (bl[l] == "pruned") f = f sprintf(" (%.1f%%)", 100 * fl[k] / fl[full])
                    printf "| %s | %s | %s | %s | %s | %s | %s |\n", sc[i], pname(b),
                        lab, f, th(st[k]), th(ins[k]), th(ipp[k]) } }
            for (j = 1; j <= 2; j++) { b = (j == 1) ? "an385" : "m0"
                fr[b] = sprintf("%.1f%%", 100 * fl["diffuse " b " pruned"] / fl["diffuse " b " full"])
                cr[b] = sprintf("%.3fx", ins["diffuse " b " pruned"] / ins["diffuse " b " minimal"])
                okf[b] = (fl["diffuse " b " pruned"] <= fl["diffuse " b " full"] / 2) ? "met" : "missed"
                okc[b] = (ins["diffuse " b " pruned"] <= 1.1 * ins["diffuse " b " minimal"]) ? "met" : "missed" }
            print ""
            print "The targets for the diffuse scene are pruned flash at most 50% of"
            print "full flash, and pruned cost within 10% of the minimal renderer'"'"'s. On"
            printf "the M3: flash %s (**%s**), cost %s the minimal renderer'"'"'s\n", fr["an385"], okf["an385"], cr["an385"]
            printf "(**%s**); on the M0: flash %s (**%s**), cost %s (**%s**).\n", okc["an385"], fr["m0"], okf["m0"], cr["m0"], okc["m0"]
            if (nd["an385"] == "" || nd["m0"] == "") exit 1
            printf "The minimal renderer'"'"'s image differs from fixtrace'"'"'s in %d bytes (at\n", nd["an385"]
            printf "most %d/255) on the an385 and in %d bytes (at most %d/255) on the m0.\n",
                md["an385"], nd["m0"], md["m0"] }
    ' "$data"
    echo "$END"
}

put() { # section file -> the page with it
    awk -v b="$BEGIN" -v e="$END" -v new="$1" '
        $0 == b { while ((getline l < new) > 0) print l; skip = 1; found = 1; next }
        $0 == e { skip = 0; next }
        !skip { print }
        END { if (!found) exit 1 }' "$DOC" ||
        { echo "pruning_table: $DOC has no '$BEGIN' line" >&2; return 1; }
}

tools() {
    GCC_V=$(arm-none-eabi-gcc --version | head -n 1 | sed 's/ (.*)//')
    QEMU_V=$(qemu-system-arm --version | head -n 1 |
        sed 's/ (.*)//; s/ emulator version//')
}

case "${1:-}" in
"") tools; measure >"$tmp/data"; section "$tmp/data" | sed '1d;$d' ;;
--write)
    tools
    measure >"$tmp/data"
    section "$tmp/data" >"$tmp/new"
    put "$tmp/new" >"$tmp/doc"
    if cmp -s "$tmp/doc" "$DOC"; then echo "$DOC unchanged"
    else cp "$tmp/doc" "$DOC"; echo "updated $DOC"; fi ;;
--check)
    # The compiler and QEMU that measured, as the page names them.
    v=$(tr '\n' ' ' <"$DOC" | tr -s ' ' |
        sed -nE 's/.*Measured by `tools\/pruning_table\.sh --write` with (.*) -O2 and ([^;]*); the seed rows.*/\1|\2/p')
    GCC_V=${v%%|*} QEMU_V=${v#*|}
    from_page >"$tmp/data"
    section "$tmp/data" >"$tmp/new"
    put "$tmp/new" >"$tmp/doc"
    cmp -s "$tmp/doc" "$DOC" && exit 0
    diff "$DOC" "$tmp/doc" | head -n 20 >&2
    exit 1 ;;
*) echo "usage: tools/pruning_table.sh [--write|--check]" >&2; exit 2 ;;
esac
