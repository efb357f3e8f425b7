// renderer.js — the WebGPU render side: sky, then the water grid (shaders/ocean.wgsl) displaced
// by the sum of the cascades' displacements and shaded from their trilinearly sampled normal/foam
// mips (cascades.js). capture() renders one frame into the canvas texture and reads it
// back for the tests (no NaN or black pixels, sky above, water below).
import { cameraMatrices } from './camera.js';

const kRings = 160;     // rings of the polar grid
const kSegments = 256;  // segments per ring

// IEEE 754 binary16 of each float (round to nearest even), for rgba16float uploads.
function toHalf(values) {
  const out = new Uint16Array(values.length);
  const f = new Float32Array(1);
  const u = new Uint32Array(f.buffer);
  for (let i = 0; i < values.length; ++i) {
    f[0] = values[i];
    const x = u[0];
    const sign = (x >>> 16) & 0x8000;
    const e = (x >>> 23) & 0xff;
    let mant = x & 0x7fffff;
    let h;
    if (e === 255) h = sign | 0x7c00 | (mant ? 0x200 : 0);
    else if (e > 142) h = sign | 0x7c00;  // overflow: infinity
    else if (e > 112) {
      h = sign | ((e - 112) << 10) | (mant >>> 13);
      const rest = mant & 0x1fff;
      if (rest > 0x1000 || (rest === 0x1000 && (h & 1))) h++;
    } else if (e > 101) {  // subnormal half
      mant |= 0x800000;
      const shift = 126 - e;
      h = sign | (mant >>> shift);
      const rest = mant & ((1 << shift) - 1), halfway = 1 << (shift - 1);
      if (rest > halfway || (rest === halfway && (h & 1))) h++;
    } else h = sign;
    out[i] = h;
  }
  return out;
}

export class Renderer {
  static async create(device, canvas, ocean) {
    const r = new Renderer();
    await r.init(device, canvas, ocean);
    return r;
  }

