// ocean/plan.hpp — the resolved simulation plan: a validated configuration with everything
// derived from it computed once (the sea state, each cascade's band and spectrum parameters, the
// far field's noise fit, the constants a renderer sizes its work by). The backends configure
// from a plan, the Simulator keeps the one it was configured with, and the renderer receives the
// plan's SurfaceDescription instead of the configuration; nothing else rebuilds a sea state.
//
// Contract: a plan is immutable once made and safe to read from any thread; copies share the
// far-noise fit, which is computed on first use (it visits every wave vector of cascade 0 four
// times: tens of milliseconds at N = 512, about a second at 2048).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/far_noise.hpp"
#include "ocean/sim.hpp"
#include "ocean/spectrum.hpp"

namespace ocean {

/// One cascade as the plan resolves it.
struct CascadePlan {
  double patch_size_m = 0.0;  ///< L of the periodic patch, m
  /// [k_min, k_max) of the band this cascade synthesises, rad/m (M.7.1, cascade_bands).
  std::array<double, 2> band_radpm{};
  /// The band's representative wavenumber for the damping, rad/m (W.14, band_wavenumbers).
  double band_wavenumber_radpm = 0.0;
  /// How its initial spectrum is generated: grid, band and seed (cascade_spectrum_params).
  InitialSpectrumParams spectrum;
  /// The wavelength, m, a renderer fades this cascade's displacement against and hex-tiles its
  /// lookups at (docs/rendering.md R.9, R.14): its band's longest wave 2π/k_min (the patch side
  /// when the band starts at 0), at most the sea's shortest peak wavelength and at least four
  /// texels.
  double tiling_wavelength_m = 0.0;
};

/// How a foam source reads a Jacobian J (M.7.4): x = (threshold − J)·gain, and the source is
/// clamp(x, 0, 1) for FoamSource::ramp, Φ(x) for FoamSource::breaking (Φ the standard normal
/// distribution function).
struct FoamSourceTerms {
  double threshold = 0.8;
  double gain = 1.0 / 0.3;
};

/// The foam sources a plan resolves (SimulationPlan::foam). For FoamSource::breaking, with
/// λ the choppiness, α the breaking acceleration and σ² slope variances (both components):
/// the sea breaks where J_true < 1 − λ·α (Longuet-Higgins 1969), J_true − 1 having the variance
/// λ²·σ²_total of the whole slope spectrum (every cascade's band and the waves shorter than the
/// finest). A cascade sees J_c − 1 through its normal method's differences (variance λ²·σ²_d,
/// covariance λ²·σ²_x with the band's exact divergence); the rest is Gaussian and independent
/// of it, so the probability of breaking given J_c is Φ((1 − λα − 1 − β(J_c − 1))/s) with
/// β = σ²_x/σ²_d and s² = λ²(σ²_total − σ⁴_x/σ²_d) (the regression of J_true on J_c): threshold
/// 1 − λα/β, gain β/s. Its mean over the cascade is the whitecap fraction of the whole sea.
struct FoamPlan {
  std::vector<FoamSourceTerms> cascades;  ///< each cascade's source
  /// The local surface's (every cascade summed on one grid, M.7.9): β = 1, s² = λ² times the
  /// variance no cascade's differences resolve.
  FoamSourceTerms local;
  /// FoamSource::breaking: each cascade's share of the bands' slope variance, what a renderer
  /// weighs the cascades' foam by (their weighted mean is the coverage); empty for ramp, whose
  /// cascades' foam a renderer unites.
  std::vector<double> weights;
};

/// The shortest wave SimulationPlan::short_waves holds, rad/m (λ ≈ 2 mm): beyond it Elfouhaily et
/// al.'s capillary range carries under 10⁻⁵ of the slope variance.
inline constexpr double kShortWaveDetailMaxRadpm = 3000.0;

/// The surface's wind drift as a fraction of U10: about 3 % (Wu 1975, "Wind-induced drift
/// currents", J. Fluid Mech. 68; Wu 1983, "Sea-surface drift currents induced by wind and
/// waves", J. Phys. Oceanogr. 13) — the speed at which floating foam moves downwind (W.29).
inline constexpr double kWindDriftFraction = 0.03;
/// The e-folding time of an oceanic whitecap's foam area in salt water, s (Monahan 1971,
/// "Oceanic whitecaps", J. Phys. Oceanogr. 1; Callaghan et al. 2012 measure 0.5–8 s) (W.30).
inline constexpr double kWhitecapDecayTimeS = 3.85;

/// What a renderer needs to know of the surface it draws, and nothing of the configuration:
/// heights that bound the waves, each cascade's patch and the scale its tiling is hidden at, the
/// foam ramp and the far field's noise.
struct SurfaceDescription {
  double significant_wave_height_m = 0.0;  ///< Hs = 4·√m0 of the sea state (M.1)
  /// T_p = 2π/ω_p of the wave system holding the most variance, s (0 when none has a peak): with
  /// Hs, what a beach's run-up is reckoned from (docs/waves.md W.40–W.41).
  double peak_period_s = 0.0;
  /// A bound on |h| of the displaced surface, m, for culling and the horizon skirt:
  /// kCrestHeightPerHs·Hs + kCrestMarginM (docs/rendering.md, Frame, step 2).
  double crest_bound_m = 0.0;
  double choppiness = 1.0;  ///< λ of the horizontal displacement
  /// A bound on |(Dx, Dz)|, m: λ·Hs (docs/rendering.md, Frame, step 2).
  double horizontal_reach_m = 0.0;
  std::array<double, 2> foam_ramp{0.8, 0.5};  ///< FoamParams' Jacobian start and full
  /// FoamPlan::weights: empty when the cascades' foam is united (FoamSource::ramp).
  std::vector<double> foam_weights;
  int resolution = 0;                         ///< N texels per side of every cascade
  std::vector<double> patch_sizes_m;          ///< L of each cascade, largest first
  std::vector<double> tiling_wavelengths_m;   ///< CascadePlan::tiling_wavelength_m of each

