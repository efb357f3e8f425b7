// far_noise.h — the far field's gradient noise (docs/rendering.md R.13) and its per-frame map
// (R.13a), one source for the C++ reference (src/sim/far_noise.cpp), the CPU backend's noise task,
// the Vulkan backend's noise kernel (src/backends/vulkan/shaders/far_noise.comp) and the
// renderer's shaders (through src/render/shaders/far_noise.h), and the CUDA backend's noise kernel
// (src/backends/cuda/far_noise.cu). Written in the subset C++, CUDA and GLSL share: 32-bit uint,
// int and float scalars, `OCEAN_FN` for `inline` (`__device__ inline` under nvcc), `OCEAN_OUT` for
// out-parameters, `OCEAN_IN` for a struct passed in; structs of 32-bit scalars only, so that
// their std430 layout equals the C++ one.
//
// Sources: Perlin, K. (2002) "Improving noise" (gradient noise, quintic fade 6t⁵ − 15t⁴ + 10t³);
// Quilez, I. (2017) "Gradient noise derivatives" (the analytic gradient); Jarzynski, M. & Olano,
// M. (2020) "Hash functions for GPU rendering", JCGT 9(3) (the PCG hash); VR-GIS FFT+Perlin
// (§III, step 5: octaves of one noise texture read at several step lengths, here the hashed
// gradient lattice read at three fitted spacings).
#ifndef OCEAN_SIM_FAR_NOISE_H
#define OCEAN_SIM_FAR_NOISE_H

