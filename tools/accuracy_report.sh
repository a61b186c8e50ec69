#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# accuracy_report.sh: writes docs/accuracy.md and docs/accuracy.svg from the
# measurements tools/accuracy.sh collected (build/accuracy/results.tsv).
#   tools/accuracy_report.sh RESULTS.tsv M4F_SAME WIDTH HEIGHT RUNS SECONDS
#   tools/accuracy_report.sh --check
# --check reads the measurements back from docs/accuracy.md's table and
# header, writes the page and the chart from them again (in a temporary
# directory) and exits 1 if either differs from the committed one: every
# figure the text derives (ratios, savings, targets met, the frontier, the
# chart) must follow the table (tests/suite_figures.sh runs it).
# Plain awk: no plotting package.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = --check ]; then
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    page=docs/accuracy.md
    # The table's cells as the TSV they were written from: commas out,
    # "–" back to "-", "∞ (identical)" back to "inf", the % sign off.
    awk -F'|' '
        /^\| setting \| scene \|/ { on = 1; next }
        on && /^\|---/ { next }
        on && !/^\|/ { exit }
        on { out = ""
             for (i = 2; i <= 13; i++) { c = $i; sub(/^ /, "", c); sub(/ $/, "", c)
                 if (i >= 6 && i <= 8) gsub(/,/, "", c)
                 if (c == "–") c = "-"
                 if (c == "∞ (identical)") c = "inf"
                 if (i == 12) sub(/%$/, "", c)
                 out = out (i > 2 ? "\t" : "") c }
             print out }' "$page" >"$tmp/results.tsv"
    secs=$(sed -nE 's/^took ([0-9]+) s\. .*/\1/p' "$page")
    runs=$(sed -nE 's/.*the median of ([0-9]+) runs.*/\1/p' "$page")
    size=$(sed -nE 's/^([0-9]+x[0-9]+) pixels\. .*/\1/p' "$page")
    same=$(sed -nE 's/^The M4F float32 image is byte-identical to the M3 soft-float one: ([a-z]+)\.$/\1/p' "$page")
    if [ ! -s "$tmp/results.tsv" ] || [ -z "$secs" ] || [ -z "$runs" ] ||
        [ -z "$size" ] || [ -z "$same" ]; then
        echo "accuracy_report: cannot read the measurements back from $page" >&2
        exit 1
    fi
    ACC_MD=$tmp/accuracy.md ACC_SVG=$tmp/accuracy.svg bash "$0" \
        "$tmp/results.tsv" "$same" "${size%x*}" "${size#*x}" "$runs" "$secs"
    rc=0
    for f in accuracy.md accuracy.svg; do
        cmp -s "$tmp/$f" "docs/$f" && continue
        echo "accuracy_report: docs/$f does not follow docs/accuracy.md's table:" >&2
        diff "docs/$f" "$tmp/$f" | head -n 20 >&2
        rc=1
    done
    exit $rc
fi
TSV=$1 M4SAME=$2 W=$3 H=$4 RUNS=$5 SECS=$6
MD=${ACC_MD:-docs/accuracy.md}
SVG=${ACC_SVG:-docs/accuracy.svg}

# ---- Figures the text quotes (seed scene, 1 spp, its own depth) -------------

# field COLUMN LABEL: column of the seed row with that label at 1 spp and
# the scene's depth (the first such row).
field() {
    awk -F'\t' -v c="$1" -v l="$2" '$1 == l && $2 == "seed" && $3 == 1 {
        print $c; exit }' "$TSV"
}
f_m3=$(field 5 fast) d_m3=$(field 5 default) p_m3=$(field 5 precise)
f_m0=$(field 6 fast) d_m0=$(field 6 default) p_m0=$(field 6 precise)
f_ps=$(field 9 fast) d_ps=$(field 9 default) p_ps=$(field 9 precise)
s32_m3=$(field 5 "reference, float32") s64_m3=$(field 5 "reference, double")
s32_ps=$(field 9 "reference, float32") s64_ps=$(field 9 "reference, double")
s32_m4=$(field 7 "reference, float32")
calc() { awk "BEGIN { printf \"$1\", $2 }"; }
# 12345.6 -> 12,345.6
commas() { echo "$1" | awk '{ d = ""; x = $1; if (x ~ /\./) {
    d = substr(x, index(x, ".")); x = substr(x, 1, index(x, ".") - 1) }
    r = ""; while (length(x) > 3) { r = "," substr(x, length(x) - 2) r
    x = substr(x, 1, length(x) - 3) } print x r d }'; }

