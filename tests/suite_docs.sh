#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The documentation keeps its promises:
# - every docs/examples/*.c compiles freestanding against core/ with the
#   tree's strict warnings (and for Cortex-M0 when arm-none-eabi-gcc is
#   there), and docs/embedding.md shows embed_example.c exactly as it is;
# - embed_example.c, linked with the core on the host and given a fake SPI
#   display, sends the right window commands and a 160x128 RGB565 picture
#   equal, byte for byte, to `fixtrace --format rgb565be --dither`;
# - tiles_example.c, on a fake panel with DMA, draws the screen tile by
#   tile and redraws a dirty rectangle, both equal to that render; and
#   oled_example.c sends the SSD1306 pages of `fixtrace --format
#   mono-page --dither diffusion`; embedding.md shows both as they are;
# - every statement shown in docs/scene-format.md before its Errors
#   section parses, and every keyword and field the parser knows (asked
#   from the parser's own error messages) has an example there;
# - port/baremetal/board_template.c, switched on, compiles for Cortex-M0,
#   M3 and RV32 (docs/porting.md);
# - README.md shows the gallery picture of every scene in scenes/ (a
#   picture that differs from a fresh render is only noted), and every
#   relative link in README.md and docs/*.md points at a file;
# - every build/posix-*/fixtrace a command block runs is built in that
#   block.
# The figures the pages quote are tests/suite_figures.sh's.
set -u
cd "$(dirname "$0")/.."
# -I for every layer folder of core/ (the Makefile exports the same).
CORE_INC=${CORE_INC:-$(for d in core/*/; do printf -- '-I%s ' "${d%/}"; done)}
FT=${FIXTRACE:-build/posix/fixtrace}
CC=${CC:-gcc}
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not found (build it with make)"
    echo "0 passed, 1 failed"
    exit 1
fi

# The examples include the package's names (<fixtrace/rt_render.h>): here
# every core header under $tmp/inc/fixtrace/ (tests/suite_cmake.sh builds
# them against the installed package, which holds only the public ones).
mkdir -p "$tmp/inc/fixtrace"
ln -s "$PWD"/core/*/*.h "$tmp/inc/fixtrace/"
PKG_INC="-I$tmp/inc"

STRICT="-std=c99 -Wall -Wextra -Werror -Wshadow -Wundef -Wdouble-promotion
    -Wstrict-prototypes -Wmissing-prototypes -Wconversion -Wno-sign-conversion
    -fno-common"

# --- docs/examples/*.c compile freestanding -------------------------------
for src in docs/examples/*.c; do
    # shellcheck disable=SC2086
    if $CC $STRICT -ffreestanding -nostdlib $PKG_INC -c "$src" \
        -o "$tmp/ex.o" 2>"$tmp/err"; then
        ok
    else
        bad "$src does not compile freestanding: $(head -c 600 "$tmp/err")"
    fi
    if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
        # shellcheck disable=SC2086
        if arm-none-eabi-gcc $STRICT -mcpu=cortex-m0 -mthumb -Os \
            -ffreestanding -nostdlib $PKG_INC -c "$src" -o "$tmp/ex_m0.o" \
            2>"$tmp/err"; then
            ok
        else
            bad "$src does not compile for Cortex-M0: $(head -c 600 "$tmp/err")"
        fi
    else
        echo "note: arm-none-eabi-gcc missing; $src checked for the host only"
    fi
done

# The board template (docs/porting.md), switched on, compiles for every
# architecture a board may have, with the firmware's flags and warnings.
sed 's/^#if 0$/#if 1/' port/baremetal/board_template.c >"$tmp/board_t.c"
grep -q '^#if 1$' "$tmp/board_t.c" && ok ||
    bad "port/baremetal/board_template.c has no '#if 0' switch line"
for target in "arm-none-eabi-gcc -mcpu=cortex-m0 -mthumb" \
    "arm-none-eabi-gcc -mcpu=cortex-m3 -mthumb" \
    "riscv64-unknown-elf-gcc -march=rv32imac -misa-spec=2.2 -mabi=ilp32"; do
    # shellcheck disable=SC2086
    set -- $target
    if ! command -v "$1" >/dev/null 2>&1; then
        echo "note: $1 missing; board_template.c not compiled with it"
        continue
    fi
    # shellcheck disable=SC2086
    if $target $STRICT -O2 -ffreestanding $CORE_INC -Iport/baremetal \
        -c "$tmp/board_t.c" -o "$tmp/board_t.o" 2>"$tmp/err"; then
        ok
    else
        bad "board_template.c does not compile with $target:" \
            "$(head -c 600 "$tmp/err")"
    fi
done

# docs/embedding.md quotes the example between two marker comments.
awk '/<!-- begin docs\/examples\/embed_example.c -->/ {on = 1; next}
     /<!-- end docs\/examples\/embed_example.c -->/ {on = 0}
     on && !/^```/' docs/embedding.md >"$tmp/quoted.c"
if [ ! -s "$tmp/quoted.c" ]; then
    bad "docs/embedding.md does not quote docs/examples/embed_example.c"
elif cmp -s "$tmp/quoted.c" docs/examples/embed_example.c; then
    ok
else
    bad "docs/embedding.md's copy of embed_example.c differs from the file:"
    diff docs/examples/embed_example.c "$tmp/quoted.c" | head -n 20
fi

# --- embed_example.c runs on the host ----------------------------------------
# A fake display: records the commands and their argument bytes, and
# expands the RGB565 pixel stream after RAMWR to a PPM the way fixtrace
# does, so the two can be compared byte for byte.
cat >"$tmp/fake_lcd.c" <<'EOF'
#include <stdio.h>
#include <string.h>
#include "embed_example.c"

static uint8_t cmds[8], args[8][4];
static size_t ncmd, nargs[8];
static FILE *ppm;
static unsigned long pixel_bytes;

void lcd_command(uint8_t cmd)
{
    if (ncmd < 8)
        cmds[ncmd++] = cmd;
}

void spi_write(const uint8_t *d, size_t n)
{
    if (ncmd > 0 && cmds[ncmd - 1] == 0x2C) {
        for (size_t i = 0; i + 1 < n; i += 2) {
            unsigned v = (unsigned)d[i] << 8 | d[i + 1];
            unsigned r = v >> 11, g = (v >> 5) & 63, b = v & 31;
            fputc((int)(r << 3 | r >> 2), ppm);
            fputc((int)(g << 2 | g >> 4), ppm);
            fputc((int)(b << 3 | b >> 2), ppm);
        }
        pixel_bytes += n;
    } else if (ncmd > 0) {
        for (size_t i = 0; i < n && nargs[ncmd - 1] < 4; i++)
            args[ncmd - 1][nargs[ncmd - 1]++] = d[i];
    }
}

int main(int argc, char **argv)
{
    static const uint8_t want_cols[4] = { 0, 0, 0, LCD_W - 1 };
    static const uint8_t want_rows[4] = { 0, 0, 0, LCD_H - 1 };
    rt_parse_error err;
    FILE *f;
    int rc;
    if (argc != 3)
        return 2;
    f = fopen(argv[1], "wb"); /* the scene, for the CLI to render */
    fputs(scene_text, f);
    fclose(f);
    ppm = fopen(argv[2], "wb");
    fprintf(ppm, "P6\n%d %d\n255\n", LCD_W, LCD_H);
    rc = render_to_lcd(&err);
    fclose(ppm);
    if (rc != 0) {
        fprintf(stderr, "render_to_lcd: %d (%u:%u %s)\n", rc,
                (unsigned)err.line, (unsigned)err.col, err.msg);
        return 1;
    }
    if (ncmd != 3 || cmds[0] != 0x2A || cmds[1] != 0x2B || cmds[2] != 0x2C ||
        nargs[0] != 4 || memcmp(args[0], want_cols, 4) != 0 ||
        nargs[1] != 4 || memcmp(args[1], want_rows, 4) != 0) {
        fprintf(stderr, "wrong window set-up: %u commands\n", (unsigned)ncmd);
        return 1;
    }
    if (pixel_bytes != (unsigned long)LCD_W * LCD_H * 2) {
        fprintf(stderr, "%lu pixel bytes, want %d\n", pixel_bytes,
                LCD_W * LCD_H * 2);
        return 1;
    }
    return 0;
}
EOF
# shellcheck disable=SC2046
if $CC -std=c99 -O1 $CORE_INC $PKG_INC -Idocs/examples "$tmp/fake_lcd.c" core/*/*.c \
    -o "$tmp/fake_lcd" 2>"$tmp/err"; then
    ok
    if "$tmp/fake_lcd" "$tmp/embed.scene" "$tmp/lcd.ppm" 2>"$tmp/err"; then
        ok
        if "$FT" -q --format rgb565be --dither -W 160 -H 128 \
            -o "$tmp/cli.ppm" "$tmp/embed.scene" 2>"$tmp/err" &&
            cmp -s "$tmp/cli.ppm" "$tmp/lcd.ppm"; then
            ok
        else
            bad "embed_example.c's picture differs from fixtrace --format" \
                "rgb565be --dither: $(head -c 300 "$tmp/err")"
        fi
    else
        bad "embed_example.c on a fake display: $(head -c 300 "$tmp/err")"
    fi
else
    bad "embed_example.c does not build on the host: $(head -c 600 "$tmp/err")"
fi

# docs/embedding.md quotes the tile and OLED examples too.
for ex in tiles_example.c oled_example.c; do
    awk -v b="<!-- begin docs/examples/$ex -->" \
        -v e="<!-- end docs/examples/$ex -->" '
        $0 == b {on = 1; next}
        $0 == e {on = 0}
        on && !/^```/' docs/embedding.md >"$tmp/quoted.c"
    if [ ! -s "$tmp/quoted.c" ]; then
        bad "docs/embedding.md does not quote docs/examples/$ex"
    elif cmp -s "$tmp/quoted.c" "docs/examples/$ex"; then
        ok
    else
        bad "docs/embedding.md's copy of $ex differs from the file:"
        diff "docs/examples/$ex" "$tmp/quoted.c" | head -n 20
    fi
done

# --- tiles_example.c runs on the host ------------------------------------
# A fake panel with a frame of its own: CASET and RASET set the window,
# RAMWR's pixels fill it. dma_start() only notes the transfer; dma_wait()
# copies it then, so a tile changed while "in flight" shows, as does a
# transfer started before the last one was waited for. The whole screen
# must equal fixtrace's render; then a rectangle of it is spoilt and
# redrawn (a dirty-rectangle update), and the screen must equal it again.
cat >"$tmp/fake_tiles.c" <<'EOF'
#include <stdio.h>
#include <string.h>
#include "tiles_example.c"

static uint8_t fb[LCD_H][LCD_W][2];
static int win[4], cmd, narg, errors;
static uint8_t arg[4];
static const uint8_t *flight;
static size_t flight_n;

void lcd_command(uint8_t c)
{
    if (flight)
        errors++; /* a command while pixels are still on the bus */
    cmd = c;
    narg = 0;
}

