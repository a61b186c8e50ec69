#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The seed's render time in headless Chromium (the page of build/web)
against the command line's, at the same size and samples: medians of
RUNS renders each, in milliseconds. Times are noise-prone; nothing
checks them.

    tools/web_time.py [WIDTH HEIGHT [SPP [RUNS]]]     (default 640 480 1 5)
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from cdp import Browser  # noqa: E402


def median(v):
    v = sorted(v)
    return v[len(v) // 2]


def main():
    a = [int(x) for x in sys.argv[1:]] + [640, 480, 1, 5][len(sys.argv) - 1:]
    w, h, spp, runs = a[:4]
    ft = os.path.join(ROOT, "build/posix/fixtrace")
    out = os.path.join(tempfile.mkdtemp(), "t.ppm")
    cli = {"fixed": [], "reference": []}
    page = {"fixed": [], "reference": []}
    with Browser(os.path.join(ROOT, "build/web")) as b:
        b.open("index.html")
        # Interleaved, so that a busy moment of the machine falls on both.
        for _ in range(runs):
            for kind, extra in (("fixed", []), ("reference",
                                                ["--reference"])):
                r = subprocess.run(
                    [ft, "-q", "--stats", "-W", str(w), "-H", str(h), "-s",
                     str(spp), "-o", out] + extra +
                    [os.path.join(ROOT, "scenes/seed.scene")],
                    capture_output=True, text=True, check=True)
                cli[kind].append(1000 * float(re.search(
                    r"render_seconds ([\d.]+)", r.stderr).group(1)))
            t = b.eval("""
await fixtrace.ready;
const $ = (id) => document.getElementById(id);
$("auto").checked = false;
$("scene").value = "scenes/seed.scene";
fixtrace.pick("scenes/seed.scene");
$("width").value = "%d"; $("height").value = "%d"; $("spp").value = "%d";
await fixtrace.render();
return [fixtrace.last().fixedMs, fixtrace.last().refMs];
""" % (w, h, spp))
            page["fixed"].append(t[0])
            page["reference"].append(t[1])
    print("seed %dx%d %d spp, medians of %d runs (ms):" % (w, h, spp, runs))
    for kind in ("fixed", "reference"):
        print("  %-9s browser %8.1f   command line %8.1f   ratio %.2f" %
              (kind, median(page[kind]), median(cli[kind]),
               median(page[kind]) / median(cli[kind])))


if __name__ == "__main__":
    main()
