#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# accuracy.sh: what accuracy costs. Measures every row of the tables in
# docs/accuracy.md, keeps them in docs/accuracy-data.tsv and writes
# docs/accuracy.md and its two charts again (tools/accuracy_report.sh;
# `make accuracy` runs it). Needs gcc, make, awk, arm-none-eabi-gcc and
# qemu-system-arm, and netpbm (pnmtopng, pamfunc) for the pictures.
#
# For each precision of unit vectors (RT_UNIT_BITS 16, 20, 24 and the
# default 30) and scene: instructions per pixel on Cortex-M3 and M0 (QEMU
# -icount, exact), host time per pixel (median of ACC_RUNS runs, noisy),
# and the error against the double reference (fixtrace --reference). For
# the default also the work knobs on the seed (spp, adaptive
# anti-aliasing, depth), measured against the ideal image too (the
# reference at 16 spp and the scene's depth); the reference renderer
# itself as firmware in soft double and soft float (bench/softref); and
# the seed's picture and error heat map at each precision
# (docs/img/accuracy/). For the default also draft renders (--draft T,
# DRAFT=T) of every scene at each threshold of DRAFTS, with the share of
# interpolated pixels, and the seed's draft picture and error map.
#
#   tools/accuracy.sh           every row (make accuracy)
#   tools/accuracy.sh --draft   only the draft rows: measures them again
#                               and puts them in place of the old ones in
#                               docs/accuracy-data.tsv, keeping the rest
#
# Environment: ACC_JOBS (QEMU runs at once, default 2), ACC_RUNS (host
# timing runs, default 7), ACC_WIDTH / ACC_HEIGHT (default 320 x 240).
# Work files go to build/accuracy/.
set -euo pipefail
cd "$(dirname "$0")/.."

# Until the top Makefile includes mk/accuracy.mk, name it explicitly (in
# MK, not in MAKE, which recursive makes inherit).
MK=${MAKE:-make}
grep -q 'mk/accuracy\.mk' Makefile || MK="$MK -f Makefile -f mk/accuracy.mk"
JOBS=${ACC_JOBS:-2}
RUNS=${ACC_RUNS:-7}
W=${ACC_WIDTH:-320}
H=${ACC_HEIGHT:-240}
WORK=build/accuracy
SCENES="seed mirrors glass textures"
BITS="16 20 24 30"
DEFAULT=30
# The work knobs of the default on the seed: "tag spp adaptive".
KNOBS="seed-s4 4 0
seed-s16 16 0
seed-a8 16 8"
# Draft thresholds, each rendered for every scene as tag "<scene>-t<T>".
DRAFTS="32 64 128"
ONLY_DRAFT=0
[ "${1:-}" = --draft ] && ONLY_DRAFT=1

# ---- One measurement job (run in parallel by xargs) -------------------------

# Instructions and pixels from a firmware log, as "instructions pixels".
log_counts() {
    awk '/^instructions /{i=$2} /^pixels /{p=$2} END{print i+0, p+0}' "$1"
}

# fw BOARD BITS: every configuration of one fixed-point firmware, one
# after the other in one build directory (only the scene and main.c
# rebuild).
job_fw() {
    local board=$1 u=$2 dir=$WORK/fw-$1-u$2 tag scene spp ad dr
    while read -r tag scene spp ad dr; do
        if ! $MK -s qemu BOARD="$board" FW_BUILD="$dir" \
            FW_DEFS="-DRT_UNIT_BITS=$u" SCENE="$scene" WIDTH="$W" \
            HEIGHT="$H" SPP="$spp" ADAPTIVE="$ad" DRAFT="${dr:-0}" \
            >"$dir.$tag.out" 2>&1; then
            echo "accuracy: $board u$u $tag failed:" >&2
            tail -n 5 "$dir.$tag.out" >&2
            return 1
        fi
        log_counts "$dir/qemu.log" >"$WORK/res/fw-$board-$u-$tag"
        cp "$dir/out.ppm" "$WORK/img/fw-$board-$u-$tag.ppm"
    done < <(configs "$u")
}

# sr VARIANT SCENES...: the reference renderer as firmware.
job_sr() {
    local v=$1 s
    shift
    for s in "$@"; do
        if ! $MK -s softref-qemu SR="$v" SCENE="scenes/$s.scene" \
            WIDTH="$W" HEIGHT="$H" SPP=1 >"$WORK/sr-$v.$s.out" 2>&1; then
            echo "accuracy: softref $v $s failed:" >&2
            tail -n 5 "$WORK/sr-$v.$s.out" >&2
            return 1
        fi
        log_counts "build/softref-$v/qemu.log" >"$WORK/res/sr-$v-$s"
        cp "build/softref-$v/out.ppm" "$WORK/img/sr-$v-$s.ppm"
    done
}

