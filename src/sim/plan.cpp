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

struct SimulationPlan::FoamFit {
  std::once_flag once;
  FoamPlan foam;
};

namespace {

// The second moments of one cascade's band (FoamPlan): σ²_x = Σ P·|k|², σ²_d = Σ P·g², and
// Σ P·|k|·g, where g·cos is what the normal method's differences make of the divergence
// |k|·cos of a unit wave (λ aside): analytic g = |k|; central differences
// (kx·sin(kx·Δ) + kz·sin(kz·Δ))/(Δ·|k|); Sobel the same with each derivative smoothed by
// (1 + cos(k⊥·Δ))/2 across it.
struct BandMoments {
  double exact = 0.0, seen = 0.0, covariance = 0.0;
};

BandMoments band_moments(const std::vector<double>& power, int n, double patch_size_m,
                         NormalMethod normals) {
  BandMoments m;
  const double dk = 2.0 * std::numbers::pi / patch_size_m, spacing = patch_size_m / n;
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const double p = power[static_cast<std::size_t>(row) * static_cast<std::size_t>(n) +
                             static_cast<std::size_t>(col)];
      if (p == 0.0) continue;
      const double kx = dk * (col - n / 2), kz = dk * (row - n / 2);
      const double k = std::hypot(kx, kz);
      double g = k;
      if (normals != NormalMethod::analytic) {
        double gx = kx * std::sin(kx * spacing) / spacing;
        double gz = kz * std::sin(kz * spacing) / spacing;
        if (normals == NormalMethod::sobel) {
          gx *= 0.5 * (1.0 + std::cos(kz * spacing));
          gz *= 0.5 * (1.0 + std::cos(kx * spacing));
        }
        g = (gx + gz) / k;
      }
      m.exact += p * k * k;
      m.seen += p * g * g;
      m.covariance += p * k * g;
    }
  }
  return m;
}

// The least gain that keeps x finite where the rest of the sea has no slope at all.
constexpr double kMinSpread = 1e-9;

FoamPlan resolve_foam(const SimulationPlan& plan) {
  const SimulationConfig& config = plan.config();
  FoamPlan f;
  const std::size_t count = plan.cascades().size();
  if (config.foam.source == FoamSource::ramp) {
    const FoamSourceTerms ramp{config.foam.jacobian_start,
                               1.0 / (config.foam.jacobian_start - config.foam.jacobian_full)};
    f.cascades.assign(count, ramp);
    f.local = ramp;
    return f;
  }
  const double lambda = config.choppiness, alpha = config.foam.breaking_acceleration;
  std::vector<BandMoments> bands;
  for (const CascadePlan& c : plan.cascades()) {
    Result<std::vector<double>> power = expected_wave_power(plan.sea(), c.spectrum);
    bands.push_back(
        power.ok() ? band_moments(power.value(), config.resolution, c.patch_size_m, config.normals)
                   : BandMoments{});
  }
  const std::optional<SlopeVariance>& tail = plan.unresolved_slope_variance();
  double total = tail ? tail->upwind + tail->crosswind : 0.0, exact = 0.0, unseen = total;
  for (const BandMoments& b : bands) {
    total += b.exact;
    exact += b.exact;
    unseen += b.exact - (b.seen > 0.0 ? b.covariance * b.covariance / b.seen : 0.0);
  }
  const auto terms = [&](double beta, double residual) -> FoamSourceTerms {
    if (!(lambda > 0.0)) return {0.0, 1.0 / kMinSpread};  // J ≡ 1: nothing breaks
    const double s = std::max(lambda * std::sqrt(std::max(residual, 0.0)), kMinSpread);
    return {1.0 - lambda * alpha / beta, beta / s};
  };
  for (const BandMoments& b : bands) {
    const bool seen = b.seen > 0.0 && b.covariance > 0.0;
    const double beta = seen ? b.covariance / b.seen : 1.0;
    f.cascades.push_back(terms(beta, total - (seen ? b.covariance * b.covariance / b.seen : 0.0)));
    f.weights.push_back(exact > 0.0 ? b.exact / exact : 1.0 / static_cast<double>(count));
  }
  f.local = terms(1.0, unseen);
  return f;
}

}  // namespace

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
    const double k_min = std::sqrt(2.0) * std::numbers::pi * n / config.cascade_patch_sizes_m[finest];
    if (tail.ok() && k_min < kShortWaveDetailMaxRadpm) {
      Result<std::vector<ShortWaveComponent>> waves = short_wave_components(
          {.waves = {.wind_speed_mps = u10,
                     .wind_direction_rad = config.sea.wind_sea.direction_rad,
                     .gravity_mps2 = wind.gravity_mps2},
           .k_min_radpm = k_min,
           .k_max_radpm = kShortWaveDetailMaxRadpm,
           .seed = config.seed});
      if (waves.ok()) {
        // On the lattice 2π/L₀ of the coarsest cascade (a shift below 2π/L₀, 10⁻⁴ of the
        // shortest k here): the ripples repeat with the sea's longest period, so that every
        // view the cascades repeat in (R.16) draws them alike too.
        const double lattice = 2.0 * std::numbers::pi / config.cascade_patch_sizes_m.front();
        for (ShortWaveComponent& w : waves.value()) {
          const double k = std::hypot(w.kx_radpm, w.kz_radpm);
          w.kx_radpm = lattice * std::round(w.kx_radpm / lattice);
          w.kz_radpm = lattice * std::round(w.kz_radpm / lattice);
          const double snapped = std::hypot(w.kx_radpm, w.kz_radpm);
          w.amplitude_m *= k / snapped;  // a·k kept
          w.omega_radps = snapped * capillary_gravity_phase_speed(snapped, wind.gravity_mps2);
        }
        plan.short_waves_ = std::move(waves).value();
      }
    }
  }
  plan.far_noise_ = std::make_shared<FarNoiseFit>();
  plan.foam_ = std::make_shared<FoamFit>();
  return plan;
}