void spi_write(const uint8_t *d, size_t n)
{
    for (size_t i = 0; i < n && narg < 4; i++)
        arg[narg++] = d[i];
    if (narg == 4 && (cmd == 0x2A || cmd == 0x2B)) {
        int *w = win + (cmd == 0x2A ? 0 : 2);
        w[0] = arg[0] << 8 | arg[1];
        w[1] = arg[2] << 8 | arg[3];
    }
}

void dma_start(const uint8_t *d, size_t n)
{
    if (flight || cmd != 0x2C)
        errors++;
    flight = d;
    flight_n = n;
}

void dma_wait(void)
{
    size_t i = 0;
    if (!flight)
        return;
    for (int y = win[2]; y <= win[3]; y++)
        for (int x = win[0]; x <= win[1]; x++, i += 2)
            if (i + 1 < flight_n && y < LCD_H && x < LCD_W)
                memcpy(fb[y][x], flight + i, 2);
    if (i != flight_n)
        errors++;
    flight = NULL;
}

static int save(const char *path)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return 1;
    fprintf(f, "P6\n%d %d\n255\n", LCD_W, LCD_H);
    for (int y = 0; y < LCD_H; y++)
        for (int x = 0; x < LCD_W; x++) {
            unsigned v = (unsigned)fb[y][x][0] << 8 | fb[y][x][1];
            unsigned r = v >> 11, g = (v >> 5) & 63, b = v & 31;
            fputc((int)(r << 3 | r >> 2), f);
            fputc((int)(g << 2 | g >> 4), f);
            fputc((int)(b << 3 | b >> 2), f);
        }
    return fclose(f) != 0;
}