  FarFieldNoise far_noise;  ///< fitted to cascade 0 (R.13)
  /// σu² + σc² of the waves shorter than the finest cascade's grid, the roughness the cascades
  /// leave out (SimulationPlan::unresolved_slope_variance; R.5); empty when no wind is given.
  std::optional<double> unresolved_slope_variance;
  /// SimulationPlan::short_waves: the waves beyond the finest cascade's grid as a sum of sines, which a
  /// renderer draws as detail normals where the pixels resolve them and otherwise leaves in the
  /// roughness (R.62); empty when no wind is given.
  std::vector<ShortWaveComponent> short_waves;
  /// The normal length a level-0 texel of the packed map stores: SimulationConfig::roughness as
  /// Aebi, VR Ocean, eqs. 49–53 encode it, quantised to 8 bits and decoded again. A mip's
  /// shorter normal carries the slope variance the filtering removed (R.5).
  double map_base_normal_length = 1.0;
  /// The wind drift of the surface that carries the foam, (x, z) m/s: kWindDriftFraction·U10
  /// along the wind (docs/waves.md W.29); zero when no wind is given (an Hs/Tp sea).
  std::array<double, 2> foam_drift_mps{0.0, 0.0};
  /// The foam's e-folding decay time, s (kWhitecapDecayTimeS): the ages of the foam on the
  /// surface are distributed as e^{−a/τ}/τ, and a renderer draws each cascade's foam spread
  /// downwind over drift·age (W.30–W.31).
  double foam_decay_time_s = kWhitecapDecayTimeS;
};

/// The crest bound's factor: the highest crest of a few thousand Rayleigh-distributed waves is
/// about 1.2·Hs (Longuet-Higgins 1952, "On the statistical distribution of the heights of sea
/// waves": H_max ≈ 1.86–2·Hs, crests about 0.6 of the height in steep seas).
inline constexpr double kCrestHeightPerHs = 1.2;
/// What the crest bound adds for the local layer's wakes and waveforms and a calm sea, m.
inline constexpr double kCrestMarginM = 0.5;

class SimulationPlan {
 public:
  /// Validates `config` (ocean::validate) and resolves it: the sea state (SeaState::make) and the
  /// cascades. The errors are those of validate and SeaState::make.
  static Result<SimulationPlan> make(const SimulationConfig& config);

  [[nodiscard]] const SimulationConfig& config() const { return config_; }
  [[nodiscard]] const SeaState& sea() const { return *sea_; }
  [[nodiscard]] const std::vector<CascadePlan>& cascades() const { return cascades_; }
  /// Hs = 4·√m0 of the sea state, m.
  [[nodiscard]] double significant_wave_height_m() const { return hs_m_; }
  /// The shortest peak wavelength 2π/k(ω_p) over the sea's wave systems, m (1e9 when none has a
  /// peak).
  [[nodiscard]] double peak_wavelength_m() const { return peak_wavelength_m_; }
  /// The slope variance of the waves shorter than the finest cascade's grid (wave vectors outside
  /// its square |kx|, |kz| ≤ π·N/L): short_wave_slope_variance for the wind sea's U10 (U19.5/1.026
  /// for Pierson–Moskowitz, Stewart 2008 §16.5) and direction. Empty when the wind sea is given
  /// by Hs and Tp, which name no wind, or by a wind outside [0.5, 60] m/s.
  [[nodiscard]] const std::optional<SlopeVariance>& unresolved_slope_variance() const {
    return unresolved_slope_variance_;
  }
  /// The unresolved waves from √2·π·N/L of the finest cascade (every direction outside its
  /// grid's square) to kShortWaveDetailMaxRadpm, as short_wave_components (16 bins of 3 waves,
  /// the configuration's seed; M.9.4): part of unresolved_slope_variance, drawn where a
  /// renderer's pixels resolve them (docs/rendering.md R.62). Empty when that is.
  [[nodiscard]] const std::vector<ShortWaveComponent>& short_waves() const { return short_waves_; }
  /// The foam sources (FoamPlan), computed on first use: for FoamSource::breaking it visits every
  /// wave vector of every cascade once (milliseconds at N = 256).
  [[nodiscard]] const FoamPlan& foam() const;
  /// The far field's noise fitted to cascade 0 (fit_far_field_noise), computed on first use.
  [[nodiscard]] const FarFieldNoise& far_noise() const;
  /// What a renderer draws this plan's surface by.
  [[nodiscard]] SurfaceDescription surface() const;

 private:
  struct FarNoiseFit;
  struct FoamFit;
  SimulationConfig config_;
  std::shared_ptr<const SeaState> sea_;
  std::vector<CascadePlan> cascades_;
  double hs_m_ = 0.0;
  double peak_wavelength_m_ = 1e9;
  std::optional<SlopeVariance> unresolved_slope_variance_;
  std::vector<ShortWaveComponent> short_waves_;
  std::shared_ptr<FarNoiseFit> far_noise_;
  std::shared_ptr<FoamFit> foam_;
};

}  // namespace ocean
