// common.wgsl — declarations shared by the compute kernels. The host prepends
// `const N: u32 = …; const LOG2N: u32 = …;` (the resolution). Every helper names the C++ or GLSL
// function it mirrors; web/tests/conformance.test.mjs compares the result with the CPU reference.

// Everything the kernels read besides the data arrays (web/src/simulation.js writes it).
struct Params {
  // The phase turns = frac(rate·a), a = phase_hi + phase_mid + phase_lo split so that every
  // partial product is exact in f32 (M.7.3; vk split_phase).
  phase_hi: f32,
  phase_mid: f32,
  phase_lo: f32,
  choppiness: f32,   // λ
  dk: f32,           // 2π/L, rad/m
  inv_spacing: f32,  // N/L, 1/m
  foam_decay: f32,   // decay_per_s·dt
  reset_foam: u32,   // 1 on the first step or after a jump back in time
  j_threshold: f32,  // breaking foam source (M.7.4): Φ((J_thr − J)·gain)
  j_gain: f32,
  pad0: f32,
  pad1: f32,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> spectrum: array<vec4f>;     // packed S' (M.6.5)
@group(0) @binding(2) var<storage, read> phase_rate: array<f32>;     // harmonic j, or ω/2π
@group(0) @binding(3) var<storage, read> twiddle: array<vec2f>;      // e^{+2πi·t/N}
@group(0) @binding(4) var<storage, read_write> planes: array<vec2f>; // 2 planes of N²
@group(0) @binding(5) var<storage, read_write> displacement: array<vec4f>; // (Dx, h, Dz, 0)
@group(0) @binding(6) var<storage, read_write> surface: array<vec4f>;      // (n, J)
@group(0) @binding(7) var<storage, read_write> foam: array<f32>;           // accumulated foam

const WG: u32 = max(N / 4u, 1u);  // threads per line of the FFT kernels

// Φ(x), the standard normal distribution function, as ½·erfc(−x/√2) by Abramowitz & Stegun,
// Handbook of Mathematical Functions, eq. 7.1.26 (packing::normal_cdf; |error| ≤ 1.5·10⁻⁷, the
// argument capped at 10.5).
fn normal_cdf(x: f32) -> f32 {
  let z = min(abs(x) * 0.70710678, 10.5);
  let t = 1.0 / (1.0 + 0.3275911 * z);
  let poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 +
             t * 1.061405429))));
  let tail = 0.5 * poly * exp(-z * z);
  return select(1.0 - tail, tail, x < 0.0);
}

fn cmul(a: vec2f, b: vec2f) -> vec2f {
  return vec2f(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}
