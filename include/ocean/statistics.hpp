// ocean/statistics.hpp — statistics of the simulated surface for one configuration over several
// seeds: measured and spectral significant wave height, height moments, slopes, Jacobian/foam,
// and two numerical checks (imaginary residue of the height transform, loop error). What
// `ocean stats` prints.
//
// Everything is measured on cascade 0 (the largest patch): its texels sample the h component of
// the displacement, its unit normals, Jacobian and foam. With a single cascade that is the whole
// surface. Equation numbers (M.n) refer to docs/math.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ocean/sim.hpp"
#include "ocean/spectrum.hpp"
#include "ocean/task_runner.hpp"

namespace ocean {

struct SurfaceStats {
  // Inputs, echoed.
  int resolution = 0;
  double patch_size_m = 0.0;  ///< cascade 0's patch side L, m
  int cascades = 0;
  int seeds = 0;  ///< realisations: seed, seed + 1, ..., seed + seeds − 1
  std::uint64_t first_seed = 0;
  double time_s = 0.0;
  double choppiness = 0.0;
  double loop_period_s = 0.0;
  std::string model;                     ///< the wind sea's spectrum model
  std::optional<double> wind_speed_mps;  ///< when the wind sea is given by wind speed

  // Significant wave height, m.
  /// 4·√(variance of h over the texels), the variance averaged over the seeds.
  double hs_measured_m = 0.0;
  /// 4·√(Σ F(k)·Δk²) over the wave vectors cascade 0 fills (no DC, no Nyquist row/column, its
  /// band): the expectation of the measured variance (M.6.2).
  double hs_spectrum_m = 0.0;
  /// 4·√m0 of the whole spectrum (Pierson–Moskowitz: 0.2093·U²/g, M.3.2).
  double hs_closed_form_m = 0.0;
  /// Σ F·Δk² / m0: the share of the variance the patch resolves.
  double resolved_variance_fraction = 0.0;
  /// Effective number of independent wave-vector pairs (Σσ²)²/Σσ⁴ with σ² = E|h̃(k)|² per pair:
  /// one realisation's variance has relative standard deviation 1/√n_eff.
  double independent_wave_vectors = 0.0;
  /// Expected relative standard deviation of hs_measured over `seeds` realisations,
  /// ½·√(1/(n_eff·seeds)).
  double hs_sampling_rel_std = 0.0;

  // Height moments pooled over all texels and seeds (empty when the surface is flat).
  double mean_height_m = 0.0;
  std::optional<double> height_skewness;
  std::optional<double> height_kurtosis;  ///< non-excess: 3 for a Gaussian

  // Slopes from the unit normals: (n_x² + n_z²)/n_y² = |∇h|², texels with n_y ≤ 0 excluded.
  double mean_square_slope = 0.0;
  double folded_fraction = 0.0;  ///< texels with n_y ≤ 0
  /// Cox & Munk (1954), clean surface: 0.003 + 5.12e-3·U12.5; set when the sea is given by wind.
  std::optional<double> cox_munk_mss;

  // Slope variance of the whole surface along and across the wind sea's direction: every
  // cascade's slopes (from its normals, each texel weighted by its area on the displaced surface,
  // max(J, 0)), summed over the cascades as the renderer sums their slopes; and the waves shorter
  // than the finest cascade's grid (short_wave_slope_variance), which the renderer adds as
  // roughness. Their sum is what Cox & Munk (1954) measured from the sun's glitter.
  SlopeVariance resolved_slope_variance;
  std::optional<SlopeVariance> unresolved_slope_variance;  ///< set when the sea is given by wind
  /// Cox & Munk (1954), clean surface: σu² = 3.16e-3·U, σc² = 0.003 + 1.92e-3·U (U at 12.5 m).
  std::optional<SlopeVariance> cox_munk_slope_variance;

  // Jacobian of the horizontal map and foam.
  double min_jacobian = 0.0;
  double foam_coverage = 0.0;  ///< fraction of texels with J < 0
  double mean_foam = 0.0;      ///< cascade 0's mean foam
  /// The whitecap fraction a renderer draws: for FoamSource::breaking every cascade's mean foam
  /// weighted by FoamPlan::weights (each is the sea's breaking probability, M.7.4); for ramp
  /// 1 − Π(1 − f̄_c/(1 + 0.6·c)) of the cascades' means, as R.11 unites them (independent
  /// cascades). Over the seeds.
  double whitecap_coverage = 0.0;
  /// Monahan & O'Muircheartaigh (1980): W = 3.84e-6·U10^3.41, set when the sea is given by wind.
  std::optional<double> monahan_whitecap_coverage;

  // Numerical checks, relative to hs_spectrum_m (empty when hs_spectrum_m is 0).
  /// Largest |imaginary part| of the inverse FFT of the height spectrum alone, over the seeds.
  std::optional<double> max_imaginary_rel_hs;
  /// max |h(t + T) − h(t)| over texels, first seed; empty when loop_period_s is 0.
  std::optional<double> loop_error_rel_hs;
};

/// Cox & Munk (1954) clean-surface mean square slope 0.003 + 5.12e-3·U, U at 12.5 m in m/s.
double cox_munk_mean_square_slope(double wind_speed_mps);
/// Monahan & O'Muircheartaigh (1980)'s whitecap fraction 3.84e-6·U10^3.41, U10 in m/s.
double monahan_whitecap_coverage(double wind_speed_mps);
/// Cox & Munk (1954)'s clean-surface up- and crosswind components, U at 12.5 m in m/s.
SlopeVariance cox_munk_slope_variance(double wind_speed_mps);

/// Simulates `seeds` realisations (config.seed + s) with the CPU backend at `time_s` and measures
/// them. Invalid configurations, seeds < 1 and non-finite times are invalid_argument.
/// The simulations and transforms run on `runner` (the caller's job system; it must outlive the
/// call); the figures do not depend on which runner. Allocates the simulators and a few fields
/// of N² values; blocks until done. Thread-safe for distinct runners.
Result<SurfaceStats> compute_surface_stats(const SimulationConfig& config, int seeds, double time_s,
                                           TaskRunner& runner);

}  // namespace ocean
