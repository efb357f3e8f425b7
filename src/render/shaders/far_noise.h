// far_noise.h — the renderer's side of the far field's noise (docs/rendering.md R.13, R.13b): the
// sum of the three fitted octaves read through the uniforms on the lattice the CPU places at the
// frame's origin and time, and the VR-GIS paper's Hermite ratio. The noise
// itself (hash, gradient lattice, one octave) is src/sim/far_noise.h, one source for the C++
// reference (src/sim/far_noise.cpp), the simulation backends' noise maps and these shaders
// (ocean.vert, ocean.frag). Written in the subset C++ and GLSL share, as that header.
#ifndef OCEAN_RENDER_FAR_NOISE_H
#define OCEAN_RENDER_FAR_NOISE_H

#include "sim/far_noise.h"
#include "render_shared.h"

#ifdef __cplusplus
namespace ocean::render::shader {
using noise::far_gradient_noise_shifted;
#define OCEAN_FN inline
#define OCEAN_OUT(T) T&
#define OCEAN_IN(T) const T&
#else
#define OCEAN_FN
#define OCEAN_OUT(T) out T
#define OCEAN_IN(T) T
#endif

// One octave at (x, z) relative to the frame's origin O, read on the lattice `o` places there at
// the frame's time (R.13b): the map's texel arithmetic (far_noise_texel) with x/s in place of
// col·Δ/s, so the two read the same field. Weight w scales it (the mesh's or the pixel's fade).
OCEAN_FN void far_octave_at(OCEAN_IN(FarOctaveUniforms) o, float x_m, float z_m, float s, float a,
                            float w, uint seed, OCEAN_OUT(float) h, OCEAN_OUT(float) sx,
                            OCEAN_OUT(float) sz) {
  float gx, gz;
  float g = far_gradient_noise_shifted(o.rest_u + x_m / s, o.rest_v + z_m / s, o.cells_u, o.cells_v,
                                       seed, gx, gz);
  h += w * a * g;
  sx += w * a / s * gx;
  sz += w * a / s * gz;
}

// The far field (R.13, moving as R.13a): the sum of the three octaves at (x, z) relative to O,
// with per-octave weights (w0, w1, w2).
OCEAN_FN void far_field_noise(OCEAN_IN(FarFieldUniforms) f, OCEAN_IN(FarOctaveUniforms) o0,
                              OCEAN_IN(FarOctaveUniforms) o1, OCEAN_IN(FarOctaveUniforms) o2,
                              float x_m, float z_m, float w0, float w1, float w2,
                              OCEAN_OUT(float) h, OCEAN_OUT(float) sx, OCEAN_OUT(float) sz) {
  h = 0.0f;
  sx = 0.0f;
  sz = 0.0f;
  far_octave_at(o0, x_m, z_m, f.cell_m.x, f.amplitude_m.x, w0, OCEAN_FAR_SEED0, h, sx, sz);
  far_octave_at(o1, x_m, z_m, f.cell_m.y, f.amplitude_m.y, w1, OCEAN_FAR_SEED1, h, sx, sz);
  far_octave_at(o2, x_m, z_m, f.cell_m.z, f.amplitude_m.z, w2, OCEAN_FAR_SEED2, h, sx, sz);
}

// The VR-GIS paper's Hermite ratio (eq. 6): 0 nearer than D_min, 1 beyond D_max, −2t³ + 3t² between.
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
