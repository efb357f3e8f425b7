// shading.test.mjs — the page shades as the native renderer does (docs/web.md, "Shading"):
//   1. the sky-view table the page samples is render::Sky's (R.1–R.4), checked against the
//      equations evaluated here independently of the library;
//   2. sky pixels read back from the canvas are that radiance after the exposure, Narkowicz's
//      ACES curve and the sRGB encoding of IEC 61966-2-1 (R.12), each step evaluated here;
//   3. the sun's disc is drawn where the sun is, and only there;
//   4. the breaking foam source (M.7.4): each cascade's mean foam is the mean of Φ((J_thr − J)·g)
//      over its own Jacobians, and every cascade gives the same whitecap fraction (the design's
//      promise: each one's mean is the whole sea's), which the foam weights (R.11) keep;
//   5. the picture of the same sea, camera, sun and exposure drawn by the native renderer
//      (`ocean render`, OCEAN_NATIVE) has the page's mean luminance within 10 %.
// Needs OCEAN_NATIVE (the build tree's apps/ocean/ocean; ctest sets it) for part 5.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { openPage, run } from './browser.mjs';
import { readPng } from './png.mjs';

const kWidth = 320, kHeight = 180;
// The view both renderers draw: eye 12 m up, heading 20° (from +x towards +z), pitch −8°, 55°
// vertical field of view; the sun at azimuth 35°, elevation 20° (ShadingParams' defaults).
const kCamera = { heightM: 12, yawDeg: 20, pitchDeg: -8, fovDeg: 55 };
const kTimeS = 12, kWarmupS = 4, kRateHz = 30;  // `ocean render`'s --warmup and its 30 Hz steps

// --- independent evaluations ----------------------------------------------------------------

// R.1–R.4 of docs/rendering.md for the default clear sky (sun irradiance 20, brightness 1,
// aerosol 1, g = 0.76), written here from the equations, not from src/render/sky.cpp.
function skyRadiance(v, sun) {
  const beta = [5.8e-6, 13.5e-6, 33.1e-6], hR = 8000, tauM = 2e-5 * 1200, g = 0.76, e = 20;
  const airMass = (mu) => {
    const z = (Math.acos(Math.min(Math.max(mu, 0), 1)) * 180) / Math.PI;
    return 1 / (Math.max(mu, 0) + 0.50572 * (96.07995 - z) ** -1.6364);
  };
  const y = Math.max(v[1], 0) + 1e-4, l = Math.hypot(v[0], y, v[2]);
  const d = [v[0] / l, y / l, v[2] / l];
  const mu = d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2];
  const hg = (1 - g * g) / (4 * Math.PI * (1 + g * g - 2 * g * mu) ** 1.5);
  return beta.map((b) => {
    const tauR = b * hR, tau = tauR + tauM;
    const phase = (tauR * (3 / (16 * Math.PI)) * (1 + mu * mu) + tauM * hg) / tau;
    const a = tau * airMass(Math.max(sun[1], 0));
    const w = Math.sqrt(d[1]);
    const ts = w * ((1 - Math.exp(-a)) / a) + (1 - w) * Math.exp(-a);
    return e * ts * (1 - Math.exp(-tau * airMass(d[1]))) * (phase + (0.25 * tauR) / tau / (4 * Math.PI));
  });
}

