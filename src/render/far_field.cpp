// The far field's CPU side (ocean/far_field.hpp, docs/rendering.md R.13): the distance range, the
// statistics of the band it replaces, the fit of the noise octaves, and the CPU reference of the
// noise the shaders evaluate (the noise itself is shaders/far_noise.h, shared with the GLSL).
//
// This work is based on:
//   - VR-GIS FFT+Perlin ("CUDA concurrent kernels: FFT + Perlin noise ocean for a VR-GIS
//   platform"), §III: Hermite ratio (eq. 6),
//     blend of the FFT and noise heights (eq. 7), octaves of one noise at several step lengths.
//   - Perlin, K. (2002) "Improving noise": gradient noise with the quintic fade.
//   - Olano, M. & Baker, D. (2010) "LEAN mapping": slope variances add, which is what the fit and
//     the renderer's roughness use.
#include "ocean/far_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "ocean/spectrum.hpp"
#include "shaders/far_noise.h"

namespace ocean::render {

namespace {

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
double fade_derivative(double t) { return 30.0 * t * t * (t * (t - 2.0) + 1.0); }

// What the simulation's normals make of the slope (i·kx, i·kz)·h̃ of one wave vector: the exact
// wavenumber for analytic normals, the central difference's sin(kΔ)/Δ (Aebi, VR Ocean, eq. 45),
// Sobel's smoothed difference (weights 1, 2, 1 across: a factor (1 + cos kΔ)/2). Δ the texel.
std::array<double, 2> slope_transfer(NormalMethod method, double kx, double kz, double spacing) {
  switch (method) {
    case NormalMethod::analytic: return {kx, kz};
    case NormalMethod::central_difference:
      return {std::sin(kx * spacing) / spacing, std::sin(kz * spacing) / spacing};
    case NormalMethod::sobel:
      return {std::sin(kx * spacing) / spacing * 0.5 * (1.0 + std::cos(kz * spacing)),
              std::sin(kz * spacing) / spacing * 0.5 * (1.0 + std::cos(kx * spacing))};
  }
  return {kx, kz};
}

}  // namespace

Status validate(const FarFieldRange& range) {
  if (!std::isfinite(range.near_m) || !std::isfinite(range.far_m) || range.near_m < 0.0 ||
      range.far_m < 0.0)
    return invalid_argument("far field range " + std::to_string(range.near_m) + ", " +
                            std::to_string(range.far_m) +
                            " must be finite distances >= 0 m (D_min, D_max)");
  if (range.near_m >= range.far_m)
    return invalid_argument("far field range: D_min = " + std::to_string(range.near_m) +
                            " m must be below D_max = " + std::to_string(range.far_m) + " m");
  return {};
}

double far_field_ratio(const FarFieldRange& range, double distance_m) {
  double t = (distance_m - range.near_m) / (range.far_m - range.near_m);
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);  // VR-GIS FFT+Perlin, eq. 6
}

UnitNoiseMoments unit_noise_moments() {
  // value = Σ_c W_c·(g_c·d_c), W_c the fade products, d_c the offset from corner c. With unit
  // gradients uniform in angle, E[g gᵀ] = I/2 and corners are independent, so E[value²] =
  // Σ W_c²|d_c|²/2 and E[(∂value/∂x)²] = Σ (∂W_c)²|d_c|²/2 + ∂W_c·W_c·d_c,x + W_c²/2; both
  // integrated over the cell by the midpoint rule (smooth integrands: error ~1e-5).
  constexpr int kPoints = 256;
  UnitNoiseMoments m;
  for (int a = 0; a < kPoints; ++a) {
    const double u = (a + 0.5) / kPoints;
    for (int b = 0; b < kPoints; ++b) {
      const double v = (b + 0.5) / kPoints;
      for (int corner = 0; corner < 4; ++corner) {
        const int cx = corner & 1, cz = corner >> 1;
        const double wu = cx ? fade(u) : 1.0 - fade(u);
        const double wv = cz ? fade(v) : 1.0 - fade(v);
        const double dwu = cx ? fade_derivative(u) : -fade_derivative(u);
        const double dx = u - cx, dz = v - cz;
        const double w = wu * wv, dw = dwu * wv, d2 = dx * dx + dz * dz;
        m.height_variance += w * w * d2 / 2.0;
        m.slope_variance += dw * dw * d2 / 2.0 + dw * w * dx + w * w / 2.0;
      }
    }
  }
  const double cells = static_cast<double>(kPoints) * kPoints;
  m.height_variance /= cells;
  m.slope_variance /= cells;
  return m;
}

