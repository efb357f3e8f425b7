// fallback.js — the page without WebGPU: the library's CPU backend compiled to WebAssembly (the
// core's reference pipeline: evolution, radix-2 FFT, finalize) steps one full-band patch, and a 2D
// canvas shows it from above, shaded by its normals and foam and tinted by its heights.
//
// Contract: draw(t) steps the core to time t (foam accumulated since the previous draw) and paints
// the canvas; it allocates one ImageData per call.
const kSun = [0.55, 0.3, -0.78];

export class CpuView {
  // sea as main.js builds it; the patch is the list's first side, synthesised over its full band.
  constructor(core, sea, canvas) {
    this.core = core;
    this.sea = { ...sea, patchSizesM: [sea.patchSizesM[0]] };
    core.configure(this.sea);
    this.n = sea.resolution;
    this.canvas = canvas;
    this.context = canvas.getContext('2d');
    this.tile = document.createElement('canvas');
    this.tile.width = this.tile.height = this.n;
    this.lastTime = null;
    this.choppiness = 1;
  }

  draw(timeS) {
    const reset = this.lastTime === null || timeS < this.lastTime;
    const dt = reset ? 0 : timeS - this.lastTime;
    this.lastTime = timeS;
    const { displacement, surface, foam } =
      this.core.reference(timeS, this.choppiness, dt, reset);
    const texels = this.n * this.n;
    let variance = 0;
    for (let i = 0; i < texels; ++i) variance += displacement[3 * i + 1] ** 2 / texels;
    const scale = 1 / Math.max(2 * Math.sqrt(variance), 1e-6);  // heights in units of 2σ
    const l = Math.hypot(...kSun);
    const image = new ImageData(this.n, this.n);
    for (let i = 0; i < texels; ++i) {
      const lit = Math.max(0, (surface[4 * i] * kSun[0] + surface[4 * i + 1] * kSun[1] +
                               surface[4 * i + 2] * kSun[2]) / l);
      const h = Math.max(-1, Math.min(1, displacement[3 * i + 1] * scale));
      const f = foam[i];
      const base = [10 + 40 * lit + 25 * h, 50 + 80 * lit + 30 * h, 90 + 90 * lit + 30 * h];
      for (let c = 0; c < 3; ++c) image.data[4 * i + c] = base[c] * (1 - f) + 235 * f;
      image.data[4 * i + 3] = 255;
    }
    this.tile.getContext('2d').putImageData(image, 0, 0);
    // The patch is periodic: tile it across the canvas, square, the canvas's height per patch.
    const { width, height } = this.canvas;
    this.context.imageSmoothingEnabled = true;
    for (let x = 0; x < width; x += height) this.context.drawImage(this.tile, x, 0, height, height);
  }
}
