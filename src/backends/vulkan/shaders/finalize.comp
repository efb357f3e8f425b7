#version 450
// finalize.comp — per texel of every cascade: displacement (float3, half4 and the RGBA16F image),
// surface gradients (central differences, Sobel or analytic), normal, Jacobian, foam with
// accumulation, and the base level of the packed RGBA8 map. Dispatch (N/8, N/8, cascades).
//
// This work is based on:
//   - Aebi, VR Ocean, §3.7–3.8: eq. 44 (displacement), eqs. 45–46 (central differences,
//     toroidal wrap), eq. 48 (Jacobian), eq. 49 (normal length), eqs. 50–51 (RGBA8).
//   - Mitchell 2005, §3.2 (Sobel normals); Vincevičius 2024, §2.3.3, eq. 2.8 (analytic slopes),
//     §2.4 (Jacobian foam and its accumulation, listing 2.4).
//   - Tessendorf, J. (2001) Simulating Ocean Water §4.4.
// Equations: docs/math.md §7. Mirrors cpu::finalize (src/backends/cpu/finalize.cpp).
#include "common.glsl"

layout(local_size_x = OCEAN_TILE, local_size_y = OCEAN_TILE) in;

layout(std430, binding = OCEAN_BINDING_PLANES) readonly buffer Planes { vec2 planes[]; };
layout(std430, binding = OCEAN_BINDING_DISPLACEMENT) writeonly buffer Disp { float disp[]; };
layout(std430, binding = OCEAN_BINDING_DISP_HALF) writeonly buffer DispHalf { uint disp_half[]; };
layout(std430, binding = OCEAN_BINDING_NORMAL) writeonly buffer Normal { float normal[]; };
layout(std430, binding = OCEAN_BINDING_JACOBIAN) writeonly buffer Jac { float jacobian_out[]; };
layout(std430, binding = OCEAN_BINDING_FOAM) buffer Foam { float foam_state[]; };
layout(std430, binding = OCEAN_BINDING_MIP_WORK) writeonly buffer MipWork { vec4 mip_work[]; };
layout(std430, binding = OCEAN_BINDING_PACKED) writeonly buffer Packed { uint packed_mips[]; };
layout(binding = OCEAN_BINDING_DISP_IMAGE, rgba16f) writeonly uniform image2DArray disp_image;
layout(binding = OCEAN_BINDING_NORMAL_IMAGE, rgba8) writeonly uniform image2DArray
    normal_image[OCEAN_MAX_MIPS];

uint plane_base(uint cascade, uint plane) { return (cascade * params.planes + plane) * N * N; }

// (Dx, h, Dz) at a wrapped texel: plane 0 = h + i·Dx, plane 1 = Dz + i·(...) (M.7.2).
vec3 displacement_at(uint cascade, int col, int row) {
  const uint i = uint(row & int(N - 1u)) * N + uint(col & int(N - 1u));
  const vec2 p0 = planes[plane_base(cascade, 0u) + i];
  return vec3(p0.y, p0.x, planes[plane_base(cascade, 1u) + i].x);
}