  async init(device, canvas, ocean) {
    this.device = device;
    this.canvas = canvas;
    this.ocean = ocean;
    this.context = canvas.getContext('webgpu');
    this.format = navigator.gpu.getPreferredCanvasFormat();
    this.context.configure({
      device, format: this.format, alphaMode: 'opaque',
      usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC });
    const response = await fetch(new URL('shaders/ocean.wgsl', import.meta.url));
    const module = device.createShaderModule({ code: await response.text() });
    const vf = GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT;
    const layout = device.createBindGroupLayout({ entries: [
      { binding: 0, visibility: vf, buffer: { type: 'uniform' } },
      { binding: 1, visibility: vf, buffer: { type: 'read-only-storage' } },
      { binding: 2, visibility: GPUShaderStage.FRAGMENT,
        texture: { sampleType: 'float', viewDimension: '2d-array' } },
      { binding: 3, visibility: GPUShaderStage.FRAGMENT, sampler: { type: 'filtering' } },
      { binding: 4, visibility: GPUShaderStage.FRAGMENT, texture: { sampleType: 'float' } },
      { binding: 5, visibility: GPUShaderStage.FRAGMENT, sampler: { type: 'filtering' } },
    ] });
    const pipelineLayout = device.createPipelineLayout({ bindGroupLayouts: [layout] });
    const depthStencil = (write) => ({
      format: 'depth24plus', depthWriteEnabled: write, depthCompare: 'less-equal' });
    const targets = [{ format: this.format }];
    [this.skyPipeline, this.waterPipeline] = await Promise.all([
      device.createRenderPipelineAsync({
        layout: pipelineLayout, depthStencil: depthStencil(false),
        vertex: { module, entryPoint: 'sky_vs' },
        fragment: { module, entryPoint: 'sky_fs', targets } }),
      device.createRenderPipelineAsync({
        layout: pipelineLayout, depthStencil: depthStencil(true),
        primitive: { cullMode: 'none' },
        vertex: { module, entryPoint: 'water_vs' },
        fragment: { module, entryPoint: 'water_fs', targets } }),
    ]);
    this.view = device.createBuffer({
      size: 320, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
    // The sky-view table (render::Sky::fill_lut, R.4) as rgba16float, which filters without any
    // optional feature (rgba32float needs 'float32-filterable').
    const sky = ocean.sky;
    this.skyTexture = device.createTexture({
      size: [sky.width, sky.height], format: 'rgba16float',
      usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    device.queue.writeTexture({ texture: this.skyTexture }, toHalf(sky.lut),
                              { bytesPerRow: sky.width * 8 }, [sky.width, sky.height]);
    this.bindGroup = device.createBindGroup({ layout, entries: [
      { binding: 0, resource: { buffer: this.view } },
      { binding: 1, resource: { buffer: ocean.displacement } },
      { binding: 2, resource: ocean.mips.texture.createView({ dimension: '2d-array' }) },
      { binding: 3, resource: device.createSampler({
        addressModeU: 'repeat', addressModeV: 'repeat', magFilter: 'linear',
        minFilter: 'linear', mipmapFilter: 'linear', maxAnisotropy: 4 }) },
      { binding: 4, resource: this.skyTexture.createView() },
      { binding: 5, resource: device.createSampler({
        addressModeU: 'repeat', addressModeV: 'clamp-to-edge', magFilter: 'linear',
        minFilter: 'linear' }) },
    ] });
    this.depth = null;
    // The render pass's GPU time, where the device has timestamp queries (gpuMs; null before the
    // first reading or without them).
    this.gpuMs = null;
    this.timer = device.features.has('timestamp-query') ? {
      querySet: device.createQuerySet({ type: 'timestamp', count: 2 }),
      resolve: device.createBuffer({
        size: 16, usage: GPUBufferUsage.QUERY_RESOLVE | GPUBufferUsage.COPY_SRC }),
      read: device.createBuffer({ size: 16, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST }),
      recorded: false, reading: false,
    } : null;
  }

  // After the frame's submit: reads the render pass's timestamps back (asynchronously) into gpuMs.
  collectGpuTime() {
    const t = this.timer;
    if (!t || !t.recorded || t.reading) return;
    t.recorded = false;
    t.reading = true;
    t.read.mapAsync(GPUMapMode.READ).then(() => {
      const [begin, end] = new BigUint64Array(t.read.getMappedRange());
      if (end > begin) this.gpuMs = Number(end - begin) / 1e6;
      t.read.unmap();
      t.reading = false;
    }, () => { t.reading = false; });
  }

  // Records the cascades' step at time t and the drawing of camera's view; returns the canvas
  // texture drawn into.
  frame(encoder, timeS, camera) {
    this.ocean.step(encoder, timeS);
    const { width, height } = this.canvas;
    if (!this.depth || this.depth.width !== width || this.depth.height !== height) {
      if (this.depth) this.depth.destroy();
      this.depth = this.device.createTexture({
        size: [width, height], format: 'depth24plus', usage: GPUTextureUsage.RENDER_ATTACHMENT });
    }
    const m = cameraMatrices(camera, width / height);
    const o = this.ocean;
    const light = o.sky.light;  // ocean_web_sky's list (web/wasm/ocean_web.cpp)
    const data = new Float32Array(80);
    data.set(m.viewProj, 0);
    data.set(m.invViewProj, 16);
    data.set([...m.eye, o.hsM], 32);
    data.set([light[0], light[1], light[2], this.exposure ?? light[17]], 36);
    const sizes = o.sea.patchSizesM;
    data.set([o.n, kRings, kSegments, sizes.length], 40);
    data.set(sizes, 44);
    data.set(o.geometryWavelengthsM, 48);
    data.set(o.foamWeights, 52);
    data.set([light[3], light[4], light[5], o.unresolvedSlopeVariance], 56);
    data.set([light[6], light[7], light[8], light[21]], 60);
    data.set([light[18], light[19], light[20], light[22]], 64);
    data.set(light.subarray(9, 13), 68);
    data.set(light.subarray(13, 17), 72);
    data.set([light[23], 0, 0, 0], 76);
    this.device.queue.writeBuffer(this.view, 0, data);
    const texture = this.context.getCurrentTexture();
    const timed = this.timer && !this.timer.reading && !this.timer.recorded;
    const pass = encoder.beginRenderPass({
      colorAttachments: [{ view: texture.createView(), loadOp: 'clear', storeOp: 'store',
                           clearValue: { r: 0, g: 0, b: 0, a: 1 } }],
      depthStencilAttachment: { view: this.depth.createView(), depthLoadOp: 'clear',
                                depthClearValue: 1, depthStoreOp: 'store' },
      ...(timed ? { timestampWrites: { querySet: this.timer.querySet,
                                       beginningOfPassWriteIndex: 0, endOfPassWriteIndex: 1 } }
                : {}),
    });
    pass.setBindGroup(0, this.bindGroup);
    pass.setPipeline(this.skyPipeline);
    pass.draw(3);
    pass.setPipeline(this.waterPipeline);
    pass.draw(kRings * kSegments * 6);
    pass.end();
    if (timed) {
      encoder.resolveQuerySet(this.timer.querySet, 0, 2, this.timer.resolve, 0);
      encoder.copyBufferToBuffer(this.timer.resolve, 0, this.timer.read, 0, 16);
      this.timer.recorded = true;
    }
    return texture;
  }

  // Renders one frame and reads the canvas back: { width, height, rgba: Uint8Array } (RGBA order).
  async capture(timeS, camera) {
    const { width, height } = this.canvas;
    const bytesPerRow = Math.ceil((width * 4) / 256) * 256;
    const staging = this.device.createBuffer({
      size: bytesPerRow * height, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
    const encoder = this.device.createCommandEncoder();
    const texture = this.frame(encoder, timeS, camera);
    encoder.copyTextureToBuffer({ texture }, { buffer: staging, bytesPerRow }, [width, height]);
    this.device.queue.submit([encoder.finish()]);
    this.collectGpuTime();
    await staging.mapAsync(GPUMapMode.READ);
    const padded = new Uint8Array(staging.getMappedRange());
    const rgba = new Uint8Array(width * height * 4);
    const bgra = this.format === 'bgra8unorm';
    for (let y = 0; y < height; ++y) {
      for (let x = 0; x < width; ++x) {
        const s = y * bytesPerRow + x * 4;
        const d = (y * width + x) * 4;
        rgba[d] = padded[s + (bgra ? 2 : 0)];
        rgba[d + 1] = padded[s + 1];
        rgba[d + 2] = padded[s + (bgra ? 0 : 2)];
        rgba[d + 3] = padded[s + 3];
      }
    }
    staging.unmap();
    staging.destroy();
    return { width, height, rgba };
  }
}
