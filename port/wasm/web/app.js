// SPDX-License-Identifier: MIT
// fixtrace in the browser: loads fixtrace.wasm (port/wasm/api.h) and the
// scenes beside this page, renders with the fixed-point core and the
// double reference, and shows their difference and the cost of the
// settings on a microcontroller. No framework; nothing from outside.
"use strict";

const $ = (id) => document.getElementById(id);
const STAT_NAMES = ["primary_rays", "shadow_rays", "reflection_rays",
                    "refraction_rays", "intersection_tests", "rays_cut",
                    "interpolated_pixels"];
// Rows rendered between two looks at the page, so that it stays live:
// the bands of the command line (port/posix/main.c), whose counters
// (--stats) depend on them a little (some set-up is per band), while the
// bytes do not.
const BAND_ROWS = 8, DRAFT_BAND_ROWS = 32;

let wasm = null;          // the module's exports
const scenes = new Map(); // "scenes/NAME.scene" -> text as loaded
let generation = 0;       // a newer render stops an older one
let lastResult = null;    // what the last finished render showed

function memory() { return new Uint8Array(wasm.memory.buffer); }

function cString(ptr) {
  const m = memory();
  let end = ptr;
  while (m[end]) end++;
  return new TextDecoder().decode(m.subarray(ptr, end));
}

async function loadWasm() {
  const bytes = await (await fetch("fixtrace.wasm")).arrayBuffer();
  const { instance } = await WebAssembly.instantiate(bytes, {});
  wasm = instance.exports;
}

// Writes a NUL-terminated name at ft_name() and bytes at ft_text().
function put(name, bytes) {
  const m = memory();
  m.set(bytes, wasm.ft_text());
  const nb = new TextEncoder().encode(name).slice(0, 255);
  m.set(nb, wasm.ft_name());
  m[wasm.ft_name() + nb.length] = 0;
}

// The scenes beside the page, and the meshes they name, handed to the
// module as files (ft_file) at the paths the command line would open.
async function loadScenes() {
  const list = (await (await fetch("scenes/index.txt")).text())
    .split("\n").filter((s) => s.length > 0);
  wasm.ft_reset();
  for (const name of list.filter((s) => s.endsWith(".obj"))) {
    const bytes = new Uint8Array(await (await fetch("scenes/" + name))
                                 .arrayBuffer());
    if (bytes.length > wasm.ft_text_capacity()) continue;
    put("scenes/" + name, bytes);
    if (wasm.ft_file(bytes.length) !== 0)
      throw new Error(cString(wasm.ft_message()));
  }
  for (const name of list.filter((s) => s.endsWith(".scene"))) {
    const text = await (await fetch("scenes/" + name)).text();
    scenes.set("scenes/" + name, text);
    const o = document.createElement("option");
    o.value = o.textContent = "scenes/" + name;
    $("scene").appendChild(o);
  }
}

// Parses the editor's text. Returns true, or false with the message
// under the editor.
function parse(name, text) {
  const bytes = new TextEncoder().encode(text);
  if (bytes.length > wasm.ft_text_capacity()) {
    showError("fixtrace: the scene is larger than the page takes");
    return false;
  }
  put(name, bytes);
  if (wasm.ft_parse(bytes.length) !== 0) {
    showError(cString(wasm.ft_message()));
    return false;
  }
  return true;
}

function showError(text) { $("error").textContent = text; }

function settings() {
  const num = (id) => Math.trunc(Number($(id).value) || 0);
  return { width: num("width"), height: num("height"), spp: num("spp"),
           depth: num("depth"), adaptive: num("adaptive"),
           draft: num("draft") };
}

// The command line that renders what the page shows.
function cliLine(name, s) {
  let a = "fixtrace -W " + s.width + " -H " + s.height + " -s " + s.spp;
  if (s.depth >= 0) a += " -d " + s.depth;
  if (s.adaptive) a += " --adaptive " + s.adaptive;
  if (s.draft) a += " --draft " + s.draft;
  return a + " " + name;
}

