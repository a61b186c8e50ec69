#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The seed's render time in headless Chromium (the page of build/web)
against the command line's, at the same size and samples: medians of
RUNS renders each, in milliseconds of wall clock. On a busy machine wall
clocks mislead, so it also gives CPU time: the command line's whole run
(getrusage), and with node, the same module under V8 (Chromium's engine)
rendering in the page's bands. Times are noise-prone; nothing checks
them.

    tools/web_time.py [WIDTH HEIGHT [SPP [RUNS]]]     (default 640 480 1 5)
"""
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from cdp import Browser  # noqa: E402


def median(v):
    v = sorted(v)
    return v[len(v) // 2]


# The module under node: CPU milliseconds of each render, fixed then
# reference, in the page's bands of 8 rows.
NODE_JS = r"""
const fs = require("fs"), [wasmPath, scene, W, H, S, runs] =
  process.argv.slice(1);
WebAssembly.instantiate(fs.readFileSync(wasmPath), {}).then(({instance}) => {
  const e = instance.exports, txt = fs.readFileSync(scene);
  new Uint8Array(e.memory.buffer).set(txt, e.ft_text());
  if (e.ft_parse(txt.length) !== 0) throw new Error("parse");
  const out = [];
  for (const which of [0, 1]) {
    const t = [];
    for (let r = 0; r < +runs; r++) {
      e.ft_begin(which, +W, +H, +S, -1, 0, 0);
      const c0 = process.cpuUsage();
      for (let y = 0; y < +H; y += 8) e.ft_rows(which, y, Math.min(+H, y + 8));
      const c = process.cpuUsage(c0);
      t.push((c.user + c.system) / 1000);
    }
    out.push(t);
  }
  console.log(JSON.stringify(out));
});
"""


def cpu_ms(cmd):
    """CPU milliseconds (user + system) of one run of cmd."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, capture_output=True, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return 1000 * (after.ru_utime - before.ru_utime + after.ru_stime -
                   before.ru_stime)


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
    print("wall clock:")
    for kind in ("fixed", "reference"):
        print("  %-9s browser %8.1f   command line %8.1f   ratio %.2f" %
              (kind, median(page[kind]), median(cli[kind]),
               median(page[kind]) / median(cli[kind])))
    node = shutil.which("node") or shutil.which("nodejs")
    if not node:
        return
    scene = os.path.join(ROOT, "scenes/seed.scene")
    r = subprocess.run([node, "-e", NODE_JS, os.path.join(
        ROOT, "build/web/fixtrace.wasm"), scene, str(w), str(h), str(spp),
        str(runs)], capture_output=True, text=True, check=True)
    v8 = json.loads(r.stdout)
    print("CPU time (command line: the whole run, parse and file included):")
    for k, (kind, extra) in enumerate((("fixed", []), ("reference",
                                                      ["--reference"]))):
        c = median([cpu_ms([ft, "-q", "-W", str(w), "-H", str(h), "-s",
                            str(spp), "-o", out] + extra + [scene])
                    for _ in range(runs)])
        print("  %-9s module in V8 %8.1f   command line %8.1f   ratio %.2f" %
              (kind, median(v8[k]), c, median(v8[k]) / c))


if __name__ == "__main__":
    main()
