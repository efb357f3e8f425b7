// conformance.test.mjs — the page's WebGPU fields equal the WebAssembly CPU reference (the
// library's scalar reference pipeline: evolution, radix-2 FFT, assembly, finalize) within the
// device bounds of docs/vulkan.md, "Conformance bounds" (kDeviceBounds): displacement
// max |ΔD|/Hs ≤ 6e-6 with Hs = 4·√var(h) of the reference frame, normal components 9e-6,
// Jacobian 7e-6, foam 2e-5. Both sides are float32 with other FFT orders and other sin/cos; the
// Vulkan backend meets the same bounds on lavapipe. Each case steps twice (t, then t + 0.5 s) so
// that foam accumulation is compared too.
import { openPage, run } from './browser.mjs';

const kBounds = { displacement: 6e-6, normal: 9e-6, jacobian: 7e-6, foam: 2e-5 };
const kDt = 0.5;

await run('conformance', async (check) => {
  for (const n of [64, 128]) {
    const { browser, page, server, logs } = await openPage({ query: `n=${n}&patch=250&t=0&panel=0` });
    const result = await page.evaluate(async (dt) => {
      const { core, simulation } = window.ocean;
      if (window.ocean.error) return { error: window.ocean.error };
      const out = [];
      for (const [t, lambda] of [[0, 1], [7.25, 1], [123.4567, 0.6], [86400.5, 1.3]]) {
        simulation.choppiness = lambda;
        simulation.lastTime = null;  // restart the foam, as the reference does
        await simulation.readFields(t);
        core.reference(t, lambda, 0, true);
        const gpu = await simulation.readFields(t + dt);
        const cpu = core.reference(t + dt, lambda, dt, false);
        const texels = cpu.foam.length;
        let variance = 0;
        for (let i = 0; i < texels; ++i) variance += cpu.displacement[3 * i + 1] ** 2 / texels;
        const worst = { displacement: 0, normal: 0, jacobian: 0, foam: 0 };
        let finite = true, foamy = 0;
        const take = (name, a, b) => {
          if (!Number.isFinite(a)) finite = false;
          worst[name] = Math.max(worst[name], Math.abs(a - b));
        };
        for (let i = 0; i < texels; ++i) {
          for (let c = 0; c < 3; ++c) {
            take('displacement', gpu.displacement[4 * i + c], cpu.displacement[3 * i + c]);
            take('normal', gpu.surface[4 * i + c], cpu.surface[4 * i + c]);
          }
          take('jacobian', gpu.surface[4 * i + 3], cpu.surface[4 * i + 3]);
          take('foam', gpu.foam[i], cpu.foam[i]);
          if (cpu.foam[i] > 0.01) foamy++;  // the breaking source is > 0 everywhere
        }
        out.push({ t, lambda, hs: 4 * Math.sqrt(variance), worst, finite, foamy });
      }
      return { out, error: window.ocean.error };
    }, kDt);
    check(!result.error, `N=${n}: page ready without WebGPU errors ${result.error ?? ''}`);
    for (const r of result.out ?? []) {
      const errors = { ...r.worst, displacement: r.worst.displacement / r.hs };
      const ok = r.finite && r.hs > 0 &&
                 Object.keys(kBounds).every((k) => errors[k] <= kBounds[k]);
      const text = Object.keys(kBounds)
                       .map((k) => `${k} ${errors[k].toExponential(2)} (≤ ${kBounds[k]})`)
                       .join(', ');
      check(ok, `N=${n} t=${r.t}+${kDt} λ=${r.lambda} Hs=${r.hs.toFixed(3)} m, ` +
                `${r.foamy} texels with foam > 1 %: ${text}`);
    }
    if (result.error || !result.out) console.log(logs.join('\n'));
    await browser.close();
    server.close();
  }
});
