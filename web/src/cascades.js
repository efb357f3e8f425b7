// cascades.js — the sea as the native simulation builds it: one Simulation per cascade (patch
// sides largest first, each synthesising its own wavenumber band from its own seed, as the core's
// cascade_spectrum_params says), their displacements gathered into one buffer for the renderer and
// their normal/foam maps mipped (mips.js).
//
// Contract: create() configures the core cascade by cascade (it is left holding the last one);
// step(t) records one frame and allocates nothing on the GPU.
import { MipChain } from './mips.js';
import { Simulation, shaderText } from './simulation.js';

export const kMaxCascades = 4;  // the renderer's uniform holds four patch sides
// The sun's azimuth and elevation, degrees: ShadingParams' defaults (ocean/render.hpp).
export const kDefaultSunDeg = [35, 20];

export class Ocean {
  static async create(device, core, sea) {
    const ocean = new Ocean();
    await ocean.init(device, core, sea);
    return ocean;
  }

  async init(device, core, sea) {
    const sizes = sea.patchSizesM;
    if (sizes.length < 1 || sizes.length > kMaxCascades) {
      throw new Error(`patch = ${sizes.join(',').slice(0, 40)} must list 1 to ${kMaxCascades} ` +
                      'patch sides');
    }
    this.device = device;
    this.sea = sea;
    this.simulations = [];
    this.geometryWavelengthsM = [];  // the render fades cascade c's displacement against these
    this.foamWeights = [];  // the render weighs cascade c's foam by these (R.11)
    for (let c = 0; c < sizes.length; ++c) {
      core.configure(sea, c);
      this.geometryWavelengthsM.push(core.geometryWavelength());
      this.foamWeights.push(core.foamTerms(1)[2]);
      this.simulations.push(await Simulation.create(device, core, { ...sea, patchSizeM: sizes[c] }));
    }
    this.hsM = core.hs();  // the crests' light (R.11)
    this.unresolvedSlopeVariance = core.unresolvedSlopeVariance();  // α₀² (R.5)
    // The native renderer's sky for the sea's sun, from the library's render::Sky (R.1–R.4).
    this.sky = core.sky(...(sea.sunDeg ?? kDefaultSunDeg));
    const n = sea.resolution;
    this.n = n;
    this.texelBytes = n * n * 16;
    this.displacement = device.createBuffer({
      size: sizes.length * this.texelBytes,
      usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST | GPUBufferUsage.COPY_SRC });
    this.mips = await MipChain.create(device, await shaderText('mips.wgsl'), this.simulations);
  }

  set choppiness(lambda) {
    for (const s of this.simulations) s.choppiness = lambda;
  }

  // Records every cascade's step at time t, the gathering of the displacements and the mips.
  step(encoder, timeS) {
    this.simulations.forEach((sim, c) => {
      sim.step(encoder, timeS);
      encoder.copyBufferToBuffer(sim.displacement, 0, this.displacement, c * this.texelBytes,
                                 this.texelBytes);
    });
    this.mips.record(encoder);
  }

  destroy() {
    for (const s of this.simulations) s.destroy();
    this.displacement.destroy();
    this.mips.destroy();
  }
}
