// ocean/far_noise.hpp — the far field's noise (docs/rendering.md R.13, R.13a): the
// gradient-noise octaves of [VR-GIS FFT+Perlin] fitted so that their height variance and
// mean-square slope equal those of the band they replace (cascade 0, the one whose period shows
// from afar), each octave advected at the mean phase velocity of that band's waves. The renderer
// evaluates the noise in its shaders (ocean/far_field.hpp); the backends compute it as a per-frame
// map (SimulationConfig::far_noise, Frame::far_noise: the CPU, Vulkan and CUDA backends). This is
// the CPU reference they mirror (one source: src/sim/far_noise.h) and what the statistics tests
// measure.
//
// Contract: plain functions, no allocation beyond the returned values, thread-safe.
#pragma once

#include <array>
#include <cstdint>

#include "ocean/core.hpp"
#include "ocean/sim.hpp"

namespace ocean {

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
  /// The band's mean phase velocity weighted by energy, Σ c(|k|)·k̂·F(k)Δk² / Σ F(k)Δk², m/s
  /// (x, z), c = ω/k of the sea's dispersion (R.13a): how fast and where its crests travel.
  std::array<double, 2> phase_velocity_mps{};
};
/// The statistics of cascade 0 of `config`: its grid's wave vectors inside its band
/// (cascade_bands), the spectrum F of its sea state. Errors of SeaState::make.
Result<BandStatistics> cascade0_statistics(const SimulationConfig& config);

/// The fitted noise: octave o has lattice spacing cell_m[o] and amplitude amplitude_m[o].
/// Octave o stands for sub-band o of cascade 0's band (its grid wavenumbers from one period to
/// the band's upper edge, split in three equal ratios): its amplitude and spacing are solved so
/// that its height variance and mean-square slope equal the sub-band's, so the octaves' sums
/// equal `target` exactly and each scale keeps its share (docs/rendering.md R.13). Octave o moves
/// at velocity_mps[o], the sub-band's mean phase velocity (R.13a).
struct FarFieldNoise {
  std::array<double, 3> cell_m{};
  std::array<double, 3> amplitude_m{};
  std::array<double, 3> slope_variance{};               ///< σx² + σz² of each octave
  std::array<std::array<double, 2>, 3> velocity_mps{};  ///< (x, z) drift of each octave, m/s
  BandStatistics target;
};
/// Fits the noise to cascade 0's statistics. A flat sea gives zero amplitudes. Errors of
/// SeaState::make.
Result<FarFieldNoise> fit_far_field_noise(const SimulationConfig& config);
/// The same fit for the sea state already made from config.sea (SimulationPlan::far_noise).
FarFieldNoise fit_far_field_noise(const SeaState& sea, const SimulationConfig& config);

/// The far field's height, m, and surface gradient (∂h/∂x, ∂h/∂z) at a world point (x, z).
struct FarFieldSample {
  double height_m = 0.0;
  double slope_x = 0.0;
  double slope_z = 0.0;
};
/// The static field (every octave weight 1), in single precision exactly as the renderer's
/// shaders compute it (R.13).
FarFieldSample far_field_noise(const FarFieldNoise& noise, double x_m, double z_m);
/// The field at time t (R.13a): octave o read at (x, z) − velocity_mps[o]·t, the lattice
/// coordinate split in double precision into whole cells and a single-precision rest (the map's
/// arithmetic), so that it stays exact however far the octaves have travelled. At t = 0 it equals
/// the static field up to float rounding.
FarFieldSample far_field_noise(const FarFieldNoise& noise, double x_m, double z_m, double time_s);

/// Octave `octave`'s (0, 1, 2) lattice coordinate of the world point (x, z) at time t,
/// ((x, z) − velocity_mps·t)/cell_m, split in double precision into whole cells (wrapped modulo
/// 2³², as the lattice's indices) and the rest in [0, 1): where the map's texel (0, 0) and the
/// renderer's frame origin place the lattice (docs/rendering.md R.13a, R.13b).
struct FarNoiseLattice {
  std::uint32_t cells_u = 0, cells_v = 0;  ///< whole cells along x and z (two's complement)
  float rest_u = 0.0f, rest_v = 0.0f;      ///< the rest along x and z
};
FarNoiseLattice far_noise_lattice(const FarFieldNoise& noise, int octave, double x_m, double z_m,
                                  double time_s);

}  // namespace ocean