// Draws `rows` rows of RGB888 pixels, w wide, into a canvas from row y.
function rgbToCanvas(canvas, rgb, w, rows, y) {
  const ctx = canvas.getContext("2d");
  const img = ctx.createImageData(w, rows);
  for (let i = 0, j = 0; i < w * rows; i++, j += 4) {
    img.data[j] = rgb[3 * i];
    img.data[j + 1] = rgb[3 * i + 1];
    img.data[j + 2] = rgb[3 * i + 2];
    img.data[j + 3] = 255;
  }
  ctx.putImageData(img, 0, y);
}

// Renders one image band by band; returns its bytes and the time spent
// inside the module, or null when a newer render took over.
async function renderOne(which, s, canvas, gen) {
  let st = wasm.ft_begin(which, s.width, s.height, s.spp, s.depth,
                         s.adaptive, s.draft);
  if (st !== 0) throw new Error(cString(wasm.ft_message()) ||
                                "bad render options");
  const w = wasm.ft_width(which), h = wasm.ft_height(which);
  canvas.width = w;
  canvas.height = h;
  const band = which === 0 && s.draft ? DRAFT_BAND_ROWS : BAND_ROWS;
  let ms = 0;
  for (let y = 0; y < h; y += band) {
    const t0 = performance.now();
    st = wasm.ft_rows(which, y, Math.min(h, y + band));
    ms += performance.now() - t0;
    if (st !== 0) throw new Error("fixtrace: render failed (status " + st +
                                  ")");
    const p = wasm.ft_image(which) + 3 * w * y;
    const rows = Math.min(h, y + band) - y;
    rgbToCanvas(canvas, memory().subarray(p, p + 3 * w * rows), w, rows, y);
    await new Promise((r) => setTimeout(r, 0));
    if (gen !== generation) return null;
  }
  const p = wasm.ft_image(which);
  return { rgb: memory().slice(p, p + 3 * w * h), w, h, ms };
}

async function render() {
  const gen = ++generation;
  const name = $("scene").value, s = settings();
  $("cli").textContent = cliLine(name, s);
  if (!parse(name, $("text").value)) {
    document.body.dataset.state = "error";
    return;
  }
  showError("");
  document.body.dataset.state = "rendering";
  try {
    const fixed = await renderOne(0, s, $("fixed"), gen);
    if (!fixed) return;
    const counts = STAT_NAMES.map((_, k) => wasm.ft_stat(0, k));
    $("t-fixed").textContent = fixed.ms.toFixed(1) + " ms";
    const ref = await renderOne(1, s, $("ref"), gen);
    if (!ref) return;
    $("t-ref").textContent = ref.ms.toFixed(1) + " ms";
    const r = compareImages(fixed.rgb, ref.rgb, fixed.w, fixed.h);
    const text = compareText(r);
    $("psnr").textContent = text.psnr;
    $("maxerr").textContent = text.maxErr;
    $("mae").textContent = text.mae;
    $("bad").textContent = text.bad;
    $("outliers").textContent = text.outliers;
    const heat = heatMap(fixed.rgb, ref.rgb, fixed.w, fixed.h);
    $("heat").width = fixed.w;
    $("heat").height = fixed.h;
    rgbToCanvas($("heat"), heat, fixed.w, fixed.h, 0);
    showStats(fixed.w * fixed.h, counts);
    showCost(fixed.w * fixed.h, counts, s);
    lastResult = { fixedMs: fixed.ms, refMs: ref.ms, counts,
                   width: fixed.w, height: fixed.h };
    document.body.dataset.state = "done";
  } catch (e) {
    showError(e.message);
    document.body.dataset.state = "error";
  }
}

function showStats(pixels, counts) {
  const body = $("stats").tBodies[0];
  body.textContent = "";
  const rows = [["pixels", pixels]].concat(
    STAT_NAMES.map((n, k) => [n, counts[k]]));
  for (const [n, v] of rows) {
    const tr = body.insertRow(), th = document.createElement("th");
    th.textContent = n;
    tr.appendChild(th);
    tr.insertCell().textContent = String(v);
  }
}

// Instructions per pixel the cost model (cost_model.js) gives for the
// counters of a render.
function estimate(cpu, pixels, counts) {
  const byName = { pixels };
  STAT_NAMES.forEach((n, k) => { byName[n] = counts[k]; });
  let sum = 0;
  COST_MODEL.terms.forEach((t, k) => { sum += COST_MODEL[cpu][k] * byName[t]; });
  return sum / pixels;
}

