// mips_check.mjs — the cascades' normal/foam mip chains, checked on an open page (render.test.mjs
// calls it, sharing its Chromium): the 2×2 box filter (Aebi, VR Ocean, eq. 52) keeps the mean, so
// the last level (1×1) of every cascade equals the mean of its level 0 read back from the same
// texture. Each level stores rgba16float, rounded to 2^-11 of its value (|value| ≤ 1: normal
// components and foam), so the two agree within log2 N · 2^-11; level 0 itself spreads far more
// about its mean, so a filter that dropped texels would miss.
export async function checkMips(page, check) {
  const result = await page.evaluate(async () => {
    const { ocean, renderer, camera } = window.ocean;
    await renderer.capture(3, camera);  // steps the cascades and rebuilds the mips
    const out = [];
    for (let layer = 0; layer < ocean.simulations.length; ++layer) {
      const level0 = await ocean.mips.read(layer, 0);
      const last = await ocean.mips.read(layer, ocean.mips.levels - 1);
      const texels = level0.length / 4;
      const mean = [0, 0, 0, 0];
      for (let i = 0; i < texels; ++i) {
        for (let c = 0; c < 4; ++c) mean[c] += level0[4 * i + c] / texels;
      }
      let spread = 0;
      for (let i = 0; i < texels; ++i) spread = Math.max(spread, Math.abs(level0[4 * i] - mean[0]));
      out.push({ patch: ocean.sea.patchSizesM[layer], levels: ocean.mips.levels, mean,
                 last: Array.from(last), spread });
    }
    return out;
  });
  for (const r of result) {
    const bound = (r.levels - 1) * 2 ** -11;
    const worst = Math.max(...r.mean.map((m, c) => Math.abs(m - r.last[c])));
    check(worst <= bound && r.spread > 10 * bound,
          `mips, cascade ${r.patch} m: the last level ${r.last.map((v) => v.toFixed(4)).join(', ')}` +
          ` is level 0's mean ${r.mean.map((v) => v.toFixed(4)).join(', ')} within ` +
          `${worst.toExponential(2)} ≤ ${bound.toExponential(2)} (level 0 spreads ` +
          `${r.spread.toFixed(3)} about it)`);
  }
}