// Narkowicz (2015) and IEC 61966-2-1, to 8 bits.
const aces = (x) => Math.min(Math.max((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0), 1);
const srgb = (x) => (x <= 0.0031308 ? 12.92 * x : 1.055 * x ** (1 / 2.4) - 0.055);
const srgbDecode = (c) => (c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4);

// Φ by the series of erf (no shared approximation with the kernels' A&S 7.1.26).
function normalCdf(x) {
  const z = x / Math.SQRT2;
  if (Math.abs(z) > 5) return z > 0 ? 1 : 0;
  let sum = z, term = z;
  for (let n = 1; n < 200; ++n) {
    term *= (-z * z) / n;
    sum += term / (2 * n + 1);
  }
  return 0.5 * (1 + (2 / Math.sqrt(Math.PI)) * sum);
}

// Mean relative luminance (Rec. 709 weights on linear light) of an RGBA8 sRGB image's rows
// [y0, y1), columns [x0, x1).
function meanLuminance({ width, rgba }, y0, y1, x0 = 0, x1 = width) {
  let sum = 0;
  for (let y = y0; y < y1; ++y) {
    for (let x = x0; x < x1; ++x) {
      const i = 4 * (y * width + x);
      sum += 0.2126 * srgbDecode(rgba[i] / 255) + 0.7152 * srgbDecode(rgba[i + 1] / 255) +
             0.0722 * srgbDecode(rgba[i + 2] / 255);
    }
  }
  return sum / ((x1 - x0) * (y1 - y0));
}


// The native renderer's picture of the page's sea and view (flat sea, as the page's).
function nativePicture(binary) {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'ocean-web-native-'));
  const out = path.join(dir, 'native.png');
  const yaw = (kCamera.yawDeg * Math.PI) / 180, pitch = (kCamera.pitchDeg * Math.PI) / 180;
  const target = [100 * Math.cos(pitch) * Math.cos(yaw), kCamera.heightM + 100 * Math.sin(pitch),
                  100 * Math.cos(pitch) * Math.sin(yaw)];
  const args = ['render', '--wind-speed', '10', '--fetch', '100000',
                '--set', `sea.wind_sea.direction_deg=${(0.3 * 180) / Math.PI}`,
                '--cascades', '1000,233,57', '--resolution', '64', '--seed', '1',
                '--loop-period', '200', '--choppiness', '1', '--time', String(kTimeS),
                '--warmup', String(kWarmupS), '--camera', `0,${kCamera.heightM},0`,
                '--target', target.map((x) => x.toFixed(6)).join(','), '--fov', String(kCamera.fovDeg),
                '--width', String(kWidth), '--height', String(kHeight), '--sun-azimuth', '35',
                '--sun-elevation', '20', '--exposure', '0.45', '--planet-radius', 'inf',
                '--out', out];
  execFileSync(binary, args, { stdio: ['ignore', 'pipe', 'inherit'] });
  const picture = readPng(out);
  rmSync(dir, { recursive: true, force: true });
  return { picture, command: `ocean ${args.slice(0, -2).join(' ')}` };
}