int main(int argc, char **argv)
{
    rt_parse_error err;
    if (argc != 4)
        return 2;
    FILE *f = fopen(argv[1], "wb"); /* the scene, for the CLI to render */
    fputs(scene_text, f);
    fclose(f);
    if (tiles_init(&err) != 0 || draw_rect(0, 0, LCD_W, LCD_H) != 0 ||
        save(argv[2]) != 0)
        return 1;
    for (int y = 70; y < 133; y++) /* spoil a rectangle, then redraw it */
        for (int x = 101; x < 172; x++)
            fb[y][x][0] = fb[y][x][1] = 0xA5;
    if (draw_rect(101, 70, 172, 133) != 0 || save(argv[3]) != 0)
        return 1;
    if (errors)
        fprintf(stderr, "%d DMA or window errors\n", errors);
    return errors != 0;
}
EOF
# shellcheck disable=SC2046
if $CC -std=c99 -O1 $CORE_INC $PKG_INC -Idocs/examples "$tmp/fake_tiles.c" \
    core/*/*.c -o "$tmp/fake_tiles" 2>"$tmp/err"; then
    if "$tmp/fake_tiles" "$tmp/tiles.scene" "$tmp/tiles.ppm" \
        "$tmp/dirty.ppm" 2>"$tmp/err" &&
        "$FT" -q --format rgb565be --dither -W 320 -H 240 \
            -o "$tmp/cli.ppm" "$tmp/tiles.scene" 2>>"$tmp/err"; then
        cmp -s "$tmp/cli.ppm" "$tmp/tiles.ppm" && ok ||
            bad "tiles_example.c's screen differs from fixtrace's render"
        cmp -s "$tmp/cli.ppm" "$tmp/dirty.ppm" && ok ||
            bad "tiles_example.c's dirty-rectangle redraw differs"
    else
        bad "tiles_example.c on a fake display: $(head -c 300 "$tmp/err")"
    fi
else
    bad "tiles_example.c does not build on the host: $(head -c 600 "$tmp/err")"
fi

# --- oled_example.c runs on the host -------------------------------------
# Its pages, as a fake SSD1306 receives them, must be the bytes of
# `fixtrace --format mono-page --dither diffusion`, page by page in order.
cat >"$tmp/fake_oled.c" <<'EOF'
#include <stdio.h>
#include "oled_example.c"

static uint8_t gram[OLED_H / 8][OLED_W];
static unsigned next_page, errors;

void oled_page(unsigned p, const uint8_t *bytes, size_t n)
{
    if (p != next_page++ || p >= OLED_H / 8 || n != OLED_W) {
        errors++;
        return;
    }
    for (size_t i = 0; i < n; i++)
        gram[p][i] = bytes[i];
}

int main(int argc, char **argv)
{
    rt_parse_error err;
    if (argc != 3)
        return 2;
    FILE *f = fopen(argv[1], "wb");
    fputs(scene_text, f);
    fclose(f);
    if (render_to_oled(&err) != 0 || errors || next_page != OLED_H / 8)
        return 1;
    f = fopen(argv[2], "wb");
    fwrite(gram, 1, sizeof gram, f);
    return fclose(f) != 0;
}
EOF
# shellcheck disable=SC2046
if $CC -std=c99 -O1 $CORE_INC $PKG_INC -Idocs/examples "$tmp/fake_oled.c" \
    core/*/*.c -o "$tmp/fake_oled" 2>"$tmp/err"; then
    if "$tmp/fake_oled" "$tmp/oled.scene" "$tmp/oled.raw" 2>"$tmp/err" &&
        "$FT" -q --format mono-page --dither diffusion -W 128 -H 64 \
            -o "$tmp/cli.raw" "$tmp/oled.scene" 2>>"$tmp/err"; then
        cmp -s "$tmp/cli.raw" "$tmp/oled.raw" && ok ||
            bad "oled_example.c's pages differ from fixtrace --format" \
                "mono-page --dither diffusion"
    else
        bad "oled_example.c on a fake panel: $(head -c 300 "$tmp/err")"
    fi
