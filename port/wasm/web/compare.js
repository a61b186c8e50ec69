// SPDX-License-Identifier: MIT
// The image comparison of `fixtrace compare` (port/posix/compare.c), for
// the page: the same metrics, thresholds, heat-map colours and wording.
"use strict";

const COMPARE_BAD_LEVEL = 2;       // a pixel is "bad" above this error
const COMPARE_OUTLIER_LEVEL = 64;  // an outlier above this
const COMPARE_EDGE_RANGE = 64;     // B is at an edge when a channel spans more

// Largest channel difference of pixel i of two RGB888 images.
function pixelErr(a, b, i) {
  let e = 0;
  for (let c = 0; c < 3; c++) {
    const d = Math.abs(a[3 * i + c] - b[3 * i + c]);
    if (d > e) e = d;
  }
  return e;
}

// Some channel spans more than COMPARE_EDGE_RANGE around (x, y) in img.
function atEdge(img, w, h, x, y) {
  for (let c = 0; c < 3; c++) {
    let lo = 255, hi = 0;
    for (let dy = -1; dy <= 1; dy++) {
      for (let dx = -1; dx <= 1; dx++) {
        const xx = x + dx, yy = y + dy;
        if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
        const v = img[3 * (yy * w + xx) + c];
        if (v < lo) lo = v;
        if (v > hi) hi = v;
      }
    }
    if (hi - lo > COMPARE_EDGE_RANGE) return true;
  }
  return false;
}

// compare_images(): a is the image judged, b the reference.
function compareImages(a, b, w, h) {
  const r = { psnr: Infinity, maxErr: 0, mae: 0, bad: 0, badPct: 0,
              outliers: 0, interiorOutliers: 0 };
  const npix = w * h;
  let sq = 0, absSum = 0;
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      const i = y * w + x;
      for (let c = 0; c < 3; c++) {
        const d = Math.abs(a[3 * i + c] - b[3 * i + c]);
        sq += d * d;
        absSum += d;
      }
      const e = pixelErr(a, b, i);
      if (e > r.maxErr) r.maxErr = e;
      if (e > COMPARE_BAD_LEVEL) r.bad++;
      if (e > COMPARE_OUTLIER_LEVEL) {
        r.outliers++;
        if (!atEdge(b, w, h, x, y)) r.interiorOutliers++;
      }
    }
  }
  r.mae = npix ? absSum / (3 * npix) : 0;
  r.badPct = npix ? 100 * r.bad / npix : 0;
  if (sq !== 0) r.psnr = 10 * Math.log10(255 * 255 / (sq / (3 * npix)));
  return r;
}

// compare_heat(): black for 0, then a ramp on log2(1 + e) through blue,
// green and yellow to red.
const HEAT_STOPS = [[0, 0, 0], [0, 0, 255], [0, 255, 0], [255, 255, 0],
                    [255, 0, 0]];
function heatColour(e, out, o) {
  if (e <= 0) {
    out[o] = out[o + 1] = out[o + 2] = 0;
    return;
  }
  let t = Math.log2(1 + e) / 8 * 4;
  if (t > 4) t = 4;
  const seg = t >= 4 ? 3 : Math.floor(t), f = t - seg;
  for (let c = 0; c < 3; c++)
    out[o + c] = Math.floor(HEAT_STOPS[seg][c] + f * (HEAT_STOPS[seg + 1][c] -
                                                      HEAT_STOPS[seg][c]) + 0.5);
}

// compare_heatmap(): the heat colour of each pixel's largest error, RGB888.
function heatMap(a, b, w, h) {
  const out = new Uint8Array(3 * w * h);
  for (let i = 0; i < w * h; i++) heatColour(pixelErr(a, b, i), out, 3 * i);
  return out;
}

// x with f decimals as C's printf("%.*f") writes it: correctly rounded,
// an exact tie to even (toFixed takes a tie upward). toFixed gives the
// exact decimal digits of a double, so a tie is seen exactly.
function cFixed(x, f) {
  const s = x.toFixed(f), long = x.toFixed(Math.min(100, f + 80));
  const dot = long.indexOf(".");
  if (!/^50*$/.test(long.slice(dot + 1 + f))) return s;
  const down = long.slice(0, f ? dot + 1 + f : dot);
  return Number(down[down.length - 1]) % 2 === 0 ? down : s;
}

// The lines `fixtrace compare` prints for these metrics.
function compareText(r) {
  return {
    psnr: r.psnr === Infinity ? "inf (identical)" : cFixed(r.psnr, 2) + " dB",
    maxErr: r.maxErr + "/255",
    mae: cFixed(r.mae, 4) + "/255",
    bad: cFixed(r.badPct, 3) + " % of pixels (" + r.bad + ")",
    outliers: r.outliers + " pixels, " + r.interiorOutliers +
              " away from edges",
  };
}