r_fast=$(calc %.2f "$d_m3 / $f_m3")
r_fast_m0=$(calc %.2f "$d_m0 / $f_m0")
r_prec=$(calc %.2f "$p_m3 / $d_m3")
r_soft=$(calc %.1f "$s64_m3 / $d_m3")
r_soft_f=$(calc %.1f "$s64_m3 / $f_m3")
r_f32=$(calc %.1f "$s32_m3 / $d_m3")
r_m4=$(calc %.2f "$s32_m4 / $d_m3")
ok() { if awk "BEGIN { exit !($1) }"; then echo met; else echo missed; fi; }
t_fast=$(ok "$r_fast >= 1.5 && $f_ps >= 35")
t_soft=$(ok "$r_soft >= 10")

# Pareto frontier over the seed points measured on the M3: a point is on it
# when no other point costs no more and is no less accurate (one of the two
# strictly). PSNR "inf" (identical to the reference) beats every number.
PTS=$(awk -F'\t' '$2 == "seed" && $3 == 1 && !seen[$1]++ && $5 != "-" {
    printf "%s\t%s\t%s\n", $1, $5, ($9 == "inf" ? 1e9 : $9) }' "$TSV")
FRONT=$(echo "$PTS" | awk -F'\t' '{ n++; l[n] = $1; c[n] = $2; p[n] = $3 }
    END { for (i = 1; i <= n; i++) { on = 1
        for (j = 1; j <= n; j++) if (j != i && c[j] <= c[i] && p[j] >= p[i] &&
            (c[j] < c[i] || p[j] > p[i])) on = 0
        if (on) print l[i] } }')
if echo "$FRONT" | grep -qx default; then t_pareto=met; else t_pareto=missed; fi
front_list=$(echo "$FRONT" | paste -sd ';' - | sed 's/;/; /g')

# ---- The table ---------------------------------------------------------------

table=$(awk -F'\t' '
function commas(x,   s, i, r, d) { if (x == "-") return "–"
    d = ""; if (x ~ /\./) { d = substr(x, index(x, ".")); x = substr(x, 1,
        index(x, ".") - 1) }
    r = ""; while (length(x) > 3) { r = "," substr(x, length(x) - 2) r
        x = substr(x, 1, length(x) - 3) } return x r d }
BEGIN { print "| setting | scene | spp | depth | M3 instr/px | M0 instr/px |" \
    " M4F instr/px | host µs/px (noisy) | PSNR dB | max err | > 2/255 |" \
    " fw = host |"
    print "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|:-:|" }
{ psnr = ($9 == "inf") ? "∞ (identical)" : $9
  printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s%% | %s |\n",
      $1, $2, $3, $4, commas($5), commas($6), commas($7),
      ($8 == "-" ? "–" : $8), psnr, $10,
      $11, ($12 == "-" ? "–" : $12) }' "$TSV")

# ---- The chart -----------------------------------------------------------------

echo "$PTS" | awk -F'\t' -v front="$(echo "$FRONT" | paste -sd '|' -)" \
    -v m4="$s32_m4" -v m4p="$s32_ps" '
function lx(v) { return log(v) / log(10) }
function X(v) { return L + (lx(v) - x0) / (x1 - x0) * (R - L) }
function Y(p) { if (p >= 1e8) return TOPY; return B - (p - y0) / (y1 - y0) * (B - T) }
function esc(s) { gsub(/&/, "\\&amp;", s); return s }
{ n++; lab[n] = $1; c[n] = $2; p[n] = $3 }
END {
    if (m4 != "" && m4 != "-") { n++; lab[n] = "float32, M4F FPU"; c[n] = m4
        p[n] = (m4p == "inf") ? 1e9 : m4p; hollow[n] = 1 }
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
        "Cost against accuracy: scenes/seed.scene, 1 spp</text>\n", L
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
        "PSNR against the double reference (dB)</text>\n", (T + B) / 2
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
    printf "<text x=\"%d\" y=\"%d\">Pareto frontier (filled red: on it). Hollow: " \
        "Cortex-M4F instructions, for comparison (not on the frontier).</text>\n",
        L + 36, Ht - 12
    print "</svg>" }' >"$SVG"

# ---- The document ---------------------------------------------------------------

{
cat <<EOF
# What accuracy costs

Generated by \`make accuracy\` (tools/accuracy.sh and
tools/accuracy_report.sh); do not edit by hand, run it again. The last run
took ${SECS} s. Instruction counts are exact and repeat to the last digit
(QEMU \`-icount\`); host times are the median of ${RUNS} runs on whatever
machine ran it, and **noisy**.

## The settings

\`RT_ACCURACY\` (core/rt_config.h) picks the math layer at compile time;
\`core/fx_math.h\` states each operation's bound.

| setting | \`RT_ACCURACY\` | multiply, dot, cross, madd | div, recip | sqrt, length | normalize |
|---|---|---|---|---|---|
| fast | 0 | round down (< 1 ulp) | within 2 ulps / 1 ulp, no correction step | within 1 ulp (no final fix-up) | within 0.7 ulp, interpolated table (no polynomial) |
| default | 1 | nearest, ties up (0.5 ulp) | correctly rounded | correctly rounded | within 0.5 + 2^-4 ulp |
| precise | 2 | nearest, ties to even | correctly rounded, ties to even | correctly rounded | correctly rounded (exact tie test) |

Every setting saturates the same way, renders the same bytes on the host
and on every board (the "fw = host" column checks the M3 and M0 images
against the host's), and passes \`tests/test_fx.c\` and \`tests/test_vec.c\`
built for it:

    make RT_DEFS=-DRT_ACCURACY=0 HOST_BUILD=build/posix-fast build/posix-fast/tests/test_fx
    build/posix-fast/tests/test_fx

Spp and depth are run-time knobs (\`-s\`, \`-d\`; firmware \`SPP=\`, and the
depth on the scene's \`image\` line).

## Measurements

${W}x${H} pixels. PSNR, max error and the share of pixels off by more than
2/255 compare each image with the double reference rendered at the same
size, spp and depth (\`fixtrace --reference\`); "∞" means identical bytes.
M3 is \`BOARD=an385\`, M0 \`BOARD=m0\` (the firmware as \`make qemu\` builds
it by default, with only the effects the scene needs), M4F QEMU's
mps2-an386 with the FPU on. Host time is \`fixtrace --stats\`'s
render_seconds (no parsing or file output) per pixel, one thread. The reference rows are port/posix/ref_render.c and ref_shapes.c, unchanged, built as
firmware (bench/softref: a small libm, soft double or, with
\`-Ddouble=float\`, soft float on the M3 and M0, hardware float on the
M4F); their host time is \`--reference\` on the host's FPU.

${table}

The M4F float32 image is byte-identical to the M3 soft-float one: ${M4SAME}.

![cost against PSNR](accuracy.svg)

## Targets

- The default setting lies on the Pareto frontier (seed, M3): **${t_pareto}**.
  On the frontier: ${front_list}.
- Fast costs at least 1.5x fewer instructions than default on the M3 at
  PSNR >= 35 dB on the seed: **${t_fast}**: ${r_fast}x fewer
  ($(commas "$f_m3") against $(commas "$d_m3") per pixel) at ${f_ps} dB; on
  the M0 ${r_fast_m0}x ($(commas "$f_m0") against $(commas "$d_m0")).
- Fixed point on the M3 costs at least 10x fewer instructions than the
  soft-double reference: **${t_soft}**: ${r_soft}x (default), ${r_soft_f}x
  (fast).

## What the numbers say

- **The math layer is a small part of the cost.** Fast saves
  $(calc %.1f "(1 - $f_m3 / $d_m3) * 100")% of the M3 instructions and
  $(calc %.1f "(1 - $f_m0 / $d_m0) * 100")% of the M0 ones: most of a
  pixel is intersection and shading code in core/rt_*.c that does its own
  64-bit arithmetic, which the setting does not touch. A 1.5x gap would
  need the intersection code itself to trade accuracy (for example
  32-bit bounding-sphere tests with a truncated closest approach), which
  is outside the math layer.
- **Fast's loss is its rounding down.** The round-down multiply, dot
  product and madd bias every shading sum and every reflected or refracted
  direction the same way (glass, with its chains of refraction, shows it
  most); the approximate square root, normalize, divide and reciprocal
  err by under 1 ulp either way. (Checked once by building fast with the
  default's rounding: it kept about half of fast's saving and lost no
  PSNR.)
- **Precise is paid for, not seen.** It costs ${r_prec}x the default's M3
  instructions (the correctly rounded normalize is most of it) and moves
  PSNR by $(calc %+.2f "$p_ps - $d_ps") dB on the seed. The remaining
  error is not arithmetic rounding but decisions (hit or miss at a
  silhouette, a texture cell, a shadow edge) taken on Q16.16 positions
  and directions, and a unit direction in Q16.16 is already within 0.55
  ulp per component in the default.
- **Floating point is the accuracy ceiling, at a price.** float32 in soft
  float on the M3 costs ${r_f32}x the default's instructions for
  ${s32_ps} dB; soft double ${r_soft}x for the reference itself. An M4F
  with its FPU runs the float32 renderer in $(commas "$s32_m4") instructions per
  pixel, ${r_m4}x the fixed-point default on the M3 (which runs the same
  Thumb-2 code on an M4), at float32's ${s32_ps} dB.
- Spp and depth are the large knobs (see their rows): cost grows with spp
  almost in proportion, and with depth as far as the scene's mirrors and
  glass send rays. Their PSNR is against the reference at the same spp
  and depth, so it measures arithmetic, not anti-aliasing; they are left
  off the chart, which compares renderings of one and the same image.

## Reproducing a row

    make accuracy                                   # everything, this page
    make -j2 build/posix/fixtrace
    make -j2 HOST_BUILD=build/posix-acc0 RT_DEFS=-DRT_ACCURACY=0 build/posix-acc0/fixtrace
    build/posix-acc0/fixtrace -W ${W} -H ${H} -o fast.ppm scenes/seed.scene
    build/posix/fixtrace --reference -W ${W} -H ${H} -o ref.ppm scenes/seed.scene
    build/posix/fixtrace compare fast.ppm ref.ppm
    build/posix-acc0/fixtrace --stats -W ${W} -H ${H} -o fast.ppm scenes/seed.scene   # render_seconds
    make qemu BOARD=an385 FW_BUILD=build/accuracy/fw-an385-acc0 \\
        FW_DEFS=-DRT_ACCURACY=0 SCENE=scenes/seed.scene WIDTH=${W} HEIGHT=${H} SPP=1
    make softref-qemu SR=m3-f64 SCENE=scenes/seed.scene WIDTH=${W} HEIGHT=${H} SPP=1
    make softref-qemu SR=m4f-f32 SCENE=scenes/seed.scene WIDTH=${W} HEIGHT=${H} SPP=1

Depth rows render a copy of the seed whose \`image\` line says another
depth (build/accuracy/scenes/). \`SR=\` variants: m3-f64, m3-f32, m0-f64,
m0-f32, m4f-f32 (mk/accuracy.mk). \`tests/suite_accuracy.sh\` repeats a
small version of this (seed at 48x36) in \`make test\`.
EOF
} >"$MD"