else
    bad "oled_example.c does not build on the host: $(head -c 600 "$tmp/err")"
fi

# --- docs/scene-format.md -----------------------------------------------------
# Statements in code blocks (fenced, or indented by 4) before "## Errors",
# with backslash continuations joined.
KW="image camera background ambient shadows light material"
KW="$KW sphere quad box cylinder cone mesh"
awk -v kw=" $KW " '
    /^## Errors/ { exit }
    /^```/ { fence = !fence; next }
    {
        line = $0
        if (!fence && line !~ /^    /) { cont = 0; next }
        sub(/^ +/, "", line)
        sub(/[ \t]*#.*$/, "", line)
        if (cont) { stmt = stmt " " line } else {
            split(line, w, " ")
            if (index(kw, " " w[1] " ") == 0) next
            stmt = line
        }
        cont = (stmt ~ / \\$/)
        if (cont) { sub(/ \\$/, "", stmt); next }
        print stmt
    }' docs/scene-format.md >"$tmp/statements"

CAM="camera eye 0 2 -8 look 0 0 0"
# The mesh examples name the gallery's models, relative to the scene.
cp -r scenes/models "$tmp/models"
n=0
while IFS= read -r stmt; do
    n=$((n + 1))
    # shellcheck disable=SC2086
    set -- $stmt
    [ $# -gt 0 ] || continue
    {
        [ "$1" = camera ] || echo "$CAM"
        # Define the material an object uses, unless the statement is one.
        if [ "$1" != material ]; then
            m=$(echo "$stmt" |
                sed -nE 's/.* material ([A-Za-z_][A-Za-z0-9_-]*).*/\1/p')
            [ -n "$m" ] && echo "material $m color 1 1 1"
        fi
        echo "$stmt"
    } >"$tmp/stmt$n.scene"
    if "$FT" -q -W 4 -H 3 -o "$tmp/stmt.ppm" "$tmp/stmt$n.scene" \
        2>"$tmp/err"; then
        ok
    else
        bad "docs/scene-format.md example does not parse: '$stmt':" \
            "$(head -n 1 "$tmp/err")"
    fi
done <"$tmp/statements"
[ "$n" -ge 12 ] && ok ||
    bad "found only $n example statements in docs/scene-format.md"

# Every abridged scene in a fenced block parses as a whole.
awk -v dir="$tmp" '
    /^```/ {
        if (on) close(f); else f = sprintf("%s/block%d.scene", dir, ++k)
        on = !on; next
    }
    on { print > f }' docs/scene-format.md
