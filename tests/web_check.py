#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The browser page (port/wasm) against the command line; run by
tests/suite_web.sh. Standard library only.

  web_check.py cost WEB_DIR
      The cost model's stated errors (port/wasm/cost_model.js, as copied
      into WEB_DIR): each scene's estimate recomputed from the coefficients
      and `fixtrace --stats` at the bench size, its measured figure equal
      to docs/bench.md's, its error equal to the one stated.
  web_check.py browser WEB_DIR
      Headless Chromium on WEB_DIR served on 127.0.0.1: the canvases'
      pixels equal the command line's bytes (core, reference, heat map),
      the metrics equal `fixtrace compare`'s, the counters `--stats`', a
      scene error reads as the command line's, and the cost table shows
      the stated errors.

Prints "ok: ..." or "FAILED: ..." per check, "note: ..." for figures, and
ends with "N passed, N failed".
"""
import base64
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
FT = os.environ.get("FIXTRACE", os.path.join(ROOT, "build/posix/fixtrace"))
if not os.path.isabs(FT):
    FT = os.path.join(ROOT, FT)
TMP = tempfile.mkdtemp(prefix="fixtrace-web-")
passed = failed = 0


def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
        print("ok: " + what)
    else:
        failed += 1
        print("FAILED: " + what)


def run(args, cwd=ROOT):
    return subprocess.run([FT] + args, cwd=cwd, capture_output=True,
                          text=True)


def cli_stats(args):
    """--stats of a render as a dict."""
    out = os.path.join(TMP, "stats.ppm")
    r = run(["-q", "--stats", "-o", out] + args)
    st = {}
    for line in r.stderr.splitlines():
        k, _, v = line.partition(" ")
        if re.fullmatch(r"\d+", v):
            st[k] = int(v)
    return st


def ppm_rgb(path):
    """The pixel bytes of a binary PPM that fixtrace wrote."""
    data = open(path, "rb").read()
    m = re.match(rb"P6\s+(\d+)\s+(\d+)\s+255\s", data)
    return data[m.end():]


def cost_model(web):
    text = open(os.path.join(web, "cost_model.js")).read()
    body = text[text.index("const COST_MODEL = ") + 19:].rstrip().rstrip(";")
    return json.loads(body)


def bench_md():
    text = open(os.path.join(ROOT, "docs/bench.md")).read()
    m = re.search(r"## Per scene, (\d+)x(\d+), (\d+) spp", text)
    meas = {}
    for line in text[m.end():].splitlines():
        c = re.match(r"\| (\w+) \| ([\d.]+) \| ([\d.]+) \|", line)
        if c:
            meas[c.group(1)] = {"m3": float(c.group(2)),
                                "m0": float(c.group(3))}
        elif line.startswith("## "):
            break
    return tuple(int(g) for g in m.groups()), meas


def check_cost(web):
    model = cost_model(web)
    (w, h, spp), meas = bench_md()
    check(model["bench_size"] == "%dx%d %d spp" % (w, h, spp),
          "cost model checked at docs/bench.md's size (%dx%d %d spp)" %
          (w, h, spp))
    check(sorted(r["scene"] for r in model["bench"]) == sorted(meas),
          "cost model checked on every scene of docs/bench.md")
    worst = {}
    for row in model["bench"]:
        st = cli_stats(["-W", str(w), "-H", str(h), "-s", str(spp),
                        "scenes/%s.scene" % row["scene"]])
        for cpu in ("m3", "m0"):
            est = sum(c * st[t] for c, t in zip(model[cpu],
                                                model["terms"])) / st["pixels"]
            got = meas[row["scene"]][cpu]
            err = 100 * (est - got) / got
            r = row[cpu]
            good = (abs(r["estimate"] - est) < 0.051 and
                    r["measured"] == got and abs(r["error_pct"] - err) < 0.051)
            check(good, "%s %s: estimate %.1f, measured %.1f, error %+.1f %% "
                  "(stated %.1f, %.1f, %+.1f %%)%s" %
                  (row["scene"], cpu, est, got, err, r["estimate"],
                   r["measured"], r["error_pct"],
                   "" if good else "; after a change to the counters or "
                   "to docs/bench.md, `make web-cost-fit` states them anew"))
            worst[cpu] = max(worst.get(cpu, 0), abs(err))
    for cpu in ("m3", "m0"):
        print("note: cost model, largest error on docs/bench.md's scenes, "
              "%s: %.1f %%" % (cpu, worst[cpu]))
    return model


# JavaScript run in the page: the RGB bytes of a canvas, base64.
CANVAS_RGB = """
const c = document.getElementById(%s);
const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
let s = "";
for (let i = 0; i < d.length; i += 4)
  s += String.fromCharCode(d[i], d[i + 1], d[i + 2]);