void main() {
  const uint col = gl_GlobalInvocationID.x, row = gl_GlobalInvocationID.y;
  const uint cascade = gl_GlobalInvocationID.z;
  if (col >= N || row >= N) return;
  const uint i = row * N + col;
  const uint texel = cascade * N * N + i;
  const int c = int(col), r = int(row);
  const vec3 d = displacement_at(cascade, c, r);

  // Displacement assembly (eq. 44): the FFT applied the sign, λ is in the spectra.
  disp[3u * texel + 0u] = d.x;
  disp[3u * texel + 1u] = d.y;
  disp[3u * texel + 2u] = d.z;
  disp_half[2u * texel + 0u] = packHalf2x16(d.xy);
  disp_half[2u * texel + 1u] = packHalf2x16(vec2(d.z, 0.0));
  imageStore(disp_image, ivec3(c, r, int(cascade)), vec4(d, 0.0));

  // Gradients ∂/∂x (gx) and ∂/∂z (gz) of (Dx, h, Dz).
  vec3 gx, gz;
  const float inv_spacing = params.inv_spacing[cascade];
  if (params.normal_method == OCEAN_NORMALS_ANALYTIC) {
    const vec2 p1 = planes[plane_base(cascade, 1u) + i];
    const vec2 p2 = planes[plane_base(cascade, 2u) + i];
    const vec2 p3 = planes[plane_base(cascade, 3u) + i];
    // ∂Dz/∂x = ∂Dx/∂z for the irrotational choppy field.
    gx = vec3(p2.y, p1.y, p3.y);
    gz = vec3(p3.y, p2.x, p3.x);
  } else if (params.normal_method == OCEAN_NORMALS_SOBEL) {
    // Smoothed central difference, weights (1, 2, 1)/8 (Sobel, Mitchell 2005, §3.2).
    gx = ((displacement_at(cascade, c + 1, r - 1) + 2.0 * displacement_at(cascade, c + 1, r) +
           displacement_at(cascade, c + 1, r + 1)) -
          (displacement_at(cascade, c - 1, r - 1) + 2.0 * displacement_at(cascade, c - 1, r) +
           displacement_at(cascade, c - 1, r + 1))) *
         0.125 * inv_spacing;
    gz = ((displacement_at(cascade, c - 1, r + 1) + 2.0 * displacement_at(cascade, c, r + 1) +
           displacement_at(cascade, c + 1, r + 1)) -
          (displacement_at(cascade, c - 1, r - 1) + 2.0 * displacement_at(cascade, c, r - 1) +
           displacement_at(cascade, c + 1, r - 1))) *
         0.125 * inv_spacing;
  } else {  // eq. 45
    gx = (displacement_at(cascade, c + 1, r) - displacement_at(cascade, c - 1, r)) * 0.5 *
         inv_spacing;
    gz = (displacement_at(cascade, c, r + 1) - displacement_at(cascade, c, r - 1)) * 0.5 *
         inv_spacing;
  }

  // Jacobian of x → x + D (eq. 48) and the normal ∂p/∂z × ∂p/∂x (M.7.5).
  const float jxx = 1.0 + gx.x, jzz = 1.0 + gz.z;
  const float jacobian = jxx * jzz - gz.x * gx.z;
  vec3 n = vec3(gz.y * gx.z - jzz * gx.y, jacobian, gz.x * gx.y - gz.y * jxx);
  const float len = length(n);
  n = len > 0.0 ? n / len : vec3(0.0, 1.0, 0.0);

  // Foam: the source on J, accumulated with Vincevičius's (2024) decay, listing 2.4 (M.7.4).
  const float x = (params.foam_threshold[cascade] - jacobian) * params.foam_gain[cascade];
  const float now = params.foam_breaking != 0u ? normal_cdf(x) : clamp(x, 0.0, 1.0);
  float foam = now;
  if (params.reset_foam == 0u) {
    const float accumulated = foam_state[texel] - params.foam_decay / max(now, 0.5);
    foam = clamp(max(accumulated, now), 0.0, 1.0);
  }
  foam_state[texel] = foam;
  jacobian_out[texel] = jacobian;
  normal[3u * texel + 0u] = n.x;
  normal[3u * texel + 1u] = n.y;
  normal[3u * texel + 2u] = n.z;

  const float blue = params.blue_is_foam != 0u ? foam : clamp(jacobian * 0.5 + 0.5, 0.0, 1.0);
  const uint chain = cascade * params.mip_offset[LOG2N + 1u];  // mip_chain_texels(N) per cascade
  mip_work[chain + i] = vec4(n * params.base_length, blue);
  packed_mips[chain + i] = pack_rgba8(n.x, n.z, blue, params.base_smoothness);
  imageStore(normal_image[0], ivec3(c, r, int(cascade)),
             vec4(n.x * 0.5 + 0.5, n.z * 0.5 + 0.5, blue, params.base_smoothness));
}
