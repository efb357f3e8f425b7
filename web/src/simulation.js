// simulation.js — the WebGPU compute side: one N×N patch, evolved, transformed and finalised each
// step into displacement, normal/Jacobian and foam storage buffers that the renderer reads.
// The initial amplitudes and phase rates come from the WebAssembly core (the library's spectrum
// module); this file only moves them to the GPU and records the kernels (shaders/*.wgsl).
//
// Contract: Simulation.create validates nothing the core has not validated; step(t) records one
// frame into a command encoder and never allocates GPU memory; readFields() is for tests.

const kFoam = { decayPerS: 0.6 };  // sim.hpp FoamParams

export async function shaderText(name) {
  const response = await fetch(new URL(`shaders/${name}`, import.meta.url));
  if (!response.ok) throw new Error(`cannot load shaders/${name}: ${response.status}`);
  return response.text();
}

// Splits a ≥ 0 into hi + mid + lo with 12 significant bits in hi and mid, as split_phase in
// src/backends/vulkan/vulkan_backend.cpp does (M.7.3).
function truncate12(x) {
  if (x === 0) return 0;
  let e = Math.ceil(Math.log2(Math.abs(x)));  // frexp exponent: x = m·2^e, m ∈ [0.5, 1)
  while (2 ** e <= Math.abs(x)) ++e;
  while (2 ** (e - 1) > Math.abs(x)) --e;
  const scale = 2 ** (12 - e);
  return Math.fround(Math.trunc(x * scale) / scale);
}
export function splitPhase(a) {
  const hi = truncate12(a);
  const mid = truncate12(a - hi);
  return [hi, mid, Math.fround(a - hi - mid)];
}

// EvolutionPhase::clock: frac(t/T) when looping, t otherwise (M.7.3).
function phaseClock(timeS, loopPeriodS) {
  if (loopPeriodS <= 0) return timeS;
  const tau = timeS / loopPeriodS;
  return tau - Math.floor(tau);
}

// The three compute pipelines for resolution n, compiled once per device and shared by the
// cascades (they differ only in their buffers).
const compiled = new WeakMap();  // device → Map(n → Promise of kernels)
function kernels(device, n) {
  if (!compiled.has(device)) compiled.set(device, new Map());
  const cache = compiled.get(device);
  if (!cache.has(n)) cache.set(n, compileKernels(device, n));
  return cache.get(n);
}
async function compileKernels(device, n) {
  const prefix = `const N: u32 = ${n}u;\nconst LOG2N: u32 = ${Math.log2(n)}u;\n`;
  const [common, fft, rowsSource, columnsSource, finalizeSource] = await Promise.all(
    ['common.wgsl', 'fft.wgsl', 'fft_rows.wgsl', 'fft_columns.wgsl', 'finalize.wgsl'].map(
      shaderText));
  const entries = [{ binding: 0, visibility: GPUShaderStage.COMPUTE, buffer: { type: 'uniform' } }];
  for (let b = 1; b <= 3; ++b)
    entries.push({ binding: b, visibility: GPUShaderStage.COMPUTE,
                   buffer: { type: 'read-only-storage' } });
  for (let b = 4; b <= 7; ++b)
    entries.push({ binding: b, visibility: GPUShaderStage.COMPUTE, buffer: { type: 'storage' } });
  const bindGroupLayout = device.createBindGroupLayout({ entries });
  const layout = device.createPipelineLayout({ bindGroupLayouts: [bindGroupLayout] });
  const pipeline = async (source) => {
    const module = device.createShaderModule({ code: prefix + common + source });
    return device.createComputePipelineAsync({ layout, compute: { module, entryPoint: 'main' } });
  };
  const [rows, columns, finalize] = await Promise.all(
    [fft + rowsSource, fft + columnsSource, finalizeSource].map(pipeline));
  return { bindGroupLayout, rows, columns, finalize };
}

export class Simulation {
  static async create(device, core, sea) {
    const sim = new Simulation();
    await sim.init(device, core, sea);
    return sim;
  }

