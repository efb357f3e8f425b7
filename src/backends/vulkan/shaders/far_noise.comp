#version 450
// far_noise.comp — the far field's noise map of one frame (docs/rendering.md R.13a): height and
// surface gradient of the three advected octaves at every texel of the window. Independent of
// the cascades' kernels: recorded beside the evolution and row FFT with no barrier between them.
// Dispatch (N/8, N/8, 1).
//
// This work is based on: VR-GIS FFT+Perlin, §III (noise height and normal maps computed
// concurrently with the FFT). Mirrors far_noise_map::fill_rows (src/sim/far_noise.cpp); the
// texel is far_noise_texel of src/sim/far_noise.h, one source for both.
#include "ocean_shared.h"
#include "sim/far_noise.h"

layout(local_size_x = OCEAN_TILE, local_size_y = OCEAN_TILE) in;

layout(std430, binding = OCEAN_FAR_BINDING_PARAMS) readonly buffer Params { FarNoiseMapParams far; };
layout(std430, binding = OCEAN_FAR_BINDING_MAP) writeonly buffer Map { float far_map[]; };

void main() {
  const uint col = gl_GlobalInvocationID.x, row = gl_GlobalInvocationID.y;
  const uint n = far.resolution;
  if (col >= n || row >= n) return;
  float h, sx, sz;
  far_noise_texel(far, col, row, h, sx, sz);
  const uint i = 3u * (row * n + col);
  far_map[i] = h;
  far_map[i + 1u] = sx;
  far_map[i + 2u] = sz;
}
