// fft_rows.wgsl — evolution fused into the first FFT axis: each workgroup evolves one row of one
// plane (h̃(k, t) from the packed spectrum, times the plane's field factor) and transforms it
// along x. Dispatch (N, 2). Mirrors fft_rows.comp, cpu::evolve and cpu::build_plane_factors.
//
// This work is based on:
//   - Tessendorf, J. (2001) Simulating Ocean Water, eqs. 43–44 (evolution), 29 (choppy
//     displacement); Aebi, VR Ocean, eqs. 24–30 (single-FMA evolution).
// Equations: docs/math.md (M.6.5), (M.7.2), (M.7.3).

// frac(x·a) with a = hi + mid + lo: x splits into two 12-bit halves so that every partial
// product with the 12-bit hi and mid is exact in f32; frac of an exact product is exact (M.7.3).
fn phase_turns(x: f32) -> f32 {
  let x_hi = bitcast<f32>(bitcast<u32>(x) & 0xFFFFF000u);
  let x_lo = x - x_hi;
  var t = fract(x_hi * params.phase_hi);
  t = fract(t + fract(x_hi * params.phase_mid));
  t = fract(t + fract(x_lo * params.phase_hi));
  t = fract(t + fract(x_lo * params.phase_mid));
  t = fract(t + fract(x * params.phase_lo));
  return t;
}

// (cos 2πτ, sin 2πτ) for τ ∈ [−0.5, 0.5] turns to float rounding: the built-in sin/cos of
// SwiftShader (Chromium's WebGPU without a GPU) err by ~1e-4 on [−π, π], twenty times the
// conformance bound. Quadrant reduction (exact: τ − q/4 is exact in f32), then Taylor series on
// |a| ≤ π/4, truncation errors below 2e-9.
fn cos_sin_turns(turns: f32) -> vec2f {
  let q = round(turns * 4.0);
  let a = 6.283185307179586 * (turns - 0.25 * q);
  let a2 = a * a;
  let s = a * (1.0 + a2 * (-1.0 / 6.0 + a2 * (1.0 / 120.0 + a2 * (-1.0 / 5040.0 +
          a2 * (1.0 / 362880.0)))));
  let c = 1.0 + a2 * (-0.5 + a2 * (1.0 / 24.0 + a2 * (-1.0 / 720.0 + a2 * (1.0 / 40320.0 +
          a2 * (-1.0 / 3628800.0)))));
  let quadrant = i32(q) & 3;
  if (quadrant == 0) { return vec2f(c, s); }
  if (quadrant == 1) { return vec2f(-s, c); }
  if (quadrant == 2) { return vec2f(-c, -s); }
  return vec2f(s, -c);
}

// cpu::build_plane_factors (central-difference normals): plane 0 = (h, Dx), plane 1 = (Dz, –).
fn plane_factor(plane: u32, kx: f32, kz: f32) -> vec2f {
  let k = sqrt(kx * kx + kz * kz);
  let ux = select(0.0, kx / k, k > 0.0);
  let uz = select(0.0, kz / k, k > 0.0);
  let lambda = params.choppiness;
  return select(vec2f(0.0, lambda * uz), vec2f(1.0 - lambda * ux, 0.0), plane == 0u);
}

@compute @workgroup_size(WG)
fn main(@builtin(workgroup_id) group: vec3u, @builtin(local_invocation_id) local: vec3u) {
  let row = group.x;
  let plane = group.y;
  let kz = params.dk * (f32(row) - f32(N / 2u));
  for (var col = local.x; col < N; col += WG) {
    let i = row * N + col;
    var turns = phase_turns(phase_rate[i]);
    turns = select(turns, turns - 1.0, turns >= 0.5);
    let cs = cos_sin_turns(turns);
    let p = spectrum[i];
    let h = vec2f(p.x * cs.x + p.z * cs.y, p.y * cs.x + p.w * cs.y);  // (M.6.5)
    let kx = params.dk * (f32(col) - f32(N / 2u));
    line[col] = cmul(plane_factor(plane, kx, kz), h);
  }
  workgroupBarrier();
  inverse_fft_shared(local.x);
  let base = plane * N * N + row * N;
  for (var col = local.x; col < N; col += WG) {
    planes[base + col] = line[col];
  }
}
