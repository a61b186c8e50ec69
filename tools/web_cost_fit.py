#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""make web-cost-fit: the web page's microcontroller cost model.

Instructions per pixel on the Cortex-M3 (BOARD=an385) and the Cortex-M0
(BOARD=m0) are modelled as a sum over the work the renderer counts (its
--stats counters) of count x cost:

    instructions = c_pixel * pixels + c_primary * primary_rays
                 + c_shadow * shadow_rays + c_reflection * reflection_rays
                 + c_refraction * refraction_rays + c_test * tests

The costs are fitted by least squares (relative error, costs kept >= 0)
over the scenes in scenes/ (but FIT_EXCLUDE) rendered by `make qemu` (firmware pruned to
the scene, instructions counted by QEMU -icount) at the FIT settings
below, with the counters from `fixtrace --stats` at the same settings.
They are then checked against what they were not fitted to: the figures
of docs/bench.md (320x240, 1 spp, written by `make bench`), with the
counters of `fixtrace --stats` at that size.

Writes port/wasm/cost_model.js (the page reads it; tests/suite_web.sh
checks the errors it states). Standard library only.
"""
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIXTRACE = os.path.join(ROOT, "build/posix/fixtrace")
OUT = os.path.join(ROOT, "port/wasm/cost_model.js")
BOARDS = [("m3", "an385"), ("m0", "m0")]
# (width, height, spp): several sample counts, so that the cost of a
# pixel and of a camera ray come apart.
FIT = [(160, 120, 1), (96, 72, 4), (64, 48, 9)]
# Scenes the fit leaves out: a mesh is one intersection test in the
# counters, however many boxes and triangles its hierarchy visits, so
# its cost is not in the counted work (the page still states its error).
FIT_EXCLUDE = {"meshes.scene"}
TERMS = ["pixels", "primary_rays", "shadow_rays", "reflection_rays",
         "refraction_rays", "intersection_tests"]
MAKE = os.environ.get("MAKE", "make")


def stats(scene, w, h, spp):
    """The --stats counters of the host renderer at these settings."""
    out = os.path.join(ROOT, "build/web-fit/stats.ppm")
    r = subprocess.run([FIXTRACE, "-q", "--stats", "-W", str(w), "-H",
                        str(h), "-s", str(spp), "-o", out, scene],
                       capture_output=True, text=True, check=True)
    st = {}
    for line in r.stderr.splitlines():
        k, _, v = line.partition(" ")
        if v and k in TERMS:
            st[k] = int(v)
    return st


CACHE = os.path.join(ROOT, "build/web-fit/qemu.json")


def qemu_ipp(board, scene, w, h, spp):
    """Instructions (total) and pixels counted by QEMU for the firmware.
    The counts are exact and repeatable, so they are kept in CACHE for
    the next run (delete it after a change to the core)."""
    cache = json.load(open(CACHE)) if os.path.exists(CACHE) else {}
    key = "%s %s %dx%d %d" % (board, scene, w, h, spp)
    if key in cache:
        return tuple(cache[key])
    r = subprocess.run([MAKE, "-s", "qemu", "BOARD=" + board,
                        "SCENE=" + scene, "WIDTH=%d" % w, "HEIGHT=%d" % h,
                        "SPP=%d" % spp,
                        "FW_BUILD=build/web-fit/fw-" + board],
                       cwd=ROOT, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("make qemu failed for %s %s:\n%s" % (board, scene,
                                                      r.stderr))
    ins = int(re.search(r"^instructions (\d+)", r.stderr, re.M).group(1))
    pix = int(re.search(r"^pixels (\d+)", r.stderr, re.M).group(1))
    cache[key] = [ins, pix]
    with open(CACHE + ".tmp", "w") as f:
        json.dump(cache, f, indent=0, sort_keys=True)
    os.replace(CACHE + ".tmp", CACHE)
    return ins, pix


def solve(a, b):
    """Least squares a x = b through the normal equations (Gauss-Jordan
    with partial pivoting); a is a list of rows."""
    n = len(a[0])
    m = [[sum(r[i] * r[j] for r in a) for j in range(n)] +
         [sum(r[i] * y for r, y in zip(a, b))] for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda i: abs(m[i][c]))
        m[c], m[p] = m[p], m[c]
        if m[c][c] == 0:
            raise ValueError("singular")
        for i in range(n):
            if i != c:
                f = m[i][c] / m[c][c]
                m[i] = [x - f * y for x, y in zip(m[i], m[c])]
    return [m[i][n] / m[i][i] for i in range(n)]


def fit(rows):
    """Costs >= 0 minimising the relative error: rows are (counters,
    instructions); a term whose cost comes out negative is dropped (its
    cost 0) and the rest fitted again."""
    active = list(range(len(TERMS)))
    while True:
        a = [[r[0][TERMS[i]] / r[1] for i in active] for r in rows]
        x = solve(a, [1.0] * len(rows))
        worst = min(range(len(active)), key=lambda k: x[k])
        if x[worst] >= 0:
            cost = [0.0] * len(TERMS)
            for k, i in enumerate(active):
                cost[i] = x[k]
            return cost
        del active[worst]


def bench_md():
    """Measured instructions per pixel per scene and board, and the size,
    from docs/bench.md."""
    text = open(os.path.join(ROOT, "docs/bench.md")).read()
    m = re.search(r"## Per scene, (\d+)x(\d+), (\d+) spp", text)
    size = tuple(int(g) for g in m.groups())
    meas = {}
    for line in text[m.end():].splitlines():
        c = re.match(r"\| (\w+) \| ([\d.]+) \| ([\d.]+) \|", line)
        if c:
            meas[c.group(1)] = {"m3": float(c.group(2)),
                                "m0": float(c.group(3))}
        elif line.startswith("## "):
            break
    return size, meas


def main():
    os.makedirs(os.path.join(ROOT, "build/web-fit"), exist_ok=True)
    scenes = sorted(f for f in os.listdir(os.path.join(ROOT, "scenes"))
                    if f.endswith(".scene"))
    rows = {b: [] for b, _ in BOARDS}
    for s in scenes:
        if s in FIT_EXCLUDE:
            continue
        path = "scenes/" + s
        for w, h, spp in FIT:
            st = stats(os.path.join(ROOT, path), w, h, spp)
            for b, board in BOARDS:
                ins, pix = qemu_ipp(board, path, w, h, spp)
                assert pix == st["pixels"]
                rows[b].append((st, ins))
                print("%-10s %3dx%-3d %2d spp %-5s %9.1f instr/pixel" %
                      (s, w, h, spp, b, ins / pix), file=sys.stderr)
    # Rounded as stored, so that the estimates below are the page's.
    cost = {b: [round(c, 4) for c in fit(rows[b])] for b, _ in BOARDS}
    (w, h, spp), meas = bench_md()
    check = []
    for s in scenes:
        name = s[:-6]
        if name not in meas:
            continue
        st = stats(os.path.join(ROOT, "scenes", s), w, h, spp)
        row = {"scene": name, "stats": {t: st[t] for t in TERMS}}
        for b, _ in BOARDS:
            est = sum(c * st[t] for c, t in zip(cost[b], TERMS)) / st["pixels"]
            row[b] = {"estimate": round(est, 1), "measured": meas[name][b],
                      "error_pct": round(100 * (est - meas[name][b]) /
                                         meas[name][b], 1)}
        check.append(row)
    fit_err = {}
    for b, _ in BOARDS:
        e = [abs(sum(c * r[0][t] for c, t in zip(cost[b], TERMS)) / r[1] - 1)
             for r in rows[b]]
        fit_err[b] = round(100 * max(e), 1)
    model = {
        "command": "make web-cost-fit",
        "terms": TERMS,
        "m3": cost["m3"],
        "m0": cost["m0"],
        "fit": ["%dx%d %d spp" % f for f in FIT],
        "fit_excludes": sorted(x[:-6] for x in FIT_EXCLUDE),
        "fit_max_error_pct": fit_err,
        "bench_size": "%dx%d %d spp" % (w, h, spp),
        "bench": check,
    }
    lines = [
        "// SPDX-License-Identifier: MIT",
        "// Generated by `make web-cost-fit` (tools/web_cost_fit.py): the",
        "// instructions one unit of counted work costs on each CPU, fitted",
        "// by least squares to `make qemu` over every scene at %s," %
        ", ".join("%dx%d %d spp" % f for f in FIT),
        "// and checked against docs/bench.md (%dx%d, %d spp). Do not edit."
        % (w, h, spp),
        "// The object below is JSON (tests/web_check.py reads it).",
        "\"use strict\";",
        "const COST_MODEL = " + json.dumps(model, indent=1) + ";",
    ]
    tmp = OUT + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, OUT)
    print("wrote %s" % os.path.relpath(OUT, ROOT), file=sys.stderr)


if __name__ == "__main__":
    main()
