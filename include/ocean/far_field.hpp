// ocean/far_field.hpp — the sea beyond the simulation's tiles (docs/rendering.md R.13–R.14): seed
// 003's far field, three octaves of gradient noise blended with the FFT field by a Hermite ratio
// of the distance (VR-GIS FFT+Perlin, eqs. 6–7), its octaves fitted so that its height variance and
// mean-square slope equal those of the band it replaces (cascade 0, the one whose period shows
// from afar). The renderer (ocean/render.hpp) evaluates it in its shaders; this is the CPU
// reference they mirror (one source: src/render/shaders/far_noise.h) and what the statistics
// tests measure.
//
// Contract: plain functions, no allocation beyond the returned values, thread-safe.
#pragma once

#include <array>

#include "ocean/core.hpp"
#include "ocean/sim.hpp"

namespace ocean::render {

/// Where the far field takes over: VR-GIS FFT+Perlin's D_min and D_max, distances from the camera
/// to the undisplaced sea point, m. Nearer than near_m the picture is the simulation alone (what
/// height queries, wakes and floating objects see); beyond far_m it is the far field alone.
struct FarFieldRange {
  double near_m = 1000.0;  ///< D_min, finite, ≥ 0
  double far_m = 2500.0;   ///< D_max, finite, > near_m
};
/// invalid_argument for a negative or non-finite distance, or near_m ≥ far_m (one line).
Status validate(const FarFieldRange& range);
/// Seed 003's eq. 6: 0 up to near_m, 1 from far_m, the Hermite step −2t³ + 3t² between.
double far_field_ratio(const FarFieldRange& range, double distance_m);

/// Variance and per-axis slope variance of gradient noise of lattice spacing 1 with unit
/// gradients drawn uniformly in angle (the expectations over the gradients, integrated over the
/// cell by quadrature: exact up to the quadrature's ~1e-5).
struct UnitNoiseMoments {
  double height_variance = 0.0;  ///< E[g²]
  double slope_variance = 0.0;   ///< E[(∂g/∂x)²] = E[(∂g/∂z)²]
};
UnitNoiseMoments unit_noise_moments();

/// What the FFT carries in a band of wavenumbers and what the noise must match.
struct BandStatistics {
  double height_variance_m2 = 0.0;  ///< Σ F(k)·Δk² over the band's wave vectors
  /// Σ |k'|²·F(k)·Δk²: the mean-square slope σx² + σz² of the simulation's normals, k' the
  /// wave vector as the configured normal method differentiates it (|k| for analytic normals,
  /// sin(kΔ)/Δ per axis for central differences, Sobel's smoothed form; Δ the texel).
  double slope_variance = 0.0;
  /// Relative standard deviation of one realisation's (one seed's) measured height variance and
  /// mean-square slope about the two sums above (few wave vectors near the peak: large).
  double height_sampling_rel_std = 0.0;
  double slope_sampling_rel_std = 0.0;
};
/// The statistics of cascade 0 of `config`: its grid's wave vectors inside its band
/// (cascade_bands), the spectrum F of its sea state. Errors of SeaState::make.
Result<BandStatistics> cascade0_statistics(const SimulationConfig& config);

/// The fitted noise: octave o has lattice spacing cell_m[o] and amplitude amplitude_m[o].
/// Octave o stands for sub-band o of cascade 0's band (its grid wavenumbers from one period to
/// the band's upper edge, split in three equal ratios): its amplitude and spacing are solved so
/// that its height variance and mean-square slope equal the sub-band's, so the octaves' sums
/// equal `target` exactly and each scale keeps its share (docs/rendering.md R.13).
struct FarFieldNoise {
  std::array<double, 3> cell_m{};
  std::array<double, 3> amplitude_m{};
  std::array<double, 3> slope_variance{};  ///< σx² + σz² of each octave
  BandStatistics target;
};
/// Fits the noise to cascade 0's statistics. A flat sea gives zero amplitudes.
Result<FarFieldNoise> fit_far_field_noise(const SimulationConfig& config);

/// The far field's height, m, and surface gradient (∂h/∂x, ∂h/∂z) at a world point (x, z): the
/// full field (every octave weight 1), in single precision exactly as the shaders compute it.
struct FarFieldSample {
  double height_m = 0.0;
  double slope_x = 0.0;
  double slope_z = 0.0;
};
FarFieldSample far_field_noise(const FarFieldNoise& noise, double x_m, double z_m);

}  // namespace ocean::render
