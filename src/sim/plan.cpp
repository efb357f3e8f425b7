// SimulationPlan: a configuration resolved once (ocean/plan.hpp).
#include "ocean/plan.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>

#include "packing.hpp"

namespace ocean {

struct SimulationPlan::FarNoiseFit {
  std::once_flag once;
  FarFieldNoise noise;
};

Result<SimulationPlan> SimulationPlan::make(const SimulationConfig& config) {
  if (Status s = validate(config); !s.ok()) return s;
  Result<SeaState> sea = SeaState::make(config.sea);
  if (!sea.ok()) return sea.status();
  SimulationPlan plan;
  plan.config_ = config;
  plan.sea_ = std::make_shared<const SeaState>(std::move(sea).value());
  const std::vector<std::array<double, 2>> bands = cascade_bands(config);
  const std::vector<double> band_k = band_wavenumbers(config);
  for (std::size_t c = 0; c < config.cascade_patch_sizes_m.size(); ++c) {
    plan.cascades_.push_back({.patch_size_m = config.cascade_patch_sizes_m[c],
                              .band_radpm = bands[c],
                              .band_wavenumber_radpm = band_k[c],
                              .spectrum = cascade_spectrum_params(config, c)});
  }
  plan.hs_m_ = 4.0 * std::sqrt(std::max(plan.sea_->variance_m2(), 0.0));  // (M.1)
  for (const WaveSystem& w : plan.sea_->systems()) {
    const double k = plan.sea_->dispersion().wavenumber(w.spectrum().peak_omega());
    if (k > 0.0)
      plan.peak_wavelength_m_ = std::min(plan.peak_wavelength_m_, 2.0 * std::numbers::pi / k);
  }
  const int n = config.resolution;
  for (CascadePlan& c : plan.cascades_) {
    const double k_min = c.band_radpm[0];
    const double longest_m = k_min > 0.0 ? 2.0 * std::numbers::pi / k_min : c.patch_size_m;
    c.tiling_wavelength_m =
        std::min(longest_m, std::max(plan.peak_wavelength_m_, 4.0 * c.patch_size_m / n));
  }
  const FrequencySpectrumParams& wind = config.sea.wind_sea.spectrum;
  const double u10 = wind.model == SpectrumModel::pierson_moskowitz ? wind.wind_speed_mps / 1.026
                                                                    : wind.wind_speed_mps;
  if (u10 >= 0.5 && u10 <= 60.0) {  // false for NaN: an Hs/Tp sea
    const std::size_t finest = config.cascade_patch_sizes_m.size() - 1;
    Result<SlopeVariance> tail = short_wave_slope_variance(
        {.wind_speed_mps = u10,
         .grid_nyquist_radpm = std::numbers::pi * n / config.cascade_patch_sizes_m[finest],
         .wind_direction_rad = config.sea.wind_sea.direction_rad,
         .gravity_mps2 = wind.gravity_mps2});
    if (tail.ok()) plan.unresolved_slope_variance_ = tail.value();
  }
  plan.far_noise_ = std::make_shared<FarNoiseFit>();
  return plan;
}

const FarFieldNoise& SimulationPlan::far_noise() const {
  std::call_once(far_noise_->once,
                 [this] { far_noise_->noise = fit_far_field_noise(*sea_, config_); });
  return far_noise_->noise;
}

SurfaceDescription SimulationPlan::surface() const {
  SurfaceDescription d;
  d.significant_wave_height_m = hs_m_;
  d.crest_bound_m = kCrestHeightPerHs * hs_m_ + kCrestMarginM;
  d.choppiness = config_.choppiness;
  d.horizontal_reach_m = config_.choppiness * hs_m_;
  d.foam_ramp = {config_.foam.jacobian_start, config_.foam.jacobian_full};
  d.resolution = config_.resolution;
  for (const CascadePlan& c : cascades_) {
    d.patch_sizes_m.push_back(c.patch_size_m);
    d.tiling_wavelengths_m.push_back(c.tiling_wavelength_m);
  }
  d.far_noise = far_noise();
  if (unresolved_slope_variance_) d.unresolved_slope_variance = unresolved_slope_variance_->total();
  const float smoothness = packing::smoothness_from_normal_length(
      packing::normal_length_from_roughness(static_cast<float>(config_.roughness)));
  const double stored = std::floor(std::clamp(smoothness, 0.0f, 1.0f) * 255.0 + 0.5) / 255.0;
  d.map_base_alpha_sq = std::pow(1.0 - stored, 4.0);  // the shaders' alpha_squared (R.5)
  return d;
}

}  // namespace ocean
