// far_noise.h — the far field's gradient noise (docs/rendering.md R.13), one source for the C++
// reference (src/render/far_field.cpp) and the shaders (ocean.vert, ocean.frag). Written in the
// subset C++ and GLSL share: 32-bit uint and float scalars, `OCEAN_FN` for `inline`, `OCEAN_OUT`
// for out-parameters, `OCEAN_IN` for a struct passed in.
//
// Sources: Perlin, K. (2002) "Improving noise" (gradient noise, quintic fade 6t⁵ − 15t⁴ + 10t³);
// Quilez, I. (2017) "Gradient noise derivatives" (the analytic gradient); Jarzynski, M. & Olano,
// M. (2020) "Hash functions for GPU rendering", JCGT 9(3) (the PCG hash); VR-GIS FFT+Perlin
// (§III, step 5: octaves of one noise texture read at several step lengths, here the hashed
// gradient lattice read at frequencies in the ratio 2 : 5 : 8).
#ifndef OCEAN_FAR_NOISE_H
#define OCEAN_FAR_NOISE_H

#include "render_shared.h"

#ifdef __cplusplus
#include <cmath>
#include <cstdint>
namespace ocean::render::shader {
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

// PCG-RXS-M-XS 32-bit hash (Jarzynski & Olano 2020).
OCEAN_FN uint far_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Unit gradient of lattice point (i, j): an angle drawn uniformly from the hash.
OCEAN_FN void far_lattice_gradient(int i, int j, uint seed, OCEAN_OUT(float) gx,
                                   OCEAN_OUT(float) gz) {
  uint h = far_hash(uint(i) ^ far_hash(uint(j) + seed));
  float angle = float(h >> 8u) * (6.2831853f / 16777216.0f);
  gx = cos(angle);
  gz = sin(angle);
}

// Gradient noise of lattice spacing 1 at (x, z) and its gradient (d_x, d_z). Zero at lattice
// points; mean 0; variance and slope variance in far_field.cpp (unit_noise_moments).
OCEAN_FN float far_gradient_noise(float x, float z, uint seed, OCEAN_OUT(float) d_x,
                                  OCEAN_OUT(float) d_z) {
  float fx = floor(x), fz = floor(z);
  int i = int(fx), j = int(fz);
  float u = x - fx, v = z - fz;
  float fu = u * u * u * (u * (u * 6.0f - 15.0f) + 10.0f);  // Perlin's quintic fade
  float fv = v * v * v * (v * (v * 6.0f - 15.0f) + 10.0f);
  float dfu = 30.0f * u * u * (u * (u - 2.0f) + 1.0f);
  float dfv = 30.0f * v * v * (v * (v - 2.0f) + 1.0f);
  float ax, az, bx, bz, cx, cz, ex, ez;
  far_lattice_gradient(i, j, seed, ax, az);
  far_lattice_gradient(i + 1, j, seed, bx, bz);
  far_lattice_gradient(i, j + 1, seed, cx, cz);
  far_lattice_gradient(i + 1, j + 1, seed, ex, ez);
  float va = ax * u + az * v;
  float vb = bx * (u - 1.0f) + bz * v;
  float vc = cx * u + cz * (v - 1.0f);
  float ve = ex * (u - 1.0f) + ez * (v - 1.0f);
  float k = va - vb - vc + ve;
  d_x = ax + fu * (bx - ax) + fv * (cx - ax) + fu * fv * (ax - bx - cx + ex) +
        dfu * (vb - va + fv * k);
  d_z = az + fu * (bz - az) + fv * (cz - az) + fu * fv * (az - bz - cz + ez) +
        dfv * (vc - va + fu * k);
  return va + fu * (vb - va) + fv * (vc - va) + fu * fv * k;
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

// The far field (R.13): the sum of the three octaves with per-octave weights (wx, wy, wz).
OCEAN_FN void far_field_noise(OCEAN_IN(FarFieldUniforms) f, float x_m, float z_m, float w0,
                              float w1, float w2, OCEAN_OUT(float) h, OCEAN_OUT(float) sx,
                              OCEAN_OUT(float) sz) {
  h = 0.0f;
  sx = 0.0f;
  sz = 0.0f;
  far_octave(x_m, z_m, f.cell_m.x, f.amplitude_m.x, w0, OCEAN_FAR_SEED0, h, sx, sz);
  far_octave(x_m, z_m, f.cell_m.y, f.amplitude_m.y, w1, OCEAN_FAR_SEED1, h, sx, sz);
  far_octave(x_m, z_m, f.cell_m.z, f.amplitude_m.z, w2, OCEAN_FAR_SEED2, h, sx, sz);
}

// Seed 003's Hermite ratio (eq. 6): 0 nearer than D_min, 1 beyond D_max, −2t³ + 3t² between.
OCEAN_FN float far_ratio(OCEAN_IN(FarFieldUniforms) f, float distance_m) {
  float t = (distance_m - f.near_m) / (f.far_m - f.near_m);
  t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
  return t * t * (3.0f - 2.0f * t);
}

#ifdef __cplusplus
}  // namespace ocean::render::shader
#endif
#undef OCEAN_FN
#undef OCEAN_OUT
#undef OCEAN_IN

#endif
