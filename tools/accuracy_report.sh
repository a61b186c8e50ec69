#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# accuracy_report.sh: writes docs/accuracy.md, docs/accuracy.svg and
# docs/accuracy-work.svg from the measurements tools/accuracy.sh collected,
# which it keeps in docs/accuracy-data.tsv, and from the sweep's
# docs/accuracy-sweep.tsv (make accuracy-sweep; tools/accuracy_sweep.py
# writes that section).
#   tools/accuracy_report.sh            write the three from the data
#   tools/accuracy_report.sh --check    exit 1 unless they follow from it
# Plain awk: no plotting package.
#
# The data's first line is "# m4f_same width height runs seconds"; then
# one row per measurement, tab-separated: label (unit bits, or
# "reference, ...") scene spp depth m3 m0 m4f host psnr maxerr bad
# fw=host adaptive psnr-vs-ideal draft interpolated-percent (the last two
# missing means 0: rows written before draft renders).
set -euo pipefail
cd "$(dirname "$0")/.."
DATA=docs/accuracy-data.tsv
OUTDIR=docs
CHECK=0
if [ "${1:-}" = --check ]; then
    CHECK=1
    OUTDIR=$(mktemp -d)
    trap 'rm -rf "$OUTDIR"' EXIT
fi
TSV=$OUTDIR/accuracy-rows.tsv
grep -v '^#' "$DATA" >"$TSV"
read -r _ M4SAME W H RUNS SECS < <(head -n 1 "$DATA")
MD=$OUTDIR/accuracy.md
SVG=$OUTDIR/accuracy.svg
SVG2=$OUTDIR/accuracy-work.svg
DEF=30

# ---- Figures the text quotes ---------------------------------------------------

# field COLUMN LABEL [SCENE [SPP [ADAPTIVE [DEPTH]]]]: that column of the
# first matching row (scene seed, 1 spp, not adaptive, any depth).
field() {
    awk -F'\t' -v c="$1" -v l="$2" -v s="${3:-seed}" -v sp="${4:-1}" \
        -v ad="${5:-0}" -v dp="${6:-}" -v dr="${7:-0}" '$1 == l && $2 == s &&
        $3 == sp && $13 == ad && (dp == "" || $4 == dp) && ($15 + 0) == dr {
        print $c; exit }' "$TSV"
}
calc() { awk "BEGIN { printf \"$1\", $2 }"; }
# 12345.6 -> 12,345.6
commas() { echo "$1" | awk '{ d = ""; x = $1; if (x ~ /\./) {
    d = substr(x, index(x, ".")); x = substr(x, 1, index(x, ".") - 1) }
    r = ""; while (length(x) > 3) { r = "," substr(x, length(x) - 2) r
    x = substr(x, 1, length(x) - 3) } print x r d }'; }
ge() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a == "inf" || a + 0 >= b + 0) }'; }

d_m3=$(field 5 $DEF) d_m0=$(field 6 $DEF) d_ps=$(field 9 $DEF)
u16_m3=$(field 5 16) u16_m0=$(field 6 16) u16_ps=$(field 9 16)
s32_m3=$(field 5 "reference, float32") s64_m3=$(field 5 "reference, double")
s32_ps=$(field 9 "reference, float32")
s32_m4=$(field 7 "reference, float32")
r_soft=$(calc %.1f "$s64_m3 / $d_m3")
r_f32=$(calc %.1f "$s32_m3 / $d_m3")
r_m4=$(calc %.2f "$s32_m4 / $d_m3")
r_16=$(calc %.3f "$d_m3 / $u16_m3")
r_16_m0=$(calc %.3f "$d_m0 / $u16_m0")
s16_m3=$(field 5 $DEF seed 16)
a8_m3=$(field 5 $DEF seed 16 8)
s1_id=$(field 14 $DEF seed 1 0 5)
s16_id=$(field 14 $DEF seed 16) a8_id=$(field 14 $DEF seed 16 8)
d0_m3=$(field 5 $DEF seed 1 0 0) d0_id=$(field 14 $DEF seed 1 0 0)
d2_m3=$(field 5 $DEF seed 1 0 2) d2_id=$(field 14 $DEF seed 1 0 2)

