#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Makes the library package for PlatformIO and Arduino in OUT (default
# build/package/fixtrace): packaging/library/ (library.json,
# library.properties, examples/, src/fixtrace.h) with every core/*/*.c and
# .h copied flat into src/, because neither build system takes a list of
# include folders from a library. The manifests' versions must be
# core/fx/fixtrace_version.h's. Publish the folder (pio pkg publish OUT)
# or zip it for the Arduino IDE (Sketch > Include Library > Add .ZIP).
set -eu
cd "$(dirname "$0")/.."
out=${1:-build/package/fixtrace}
want=$(sed -nE 's/^#define FIXTRACE_VERSION_(MAJOR|MINOR|PATCH) +([0-9]+).*/\2/p' \
    core/fx/fixtrace_version.h | paste -sd. -)
for f in packaging/library/library.json packaging/library/library.properties; do
    if ! grep -qE "(\"version\": \"|^version=)$want(\"|$)" "$f"; then
        echo "package_library: $f does not say version $want" \
            "(core/fx/fixtrace_version.h)" >&2
        exit 1
    fi
done
dup=$(ls core/*/*.[ch] | xargs -n1 basename | sort | uniq -d)
if [ -n "$dup" ]; then
    echo "package_library: core files share a name, src/ cannot be flat: $dup" >&2
    exit 1
fi
rm -rf "$out"
mkdir -p "$out"
cp -R packaging/library/. "$out/"
cp core/*/*.c core/*/*.h "$out/src/"
cp LICENSE "$out/"
echo "wrote $out (fixtrace $want)"
