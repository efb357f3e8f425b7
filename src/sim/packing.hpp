// The per-texel surface formulas every consumer of the displacement shares (docs/math.md M.7.4,
// M.7.5; Aebi, VR Ocean, eqs. 48–53): the Jacobian and normal of the displaced surface from its
// gradients, the foam ramp and accumulation, and the RGBA8 packing. The CPU backend's finalize,
// apply_band_roles and the local surface (local_surface.cpp) use these, so a texel means the same
// thing wherever it is computed. Private to src/.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace ocean::packing {

/// Roughness → normal length (Aebi, VR Ocean, eq. 49).
float normal_length_from_roughness(float roughness);
/// Normal length → smoothness (Aebi, VR Ocean, eq. 53).
float smoothness_from_normal_length(float length);
/// RGBA8 packing of Aebi, VR Ocean, eqs. 50–51, from a unit normal, blue value and smoothness.
std::uint32_t pack_rgba8(float nx, float nz, float blue, float smoothness);

/// ∂/∂x and ∂/∂z of (Dx, h, Dz), world units.
struct Gradients {
  float dx_dx, h_dx, dz_dx, dx_dz, h_dz, dz_dz;
};

/// The Jacobian (eq. 48) and unit normal (M.7.5) of the displaced surface at a point.
struct SurfacePoint {
  float jacobian;
  std::array<float, 3> normal;
};
inline SurfacePoint surface_point(const Gradients& g) {
  // Jacobian of the horizontal map x → x + D (eq. 48).
  const float jxx = 1.0f + g.dx_dx, jzz = 1.0f + g.dz_dz;
  const float jacobian = jxx * jzz - g.dx_dz * g.dz_dx;
  // Normal of the displaced surface: ∂p/∂z × ∂p/∂x (M.7.5; eq. 47 when λ = 0).
  float nx = g.h_dz * g.dz_dx - jzz * g.h_dx;
  float ny = jacobian;
  float nz = g.dx_dz * g.h_dx - g.h_dz * jxx;
  const float length = std::sqrt(nx * nx + ny * ny + nz * nz);
  if (length > 0.0f) {
    nx /= length, ny /= length, nz /= length;
  } else {
    nx = 0.0f, ny = 1.0f, nz = 0.0f;
  }
  return {jacobian, {nx, ny, nz}};
}

/// The foam ramp on J and its accumulation (M.7.4; Vincevičius 2024, listing 2.4): `previous`
/// the foam of the last frame, `decay` decay_per_s·Δt, `j_range` J_start − J_full.
inline float accumulate_foam(float jacobian, float previous, bool reset, float j_start,
                             float j_range, float decay) {
  const float now = std::clamp((j_start - jacobian) / j_range, 0.0f, 1.0f);
  if (reset) return now;
  const float accumulated = previous - decay / std::max(now, 0.5f);
  return std::clamp(std::max(accumulated, now), 0.0f, 1.0f);
}

}  // namespace ocean::packing
