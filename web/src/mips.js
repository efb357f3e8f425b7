// mips.js — the cascades' normal/foam mip chains (shaders/mips.wgsl): one rgba16float 2D-array
// texture, a layer per cascade, log2 N + 1 levels, rebuilt by compute passes after every step
// and sampled trilinearly by the renderer.
//
// Contract: record() allocates nothing on the GPU (its bind groups are made once); read() is for
// tests.
export const kMipFormat = 'rgba16float';

export class MipChain {
  static async create(device, shaderText, simulations) {
    const chain = new MipChain();
    await chain.init(device, shaderText, simulations);
    return chain;
  }

  async init(device, shaderText, simulations) {
    this.device = device;
    const n = simulations[0].n;
    this.n = n;
    this.levels = Math.log2(n) + 1;
    this.texture = device.createTexture({
      size: [n, n, simulations.length], format: kMipFormat, mipLevelCount: this.levels,
      usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.STORAGE_BINDING |
             GPUTextureUsage.COPY_SRC });
    const module = device.createShaderModule({ code: shaderText });
    const pipeline = (entryPoint) =>
      device.createComputePipelineAsync({ layout: 'auto', compute: { module, entryPoint } });
    const [copy, filter] = await Promise.all([pipeline('copy_level0'), pipeline('box_filter')]);
    const view = (layer, level) => this.texture.createView({
      dimension: '2d', baseArrayLayer: layer, arrayLayerCount: 1, baseMipLevel: level,
      mipLevelCount: 1 });
    // Per layer: the level-0 copy, then one box filter per further level.
    this.passes = simulations.map((sim, layer) => {
      const steps = [{ pipeline: copy, size: n, bindGroup: device.createBindGroup({
        layout: copy.getBindGroupLayout(0), entries: [
          { binding: 0, resource: { buffer: sim.surface } },
          { binding: 1, resource: { buffer: sim.foam } },
          { binding: 2, resource: view(layer, 0) }] }) }];
      for (let level = 1; level < this.levels; ++level) {
        steps.push({ pipeline: filter, size: n >> level, bindGroup: device.createBindGroup({
          layout: filter.getBindGroupLayout(0), entries: [
            { binding: 3, resource: view(layer, level - 1) },
            { binding: 4, resource: view(layer, level) }] }) });
      }
      return steps;
    });
  }

  // Records the rebuilding of every layer's chain from its simulation's current fields.
  record(encoder) {
    for (const steps of this.passes) {
      for (const { pipeline, size, bindGroup } of steps) {
        // One pass per level: the next level reads what this one wrote.
        const pass = encoder.beginComputePass();
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, bindGroup);
        pass.dispatchWorkgroups(Math.ceil(size / 8), Math.ceil(size / 8));
        pass.end();
      }
    }
  }

  // Reads level `level` of layer `layer` back as a Float32Array of (nx, ny, nz, foam) per texel.
  async read(layer, level) {
    const size = this.n >> level;
    const bytesPerRow = Math.ceil((size * 8) / 256) * 256;
    const staging = this.device.createBuffer({
      size: bytesPerRow * size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
    const encoder = this.device.createCommandEncoder();
    encoder.copyTextureToBuffer({ texture: this.texture, mipLevel: level, origin: [0, 0, layer] },
                                { buffer: staging, bytesPerRow }, [size, size, 1]);
    this.device.queue.submit([encoder.finish()]);
    await staging.mapAsync(GPUMapMode.READ);
    const halves = new Uint16Array(staging.getMappedRange());
    const out = new Float32Array(4 * size * size);
    for (let row = 0; row < size; ++row) {
      for (let i = 0; i < 4 * size; ++i) out[4 * size * row + i] = halfToFloat(halves[(bytesPerRow / 2) * row + i]);
    }
    staging.unmap();
    staging.destroy();
    return out;
  }

  destroy() {
    this.texture.destroy();
  }
}

// IEEE 754 binary16 → number.
function halfToFloat(h) {
  const sign = h & 0x8000 ? -1 : 1;
  const exponent = (h >> 10) & 0x1f;
  const fraction = h & 0x3ff;
  if (exponent === 0) return sign * 2 ** -14 * (fraction / 1024);
  if (exponent === 31) return fraction ? NaN : sign * Infinity;
  return sign * 2 ** (exponent - 15) * (1 + fraction / 1024);
}