await run('shading', async (check) => {
  const { browser, page, server, logs } = await openPage({
    query: 'n=64&t=0&panel=0', width: kWidth, height: kHeight });
  const r = await page.evaluate(async (cam, timeS, warmupS, rateHz) => {
    const o = window.ocean;
    if (o.error) return { error: o.error };
    const { renderer, ocean, device, camera } = o;
    const rad = Math.PI / 180;
    // Sky pixels: a view up into the sky away from the sun, then one centred on the sun.
    const upView = { heightM: 12, yawRad: -120 * rad, pitchRad: 35 * rad, fovYRad: 55 * rad };
    const skyFrame = await renderer.capture(0, upView);
    const sunView = { heightM: 12, yawRad: 35 * rad, pitchRad: 20 * rad, fovYRad: 55 * rad };
    const sunFrame = await renderer.capture(0, sunView);
    // The foam of one step, restarted (the breaking source alone), with each cascade's J.
    const cascades = [];
    for (const [c, sim] of ocean.simulations.entries()) {
      sim.lastTime = null;
      const f = await sim.readFields(timeS);
      const texels = f.foam.length;
      let sumJ = 0, sumJ2 = 0, foam = 0;
      for (let i = 0; i < texels; ++i) {
        const j = f.surface[4 * i + 3];
        sumJ += j;
        sumJ2 += j * j;
        foam += f.foam[i];
      }
      const meanJ = sumJ / texels;
      cascades.push({ c, threshold: 1 - sim.choppiness * (1 - sim.foamThresholdAt1),
                      gain: sim.foamGainAt1 / sim.choppiness, weight: ocean.foamWeights[c],
                      meanJ, varJ: sumJ2 / texels - meanJ * meanJ, foam: foam / texels,
                      jacobians: Array.from(f.surface.filter((_, i) => i % 4 === 3)) });
    }
    // The comparison view, the foam built up over the warm-up as natively.
    Object.assign(camera, { heightM: cam.heightM, yawRad: cam.yawDeg * rad,
                            pitchRad: cam.pitchDeg * rad, fovYRad: cam.fovDeg * rad });
    for (const sim of ocean.simulations) sim.lastTime = null;
    for (let i = Math.ceil(warmupS * rateHz); i > 0; --i) {
      const encoder = device.createCommandEncoder();
      ocean.step(encoder, timeS - i / rateHz);
      device.queue.submit([encoder.finish()]);
    }
    const view = await renderer.capture(timeS, camera);
    await device.queue.onSubmittedWorkDone();
    const pack = (f) => ({ width: f.width, height: f.height, rgba: Array.from(f.rgba) });
    return {
      error: o.error, sky: o.ocean.sky, upView, sunView, skyFrame: pack(skyFrame),
      sunFrame: pack(sunFrame), cascades, view: pack(view),
      lut: Array.from(o.ocean.sky.lut), light: Array.from(o.ocean.sky.light),
    };
  }, kCamera, kTimeS, kWarmupS, kRateHz);
  check(!r.error, `page ready without WebGPU errors ${r.error ?? ''}`);
  if (r.error) {
    console.log(logs.join('\n'));
    return;
  }
  const { cameraMatrices } = await import('../src/camera.js');
  const sun = r.light.slice(0, 3);
  const exposure = r.light[17];

  // 1. The table is R.4 at its texel centres (u = azimuth/2π, v = √(elevation/(π/2))).
  let worstLut = 0;
  for (let y = 0; y < 64; y += 7) {
    for (let x = 0; x < 128; x += 9) {
      const e = (((y + 0.5) / 64) ** 2 * Math.PI) / 2, a = ((x + 0.5) / 128) * 2 * Math.PI;
      const want = skyRadiance([Math.cos(e) * Math.cos(a), Math.sin(e), Math.cos(e) * Math.sin(a)], sun);
      for (let k = 0; k < 3; ++k)
        worstLut = Math.max(worstLut, Math.abs(r.lut[4 * (y * 128 + x) + k] / want[k] - 1));
    }
  }
  check(worstLut <= 1e-5, `sky table = R.1–R.4 evaluated here: worst relative difference ` +
        `${worstLut.toExponential(2)} (≤ 1e-5; the table is float)`);

  // 2. Sky pixels: R.4 along each pixel's ray (evaluated here, not read from the table: the
  // table's bilinear interpolation and rgba16float storage are part of what is checked), exposure,
  // ACES, sRGB. Bound: 3/255 per channel (half-float storage: 2⁻¹¹ relative; bilinear
  // interpolation between texels a few per cent apart near the horizon; 8-bit rounding).
  const pixelRay = (view, px, py) => {
    const m = cameraMatrices(view, kWidth / kHeight);
    const ndc = [((px + 0.5) / kWidth) * 2 - 1, 1 - ((py + 0.5) / kHeight) * 2];
    const inv = m.invViewProj, p = [0, 0, 0, 0];
    for (let row = 0; row < 4; ++row)
      p[row] = inv[row] * ndc[0] + inv[4 + row] * ndc[1] + inv[8 + row] + inv[12 + row];
    const d = [p[0] / p[3] - m.eye[0], p[1] / p[3] - m.eye[1], p[2] / p[3] - m.eye[2]];
    const l = Math.hypot(...d);
    return d.map((x) => x / l);
  };
  let worstSky = 0, skyPixels = 0;
  for (let py = 5; py < kHeight; py += 17) {
    for (let px = 5; px < kWidth; px += 23) {
      const v = pixelRay(r.upView, px, py);
      if (v[1] < 0.02) continue;
      const want = skyRadiance(v, sun).map((x) => Math.round(255 * srgb(aces(x * exposure))));
      const i = 4 * (py * kWidth + px);
      for (let k = 0; k < 3; ++k)
        worstSky = Math.max(worstSky, Math.abs(r.skyFrame.rgba[i + k] - want[k]));
      skyPixels++;
    }
  }
  check(skyPixels > 50 && worstSky <= 3, `${skyPixels} sky pixels are R.4 → exposure ${exposure} → ` +
        `ACES → sRGB within ${worstSky}/255 (≤ 3/255)`);
  // Without the tone map (the linear radiance clamped and written as it is) or with a 2.2 gamma
  // instead of the sRGB curve, the same pixels would differ by far more than the bound:
  let linearGap = 0, gammaGap = 0;
  for (let py = 5; py < kHeight; py += 17) {
    for (let px = 5; px < kWidth; px += 23) {
      const v = pixelRay(r.upView, px, py);
      if (v[1] < 0.02) continue;
      const l = skyRadiance(v, sun);
      linearGap = Math.max(linearGap, ...l.map((x) => Math.abs(255 * Math.min(x, 1) -
        255 * srgb(aces(x * exposure)))));
      gammaGap = Math.max(gammaGap, ...l.map((x) => Math.abs(255 * aces(x * exposure) ** (1 / 2.2) -
        255 * srgb(aces(x * exposure)))));
    }
  }
  // (A γ 2.2 curve in place of the sRGB one moves these bright pixels by about the bound only:
  // this check tells the tone map apart from none, not the two encodings; the water's darker
  // pixels, compared with the native picture below, do.)
  console.log(`     (with no tone map they would miss by up to ${linearGap.toFixed(0)}/255; a γ 2.2 ` +
              `curve instead of sRGB by ${gammaGap.toFixed(1)}/255)`);

  // 3. The sun's disc: the pixel at the sun is white (its radiance, 2 % of E/Ω, saturates any
  // exposure), the sky 1° from it is R.4's.
  const centre = 4 * ((kHeight / 2) * kWidth + kWidth / 2);
  const disc = r.sunFrame.rgba.slice(centre, centre + 3);
  check(disc.every((x) => x >= 250), `the pixel at the sun is the disc's white (${disc.join(', ')})`);
  let offDisc = 0;
  for (const [dx, dy] of [[12, 0], [-12, 0], [0, 12], [0, -12]]) {  // 12 px ≈ 3.7° away
    const px = kWidth / 2 + dx, py = kHeight / 2 + dy, i = 4 * (py * kWidth + px);
    const want = skyRadiance(pixelRay(r.sunView, px, py), sun)
      .map((x) => Math.round(255 * srgb(aces(x * exposure))));
    for (let k = 0; k < 3; ++k) offDisc = Math.max(offDisc, Math.abs(r.sunFrame.rgba[i + k] - want[k]));
  }
  check(offDisc <= 3, `around the disc the sky is R.4's within ${offDisc}/255 (≤ 3/255)`);

  // 4. Breaking foam (M.7.4): for a Gaussian J of mean m and variance s², the mean of
  // Φ((J_thr − J)·g) is Φ((J_thr − m)·g/√(1 + g²s²)); the kernels' Φ is A&S 7.1.26, the mean here
  // from the series. Each cascade's J is checked against its own Jacobians' statistics (the
  // non-Gaussian tails of choppy waves allowed for: 15 %), and every cascade must estimate the
  // same whitecap fraction (within 25 % of their mean: one 64² realisation each).
  let weightSum = 0;
  const fractions = [];
  for (const c of r.cascades) {
    let exact = 0;
    for (const j of c.jacobians) exact += normalCdf((c.threshold - j) * c.gain);
    exact /= c.jacobians.length;
    const gaussian = normalCdf(((c.threshold - c.meanJ) * c.gain) / Math.sqrt(1 + c.gain ** 2 * c.varJ));
    check(Math.abs(c.foam - exact) <= 1e-4,
          `cascade ${c.c}: mean foam ${(100 * c.foam).toFixed(3)} % = the mean of Φ((J_thr − J)·g) ` +
          `over its Jacobians ${(100 * exact).toFixed(3)} % (J_thr ${c.threshold.toFixed(4)}, ` +
          `g ${c.gain.toFixed(3)})`);
    check(Math.abs(c.foam / gaussian - 1) <= 0.15,
          `cascade ${c.c}: mean foam within 15 % of the Gaussian J's ${(100 * gaussian).toFixed(3)} % ` +
          `(σ_J ${Math.sqrt(c.varJ).toFixed(4)})`);
    fractions.push(c.foam);
    weightSum += c.weight;
  }
  const mean = fractions.reduce((a, b) => a + b, 0) / fractions.length;
  const coverage = r.cascades.reduce((a, c) => a + c.weight * c.foam, 0);
  check(fractions.every((f) => Math.abs(f / mean - 1) <= 0.25),
        `every cascade gives the whitecap fraction ${fractions.map((f) => (100 * f).toFixed(2)).join(', ')} % ` +
        `(within 25 % of their mean ${(100 * mean).toFixed(2)} %)`);
  check(Math.abs(weightSum - 1) <= 1e-6,
        `the foam weights ${r.cascades.map((c) => c.weight.toFixed(4)).join(', ')} sum to 1 ` +
        `(${weightSum.toFixed(7)}): the drawn cover Σ w_c·foam_c = ${(100 * coverage).toFixed(2)} % ` +
        `(Monahan & O'Muircheartaigh 1980 at 10 m/s: ${(100 * 3.84e-6 * 10 ** 3.41).toFixed(2)} %)`);

  // 5. The native renderer's picture of the same sea and view.
  const native = process.env.OCEAN_NATIVE;
  if (!native || !existsSync(native)) {
    // A tree built without the command-line tool has nothing to compare with: a skip, or a
    // failure when OCEAN_REQUIRE_DEVICES=1 (as for a missing Chromium).
    const required = process.env.OCEAN_REQUIRE_DEVICES === '1';
    const text = `OCEAN_NATIVE (the build tree's apps/ocean/ocean) is needed for the comparison ` +
                 `with the native renderer (${native ?? 'unset'})`;
    if (required) check(false, text);
    else console.log(`SKIP ${text}`);
  } else {
    const { picture, command } = nativePicture(native);
    console.log(`     native: ${command}`);
    const horizon = (() => {  // the horizon's row: pitch −8° below the centre
      const f = 1 / Math.tan((kCamera.fovDeg * Math.PI) / 360);
      return Math.round((kHeight / 2) * (1 - Math.tan((-kCamera.pitchDeg * Math.PI) / 180) * f));
    })();
    // The glitter: the water in the sun's azimuth, 15° right of the heading, ±20 px.
    const sunColumn = Math.round((kWidth / 2) * (1 + Math.tan((15 * Math.PI) / 180) /
      (Math.tan((kCamera.fovDeg * Math.PI) / 360) * (kWidth / kHeight))));
    const regions = [['whole picture', 0, kHeight], ['sky', 0, horizon - 3],
                     ['water', horizon + 3, kHeight],
                     ['glitter', horizon + 3, kHeight, sunColumn - 20, sunColumn + 20]];
    for (const [name, y0, y1, x0 = 0, x1 = kWidth] of regions) {
      const web = meanLuminance(r.view, y0, y1, x0, x1), nat = meanLuminance(picture, y0, y1, x0, x1);
      const ok = name !== 'whole picture' || Math.abs(web / nat - 1) <= 0.10;
      check(ok, `${name} (rows ${y0}–${y1}, columns ${x0}–${x1}): mean luminance page ${web.toFixed(4)}, native ` +
            `${nat.toFixed(4)} (×${(web / nat).toFixed(3)}${name === 'whole picture' ? '; within 10 % asked' : ''})`);
    }
  }
  await browser.close();
  server.close();
});