#if defined(__CUDACC__)
// CUDA: device functions. floor, cos and sin are CUDA's float overloads (floorf, cosf, sinf: the
// accurate functions, 2 ulp, not the __cosf intrinsics; the backend builds without
// --use_fast_math and with --fmad=false, so no product is fused into an addition, as on the CPU).
#include <cstdint>
namespace ocean::noise {
using uint = std::uint32_t;
#define OCEAN_FN __device__ inline
#define OCEAN_OUT(T) T&
#define OCEAN_IN(T) const T&
#elif defined(__cplusplus)
#include <cmath>
#include <cstdint>
namespace ocean::noise {
using uint = std::uint32_t;
using std::cos;
using std::floor;
using std::sin;
#define OCEAN_FN inline
#define OCEAN_OUT(T) T&
#define OCEAN_IN(T) const T&
#else
#define OCEAN_FN
#define OCEAN_OUT(T) out T
#define OCEAN_IN(T) T
#endif

// Seeds of the three octaves: independent lattices, so the octaves' cross terms average out.
#define OCEAN_FAR_SEED0 0x68e31da4u
#define OCEAN_FAR_SEED1 0xb5297a4du
#define OCEAN_FAR_SEED2 0x1b56c4e9u
#define OCEAN_FAR_OCTAVES 3

// PCG-RXS-M-XS 32-bit hash (Jarzynski & Olano 2020).
OCEAN_FN uint far_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Unit gradient of lattice point (i, j) (as 32-bit words: index arithmetic wraps modulo 2³²): an
// angle drawn uniformly from the hash.
OCEAN_FN void far_lattice_gradient(uint i, uint j, uint seed, OCEAN_OUT(float) gx,
                                   OCEAN_OUT(float) gz) {
  uint h = far_hash(i ^ far_hash(j + seed));
  float angle = float(h >> 8u) * (6.2831853f / 16777216.0f);
  gx = cos(angle);
  gz = sin(angle);
}

// The unit gradients at the four corners of a lattice cell (i, j): a at (i, j), b at (i + 1, j),
// c at (i, j + 1), e at (i + 1, j + 1).
struct FarCell {
  float ax, az, bx, bz, cx, cz, ex, ez;
};

OCEAN_FN FarCell far_cell(uint i, uint j, uint seed) {
  FarCell g;
  far_lattice_gradient(i, j, seed, g.ax, g.az);
  far_lattice_gradient(i + 1u, j, seed, g.bx, g.bz);
  far_lattice_gradient(i, j + 1u, seed, g.cx, g.cz);
  far_lattice_gradient(i + 1u, j + 1u, seed, g.ex, g.ez);
  return g;
}

// Gradient noise at (u, v) ∈ [0, 1)² inside a cell with corner gradients g, and its gradient
// (d_x, d_z).
OCEAN_FN float far_cell_noise(float u, float v, OCEAN_IN(FarCell) g, OCEAN_OUT(float) d_x,
                              OCEAN_OUT(float) d_z) {
  float fu = u * u * u * (u * (u * 6.0f - 15.0f) + 10.0f);  // Perlin's quintic fade
  float fv = v * v * v * (v * (v * 6.0f - 15.0f) + 10.0f);
  float dfu = 30.0f * u * u * (u * (u - 2.0f) + 1.0f);
  float dfv = 30.0f * v * v * (v * (v - 2.0f) + 1.0f);
  float va = g.ax * u + g.az * v;
  float vb = g.bx * (u - 1.0f) + g.bz * v;
  float vc = g.cx * u + g.cz * (v - 1.0f);
  float ve = g.ex * (u - 1.0f) + g.ez * (v - 1.0f);
  float k = va - vb - vc + ve;
  d_x = g.ax + fu * (g.bx - g.ax) + fv * (g.cx - g.ax) + fu * fv * (g.ax - g.bx - g.cx + g.ex) +
        dfu * (vb - va + fv * k);
  d_z = g.az + fu * (g.bz - g.az) + fv * (g.cz - g.az) + fu * fv * (g.az - g.bz - g.cz + g.ez) +
        dfv * (vc - va + fu * k);
  return va + fu * (vb - va) + fv * (vc - va) + fu * fv * k;
}

// Gradient noise of lattice spacing 1 at lattice point (shift_i, shift_j) + (x, z) and its
// gradient (d_x, d_z): the integer shift keeps a far-travelled point exact in single precision.
// Zero at lattice points; mean 0; variance and slope variance in src/sim/far_noise.cpp
// (unit_noise_moments).
OCEAN_FN float far_gradient_noise_shifted(float x, float z, uint shift_i, uint shift_j, uint seed,
                                          OCEAN_OUT(float) d_x, OCEAN_OUT(float) d_z) {
  float fx = floor(x), fz = floor(z);
  uint i = uint(int(fx)) + shift_i, j = uint(int(fz)) + shift_j;
  return far_cell_noise(x - fx, z - fz, far_cell(i, j, seed), d_x, d_z);
}

// Gradient noise of lattice spacing 1 at (x, z) (no shift).
OCEAN_FN float far_gradient_noise(float x, float z, uint seed, OCEAN_OUT(float) d_x,
                                  OCEAN_OUT(float) d_z) {
  return far_gradient_noise_shifted(x, z, 0u, 0u, seed, d_x, d_z);
}

// One octave: amplitude a, lattice spacing s (m); weight w scales it (the mesh's or the pixel's
// fade, 1 for the full field). Adds the height and the surface gradient to h, sx, sz.
OCEAN_FN void far_octave(float x_m, float z_m, float s, float a, float w, uint seed,
                         OCEAN_OUT(float) h, OCEAN_OUT(float) sx, OCEAN_OUT(float) sz) {
  float gx, gz;
  float g = far_gradient_noise(x_m / s, z_m / s, seed, gx, gz);
  h += w * a * g;
  sx += w * a / s * gx;
  sz += w * a / s * gz;
}

// The per-frame noise map (R.13a): octave o read on the map's texel grid. Texel (col, row) lies at
// lattice point (shift_u, shift_v) + (origin_u + col·step, origin_v + row·step) of the octave: the
// host splits the world position of texel (0, 0), advected by the octave's phase speed, into the
// whole lattice cells (shift, wrapping modulo 2³²) and the rest (origin, in [0, 1)).
struct FarNoiseOctave {
  float origin_u;     // lattice coordinate of texel (0, 0), fractional part, along x
  float origin_v;     // the same along z
  uint shift_u;       // whole lattice cells of texel (0, 0) along x (two's complement)
  uint shift_v;       // the same along z
  float step;         // texel spacing in lattice cells, Δ/s
  float amplitude_m;  // a
  float inv_cell;     // 1/s, 1/m
  uint seed;          // OCEAN_FAR_SEED0 … 2
};

struct FarNoiseMapParams {
  FarNoiseOctave octave[OCEAN_FAR_OCTAVES];
  uint resolution;  // N texels per side
  uint map_pad0;
  uint map_pad1;
  uint map_pad2;
};

// Height (m) and surface gradient (∂h/∂x, ∂h/∂z) of the map's texel (col, row): the sum of the
// octaves.
OCEAN_FN void far_noise_texel(OCEAN_IN(FarNoiseMapParams) p, uint col, uint row, OCEAN_OUT(float) h,
                              OCEAN_OUT(float) sx, OCEAN_OUT(float) sz) {
  h = 0.0f;
  sx = 0.0f;
  sz = 0.0f;
  for (int o = 0; o < OCEAN_FAR_OCTAVES; ++o) {
    float gx, gz;
    float u = p.octave[o].origin_u + float(col) * p.octave[o].step;
    float v = p.octave[o].origin_v + float(row) * p.octave[o].step;
    float g = far_gradient_noise_shifted(u, v, p.octave[o].shift_u, p.octave[o].shift_v,
                                         p.octave[o].seed, gx, gz);
    float a = p.octave[o].amplitude_m;
    h += a * g;
    sx += a * p.octave[o].inv_cell * gx;
    sz += a * p.octave[o].inv_cell * gz;
  }
}

#ifdef __cplusplus
}  // namespace ocean::noise
#endif
#undef OCEAN_FN
#undef OCEAN_OUT
#undef OCEAN_IN

#endif