# The targets of the default: seed, mirrors, glass and textures at 70 dB.
targets=""
for s in seed mirrors glass textures; do
    p=$(field 9 $DEF "$s")
    if ge "$p" 70; then v=met; else v=missed; fi
    targets="$targets${targets:+; }$s $p dB ($v)"
done

# Pareto frontier of points "label<TAB>cost<TAB>psnr[<TAB>hollow]" (hollow
# points are shown, not ranked): a point is on it when no other costs no
# more and is no less accurate (one of the two strictly). "inf" beats all.
frontier() {
    awk -F'\t' '$4 != "hollow" { n++; l[n] = $1; c[n] = $2; p[n] = $3 }
    END { for (i = 1; i <= n; i++) { on = 1
        for (j = 1; j <= n; j++) if (j != i && c[j] <= c[i] && p[j] >= p[i] &&
            (c[j] < c[i] || p[j] > p[i])) on = 0
        if (on) print l[i] } }'
}

# chart POINTS TITLE YLABEL LEGEND OUT: the cost/accuracy plot.
chart() {
    local front
    front=$(echo "$1" | frontier | paste -sd '|' -)
    echo "$1" | awk -F'\t' -v front="$front" -v title="$2" -v ylabel="$3" \
        -v legend="$4" '
function lx(v) { return log(v) / log(10) }
function X(v) { return L + (lx(v) - x0) / (x1 - x0) * (R - L) }
function Y(p) { if (p >= 1e8) return TOPY; return B - (p - y0) / (y1 - y0) * (B - T) }
function esc(s) { gsub(/&/, "\\&amp;", s); return s }
{ n++; lab[n] = $1; c[n] = $2; p[n] = $3; hollow[n] = ($4 == "hollow") }
END {
    split(front, f, "|"); for (i in f) onf[f[i]] = 1
    lo = 1e30; hi = 0; pmin = 1e30; pmax = 0
    for (i = 1; i <= n; i++) { if (c[i] < lo) lo = c[i]; if (c[i] > hi) hi = c[i]
        if (p[i] < 1e8) { if (p[i] < pmin) pmin = p[i]; if (p[i] > pmax) pmax = p[i] } }
    x0 = int(lx(lo)); x1 = int(lx(hi)) + 1
    y0 = int(pmin / 5) * 5 - 5; y1 = int(pmax / 5) * 5 + 5
    Wd = 760; Ht = 500; L = 70; R = 730; T = 80; B = 420; TOPY = 55
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" " \
        "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">\n",
        Wd, Ht, Wd, Ht
    printf "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", Wd, Ht
    printf "<text x=\"%d\" y=\"18\" font-size=\"14\" font-weight=\"bold\">" \
        "%s</text>\n", L, title
    for (e = x0; e <= x1; e++) { xx = X(10 ^ e)
        printf "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#ddd\"/>\n",
            xx, T - 30, xx, B
        printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">10<tspan " \
            "dy=\"-6\" font-size=\"9\">%d</tspan></text>\n", xx, B + 18, e
        if (e < x1) for (k = 2; k <= 9; k++) { xm = X(k * 10 ^ e)
            printf "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#f2f2f2\"/>\n",
                xm, T - 30, xm, B } }
    for (v = y0; v <= y1; v += 5) { yy = Y(v)
        printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ddd\"/>\n",
            L, yy, R, yy
        printf "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%d</text>\n", L - 6, yy + 4, v }
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#ddd\" " \
        "stroke-dasharray=\"2,3\"/>\n", L, TOPY, R, TOPY
    printf "<text x=\"%d\" y=\"%d\" text-anchor=\"end\">∞</text>\n", L - 6, TOPY + 4
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"black\"/>\n", L, B, R, B
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"black\"/>\n", L, T - 30, L, B
    printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">instructions per pixel " \
        "(log scale; Cortex-M3 unless marked)</text>\n", (L + R) / 2, B + 40
    printf "<text transform=\"translate(20 %d) rotate(-90)\" text-anchor=\"middle\">" \
        "%s</text>\n", (T + B) / 2, ylabel
    # Frontier: the M3 points on it, in order of cost, as a step line.
    m = 0; for (i = 1; i <= n; i++) if (onf[lab[i]] && !hollow[i]) { m++; o[m] = i }
    for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++)
        if (c[o[j]] < c[o[i]]) { t = o[i]; o[i] = o[j]; o[j] = t }
    path = ""
    for (i = 1; i <= m; i++) { k = o[i]
        if (i > 1) path = path sprintf(" %.1f,%.1f", X(c[k]), Y(p[o[i - 1]]))
        path = path sprintf(" %.1f,%.1f", X(c[k]), Y(p[k])) }
    if (m > 0) printf "<polyline points=\"%s\" fill=\"none\" stroke=\"#d62728\" " \
        "stroke-width=\"1.5\" stroke-dasharray=\"6,3\"/>\n", path
    # Labels right of their points (left and above near the right edge),
    # with a leader line; overlapping labels are pushed apart vertically.
    for (i = 1; i <= n; i++) { px[i] = X(c[i]); py[i] = Y(p[i])
        right[i] = px[i] < R - 250
        ly[i] = right[i] ? py[i] + 4 : py[i] - 12 # left ones above
        txt[i] = sprintf("%s: %.0f instr/px, %s", lab[i], c[i],
            (p[i] >= 1e8) ? "∞" : sprintf("%.1f dB", p[i]))
        tx[i] = right[i] ? px[i] + 40 : px[i] - 40
        w = 6.6 * length(txt[i]); x0b[i] = right[i] ? tx[i] : tx[i] - w
        x1b[i] = x0b[i] + w }
    for (pass = 0; pass < 2 * n; pass++) for (i = 1; i <= n; i++)
        for (j = 1; j <= n; j++) { if (i == j) continue
            if (x0b[i] < x1b[j] && x0b[j] < x1b[i] && ly[j] >= ly[i] &&
                ly[j] - ly[i] < 15 && (ly[j] > ly[i] || j > i))
                ly[j] = ly[i] + 15 # label on label
            if (px[j] > x0b[i] - 6 && px[j] < x1b[i] + 6 &&
                (py[j] - ly[i] + 4)^2 < 100)
                ly[i] += 15 } # label on another point
    for (i = 1; i <= n; i++) { xx = px[i]; yy = py[i]
        col = onf[lab[i]] && !hollow[i] ? "#d62728" : "#1f77b4"
        printf "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5\" fill=\"%s\" stroke=\"%s\" " \
            "stroke-width=\"1.5\"/>\n", xx, yy, hollow[i] ? "white" : col, col
        printf "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" " \
            "stroke=\"#999\" stroke-width=\"0.7\"/>\n", xx + (right[i] ? 6 : -6),
            yy, tx[i] + (right[i] ? -3 : 3), ly[i] - 4
        printf "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\">%s</text>\n",
            tx[i], ly[i], right[i] ? "start" : "end", esc(txt[i]) }
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#d62728\" " \
        "stroke-width=\"1.5\" stroke-dasharray=\"6,3\"/>\n", L, Ht - 16, L + 30, Ht - 16
    printf "<text x=\"%d\" y=\"%d\">%s</text>\n", L + 36, Ht - 12, legend
    print "</svg>" }' >"$5"
}