return [c.width, c.height, btoa(s)];
"""


def page_render(b, scene, text, opts):
    """Sets the page's scene, text and controls, renders, and returns the
    page's state."""
    js = """
await fixtrace.ready;
const $ = (id) => document.getElementById(id);
$("auto").checked = false;
$("scene").value = %s;
fixtrace.pick(%s);
if (%s !== null) $("text").value = %s;
const o = %s;
for (const k in o) $(k).value = String(o[k]);
await fixtrace.render();
const cells = (id) => Array.from($(id).querySelectorAll("tbody tr")).map(
  (tr) => Array.from(tr.cells).map((c) => c.textContent));
return {state: document.body.dataset.state, error: $("error").textContent,
        psnr: $("psnr").textContent, maxerr: $("maxerr").textContent,
        mae: $("mae").textContent, bad: $("bad").textContent,
        outliers: $("outliers").textContent, stats: cells("stats"),
        cost: cells("cost-check"), cli: $("cli").textContent,
        last: fixtrace.last()};
""" % (json.dumps(scene), json.dumps(scene), json.dumps(text),
       json.dumps(text), json.dumps(opts))
    return b.eval(js)


def canvas(b, name):
    w, h, data = b.eval(CANVAS_RGB % json.dumps(name))
    return w, h, base64.b64decode(data)


def check_render(b, scene, opts, args, with_ref):
    """One render on the page against the command line."""
    st = page_render(b, "scenes/%s.scene" % scene, None, opts)
    label = "%s %s" % (scene, " ".join(args))
    check(st["state"] == "done", "%s: the page rendered (%s)" %
          (label, st["error"].strip() or st["state"]))
    if st["state"] != "done":
        return st
    fixed = os.path.join(TMP, "fixed.ppm")
    run(["-q", "-o", fixed] + args + ["scenes/%s.scene" % scene])
    w, h, rgb = canvas(b, "fixed")
    check(rgb == ppm_rgb(fixed),
          "%s: fixed-point canvas (%dx%d) equals the command line's bytes" %
          (label, w, h))
    want = cli_stats(args + ["scenes/%s.scene" % scene])
    got = {row[0]: int(row[1]) for row in st["stats"]}
    check(all(got[k] == want[k] for k in got) and len(got) == 8,
          "%s: counters equal --stats (%s)" %
          (label, ", ".join("%s %d" % (k, v) for k, v in got.items())))
    check(st["cli"] == "fixtrace " + " ".join(args) + " scenes/%s.scene" %
          scene, "%s: the page names its command line (%s)" %
          (label, st["cli"]))
    if not with_ref:
        return st
    ref = os.path.join(TMP, "ref.ppm")
    run(["-q", "--reference", "-o", ref] + args +
        ["scenes/%s.scene" % scene])
    _, _, rgb = canvas(b, "ref")
    check(rgb == ppm_rgb(ref), "%s: reference canvas equals "
          "`fixtrace --reference`'s bytes" % label)
    diff = os.path.join(TMP, "diff.ppm")
    cmp = subprocess.run([FT, "compare", fixed, ref, "--diff", diff],
                         capture_output=True, text=True)
    _, _, rgb = canvas(b, "heat")
    check(rgb == ppm_rgb(diff), "%s: heat-map canvas equals "
          "`fixtrace compare --diff`'s bytes" % label)
    lines = dict(re.findall(r"^([^:]+):\s+(.*)$", cmp.stdout, re.M))
    for key, field in (("PSNR", "psnr"), ("max error", "maxerr"),
                       ("mean abs error", "mae")):
        check(lines.get(key) == st[field], "%s: %s on the page '%s', "
              "fixtrace compare '%s'" % (label, key, st[field],
                                        lines.get(key)))
    bad = [v for k, v in lines.items() if k.startswith("off by")]
    out = [v for k, v in lines.items() if k.startswith("outliers")]
    check(bad == [st["bad"]] and out == [st["outliers"]],
          "%s: pixels off '%s' and outliers '%s' equal fixtrace compare's" %
          (label, st["bad"], st["outliers"]))
    return st