# The configurations of a setting: "tag scene-file spp adaptive draft".
# Every setting renders the scenes; the default also the work knobs and
# the drafts (with --draft, only those).
configs() {
    local s d t tag spp ad
    if [ "$1" = "$DEFAULT" ]; then
        for s in $SCENES; do
            for t in $DRAFTS; do
                echo "$s-t$t scenes/$s.scene 1 0 $t"
            done
        done
    fi
    [ "$ONLY_DRAFT" = 1 ] && return
    for s in $SCENES; do
        echo "$s scenes/$s.scene 1 0"
    done
    if [ "$1" = "$DEFAULT" ]; then
        while read -r tag spp ad; do
            echo "$tag scenes/seed.scene $spp $ad"
        done <<<"$KNOBS"
        for d in 0 1 2 3; do
            echo "seed-d$d $WORK/scenes/seed-d$d.scene 1 0"
        done
    fi
}

if [ "${1:-}" = --job ]; then
    [ "${2:-}" = --draft ] && { ONLY_DRAFT=1; shift; }
    shift
    kind=$1
    shift
    "job_$kind" "$@"
    exit
fi

# ---- Set-up -------------------------------------------------------------------

for tool in arm-none-eabi-gcc qemu-system-arm awk; do
    command -v "$tool" >/dev/null || {
        echo "accuracy: $tool not found (see README.md)" >&2
        exit 1
    }
