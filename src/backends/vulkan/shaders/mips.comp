#version 450
// mips.comp — one level of the packed normal/foam/smoothness mip chain for every cascade: 2×2 box
// filter of the unnormalised, roughness-scaled normals, whose shrinking length becomes
// smoothness. Dispatch (size/8, size/8, cascades) per level, level 1 … log2 N.
//
// This work is based on:
//   - Aebi, VR Ocean, §3.9 and §4.4: eq. 52 (box filter), eq. 53 (length → smoothness), eq. 55
//     (contiguous mip offsets); Toksvig, M. (2005) Mipmapping normal maps, JGT 10(3).
// Equations: docs/math.md (M.7.5). Mirrors cpu::build_mips (src/backends/cpu/mips.cpp).
#include "common.glsl"

layout(local_size_x = OCEAN_TILE, local_size_y = OCEAN_TILE) in;

layout(std430, binding = OCEAN_BINDING_MIP_WORK) buffer MipWork { vec4 mip_work[]; };
layout(std430, binding = OCEAN_BINDING_PACKED) writeonly buffer Packed { uint packed_mips[]; };
layout(binding = OCEAN_BINDING_NORMAL_IMAGE, rgba8) writeonly uniform image2DArray
    normal_image[OCEAN_MAX_MIPS];

layout(push_constant) uniform Push { MipPush push; };

void main() {
  const uint col = gl_GlobalInvocationID.x, row = gl_GlobalInvocationID.y;
  const uint cascade = gl_GlobalInvocationID.z;
  const uint size = push.size;
  if (col >= size || row >= size) return;
  const uint chain = cascade * params.mip_offset[LOG2N + 1u];
  const uint src = chain + params.mip_offset[push.level - 1u];
  const uint src_size = 2u * size;
  vec4 sum = vec4(0.0);
  for (uint j = 0u; j < 2u; ++j)
    for (uint i = 0u; i < 2u; ++i) sum += mip_work[src + (2u * row + j) * src_size + 2u * col + i];
  const vec4 v = 0.25 * sum;  // eq. 52
  const uint d = chain + params.mip_offset[push.level] + row * size + col;
  mip_work[d] = v;
  const float len = length(v.xyz);
  const float smoothness = smoothness_from_normal_length(len);  // eq. 53
  const float inv = len > 0.0 ? 1.0 / len : 0.0;
  packed_mips[d] = pack_rgba8(v.x * inv, v.z * inv, v.w, smoothness);
  imageStore(normal_image[push.level], ivec3(int(col), int(row), int(cascade)),
             vec4(v.x * inv * 0.5 + 0.5, v.z * inv * 0.5 + 0.5, v.w, smoothness));
}
