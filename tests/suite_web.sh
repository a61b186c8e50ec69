#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The browser page (make web, port/wasm): the module imports nothing and
# the page fetches nothing from outside its folder; the cost model's stated
# errors against docs/bench.md; then, in headless Chromium on a local
# server, the canvases against the command line's bytes, the metrics
# against `fixtrace compare`, a scene error against the command line's
# message (tests/web_check.py). Without clang and wasm-ld, or without
# Chromium, the part that needs them prints SKIPPED.
set -u
cd "$(dirname "$0")/.."
FT=${FIXTRACE:-build/posix/fixtrace}
export FIXTRACE=$FT
MAKE=${MAKE:-make}
WEB=build/web
pass=0 fail=0 skip=0

if [ ! -x "$FT" ]; then
    echo "FAILED: $FT not found (build it with make)"
    echo "0 passed, 1 failed"
    exit 1
fi
if ! command -v clang >/dev/null || ! command -v wasm-ld >/dev/null; then
    echo "SKIPPED: make web needs clang and wasm-ld (apt-get install --no-install-recommends clang lld)"
    echo "0 passed, 0 failed, 1 skipped"
    exit 0
fi
if $MAKE -s web WEB_BUILD=$WEB >/dev/null; then
    pass=$((pass + 1))
else
    echo "FAILED: make web"
    echo "$pass passed, 1 failed"
    exit 1
fi

# The module stands alone: no import section (id 2) among its sections.
if python3 - "$WEB/fixtrace.wasm" <<'PY'
import sys
d = open(sys.argv[1], "rb").read()
assert d[:8] == b"\0asm\1\0\0\0", "not a WebAssembly module"
i, ids = 8, []
while i < len(d):
    sid = d[i]; i += 1
    n = shift = 0
    while True:
        b = d[i]; i += 1
        n |= (b & 0x7F) << shift; shift += 7
        if not b & 0x80:
            break
    ids.append(sid); i += n
assert 2 not in ids, "the module imports something"
print("note: fixtrace.wasm is %d bytes" % len(d))
PY
then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAILED: the module imports"; fi

# Nothing from outside the folder: no absolute URL in the page's files.
if grep -nE '(https?:)?//[a-z0-9.-]+\.[a-z]{2,}/' $WEB/*.html $WEB/*.js $WEB/*.css; then
    fail=$((fail + 1)); echo "FAILED: the page names an outside address"
else
    pass=$((pass + 1))
fi

count() { # adds a web_check.py run's summary line
    local line
    line=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$1" | tail -n 1)
    if [ -z "$line" ]; then
        fail=$((fail + 1)); echo "FAILED: tests/web_check.py gave no summary"
        return
    fi
    pass=$((pass + ${line%% passed*}))
    line=${line#* passed, }
    fail=$((fail + ${line%% failed*}))
}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
python3 tests/web_check.py cost $WEB >"$log" 2>&1
grep -E '^(FAILED|note)' "$log"
count "$log"

if ! command -v chromium >/dev/null; then
    echo "SKIPPED: the browser check needs chromium (apt-get install --no-install-recommends chromium)"
    skip=1
else
    timeout 120 python3 tests/web_check.py browser $WEB >"$log" 2>&1
    grep -E '^(FAILED|note|Traceback|[A-Za-z]*Error)' "$log"
    count "$log"
fi
if [ $skip -gt 0 ]; then
    echo "$pass passed, $fail failed, $skip skipped"
else
    echo "$pass passed, $fail failed"
fi
[ $fail -eq 0 ]