function showCost(pixels, counts, s) {
  const m3 = estimate("m3", pixels, counts), m0 = estimate("m0", pixels, counts);
  $("ipp-m3").textContent = m3.toFixed(0);
  $("ipp-m0").textContent = m0.toFixed(0);
  // At one instruction a cycle, as the README's frame times assume (real
  // parts land above: wait states, multi-cycle loads and branches).
  $("frame-cost").textContent = "so about " +
    (m3 * pixels / 72e6).toFixed(2) + " s a frame on a 72 MHz M3 and " +
    (m0 * pixels / 48e6).toFixed(2) + " s on a 48 MHz M0 at one " +
    "instruction a cycle.";
  $("cost-how").textContent = "From this render's counted work and a cost " +
    "per unit (pixel, camera ray, shadow ray, reflected ray, refracted ray, " +
    "intersection test) fitted by least squares to QEMU's instruction " +
    "counts for the firmware (" + COST_MODEL.fit.join(", ") + "; `" +
    COST_MODEL.command + "`). The fit stays within " +
    COST_MODEL.fit_max_error_pct.m3 + " % (M3) and " +
    COST_MODEL.fit_max_error_pct.m0 + " % (M0) of the counts it was " +
    "fitted to; the table checks it at " + COST_MODEL.bench_size +
    ", which it was not fitted to. Left out of the fit: " +
    COST_MODEL.fit_excludes.join(", ") + " (a mesh counts as one " +
    "intersection test, however many boxes and triangles of its " +
    "hierarchy a ray visits, so the counters miss its work). Texture " +
    "and bump look-ups are not counted either." +
    (s.adaptive || s.draft ? " Adaptive and draft bookkeeping is not in " +
     "the model." : "");
}

function showCostCheck() {
  const body = $("cost-check").tBodies[0];
  const pct = (e) => (e > 0 ? "+" : "") + e.toFixed(1) + " %";
  for (const row of COST_MODEL.bench) {
    const tr = body.insertRow();
    tr.dataset.scene = row.scene;
    for (const v of [row.scene, row.m3.estimate.toFixed(1),
                     row.m3.measured.toFixed(1), pct(row.m3.error_pct),
                     row.m0.estimate.toFixed(1), row.m0.measured.toFixed(1),
                     pct(row.m0.error_pct)])
      tr.insertCell().textContent = v;
  }
}

// Picks a scene: its text in the editor, a width of at most 320 at its
// aspect, and its own depth; 1 sample per pixel, no adaptive, no draft.
function pick(name) {
  $("text").value = scenes.get(name) || "";
  if (parse(name, $("text").value)) {
    $("width").value = Math.min(wasm.ft_scene_width(), 320);
    $("height").value = Math.round(wasm.ft_scene_height() *
                                   $("width").value / wasm.ft_scene_width());
    $("spp").value = "1";
    $("depth").value = "-1";
    $("adaptive").value = "0";
    $("draft").value = "0";
  }
}

let timer = 0;
function changed() {
  if (!$("auto").checked) return;
  clearTimeout(timer);
  timer = setTimeout(render, 300);
}

// For tests (tests/web_check.py) and the console: resolves once the
// module and the scenes are in; fixtrace.render() resolves when a render
// has finished or stopped on an error.
window.fixtrace = {
  ready: (async () => {
    await loadWasm();
    await loadScenes();
    showCostCheck();
    $("scene").addEventListener("change", () => { pick($("scene").value);
                                                  render(); });
    $("render").addEventListener("click", render);
    $("text").addEventListener("input", changed);
    for (const id of ["width", "height", "spp", "depth", "adaptive", "draft"])
      $(id).addEventListener("change", changed);
    const first = scenes.has("scenes/seed.scene") ? "scenes/seed.scene"
                                                  : $("scene").value;
    $("scene").value = first;
    pick(first);
  })(),
  render,
  pick,
  last: () => lastResult,
};
window.fixtrace.ready.then(render, (e) => showError(String(e)));
