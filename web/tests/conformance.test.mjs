// conformance.test.mjs — the page's WebGPU displacement (Dx, h, Dz) at several times equals the
// WebAssembly CPU reference (the library's scalar reference pipeline) within the device bound of
// docs/vulkan.md, "Conformance bounds": max |ΔD|/Hs ≤ 6e-6 (kDeviceBounds), Hs = 4·√var(h) of the
// reference frame. Both sides are float32 with other FFT orders and GPU sin/cos; the Vulkan
// backend meets the same bound on lavapipe.
import { openPage, run } from './browser.mjs';

const kBound = 6e-6;

await run('conformance', async (check) => {
  for (const n of [64, 128]) {
    const { browser, page, server, logs } = await openPage({ query: `n=${n}&t=0&panel=0` });
    const result = await page.evaluate(async () => {
      const { core, simulation } = window.ocean;
      if (window.ocean.error) return { error: window.ocean.error };
      const out = [];
      for (const [t, lambda] of [[0, 1], [7.25, 1], [123.4567, 0.6], [86400.5, 1.3]]) {
        simulation.choppiness = lambda;
        const gpu = await simulation.readDisplacement(t);
        const cpu = core.reference(t, lambda);
        const texels = cpu.length / 3;
        let variance = 0, worst = 0, finite = true;
        for (let i = 0; i < texels; ++i) variance += cpu[3 * i + 1] ** 2 / texels;
        for (let i = 0; i < texels; ++i) {
          for (let c = 0; c < 3; ++c) {
            const d = Math.abs(gpu[4 * i + c] - cpu[3 * i + c]);
            if (!Number.isFinite(gpu[4 * i + c])) finite = false;
            worst = Math.max(worst, d);
          }
        }
        out.push({ t, lambda, hs: 4 * Math.sqrt(variance), worst, finite });
      }
      return { out, error: window.ocean.error };
    });
    check(!result.error, `N=${n}: page ready without WebGPU errors ${result.error ?? ''}`);
    for (const r of result.out ?? []) {
      const relative = r.worst / r.hs;
      check(r.finite && r.hs > 0 && relative <= kBound,
            `N=${n} t=${r.t} λ=${r.lambda}: max |ΔD|/Hs = ${relative.toExponential(2)} ` +
            `(bound ${kBound}, Hs = ${r.hs.toFixed(3)} m)`);
    }
    if (result.error || !result.out) console.log(logs.join('\n'));
    await browser.close();
    server.close();
  }
});