# The precision ladder on the seed (M3), with the float references; the
# M4F's float32 is shown hollow, for comparison.
PTS=$(awk -F'\t' '$2 == "seed" && $3 == 1 && $13 == 0 && $4 == 5 &&
    $5 != "-" && ($15 + 0) == 0 && !seen[$1]++ {
    lab = ($1 ~ /^[0-9]+$/) ? $1 " unit bits" ($1 == 30 ? " (default)" : "") : $1
    printf "%s\t%s\t%s\n", lab, $5, ($9 == "inf" ? 1e9 : $9) }' "$TSV")
if [ -n "$s32_m4" ] && [ "$s32_m4" != "-" ]; then
    PTS=$(printf '%s\nfloat32, M4F FPU\t%s\t%s\thollow' "$PTS" "$s32_m4" \
        "$(echo "$s32_ps" | sed 's/^inf$/1e9/')")
fi
FRONT=$(echo "$PTS" | frontier)
front_list=$(echo "$FRONT" | paste -sd ';' - | sed 's/;/; /g')
if echo "$FRONT" | grep -q "(default)"; then t_pareto=met; else t_pareto=missed; fi
chart "$PTS" "Cost against accuracy: scenes/seed.scene, 1 spp, by precision of unit vectors" \
    "PSNR against the double reference (dB)" \
    "Pareto frontier (filled red: on it). Hollow: Cortex-M4F instructions, for comparison." \
    "$SVG"

# The work knobs of the default, against the ideal image.
PTS2=$(awk -F'\t' '$1 == 30 && $2 == "seed" {
    lab = $3 " spp" ($13 > 0 ? ", adaptive " $13 : "") \
        (($15 + 0) > 0 ? ", draft " $15 : "") ", depth " $4
    printf "%s\t%s\t%s\n", lab, $5, ($14 == "inf" ? 1e9 : $14) }' "$TSV")
FRONT2=$(echo "$PTS2" | frontier)
front2_list=$(echo "$FRONT2" | paste -sd ';' - | sed 's/;/; /g')
chart "$PTS2" "Work against the ideal image: scenes/seed.scene, 30 unit bits" \
    "PSNR against the reference at 16 spp, depth 5 (dB)" \
    "Pareto frontier (filled red: on it)." "$SVG2"

# ---- The tables ------------------------------------------------------------------

TABFN='function commas(x,   i, r, d) { if (x == "-" || x == "") return "–"
    d = ""; if (x ~ /\./) { d = substr(x, index(x, ".")); x = substr(x, 1,
        index(x, ".") - 1) }
    r = ""; while (length(x) > 3) { r = "," substr(x, length(x) - 2) r
        x = substr(x, 1, length(x) - 3) } return x r d }