for b in "$tmp"/block*.scene; do
    [ -f "$b" ] || continue
    grep -q '^camera ' "$b" || continue
    "$FT" -q -W 4 -H 3 -o "$tmp/b.ppm" "$b" 2>"$tmp/err" && ok ||
        bad "a fenced scene in docs/scene-format.md does not parse:" \
            "$(head -n 1 "$tmp/err")"
done

# The parser's own lists of keywords and fields: each needs an example.
ask() { # scene text -> the parser's "expected one of" list
    printf '%b' "$1" >"$tmp/ask.scene"
    "$FT" -q -W 2 -H 2 -o "$tmp/ask.ppm" "$tmp/ask.scene" 2>&1 |
        sed -nE '1s/.*expected one of: ([^)]*)\).*/\1/p'
}
has_example() { # keyword [field]: some example statement uses it
    if [ $# -eq 1 ]; then
        grep -qE "^$1( |$)" "$tmp/statements"
    else
        grep -E "^$1( |$)" "$tmp/statements" | grep -qE " $2( |$)"
    fi
}
kws=$(ask "$CAM\nzzz 1\n")
[ -n "$kws" ] && ok || bad "could not ask the parser for its keywords"
for k in $kws; do
    has_example "$k" && ok || bad "docs/scene-format.md has no example of '$k'"
done
for k in image light camera material sphere quad box cylinder cone mesh; do
    case $k in
    image) probe="$CAM\nimage 8 8 zzz 1\n" ;;
    light) probe="$CAM\nlight 0 0 0 zzz 1\n" ;;
    camera) probe="camera zzz 1\n" ;;
    material) probe="$CAM\nmaterial m zzz 1\n" ;;
    *) probe="$CAM\n$k zzz 1\n" ;;
    esac
    fields=$(ask "$probe")
    [ -n "$fields" ] && ok ||
        bad "could not ask the parser for the fields of '$k'"
    for f in $fields; do
        has_example "$k" "$f" && ok ||
            bad "docs/scene-format.md has no example of '$k ... $f'"
    done