const FoamPlan& SimulationPlan::foam() const {
  std::call_once(foam_->once, [this] { foam_->foam = resolve_foam(*this); });
  return foam_->foam;
}

const FarFieldNoise& SimulationPlan::far_noise() const {
  std::call_once(far_noise_->once,
                 [this] { far_noise_->noise = fit_far_field_noise(*sea_, config_); });
  return far_noise_->noise;
}

SurfaceDescription SimulationPlan::surface() const {
  SurfaceDescription d;
  d.significant_wave_height_m = hs_m_;
  double most = -1.0;  // the peak of the system with the largest variance (W.40)
  for (const WaveSystem& w : sea_->systems()) {
    const double m0 = w.spectrum().moment(0), omega_p = w.spectrum().peak_omega();
    if (m0 > most && omega_p > 0.0 && std::isfinite(omega_p)) {
      most = m0;
      d.peak_period_s = 2.0 * std::numbers::pi / omega_p;
    }
  }
  d.crest_bound_m = kCrestHeightPerHs * hs_m_ + kCrestMarginM;
  d.choppiness = config_.choppiness;
  d.horizontal_reach_m = config_.choppiness * hs_m_;
  d.foam_ramp = {config_.foam.jacobian_start, config_.foam.jacobian_full};
  d.foam_weights = foam().weights;
  d.resolution = config_.resolution;
  for (const CascadePlan& c : cascades_) {
    d.patch_sizes_m.push_back(c.patch_size_m);
    d.tiling_wavelengths_m.push_back(c.tiling_wavelength_m);
  }
  d.far_noise = far_noise();
  if (unresolved_slope_variance_) d.unresolved_slope_variance = unresolved_slope_variance_->total();
  d.short_waves = short_waves_;
  const float smoothness = packing::smoothness_from_normal_length(
      packing::normal_length_from_roughness(static_cast<float>(config_.roughness)));
  const double stored = std::floor(std::clamp(smoothness, 0.0f, 1.0f) * 255.0 + 0.5) / 255.0;
  d.map_base_normal_length = packing::normal_length_from_smoothness(static_cast<float>(stored));
  // The foam's drift (W.29): kWindDriftFraction·U10 along the wind sea's mean direction.
  const FrequencySpectrumParams& wind = config_.sea.wind_sea.spectrum;
  const double u10 = wind.model == SpectrumModel::pierson_moskowitz ? wind.wind_speed_mps / 1.026
                                                                    : wind.wind_speed_mps;
  if (u10 >= 0.5 && u10 <= 60.0) {  // false for NaN: an Hs/Tp sea has no wind to drift with
    const double theta = config_.sea.wind_sea.direction_rad;
    d.foam_drift_mps = {kWindDriftFraction * u10 * std::cos(theta),
                        kWindDriftFraction * u10 * std::sin(theta)};
  }
  d.foam_decay_time_s = kWhitecapDecayTimeS;
  return d;
}

}  // namespace ocean
