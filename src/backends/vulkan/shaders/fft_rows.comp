#version 450
// fft_rows.comp — evolution fused into the first FFT axis: each workgroup evolves one row of one
// plane of one cascade (h̃(k, t) from the packed spectrum, times the plane's field factor) and
// transforms it along x. Dispatch (N, planes, cascades).
//
// This work is based on:
//   - Tessendorf, J. (2001) Simulating Ocean Water, eqs. 43–44 (evolution), 29 (choppy
//     displacement), 37 (slopes); Aebi, VR Ocean, eqs. 24–30 (single-FMA evolution).
// Equations: docs/math.md (M.6.5), (M.7.2), (M.7.3). Mirrors cpu::evolve and
// cpu::build_plane_factors.
#include "common.glsl"
#include "fft.glsl"

layout(std430, binding = OCEAN_BINDING_SPECTRUM) readonly buffer Spectrum { vec4 spectrum[]; };
layout(std430, binding = OCEAN_BINDING_PHASE_RATE) readonly buffer Rate { float phase_rate[]; };

// frac(x·a) with a = hi + mid + lo: x splits into two 12-bit halves so that every partial
// product with the 12-bit hi and mid is exact in FP32; frac of an exact product is exact (M.7.3).
float phase_turns(float x) {
  precise float x_hi = uintBitsToFloat(floatBitsToUint(x) & 0xFFFFF000u);
  precise float x_lo = x - x_hi;
  precise float t = fract(x_hi * params.phase_hi);
  t = fract(t + fract(x_hi * params.phase_mid));
  t = fract(t + fract(x_lo * params.phase_hi));
  t = fract(t + fract(x_lo * params.phase_mid));
  t = fract(t + fract(x * params.phase_lo));
  return t;
}

// cpu::build_plane_factors: plane p's spectrum is factor·h̃ (M.7.2).
vec2 plane_factor(uint plane, float kx, float kz) {
  const float k = sqrt(kx * kx + kz * kz);
  const float ux = k > 0.0 ? kx / k : 0.0;
  const float uz = k > 0.0 ? kz / k : 0.0;
  const float lambda = params.choppiness;
  if (params.normal_method == OCEAN_NORMALS_ANALYTIC) {
    if (plane == 0u) return vec2(1.0 - lambda * ux, 0.0);        // (h, Dx)
    if (plane == 1u) return vec2(-kx, lambda * uz);               // (Dz, ∂h/∂x)
    if (plane == 2u) return vec2(0.0, kz - lambda * kx * ux);     // (∂h/∂z, ∂Dx/∂x)
    return vec2(-lambda * kz * uz, -lambda * kz * ux);            // (∂Dz/∂z, ∂Dx/∂z)
  }
  return plane == 0u ? vec2(1.0 - lambda * ux, 0.0) : vec2(0.0, lambda * uz);
}

void main() {
  const uint row = gl_WorkGroupID.x, plane = gl_WorkGroupID.y, cascade = gl_WorkGroupID.z;
  const uint spectrum_base = cascade * N * N + row * N;
  const float dk = params.dk[cascade];
  const float kz = dk * (float(row) - float(N / 2u));
  for (uint col = gl_LocalInvocationID.x; col < N; col += gl_WorkGroupSize.x) {
    const uint i = spectrum_base + col;
    float turns = phase_turns(phase_rate[i]);
    turns = turns >= 0.5 ? turns - 1.0 : turns;
    const float phase = 6.283185307179586 * turns;
    const float c = cos(phase), s = sin(phase);
    const vec4 p = spectrum[i];
    const vec2 h = vec2(p.x * c + p.z * s, p.y * c + p.w * s);  // (M.6.5)
    const float kx = dk * (float(col) - float(N / 2u));
    line[col] = cmul(plane_factor(plane, kx, kz), h);
  }
  barrier();
  inverse_fft_shared();
  const uint out_base = (cascade * params.planes + plane) * N * N + row * N;
  for (uint col = gl_LocalInvocationID.x; col < N; col += gl_WorkGroupSize.x)
    planes[out_base + col] = line[col];
}