done
for v in both top bottom none; do
    grep -qE "^cylinder .*caps $v( |$)" "$tmp/statements" && ok ||
        bad "docs/scene-format.md has no example of 'caps $v'"
done
for v in x y z; do
    grep -qE "^material .*stripes $v " "$tmp/statements" && ok ||
        bad "docs/scene-format.md has no example of 'stripes $v'"
done
for v in on off; do
    grep -qE "^shadows $v$" "$tmp/statements" && ok ||
        bad "docs/scene-format.md has no example of 'shadows $v'"
done

# --- README gallery and links ------------------------------------------------
for scene in scenes/*.scene; do
    name=$(basename "$scene" .scene)
    img=docs/img/$name.png
    if [ ! -f "$img" ]; then
        bad "$img is missing (run make gallery)"
    elif ! grep -q "($img)" README.md; then
        bad "README.md does not show $img"
    else
        ok
    fi
done

# A picture that no longer matches its scene is only noted, not failed:
# any intended change to the images (make update-checksums) also calls for
# `make gallery`, and this says which pictures are behind.
stale=""
for scene in scenes/*.scene; do
    name=$(basename "$scene" .scene)
    [ -f "docs/img/$name.png" ] || continue
    "$FT" -q -W 320 -H 240 -s 4 -o "$tmp/g.png" "$scene" 2>/dev/null &&
        ! "$FT" compare "$tmp/g.png" "docs/img/$name.png" 2>/dev/null |
        grep -q 'inf (identical)' && stale="$stale $name"
done
[ -z "$stale" ] ||
    echo "note: docs/img is out of date for:$stale (run make gallery)"

for md in README.md docs/*.md port/baremetal/README.md; do
    dir=$(dirname "$md")
    # [text](target) with a relative target; drop any #anchor.
    grep -oE '\]\([^)#][^)]*\)' "$md" | sed -E 's/^\]\(//; s/\)$//; s/#.*//' |
        grep -vE '^[a-z]+:' | sort -u | while IFS= read -r target; do
        if [ -e "$dir/$target" ]; then
            echo ok
        else
            echo "FAILED: $md links to $target, which does not exist"
        fi
    done
done >"$tmp/links"
grep -v '^ok$' "$tmp/links"
pass=$((pass + $(grep -c '^ok$' "$tmp/links")))
fail=$((fail + $(grep -c '^FAILED' "$tmp/links")))

# Every build/posix-*/fixtrace a command block runs is built in that block
# (build/posix is what `make` builds).
for md in README.md docs/*.md port/baremetal/README.md; do
    awk -v md="$md" '
        /^```/ || !/^    / { if (!/^    /) delete built; next }
        { for (i = 1; i <= NF; i++) if ($i ~ /^HOST_BUILD=build\/posix-/) {
              d = $i; sub(/^HOST_BUILD=/, "", d); built[d] = 1 } }
        match($0, /build\/posix-[A-Za-z0-9_-]+\/fixtrace/) {
            d = substr($0, RSTART, RLENGTH); sub(/\/fixtrace$/, "", d)
            if (!(d in built)) print "FAILED: " md ": " d "/fixtrace is run but not built in its block: " $0 }
    ' "$md"
done >"$tmp/blocks"
if [ -s "$tmp/blocks" ]; then
    cat "$tmp/blocks"
    fail=$((fail + $(wc -l <"$tmp/blocks")))
else
    ok
fi

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
