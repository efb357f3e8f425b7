#version 450
// far_map.comp — the far field's noise map as the renderer samples it (docs/rendering.md R.13b):
// the frame's float3 (h, ∂h/∂x, ∂h/∂z) per texel (Frame::far_noise's array, uploaded, or the
// Vulkan backend's buffer where it lies), less the octaves whose cells span fewer than four
// texels (point samples of those alias; the per-pixel noise draws them instead), into level 0 of
// an RGBA16F image with the squared slope in alpha, the second moment whose mean over a mip's
// texels keeps the slope variance the averaging removes (LEAN mapping, Olano & Baker 2010). The
// octaves removed are far_noise_texel of src/sim/far_noise.h — the arithmetic that made the map —
// with the kept octaves' amplitudes 0, so they cancel to rounding. The coarser levels are blits
// (2×2 means). Dispatch (⌈N/8⌉, ⌈N/8⌉, 1).
#include "render_shared.h"
#include "sim/far_noise.h"

layout(local_size_x = OCEAN_RENDER_FAR_TILE, local_size_y = OCEAN_RENDER_FAR_TILE) in;

layout(std430, binding = OCEAN_RENDER_FAR_BINDING_SOURCE) readonly buffer Source { float map[]; };
layout(binding = OCEAN_RENDER_FAR_BINDING_IMAGE, rgba16f) writeonly uniform image2DArray level0;
layout(push_constant) uniform Push { FarNoiseMapParams removed; } push;

void main() {
  const uvec2 t = gl_GlobalInvocationID.xy;
  const uint n = push.removed.resolution;
  if (t.x >= n || t.y >= n) return;
  const uint i = 3u * (t.y * n + t.x);
  float rh, rsx, rsz;
  far_noise_texel(push.removed, t.x, t.y, rh, rsx, rsz);
  const float h = map[i] - rh, sx = map[i + 1u] - rsx, sz = map[i + 2u] - rsz;
  imageStore(level0, ivec3(t, 0), vec4(h, sx, sz, sx * sx + sz * sz));
}