def check_error(b, web, text, what):
    """A scene with an error: the page's message is the command line's,
    run in the served folder on the same text."""
    with open(os.path.join(web, "scenes/seed.scene"), "w") as f:
        f.write(text)
    want = run(["-q", "-o", os.path.join(TMP, "x.ppm"),
                "scenes/seed.scene"], cwd=web)
    st = page_render(b, "scenes/seed.scene", text, {})
    check(want.returncode == 2 and st["state"] == "error" and
          st["error"] == want.stderr,
          "%s: the page shows the command line's message:\n%s" %
          (what, st["error"]))


def check_option_error(b, opts, args):
    """A control out of its range: the page says what the command line
    says of the same option."""
    want = run(["-q", "-o", os.path.join(TMP, "x.ppm")] + args +
               ["scenes/seed.scene"])
    st = page_render(b, "scenes/seed.scene", None, opts)
    check(want.returncode == 2 and st["state"] == "error" and
          st["error"] + "\n" == want.stderr,
          "%s: the page says '%s'" % (" ".join(args), st["error"]))


BROKEN_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"
# Numbers in exponent form, which the OBJ reader hands to strtod.
EXPO_OBJ = ("v -5e-1 0 -0.5E+0\nv 1e0 0 -5e-1\nv 0 0 7.5e-1\n"
            "v 125E-3 1.2e0 0\nv 2.5e-1 2.5e-1 2.5e-1\n"
            "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n")
EXPO_SCENE = """image 64 48
camera eye 0 2 -5 look 0 0.5 0 fov 50
light -5 9 -6
material m color 0.8 0.3 0.2 shininess 20
material floor checker 0.3 0.3 0.35 1.0 color 0.8 0.8 0.8 reflect 0.3
quad corner -5 0 -5 edge1 0 0 10 edge2 10 0 0 material floor
mesh file "models/expo.obj" material m rotate 10 25 -40 scale 1.5 smooth
"""


def check_scene_text(b, web, text, what):
    """A scene given as text renders on the page as on the command line
    (core and reference), run in the served folder."""
    with open(os.path.join(web, "scenes/seed.scene"), "w") as f:
        f.write(text)
    size = re.search(r"^image (\d+) (\d+)", text, re.M)
    st = page_render(b, "scenes/seed.scene", text, {
        "width": int(size.group(1)), "height": int(size.group(2))})
    check(st["state"] == "done", "%s: the page rendered (%s)" %
          (what, st["error"].strip() or st["state"]))
    for canvas_name, extra in (("fixed", []), ("ref", ["--reference"])):
        out = os.path.join(TMP, canvas_name + ".ppm")
        r = run(["-q", "-o", out] + extra + ["scenes/seed.scene"], cwd=web)
        _, _, rgb = canvas(b, canvas_name)
        check(r.returncode == 0 and rgb == ppm_rgb(out),
              "%s: the %s canvas equals the command line's bytes" %
              (what, canvas_name))


