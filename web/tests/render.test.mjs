// render.test.mjs — the page draws the sea: a frame read back from the canvas has sky above and
// water below the horizon, no black or NaN-coloured pixels, and changes over time; the panel
// changes the sea (Hs of the read-back heights grows with the wind, as the spectrum says); the
// mip chains keep their means (mips_check.mjs).
import { openPage, run } from './browser.mjs';
import { checkMips } from './mips_check.mjs';

// Mean luminance and blueness of rows [y0, y1) and the count of black pixels of a capture.
function stats({ width, rgba }, y0, y1) {
  let luminance = 0, black = 0;
  for (let y = y0; y < y1; ++y) {
    for (let x = 0; x < width; ++x) {
      const i = 4 * (y * width + x);
      const l = 0.2126 * rgba[i] + 0.7152 * rgba[i + 1] + 0.0722 * rgba[i + 2];
      luminance += l;
      if (rgba[i] + rgba[i + 1] + rgba[i + 2] === 0) black++;
    }
  }
  return { luminance: luminance / ((y1 - y0) * width), black };
}

// The lengths the grid fades each cascade's displacement against (R.9), from their definition:
// the longest wave of the band — the patch side for cascade 0, 2π/k_min = 4·L(c−1)/N past it, the
// bands handing over at half the previous cascade's Nyquist (M.7.1) — capped at the peak
// wavelength 2πg/ωp² (deep water, ω² = gk; the default sea has one wave system) but not below
// four texels, 4·L/N.
async function checkGeometryWavelengths(page, check) {
  const r = await page.evaluate(() => ({
    sizes: window.ocean.sea.patchSizesM, n: window.ocean.sea.resolution,
    omegaP: window.ocean.core.peakOmega(), got: window.ocean.ocean.geometryWavelengthsM }));
  const peak = (2 * Math.PI * 9.81) / r.omegaP ** 2;  // g: the library's kDefaultGravity
  r.sizes.forEach((size, c) => {
    const longest = c === 0 ? size : (4 * r.sizes[c - 1]) / r.n;
    const want = Math.min(longest, Math.max(peak, (4 * size) / r.n));
    check(Math.abs(r.got[c] - want) <= 1e-9 * want,
          `cascade ${size} m fades against ${r.got[c]?.toFixed(3)} m (${want.toFixed(3)} m; ` +
          `peak wavelength ${peak.toFixed(2)} m)`);
  });
}

await run('render', async (check) => {
  const { browser, page, server, logs } = await openPage({ query: 'n=64&t=0&panel=0' });
  const result = await page.evaluate(async () => {
    const { renderer, camera } = window.ocean;
    if (window.ocean.error) return { error: window.ocean.error };
    Object.assign(camera, { heightM: 10, pitchRad: 0, yawRad: 0.4 });
    const frames = [];
    for (const t of [1, 2.5]) {
      const c = await renderer.capture(t, camera);
      frames.push({ width: c.width, height: c.height, rgba: Array.from(c.rgba) });
    }
    return { frames, error: window.ocean.error };
  });
  check(!result.error, `page ready without WebGPU errors ${result.error ?? ''}`);
  if (result.error) {
    console.log(logs.join('\n'));
  } else {
    const [a, b] = result.frames;
    const h = a.height;
    // Pitch 0: the horizon is the middle row; skip a band around it (waves cross it).
    const sky = stats(a, 0, Math.floor(0.35 * h));
    const sea = stats(a, Math.ceil(0.65 * h), h);
    const all = stats(a, 0, h);
    check(all.black === 0, `no black pixels (${all.black} of ${a.width * h})`);
    check(sky.luminance > sea.luminance + 30,
          `sky above is brighter than water below (${sky.luminance.toFixed(1)} vs ` +
          `${sea.luminance.toFixed(1)})`);
    let changed = 0;
    for (let i = 0; i < a.rgba.length; i += 4) if (a.rgba[i] !== b.rgba[i]) changed++;
    check(changed > 0.05 * a.width * h, `the sea moves: ${changed} pixels differ between t = 1 s ` +
          'and t = 2.5 s');
    await checkMips(page, check);
    await checkGeometryWavelengths(page, check);
  }

  // Panel: wind 6 → 14 m/s. Hs of the heights read back from the GPU follows the spectrum's
  // 4·√m0 (U² scaling of fetch-limited JONSWAP, Hasselmann et al. 1973): it must grow.
  const hs = await page.evaluate(async () => {
    const out = [];
    for (const wind of [6, 14]) {
      const form = document.getElementById('panel');
      form.elements.wind.value = String(wind);
      await window.ocean.applyPanel();
      // The cascades synthesise disjoint bands of independent draws: their variances add.
      let v = 0;
      for (const simulation of window.ocean.ocean.simulations) {
        const d = (await simulation.readFields(3)).displacement;
        for (let i = 0; i < d.length / 4; ++i) v += d[4 * i + 1] ** 2 / (d.length / 4);
      }
      out.push({ wind, measured: 4 * Math.sqrt(v), spectrum: window.ocean.core.hs() });
    }
    return out;
  });
  for (const r of hs) {
    check(Number.isFinite(r.measured) && r.measured > 0,
          `wind ${r.wind} m/s: Hs from read-back heights ${r.measured.toFixed(3)} m ` +
          `(spectrum ${r.spectrum.toFixed(3)} m)`);
  }
  // Together the cascades hold the whole spectrum (the last one's Nyquist, π·64/57 m = 3.5 rad/m,
  // leaves out a negligible tail): Hs within the ±15 % that one realisation of these grids spreads.
  for (const r of hs) {
    check(Math.abs(r.measured / r.spectrum - 1) <= 0.15,
          `wind ${r.wind} m/s: the cascades' summed Hs is the spectrum's within 15 % ` +
          `(×${(r.measured / r.spectrum).toFixed(3)})`);
  }
  // The spectrum's own ratio is ≈2.1; the same seed draws the same Gaussians for both winds, so
  // the realisations scale together, less the energy the 64² grid cannot hold: ask for ×1.5.
  check(hs[1].measured > 1.5 * hs[0].measured,
        `Hs grows with the wind (6 → 14 m/s: ×${(hs[1].measured / hs[0].measured).toFixed(2)}, ` +
        `spectrum ×${(hs[1].spectrum / hs[0].spectrum).toFixed(2)}; more than ×1.5 asked)`);
  await browser.close();
  server.close();
});
