#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Culling of camera rays (core/accel/rt_cull.c) and of shadow and secondary
# rays (the direction grids, core/accel/rt_dirgrid.c) must never change a pixel:
# random scenes with tiny, huge, near and far objects, reflective and
# glass materials, random cameras and one to three lights anywhere
# (inside objects too, and in closed glass in view) render the same bytes
# in the normal build and with RT_CULL=0 RT_DIR_GRID=0.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
MAKE=${MAKE:-make}
NOCULL=build/nocull/fixtrace
pass=0 fail=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if ! $MAKE -s HOST_BUILD=build/nocull RT_DEFS="-DRT_CULL=0 -DRT_DIR_GRID=0" "$NOCULL" >"$tmp/log" 2>&1; then
    echo "FAILED: cannot build the renderer without culling: $(tail -5 "$tmp/log")"
    echo "0 passed, 1 failed"
    exit 1
fi
for seed in $(seq 1 150); do
    awk -v seed="$seed" 'BEGIN {
        srand(seed);
        ex = rand() * 40 - 20; ey = rand() * 20 - 2; ez = -5 - rand() * 60;
        printf "camera eye %.3f %.3f %.3f look %.3f %.3f %.3f fov %.2f\n",
               ex, ey, ez, rand() * 4 - 2, rand() * 4, rand() * 10,
               1 + rand() * 170;
        nl = 1 + int(rand() * 3);
        for (i = 0; i < nl; i++)
            printf "light %.3f %.3f %.3f color 0.5 0.5 0.5\n", rand() * 60 - 30,
                   rand() * 50 - 5, rand() * 200 - 40;
        print "material m color 0.8 0.5 0.3 reflect 0.3";
        print "material g color 1 1 1 transparency 0.8 ior 1.3";
        if (rand() < 0.3) { # a light in view, inside closed glass
            lx = rand() * 4 - 2; ly = 1 + rand() * 3; lz = rand() * 10;
            printf "light %.3f %.3f %.3f color 0.5 0.5 0.5\n", lx, ly, lz;
            r = 0.5 + rand() * 2;
            if (rand() < 0.5) printf "sphere center %.3f %.3f %.3f radius %.3f material g\n", lx, ly + r / 3, lz, r;
            else printf "box min %.3f %.3f %.3f max %.3f %.3f %.3f material g\n", lx - r, ly - r / 2, lz - r, lx + r / 2, ly + r, lz + r;
        }
        print "quad corner -30 0 -30 edge1 0 0 60 edge2 60 0 0 material m";
        n = 3 + int(rand() * 12);
        for (i = 0; i < n; i++) {
            k = rand(); r = (rand() < 0.3) ? 0.002 + rand() * 0.05 : 0.2 + rand() * 4;
            x = rand() * 60 - 30; y = rand() * 10; z = rand() * 200 - 40;
            mat = (rand() < 0.2) ? "g" : "m";
            if (k < 0.4) printf "sphere center %.4f %.4f %.4f radius %.4f material %s\n", x, y, z, r, mat;
            else if (k < 0.6) printf "box min %.3f %.3f %.3f max %.3f %.3f %.3f material %s\n", x, y, z, x + r, y + r * 1.5, z + r, mat;
            else if (k < 0.8) printf "cylinder base %.3f %.3f %.3f radius %.3f height %.3f material %s\n", x, y, z, r, r * 2, mat;
            else printf "cone base %.3f %.3f %.3f radius %.3f height %.3f material %s\n", x, y, z, r, r * 2, mat;
        }
    }' >"$tmp/s$seed.scene"
    spp=$(( seed % 3 == 0 ? 4 : 1 ))
    if "$FT" -q -W 72 -H 54 -s $spp -o "$tmp/a.ppm" "$tmp/s$seed.scene" 2>"$tmp/err" &&
       "$NOCULL" -q -W 72 -H 54 -s $spp -o "$tmp/b.ppm" "$tmp/s$seed.scene" 2>>"$tmp/err" &&
       cmp -s "$tmp/a.ppm" "$tmp/b.ppm"; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAILED: random scene $seed (spp $spp) differs with culling: $(cat "$tmp/err")"
        cp "$tmp/s$seed.scene" "build/cull-fail-$seed.scene" 2>/dev/null
    fi
done
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