  async init(device, core, sea) {
    this.device = device;
    this.sea = sea;
    const n = sea.resolution;
    this.n = n;
    const texels = n * n;
    const storage = GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST;
    const upload = (array, usage = storage) => {
      const buffer = device.createBuffer({ size: array.byteLength, usage });
      device.queue.writeBuffer(buffer, 0, array);
      return buffer;
    };
    this.spectrum = upload(core.packed());
    this.phaseRate = upload(core.phaseRate());
    // The breaking foam source's terms at λ = 1 (FoamPlan, M.7.4) and the cascade's foam weight
    // (R.11); step() scales them to the choppiness as the plan's formulas do.
    const terms = core.foamTerms(1);
    [this.foamThresholdAt1, this.foamGainAt1, this.foamWeight] = terms;
    const twiddle = new Float32Array(2 * n);  // e^{+2πi·t/N} in double, stored as float
    for (let t = 0; t < n; ++t) {
      twiddle[2 * t] = Math.cos((2 * Math.PI * t) / n);
      twiddle[2 * t + 1] = Math.sin((2 * Math.PI * t) / n);
    }
    this.twiddle = upload(twiddle);
    this.planes = device.createBuffer({ size: 2 * texels * 8, usage: GPUBufferUsage.STORAGE });
    const out = GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC;
    this.displacement = device.createBuffer({ size: texels * 16, usage: out });
    this.surface = device.createBuffer({ size: texels * 16, usage: out });
    this.foam = device.createBuffer({ size: texels * 4, usage: out });
    this.params = device.createBuffer({
      size: 48, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });

    const { bindGroupLayout, rows, columns, finalize } = await kernels(device, n);
    [this.rowsPipeline, this.columnsPipeline, this.finalizePipeline] = [rows, columns, finalize];
    const buffers = [this.params, this.spectrum, this.phaseRate, this.twiddle, this.planes,
                     this.displacement, this.surface, this.foam];
    this.bindGroup = device.createBindGroup({
      layout: bindGroupLayout,
      entries: buffers.map((buffer, binding) => ({ binding, resource: { buffer } })),
    });
    this.lastTime = null;
    this.choppiness = 1.0;
  }

  // Records one frame at time t (s) into encoder.
  step(encoder, timeS) {
    const [hi, mid, lo] = splitPhase(phaseClock(timeS, this.sea.loopPeriodS));
    const reset = this.lastTime === null || timeS < this.lastTime;
    const dt = reset ? 0 : timeS - this.lastTime;
    this.lastTime = timeS;
    const data = new ArrayBuffer(48);
    const f = new Float32Array(data);
    const u = new Uint32Array(data);
    f.set([hi, mid, lo, this.choppiness, (2 * Math.PI) / this.sea.patchSizeM,
           this.n / this.sea.patchSizeM, kFoam.decayPerS * dt]);
    u[7] = reset ? 1 : 0;
    f[8] = this.choppiness > 0 ? 1 - this.choppiness * (1 - this.foamThresholdAt1) : 0;
    f[9] = this.choppiness > 0 ? this.foamGainAt1 / this.choppiness : 1e9;
    this.device.queue.writeBuffer(this.params, 0, data);

    const pass = encoder.beginComputePass();
    pass.setBindGroup(0, this.bindGroup);
    pass.setPipeline(this.rowsPipeline);
    pass.dispatchWorkgroups(this.n, 2);
    pass.setPipeline(this.columnsPipeline);
    pass.dispatchWorkgroups(this.n, 2);
    pass.setPipeline(this.finalizePipeline);
    pass.dispatchWorkgroups(Math.ceil(this.n / 8), Math.ceil(this.n / 8));
    pass.end();
  }

  // Steps to time t and reads the fields back: { displacement: (Dx, h, Dz, 0), surface:
  // (nx, ny, nz, J), foam } per texel as Float32Arrays.
  async readFields(timeS) {
    const encoder = this.device.createCommandEncoder();
    this.step(encoder, timeS);
    const sources = { displacement: this.displacement, surface: this.surface, foam: this.foam };
    const staging = {};
    for (const [name, buffer] of Object.entries(sources)) {
      staging[name] = this.device.createBuffer({
        size: buffer.size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
      encoder.copyBufferToBuffer(buffer, 0, staging[name], 0, buffer.size);
    }
    this.device.queue.submit([encoder.finish()]);
    const out = {};
    for (const [name, buffer] of Object.entries(staging)) {
      await buffer.mapAsync(GPUMapMode.READ);
      out[name] = new Float32Array(buffer.getMappedRange().slice(0));
      buffer.unmap();
      buffer.destroy();
    }
    return out;
  }

  destroy() {
    for (const b of [this.spectrum, this.phaseRate, this.twiddle, this.planes, this.displacement,
                     this.surface, this.foam, this.params]) b.destroy();
  }
}