done
start=$SECONDS
mkdir -p "$WORK/res" "$WORK/img" "$WORK/scenes" "$WORK/host"
rm -f "$WORK"/res/* "$WORK"/img/*

# Depth variants of the seed: only its `image` line's depth differs.
for d in 0 1 2 3; do
    sed -E "s/^(image .*depth) [0-9]+/\1 $d/" scenes/seed.scene \
        >"$WORK/scenes/seed-d$d.scene"
    grep -q "^image .*depth $d" "$WORK/scenes/seed-d$d.scene" || {
        echo "accuracy: no depth on the seed's image line" >&2
        exit 1
    }
done

[ "$ONLY_DRAFT" = 1 ] && BITS=$DEFAULT
echo "accuracy: host builds"
for u in $BITS; do
    $MK -s -j"$JOBS" SANITIZE= HOST_BUILD=build/posix-u$u \
        RT_DEFS=-DRT_UNIT_BITS=$u build/posix-u$u/fixtrace
done
REF=build/posix-u$DEFAULT/fixtrace

# Scene file, spp and adaptive threshold of a tag (seed, seed-s4,
# seed-a8, seed-d2, glass, ...).
tag_scene() {
    case $1 in
    *-t*) echo "scenes/${1%%-t*}.scene" ;;
    seed-d*) echo "$WORK/scenes/$1.scene" ;;
    seed-*) echo scenes/seed.scene ;;
    *) echo "scenes/$1.scene" ;;
    esac
}
tag_spp() {
    case $1 in
    seed-s*) echo "${1#seed-s}" ;;
    seed-a*) echo 16 ;;
    *) echo 1 ;;
    esac
}
tag_ad() {
    case $1 in
    seed-a*) echo "${1#seed-a}" ;;
    *) echo 0 ;;
    esac
}
tag_draft() {
    case $1 in
    *-t*) echo "${1##*-t}" ;;
    *) echo 0 ;;
    esac
}
# The fixtrace options of a tag.
tag_opts() {
    local o="-s $(tag_spp "$1")"
    [ "$(tag_ad "$1")" -gt 0 ] && o="$o --adaptive $(tag_ad "$1")"
    [ "$(tag_draft "$1")" -gt 0 ] && o="$o --draft $(tag_draft "$1")"
    echo "$o"
}

echo "accuracy: host renders and references"
REFS="$SCENES seed-s4 seed-s16 seed-d0 seed-d1 seed-d2 seed-d3"
[ "$ONLY_DRAFT" = 1 ] && REFS="$SCENES seed-s16"
for tag in $REFS; do
    $REF -q --reference -W "$W" -H "$H" -s "$(tag_spp "$tag")" \
        -o "$WORK/img/ref-$tag.ppm" "$(tag_scene "$tag")"
done
# A draft is held to the full render's reference.
for s in $SCENES; do
    for t in $DRAFTS; do
        cp "$WORK/img/ref-$s.ppm" "$WORK/img/ref-$s-t$t.ppm"
    done
done
# Adaptive anti-aliasing is a fixed-point shortcut to 16 spp: its
# reference is the full 16 spp one.
cp "$WORK/img/ref-seed-s16.ppm" "$WORK/img/ref-seed-a8.ppm"
# The ideal image the work knobs are held to: 16 spp, the scene's depth.
IDEAL=$WORK/img/ref-seed-s16.ppm
for u in $BITS; do
    for tag in $(configs "$u" | awk '{print $1}'); do
        # shellcheck disable=SC2046
        build/posix-u$u/fixtrace -q --stats -W "$W" -H "$H" \
            $(tag_opts "$tag") -o "$WORK/img/host-$u-$tag.ppm" \
            "$(tag_scene "$tag")" 2>"$WORK/res/stats-$u-$tag"
    done
done

echo "accuracy: firmware runs under QEMU ($JOBS at once)"
if [ "$ONLY_DRAFT" = 1 ]; then
    printf '%s\n' "--draft fw m0 $DEFAULT" "--draft fw an385 $DEFAULT"
else
    for u in $DEFAULT 16 20 24; do
        echo "fw m0 $u"
        echo "fw an385 $u"
    done
    echo "sr m0-f64 seed"
    echo "sr m3-f64 $SCENES"
    echo "sr m0-f32 seed"
    echo "sr m3-f32 $SCENES"
    echo "sr m4f-f32 $SCENES"
fi | xargs -P "$JOBS" -L 1 bash "$0" --job

# ---- Host time: nothing else runs now; still noisy ----------------------------

echo "accuracy: host timing ($RUNS runs each)"
median() {
    sort -g | awk '{ v[NR] = $1 }
        END { if (NR % 2) print v[(NR + 1) / 2]
              else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
host_time() { # fixtrace-binary tag [--reference]: median microseconds/pixel
    local bin=$1 tag=$2 i
    shift 2
    for ((i = 0; i < RUNS; i++)); do
        # shellcheck disable=SC2046
        "$bin" --stats "$@" -W "$W" -H "$H" $(tag_opts "$tag") \
            -o "$WORK/host/t.ppm" "$(tag_scene "$tag")" 2>&1 |
            awk '/^render_seconds /{print $2}'
    done | median | awk -v p=$((W * H)) '{printf "%.3f\n", $1 * 1e6 / p}'
}
for u in $BITS; do
    for tag in $(configs "$u" | awk '{print $1}'); do
        host_time build/posix-u$u/fixtrace "$tag" >"$WORK/res/host-$u-$tag"
    done
done
for tag in $SCENES; do
    [ "$ONLY_DRAFT" = 1 ] && break
    host_time "$REF" "$tag" --reference >"$WORK/res/host-ref-$tag"
done

# ---- Compare and tabulate --------------------------------------------------------

# "psnr max_err bad_pct" of image $1 against $2 (psnr "inf" if identical).
errors() {
    $REF compare "$1" "$2" | awk '
        /^PSNR:/ { p = ($2 == "inf") ? "inf" : $2 }
        /^max error:/ { split($3, a, "/"); m = a[1] }
        /^off by > 2:/ { b = $5 }
        END { print p, m, b }'
}
res() { cat "$WORK/res/$1" 2>/dev/null || echo "- -"; }
ipp() { # instructions per pixel from a result file, or -
    res "$1" | awk '{ if ($2 > 0) printf "%.1f", $1 / $2; else print "-" }'
}

# One row per line, tab-separated: label scene spp depth m3 m0 m4f host
# psnr maxerr bad identical(firmware == host image) adaptive
# psnr-against-the-ideal (seed only) draft interpolated-percent
TSV=$WORK/results.tsv
: >"$TSV"
depth_of() {
    awk '/^image /{for (i = 1; i < NF; i++) if ($i == "depth") print $(i + 1)}' \
        "$(tag_scene "$1")"
}
ideal() { # PSNR of a seed image against the ideal one, or -
    case $2 in
    seed*) errors "$1" "$IDEAL" | awk '{print $1}' ;;
    *) echo - ;;
    esac
}
for u in $BITS; do
    for tag in $(configs "$u" | awk '{print $1}'); do
        img=$WORK/img/host-$u-$tag.ppm
        e=$(errors "$img" "$WORK/img/ref-$tag.ppm")
        same=yes
        for b in an385 m0; do
            cmp -s "$WORK/img/fw-$b-$u-$tag.ppm" "$img" || same=no
        done
        interp=$(awk -v p=$((W * H)) '/^interpolated_pixels /{
            printf "%.1f", 100 * $2 / p }' "$WORK/res/stats-$u-$tag")
        printf '%s\t%s\t%s\t%s\t%s\t%s\t-\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' \
            "$u" "${tag%%-*}" "$(tag_spp "$tag")" \
            "$(depth_of "$tag")" "$(ipp "fw-an385-$u-$tag")" \
            "$(ipp "fw-m0-$u-$tag")" "$(res "host-$u-$tag")" \
            "$(echo "$e" | tr ' ' '\t')" "$same" "$(tag_ad "$tag")" \
            "$(ideal "$img" "$tag")" "$(tag_draft "$tag")" \
            "${interp:-0.0}" >>"$TSV"
    done
done
for prec in f32 f64; do
    [ "$ONLY_DRAFT" = 1 ] && break
    for s in $SCENES; do
        e=$(errors "$WORK/img/sr-m3-$prec-$s.ppm" "$WORK/img/ref-$s.ppm")
        m0=-
        [ -f "$WORK/res/sr-m0-$prec-$s" ] && m0=$(ipp "sr-m0-$prec-$s")
        m4=-
        [ "$prec" = f32 ] && m4=$(ipp "sr-m4f-f32-$s")
        host=-
        [ "$prec" = f64 ] && host=$(res "host-ref-$s")
        label="reference, float32"
        [ "$prec" = f64 ] && label="reference, double"
        printf '%s\t%s\t1\t%s\t%s\t%s\t%s\t%s\t%s\t-\t0\t%s\t0\t0.0\n' \
            "$label" "$s" "$(depth_of "$s")" "$(ipp "sr-m3-$prec-$s")" \
            "$m0" "$m4" "$host" "$(echo "$e" | tr ' ' '\t')" \
            "$(ideal "$WORK/img/sr-m3-$prec-$s.ppm" "$s")" >>"$TSV"
    done
done
# The M4F float32 image must be the M3 float32 image (same IEEE single).
m4same=yes
for s in $SCENES; do
    [ "$ONLY_DRAFT" = 1 ] && break
    cmp -s "$WORK/img/sr-m4f-f32-$s.ppm" "$WORK/img/sr-m3-f32-$s.ppm" ||
        m4same=no
done

# ---- Pictures: the seed at each precision and its error heat map ------------

if command -v pnmtopng >/dev/null && command -v pamfunc >/dev/null; then
    mkdir -p docs/img/accuracy
    for u in $BITS; do
        [ "$ONLY_DRAFT" = 1 ] && break
        cp "$WORK/img/host-$u-seed.ppm" "$WORK/host/seed-u$u.ppm"
        $REF compare "$WORK/img/host-$u-seed.ppm" "$WORK/img/ref-seed.ppm" \
            --diff "$WORK/host/diff-u$u.ppm" >/dev/null || true
        pnmtopng -compression 9 "$WORK/host/seed-u$u.ppm" \
            >docs/img/accuracy/seed-u$u.png
        # The error image, brightened 8 times so that flips and
        # small errors alike can be seen.
        pamfunc -multiplier=8 "$WORK/host/diff-u$u.ppm" |
            pnmtopng -compression 9 >docs/img/accuracy/diff-u$u.png
    done
    # The seed's draft at the middle threshold, and its error.
    t=$(echo $DRAFTS | awk '{ print $(int((NF + 1) / 2)) }')
    $REF compare "$WORK/img/host-$DEFAULT-seed-t$t.ppm" \
        "$WORK/img/ref-seed.ppm" --diff "$WORK/host/diff-draft.ppm" \
        >/dev/null || true
    pnmtopng -compression 9 "$WORK/img/host-$DEFAULT-seed-t$t.ppm" \
        >docs/img/accuracy/seed-draft$t.png
    pamfunc -multiplier=8 "$WORK/host/diff-draft.ppm" |
        pnmtopng -compression 9 >docs/img/accuracy/diff-draft$t.png
else
    echo "accuracy: pnmtopng (netpbm) not found: pictures not updated" >&2
fi

elapsed=$((SECONDS - start))
if [ "$ONLY_DRAFT" = 1 ]; then
    # The other rows and the header stay; the draft rows are replaced.
    { head -n 1 docs/accuracy-data.tsv
      grep -v '^#' docs/accuracy-data.tsv | awk -F'\t' '($15 + 0) == 0'
      cat "$TSV"; } >"$WORK/data.tsv"
    mv "$WORK/data.tsv" docs/accuracy-data.tsv
else
    {
        echo "# $m4same $W $H $RUNS $elapsed"
        cat "$TSV"
    } >docs/accuracy-data.tsv
fi
bash tools/accuracy_report.sh
echo "accuracy: wrote docs/accuracy.md, its charts and data in ${elapsed} s"
