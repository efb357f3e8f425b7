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

#include "ocean/plan.hpp"

namespace ocean::packing {

/// Roughness → normal length (Aebi, VR Ocean, eq. 49).
float normal_length_from_roughness(float roughness);
/// Normal length → smoothness (Aebi, VR Ocean, eq. 53).
float smoothness_from_normal_length(float length);
/// Smoothness → normal length: eq. 53 inverted, (1 − t)(1 + 0.15·t) = (1 − s)², |n| = (t + 2)/3
/// (the shaders' stored_normal_length, R.5).
float normal_length_from_smoothness(float smoothness);
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

/// The coefficients of erfc(z) ≈ t·(a1 + t·(a2 + … + t·a5))·e^{−z²}, t = 1/(1 + p·z), z ≥ 0,
/// |error| ≤ 1.5·10⁻⁷ (Abramowitz & Stegun, Handbook of Mathematical Functions, eq. 7.1.26).
/// The Vulkan and CUDA kernels use the same constants (ocean_shared.h, kernels.cu).
inline constexpr float kErfcP = 0.3275911f;
inline constexpr std::array<float, 5> kErfcA{0.254829592f, -0.284496736f, 1.421413741f,
                                             -1.453152027f, 1.061405429f};
/// z beyond which e^{−z²} < 10⁻⁴⁷, 0 in float (denormals included): the argument is capped there,
/// so that a gain of 10⁹ (FoamSourceTerms when the rest of the sea has no slope) stays finite
/// throughout.
inline constexpr float kErfcZMax = 10.5f;

/// Φ(x), the standard normal distribution function: ½·erfc(−x/√2) by eq. 7.1.26.
inline float normal_cdf(float x) {
  const float z = std::min(std::fabs(x) * 0.70710678f, kErfcZMax);
  const float t = 1.0f / (1.0f + kErfcP * z);
  const float poly =
      t * (kErfcA[0] + t * (kErfcA[1] + t * (kErfcA[2] + t * (kErfcA[3] + t * kErfcA[4]))));
  const float tail = 0.5f * poly * std::exp(-z * z);  // Φ(−|x|)
  return x < 0.0f ? tail : 1.0f - tail;
}

/// A foam source's terms as the kernels read them (FoamSourceTerms, FoamSource).
struct FoamTerms {
  float threshold = 0.8f;
  float gain = 1.0f / 0.3f;
  bool breaking = false;  ///< Φ((threshold − J)·gain); false: clamp((threshold − J)·gain, 0, 1)
};

/// The kernels' terms of a plan's source (SimulationPlan::foam): for the ramp `terms` is not read,
/// its J_start − J_full inverted in float as every backend does.
inline FoamTerms foam_terms(const FoamParams& params, const FoamSourceTerms& terms) {
  if (params.source == FoamSource::ramp) {
    return {static_cast<float>(params.jacobian_start),
            1.0f / static_cast<float>(params.jacobian_start - params.jacobian_full), false};
  }
  return {static_cast<float>(terms.threshold), static_cast<float>(terms.gain), true};
}

/// The foam a texel of Jacobian J makes this frame (M.7.4).
inline float foam_source(float jacobian, const FoamTerms& t) {
  const float x = (t.threshold - jacobian) * t.gain;
  return t.breaking ? normal_cdf(x) : std::clamp(x, 0.0f, 1.0f);
}

/// The foam's accumulation (M.7.4; Vincevičius 2024, listing 2.4): `now` the source of this
/// frame, `previous` the foam of the last frame, `decay` decay_per_s·Δt.
inline float accumulate_foam(float now, float previous, bool reset, float decay) {
  if (reset) return now;
  const float accumulated = previous - decay / std::max(now, 0.5f);
  return std::clamp(std::max(accumulated, now), 0.0f, 1.0f);
}

}  // namespace ocean::packing