function db(x) { return (x == "inf") ? "∞ (identical)" : (x == "-" ? "–" : x) }'
table1=$(awk -F'\t' "$TABFN"'
BEGIN { print "| unit bits | scene | M3 instr/px | M0 instr/px | M4F instr/px |" \
    " host µs/px (noisy) | PSNR dB | max err | > 2/255 | fw = host |"
    print "|---|---|--:|--:|--:|--:|--:|--:|--:|:-:|" }
$3 == 1 && $13 == 0 && ($15 + 0) == 0 &&
    ($1 !~ /^[0-9]+$/ || $2 != "seed" || $4 == 5) && !seen[$1 "/" $2]++ {
  lab = ($1 == 30) ? "**30 (default)**" : $1
  printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s%% | %s |\n",
      lab, $2, commas($5), commas($6), commas($7), ($8 == "-" ? "–" : $8),
      db($9), $10, $11, ($12 == "-" ? "–" : $12) }' "$TSV")
table2=$(awk -F'\t' "$TABFN"'
BEGIN { print "| spp | adaptive | depth | M3 instr/px | M0 instr/px |" \
    " host µs/px (noisy) | PSNR dB, same spp and depth | PSNR dB, ideal |" \
    " fw = host |"
    print "|--:|--:|--:|--:|--:|--:|--:|--:|:-:|" }
$1 == 30 && $2 == "seed" && ($15 + 0) == 0 {
  printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $3,
      ($13 > 0 ? $13 : "–"), $4, commas($5), commas($6), $8, db($9),
      db($14), $12 }' "$TSV")

# Draft renders: each scene at each threshold, with the default's cost
# beside it.
table3=$(awk -F'\t' "$TABFN"'
BEGIN { print "| scene | draft T | M3 instr/px | M3 fewer | M0 instr/px |" \
    " M0 fewer | PSNR dB | max err | > 2/255 | interpolated | fw = host |"
    print "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|:-:|" }
$1 == 30 && $3 == 1 && $13 == 0 && ($15 + 0) == 0 && !(($2) in d3) {
    d3[$2] = $5; d0[$2] = $6 }
$1 == 30 && ($15 + 0) > 0 { n++; r[n] = $0 }
END { for (i = 1; i <= n; i++) { split(r[i], c, "\t")
  printf "| %s | %s | %s | %.2fx | %s | %.2fx | %s | %s | %s%% | %s%% | %s |\n",
      c[2], c[15], commas(c[5]), d3[c[2]] / c[5], commas(c[6]),
      d0[c[2]] / c[6], db(c[9]), c[10], c[11], c[16], c[12] } }' "$TSV")
# The target: the seed at 2x fewer M3 instructions at 38 dB or more, and
# glass and mirrors at 35 dB or more at that threshold.
draft_t=$(awk -F'\t' '$1 == 30 && $3 == 1 && $13 == 0 && ($15 + 0) == 0 &&
    $2 == "seed" && !d { d = $5 }
    $1 == 30 && $2 == "seed" && ($15 + 0) > 0 && d / $5 >= 2 && $9 >= 38 &&
    (best == "" || $15 < best) { best = $15 } END { print best }' "$TSV")
if [ -n "$draft_t" ]; then
    t_draft="met at T = $draft_t: $(field 5 $DEF seed 1 0 5 "$draft_t") M3 instructions per pixel against $(field 5 $DEF seed 1 0 5) ($(calc %.2f "$(field 5 $DEF seed 1 0 5) / $(field 5 $DEF seed 1 0 5 "$draft_t")")x; M0 $(calc %.2f "$(field 6 $DEF seed 1 0 5) / $(field 6 $DEF seed 1 0 5 "$draft_t")")x) at $(field 9 $DEF seed 1 0 5 "$draft_t") dB"
    for s in glass mirrors; do
        p=$(field 9 $DEF "$s" 1 0 "" "$draft_t")
        if [ -n "$p" ] && ge "$p" 35; then v=met; else v=missed; fi
        t_draft="$t_draft; $s ${p:-–} dB ($v)"
    done
else
    draft_t=64
    t_draft="missed"
fi
draft_pic=$(awk -F'\t' -v t="$draft_t" '$1 == 30 && $2 == "seed" && $15 == t {
    printf "| draft %s: %s dB | ![seed, draft %s](img/accuracy/seed-draft%s.png) | ![error, draft %s](img/accuracy/diff-draft%s.png) |\n",
        t, $9, t, t, t, t; exit }' "$TSV")

# The pictures, with the PSNR of each.
pics=$(awk -F'\t' '$2 == "seed" && $3 == 1 && $13 == 0 && $4 == 5 &&
    $1 ~ /^[0-9]+$/ && !seen[$1]++ { printf "%s %s\n", $1, $9 }' "$TSV" |
    sort -n | awk '{
    printf "| %s: %s dB | ![seed, %s unit bits](img/accuracy/seed-u%s.png) | ![error, %s unit bits](img/accuracy/diff-u%s.png) |\n",
        $1, $2, $1, $1, $1, $1 }')

# ---- The document -----------------------------------------------------------------

{
cat <<EOF
# What accuracy costs

Generated by \`make accuracy\` (tools/accuracy.sh and
tools/accuracy_report.sh); do not edit by hand, run it again. The last run
took ${SECS} s. Instruction counts are exact and repeat to the last digit
(QEMU \`-icount\`); host times are the median of ${RUNS} runs on whatever
machine ran it, and **noisy**. ${W}x${H} pixels throughout.

## Where the error comes from

At one sample per pixel almost all of the squared error against the
double reference comes from a few pixels where a decision flips: hit or
miss at a silhouette, shadow or light, which texture cell, most of them
seen in reflections and through glass. A single full-contrast flipped
pixel caps a ${W}x${H} image near 52 dB. Those decisions are taken on
unit vectors (ray directions, normals, directions to lights), whose
angle error grows with every unit a ray travels. So unit vectors carry
\`RT_UNIT_BITS\` fraction bits (core/fx/fx_dir.h, Q2.30 by default) while
positions, distances and colours stay Q16.16; the bounding tests near a
silhouette, the quads' edges and the frame cylinders and cones are
solved in work at that precision too (docs/numerics.md).

## Precision of unit vectors

\`RT_UNIT_BITS\` (16..30, core/fx/rt_config.h) sets those fraction bits at
compile time. It is a measuring device more than a knob: every bit count
does the same 64-bit products, so fewer bits buy no speed. The default's
30 bits cost ${r_16}x the instructions of 16 bits on the M3 (${r_16_m0}x on
the M0) for ${d_ps} dB instead of ${u16_ps} on the seed. Leave it at 30.

PSNR, max error and the share of pixels off by more than 2/255 compare
each image with the double reference at the same size, spp and depth
(\`fixtrace --reference\`); "∞" means identical bytes. M3 is
\`BOARD=an385\`, M0 \`BOARD=m0\` (the firmware as \`make qemu\` builds it,
with only the effects the scene needs), M4F QEMU's mps2-an386 with the FPU
on; "fw = host" checks the M3 and M0 images against the host's, byte for
byte. Host time is \`fixtrace --stats\`'s render_seconds per pixel, one
thread. The reference rows are port/posix/ref_render.c and ref_shapes.c,
unchanged, built as firmware (bench/softref: a small libm, soft double
or, with \`-Ddouble=float\`, soft float on the M3 and M0, hardware float on
the M4F); their host time is \`--reference\` on the host's FPU.

${table1}

The M4F float32 image is byte-identical to the M3 soft-float one: ${M4SAME}.

![cost against PSNR by precision](accuracy.svg)

The seed at each precision, and its error against the reference
(\`fixtrace compare --diff\`, brightened 8 times: black where the two
agree):

| unit bits | image | error |
|---|---|---|
${pics}
${draft_pic}

## The work knobs

Samples per pixel (\`-s\`, firmware \`SPP=\`), adaptive anti-aliasing
(\`--adaptive T\`, firmware \`ADAPTIVE=\`: only pixels whose neighbourhood
differs by more than T levels get the full grid) and the depth on the
scene's \`image\` line are run-time choices. They are measured twice:
against the reference at the same spp and depth (the arithmetic) and
against the ideal image, the reference at 16 spp and the seed's depth 5
(what a viewer sees).

${table2}

![work against the ideal image](accuracy-work.svg)

## Draft renders

A draft (\`--draft T\`, firmware \`DRAFT=T\`, \`rt_options.draft\`;
docs/effects.md) traces every 4th pixel of every 4th row, then, level by
level, each pixel between only where its neighbours disagree: other
objects or texture cells along their paths, other shadows, colours more
than T levels apart, or an object the row's culling allows that could
hide between them; the rest is the mean of the neighbours. PSNR, errors
and "fw = host" as in the first table, against the reference of the full
render; "fewer" is the default's instructions per pixel (the first
table) divided by the draft's; "interpolated" the share of pixels
without a ray of their own (\`--stats\`).

${table3}

The seed's draft is a point on the chart of the work knobs above; its
picture is the last row of the pictures' table.

$(python3 tools/accuracy_sweep.py report)

## Which to use

- **Every use: the default, 30 unit bits.** No precision is cheaper, and
  the seed is at ${d_ps} dB against the reference, where float32 is at
  ${s32_ps}.
- **A still frame to show:** 16 spp with \`--adaptive 8\`:
  $(commas "$a8_m3") instructions per pixel on the M3 against
  $(commas "$s16_m3") for the full 16 spp, at ${a8_id} dB against the
  ideal image (16 spp: ${s16_id}).
- **Quick previews and slow parts:** a draft, \`--draft ${draft_t}\`
  (\`DRAFT=${draft_t}\`): $(commas "$(field 5 $DEF seed 1 0 5 "$draft_t")")
  instructions per pixel on the M3 for the seed, at
  $(field 9 $DEF seed 1 0 5 "$draft_t") dB against the reference. It saves
  least where reflections and glass make most pixels differ from their
  neighbours (the draft table).
- **Previews:** 1 spp (${s1_id} dB against the ideal,
  $(commas "$d_m3") instructions per pixel), or a lower depth for scenes
  of mirrors and glass: depth 2 costs $(commas "$d2_m3") at ${d2_id} dB,
  depth 0 $(commas "$d0_m3") at ${d0_id} dB.
- **Float hardware:** an M4F runs the float32 reference in
  $(commas "$s32_m4") instructions per pixel, ${r_m4}x the fixed-point
  default on the M3; soft float on the M3 costs ${r_f32}x, soft double
  ${r_soft}x.

## Targets

- The default lies on the Pareto frontier of the precision ladder (seed,
  M3): **${t_pareto}**. On the frontier: ${front_list}.
- The default against the reference, 1 spp: ${targets}.
- On the frontier of the work knobs: ${front2_list}.
- A draft of the seed at half the default's M3 instructions or fewer, at
  38 dB or more, with glass and mirrors at 35 dB or more:
  **${t_draft}**.

## Reproducing a row

    make accuracy                                   # everything, this page
    make -j2 build/posix/fixtrace
    make -j2 HOST_BUILD=build/posix-u16 RT_DEFS=-DRT_UNIT_BITS=16 build/posix-u16/fixtrace
    build/posix-u16/fixtrace -W ${W} -H ${H} -o u16.ppm scenes/seed.scene
    build/posix/fixtrace --reference -W ${W} -H ${H} -o ref.ppm scenes/seed.scene
    build/posix/fixtrace compare u16.ppm ref.ppm --diff diff.ppm
    build/posix-u16/fixtrace --stats -W ${W} -H ${H} -o u16.ppm scenes/seed.scene   # render_seconds
    make qemu BOARD=an385 FW_BUILD=build/accuracy/fw-an385-u16 \\
        FW_DEFS=-DRT_UNIT_BITS=16 SCENE=scenes/seed.scene WIDTH=${W} HEIGHT=${H} SPP=1
    make qemu BOARD=an385 SCENE=scenes/seed.scene WIDTH=${W} HEIGHT=${H} SPP=16 ADAPTIVE=8
    tools/accuracy.sh --draft                       # only the draft rows
    build/posix/fixtrace --stats --draft ${draft_t} -W ${W} -H ${H} -o d.ppm scenes/seed.scene
    make qemu BOARD=m0 SCENE=scenes/seed.scene WIDTH=${W} HEIGHT=${H} DRAFT=${draft_t}
    make softref-qemu SR=m3-f64 SCENE=scenes/seed.scene WIDTH=${W} HEIGHT=${H} SPP=1
    make softref-qemu SR=m4f-f32 SCENE=scenes/seed.scene WIDTH=${W} HEIGHT=${H} SPP=1

Depth rows render a copy of the seed whose \`image\` line says another
depth (build/accuracy/scenes/). \`SR=\` variants: m3-f64, m3-f32, m0-f64,
m0-f32, m4f-f32 (mk/accuracy.mk). \`tests/suite_accuracy.sh\` repeats a
small version of this (seed at 48x36) in \`make test\`.
EOF
} >"$MD"
rm -f "$TSV"

if [ "$CHECK" = 1 ]; then
    st=0
    for f in accuracy.md accuracy.svg accuracy-work.svg; do
        if ! cmp -s "$OUTDIR/$f" "docs/$f"; then
            echo "docs/$f does not follow docs/accuracy-data.tsv" \
                "(run make accuracy):" >&2
            diff "docs/$f" "$OUTDIR/$f" | head -n 10 >&2
            st=1
        fi
    done
    exit $st
fi