namespace {

// Cascade 0's wave vectors (as make_initial_spectrum fills them and src/statistics sums them)
// whose |k| lies in [k_from, k_to) ∩ its band: the sums of BandStatistics.
Result<BandStatistics> band_statistics(const SimulationConfig& config, double k_from, double k_to) {
  Result<SeaState> sea = SeaState::make(config.sea);
  if (!sea.ok()) return sea.status();
  const std::array<double, 2> band = cascade_bands(config).front();
  const int n = config.resolution, half = n / 2;
  const double dk = 2.0 * std::numbers::pi / config.cascade_patch_sizes_m.front();
  const double spacing = config.cascade_patch_sizes_m.front() / n;
  BandStatistics s;
  double h2 = 0.0, s2 = 0.0;
  for (int row = 1; row < n; ++row) {
    for (int col = 1; col < n; ++col) {
      const double kx = dk * (col - half), kz = dk * (row - half);
      const double k = std::hypot(kx, kz);
      if (k <= 0.0 || k < band[0] || k >= band[1] || k < k_from || k >= k_to) continue;
      const double power = sea.value().wave_vector_spectrum(kx, kz) * dk * dk;
      const std::array<double, 2> t = slope_transfer(config.normals, kx, kz, spacing);
      const double slope_power = (t[0] * t[0] + t[1] * t[1]) * power;
      s.height_variance_m2 += power;
      s.slope_variance += slope_power;
      h2 += power * power;
      s2 += slope_power * slope_power;
    }
  }
  // A pair (k, −k) is one complex Gaussian whose |A|² (mean 2p) spreads by its mean: the
  // variance of a realisation's sum is Σ_pairs (2p)² = 2·Σ_k p².
  if (s.height_variance_m2 > 0.0)
    s.height_sampling_rel_std = std::sqrt(2.0 * h2) / s.height_variance_m2;
  if (s.slope_variance > 0.0) s.slope_sampling_rel_std = std::sqrt(2.0 * s2) / s.slope_variance;
  return s;
}

}  // namespace

Result<BandStatistics> cascade0_statistics(const SimulationConfig& config) {
  return band_statistics(config, 0.0, std::numeric_limits<double>::infinity());
}

Result<FarFieldNoise> fit_far_field_noise(const SimulationConfig& config) {
  Result<BandStatistics> target = cascade0_statistics(config);
  if (!target.ok()) return target.status();
  FarFieldNoise noise;
  noise.target = target.value();
  const UnitNoiseMoments unit = unit_noise_moments();
  // The band's wavenumbers on the grid, from the lowest (one period) to its upper edge or the
  // grid's corner, in three equal ratios: octave o stands for the waves of sub-band o.
  const int n = config.resolution;
  const double dk = 2.0 * std::numbers::pi / config.cascade_patch_sizes_m.front();
  const std::array<double, 2> band = cascade_bands(config).front();
  const double k_lo = std::max(band[0], dk);
  const double k_hi = std::min(band[1], dk * (n / 2) * std::numbers::sqrt2);
  const double step = std::cbrt(std::max(k_hi / k_lo, 1.0));
  double k_from = 0.0;
  for (std::size_t o = 0; o < 3; ++o) {
    const double k_to = o == 2 ? std::numeric_limits<double>::infinity()
                               : k_lo * std::pow(step, static_cast<double>(o + 1));
    Result<BandStatistics> sub = band_statistics(config, k_from, k_to);
    if (!sub.ok()) return sub.status();
    const double var_h = sub.value().height_variance_m2, var_s = sub.value().slope_variance;
    // One octave of spacing ℓ and amplitude a has a²G = var_h and 2a²Gs/ℓ² = var_s.
    if (var_h > 0.0 && var_s > 0.0) {
      noise.cell_m[o] =
          std::sqrt(2.0 * unit.slope_variance * var_h / (unit.height_variance * var_s));
      noise.amplitude_m[o] = std::sqrt(var_h / unit.height_variance);
      noise.slope_variance[o] = var_s;
    } else {  // an empty sub-band: an octave of zero amplitude at the sub-band's scale
      noise.cell_m[o] = std::numbers::pi / (k_lo * std::pow(step, static_cast<double>(o) + 0.5));
    }
    k_from = k_to;
  }
  return noise;
}

FarFieldSample far_field_noise(const FarFieldNoise& noise, double x_m, double z_m) {
  shader::FarFieldUniforms f{};
  f.cell_m = {static_cast<float>(noise.cell_m[0]), static_cast<float>(noise.cell_m[1]),
              static_cast<float>(noise.cell_m[2]), 0.0f};
  f.amplitude_m = {static_cast<float>(noise.amplitude_m[0]),
                   static_cast<float>(noise.amplitude_m[1]),
                   static_cast<float>(noise.amplitude_m[2]), 0.0f};
  float h = 0.0f, sx = 0.0f, sz = 0.0f;
  shader::far_field_noise(f, static_cast<float>(x_m), static_cast<float>(z_m), 1.0f, 1.0f, 1.0f, h,
                          sx, sz);
  return {.height_m = h, .slope_x = sx, .slope_z = sz};
}

}  // namespace ocean::render