def check_browser(web_dir, model):
    from cdp import Browser
    # A copy of the page's folder with a broken OBJ file among the meshes.
    web = os.path.join(TMP, "web")
    shutil.copytree(web_dir, web)
    with open(os.path.join(web, "scenes/models/broken.obj"), "w") as f:
        f.write(BROKEN_OBJ)
    with open(os.path.join(web, "scenes/models/expo.obj"), "w") as f:
        f.write(EXPO_OBJ)
    with open(os.path.join(web, "scenes/index.txt"), "a") as f:
        f.write("models/broken.obj\nmodels/expo.obj\n")
    with Browser(web) as b:
        b.open("index.html")
        b.eval("await fixtrace.ready; return 1")
        check_render(b, "seed", {"width": 160, "height": 120, "spp": 1,
                                 "depth": -1, "adaptive": 0, "draft": 0},
                     ["-W", "160", "-H", "120", "-s", "1"], True)
        check_render(b, "textures", {"width": 96, "height": 72, "spp": 4,
                                     "depth": 2, "adaptive": 0, "draft": 0},
                     ["-W", "96", "-H", "72", "-s", "4", "-d", "2"], True)
        check_render(b, "meshes", {"width": 128, "height": 96, "spp": 1,
                                   "depth": -1, "adaptive": 0, "draft": 0},
                     ["-W", "128", "-H", "96", "-s", "1"], True)
        check_render(b, "glass", {"width": 96, "height": 72, "spp": 4,
                                  "depth": 3, "adaptive": 8, "draft": 32},
                     ["-W", "96", "-H", "72", "-s", "4", "-d", "3",
                      "--adaptive", "8", "--draft", "32"], False)
        check_scene_text(b, web, EXPO_SCENE, "an OBJ file with numbers in "
                         "exponent form, rotated")
        seed = open(os.path.join(ROOT, "scenes/seed.scene")).read()
        check_error(b, web, re.sub(r"^camera", "camra", seed, count=1,
                                   flags=re.M), "a misspelt keyword")
        check_error(b, web, seed + "\nsphere center 0 1 0 radius -2 "
                    "material nosuch\n", "a bad value at the end")
        check_error(b, web, seed + "\nmesh file \"models/nothere.obj\" "
                    "material mirror\n", "a mesh file that is not there")
        check_error(b, web, seed + "\nmesh file \"models/broken.obj\" "
                    "material mirror\n", "an OBJ file with an error")
        check_option_error(b, {"adaptive": 300, "spp": 4},
                           ["-s", "4", "--adaptive", "300"])
        check_option_error(b, {"adaptive": 8, "spp": 1},
                           ["-s", "1", "--adaptive", "8"])
        # The cost table as the page shows it: the stated errors.
        st = page_render(b, "scenes/seed.scene", None, {
            "width": 320, "height": 240, "spp": 1, "depth": -1,
            "adaptive": 0, "draft": 0})
        pct = lambda e: ("+" if e > 0 else "") + "%.1f %%" % e
        want = [[r["scene"], "%.1f" % r["m3"]["estimate"],
                 "%.1f" % r["m3"]["measured"], pct(r["m3"]["error_pct"]),
                 "%.1f" % r["m0"]["estimate"], "%.1f" % r["m0"]["measured"],
                 pct(r["m0"]["error_pct"])] for r in model["bench"]]
        check(st["cost"] == want, "the page's cost table states the "
              "checked estimates and errors (%d scenes)" % len(want))
        # The seed's render time here and on the command line, for the
        # record (no threshold: times are noise).
        r = run(["-q", "--stats", "-o", os.path.join(TMP, "t.ppm"), "-W",
                 "320", "-H", "240", "-s", "1", "scenes/seed.scene"])
        secs = re.search(r"render_seconds ([\d.]+)", r.stderr).group(1)
        print("note: seed 320x240 1 spp: browser %.1f ms (fixed), %.1f ms "
              "(reference); command line %.1f ms (fixed)" %
              (st["last"]["fixedMs"], st["last"]["refMs"],
               float(secs) * 1000))


def main():
    mode, web = sys.argv[1], sys.argv[2]
    model = check_cost(web) if mode == "cost" else cost_model(web)
    if mode == "browser":
        try:
            check_browser(web, model)
        except OSError as e:
            check(False, "the browser check ran (%s)" % e)
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
