// FrequencySpectrum: validation, the per-model evaluation of S(ω) and its spectral moments.
//
// Sources for each model are cited in pierson_moskowitz.cpp, jonswap.cpp, tma.cpp and
// phillips.cpp. Equations: docs/math.md §3.
#include <array>
#include <cassert>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "internal.hpp"

namespace ocean {

std::string_view to_string(SpectrumModel model) { return name_of(kSpectrumModelNames, model); }

Result<SpectrumModel> parse_spectrum_model(std::string_view name) {
  if (std::optional<SpectrumModel> m = value_of(kSpectrumModelNames, name)) return *m;
  return invalid_argument("model = '" + excerpt(name) + "' is unknown: must be one of " +
                          name_list(kSpectrumModelNames, ", ", ", "));
}

namespace {

bool is_set(double v) { return !std::isnan(v); }

// The field's closed range in kSeaStateParameters.
Status require_range(std::string_view field, double value) {
  const params::ParameterDoc& p = sea_state_parameter(field);
  return require_in_range(p.field, value, p.lo, p.hi);
}

// "<flag> = '<text>' is unknown: must be a or b".
template <class E, std::size_t N>
Result<E> parse_name(std::string_view flag, const std::array<EnumName<E>, N>& table,
                     std::string_view text) {
  if (std::optional<E> value = value_of(table, text)) return *value;
  return invalid_argument(std::string(flag) + " = '" + excerpt(text) + "' is unknown: must be " +
                          name_list(table, ", ", " or "));
}

Status validate_params(const FrequencySpectrumParams& p) {
  const std::string model(to_string(p.model));
  if (Status s = require_range("gravity_mps2", p.gravity_mps2); !s.ok()) return s;
  const bool hs_form = is_set(p.significant_wave_height_m) || is_set(p.peak_period_s);
  const bool wind_form = is_set(p.wind_speed_mps);
  if (hs_form && wind_form) {
    return invalid_argument(
        "give either significant_wave_height_m + peak_period_s or "
        "wind_speed_mps, not both");
  }
  if (!hs_form && !wind_form) {
    return invalid_argument(model +
                            " needs a sea state: significant_wave_height_m + "
                            "peak_period_s, or wind_speed_mps");
  }
  if (hs_form) {
    if (p.model == SpectrumModel::phillips) {
      return invalid_argument("phillips is parameterised by wind_speed_mps, not Hs/Tp");
    }
    if (!is_set(p.significant_wave_height_m) || !is_set(p.peak_period_s)) {
      return invalid_argument("significant_wave_height_m and peak_period_s must be given together");
    }
    if (Status s = require_range("significant_wave_height_m", p.significant_wave_height_m);
        !s.ok()) {
      return s;
    }
    if (Status s = require_range("peak_period_s", p.peak_period_s); !s.ok()) {
      return s;
    }
  } else if (Status s = require_range("wind_speed_mps", p.wind_speed_mps); !s.ok()) {
    return s;
  }
  const bool jonswap_family = p.model == SpectrumModel::jonswap || p.model == SpectrumModel::tma;
  if (is_set(p.fetch_m)) {
    if (!jonswap_family || hs_form) {
      return invalid_argument("fetch_m applies only to jonswap/tma given by wind_speed_mps");
    }
    if (Status s = require_range("fetch_m", p.fetch_m); !s.ok()) return s;
  } else if (jonswap_family && wind_form) {
    return invalid_argument(model + " from wind_speed_mps needs fetch_m (fetch-limited sea)");
  }
  if (is_set(p.gamma)) {
    if (!jonswap_family) return invalid_argument("gamma applies only to jonswap/tma");
    if (Status s = require_range("gamma", p.gamma); !s.ok()) return s;
  }
  if (Status s = require_in_range("sigma_a", p.sigma_a, 1e-3, 1.0); !s.ok()) return s;
  if (Status s = require_in_range("sigma_b", p.sigma_b, 1e-3, 1.0); !s.ok()) return s;
  if (Status s = require_depth(p.depth_m); !s.ok()) return s;
  if (std::isfinite(p.depth_m) && p.model != SpectrumModel::tma) {
    return invalid_argument("depth_m applies only to tma (" + model + " is a deep-water model)");
  }
  if (p.model != SpectrumModel::phillips) {
    if (is_set(p.phillips_amplitude))
      return invalid_argument("phillips_amplitude applies only to phillips");
    if (p.small_wave_cutoff_m != 0.0)
      return invalid_argument("small_wave_cutoff_m applies only to phillips");
  } else {
    if (is_set(p.phillips_amplitude)) {
      // (0, 1e6]: the default is 5.5e-3; the bound keeps S finite for every valid wind.
      if (!(p.phillips_amplitude > 0.0 && p.phillips_amplitude <= 1e6)) {
        return invalid_argument("phillips_amplitude = " + format_number(p.phillips_amplitude) +
                                " is out of range: must be in (0, 1e+06]");
      }
    }
    if (Status s = require_non_negative("small_wave_cutoff_m", p.small_wave_cutoff_m); !s.ok()) {
      return s;
    }
  }
  return {};
}

}  // namespace

Result<FrequencySpectrum> FrequencySpectrum::make(const FrequencySpectrumParams& params) {
  if (Status s = validate_params(params); !s.ok()) return s;
  FrequencySpectrum spec;
  spec.params_ = params;
  const double g = params.gravity_mps2;
  const bool hs_form = is_set(params.significant_wave_height_m);
  switch (params.model) {
    case SpectrumModel::pierson_moskowitz:
      spec.omega_p_ = hs_form ? 2.0 * kPi / params.peak_period_s
                              : pierson_moskowitz_peak_omega(params.wind_speed_mps, g);
      spec.alpha_ = hs_form ? 0.0 : pierson_moskowitz_alpha();
      break;
    case SpectrumModel::jonswap:
    case SpectrumModel::tma:
      if (hs_form) {
        spec.omega_p_ = 2.0 * kPi / params.peak_period_s;
        spec.gamma_ = is_set(params.gamma) ? params.gamma
                                           : jonswap_gamma_dnv(params.significant_wave_height_m,
                                                               params.peak_period_s);
        spec.scale_ = 1.0 - 0.287 * std::log(spec.gamma_);  // A_γ, DNV-RP-C205 (M.3.4)
      } else {
        const auto [alpha, omega_p] =
            jonswap_fetch_law(params.wind_speed_mps, params.fetch_m, g, params.fetch_law);
        spec.alpha_ = alpha;
        spec.omega_p_ = omega_p;
        spec.gamma_ = is_set(params.gamma) ? params.gamma : 3.3;  // Hasselmann's mean γ
      }
      break;
    case SpectrumModel::phillips:
      spec.phillips_a_ = is_set(params.phillips_amplitude) ? params.phillips_amplitude
                                                           : phillips_default_amplitude();
      spec.omega_p_ = std::pow(0.8, 0.25) * g / params.wind_speed_mps;  // (M.3.14)
      break;
  }
  if (hs_form && params.model != SpectrumModel::pierson_moskowitz &&
      params.normalization == JonswapNormalization::exact) {
    // Scale the deep-water JONSWAP so that 4·√m0 = Hs exactly (before any depth factor).
    FrequencySpectrum deep = spec;
    deep.params_.model = SpectrumModel::jonswap;
    deep.scale_ = 1.0;
    const double hs = params.significant_wave_height_m;
    spec.scale_ = hs * hs / 16.0 / deep.moment(0);
  }
  return spec;
}

double FrequencySpectrum::jonswap_shape(double omega) const {
  const FrequencySpectrumParams& p = params_;
  // Wind form: α·g²/ω⁵·exp(−5/4·(ωp/ω)⁴) = α·g²/ωp⁵ · r⁵·exp(−5/4·r⁴), r = ωp/ω   (M.3.7)
  const double base =
      is_set(p.significant_wave_height_m)
          ? scale_ * pierson_moskowitz_hs_tp(omega, p.significant_wave_height_m, p.peak_period_s)
          : pm_spectrum(alpha_ * p.gravity_mps2 * p.gravity_mps2 / std::pow(omega_p_, 5.0),
                        omega_p_ / omega, 1.25);
  return base * jonswap_peak_enhancement(omega, omega_p_, gamma_, p.sigma_a, p.sigma_b);  // (M.3.5)
}

double FrequencySpectrum::operator()(double omega) const {
  if (!(omega > 0.0)) return 0.0;
  const FrequencySpectrumParams& p = params_;
  switch (p.model) {
    case SpectrumModel::pierson_moskowitz:
      return is_set(p.significant_wave_height_m)
                 ? pierson_moskowitz_hs_tp(omega, p.significant_wave_height_m, p.peak_period_s)
                 : pierson_moskowitz_wind(omega, p.wind_speed_mps, p.gravity_mps2);
    case SpectrumModel::jonswap: return jonswap_shape(omega);
    case SpectrumModel::tma:
      return jonswap_shape(omega) *
             tma_depth_factor(omega, p.depth_m, p.gravity_mps2, p.depth_factor);  // (M.3.9)
    case SpectrumModel::phillips:
      return phillips_omega_density(omega, phillips_a_, p.wind_speed_mps, p.gravity_mps2,
                                    p.small_wave_cutoff_m);  // (M.3.11)
  }
  return 0.0;
}

double FrequencySpectrum::moment(int n) const {
  assert(n >= -1 && n <= 2);  // the moments that converge to the stated accuracy
  // ∫ωⁿS(ω)dω = ∫ω^(n+1)S(ω)du with ω = ωp·e^u: composite Simpson on u ∈ [ln 0.02, ln 5000].
  // Below 0.02·ωp every model is < e^(−10⁶)·peak; above 5000·ωp the ω⁻⁵ tail leaves < 1e-14
  // of m0 and < 1e-7 of m2.
  constexpr int kIntervals = 40000;  // even
  const double u0 = std::log(0.02);
  const double u1 = std::log(5000.0);
  const double h = (u1 - u0) / kIntervals;
  double sum = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double omega = omega_p_ * std::exp(u0 + h * i);
    const double f = std::pow(omega, n + 1) * (*this)(omega);
    const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += weight * f;
  }
  return sum * h / 3.0;
}

Result<FrequencySpectrumParams> resolve(const SpectrumInputs& in) {
  FrequencySpectrumParams p;
  Result<SpectrumModel> model = parse_spectrum_model(in.model);
  if (!model.ok()) return Status(model.status().code(), "--model: " + model.status().message());
  p.model = model.value();
  // Each number with the field that names its flag in kSeaStateParameters.
  const std::tuple<std::string_view, const std::optional<double>*, double*> numbers[] = {
      {"significant_wave_height_m", &in.hs, &p.significant_wave_height_m},
      {"peak_period_s", &in.tp, &p.peak_period_s},
      {"wind_speed_mps", &in.wind_speed, &p.wind_speed_mps},
      {"fetch_m", &in.fetch, &p.fetch_m},
      {"depth_m", &in.depth, &p.depth_m},
      {"gravity_mps2", &in.gravity, &p.gravity_mps2},
      {"phillips_amplitude", &in.phillips_amplitude, &p.phillips_amplitude},
      {"small_wave_cutoff_m", &in.cutoff_length, &p.small_wave_cutoff_m},
      {"gamma", &in.gamma, &p.gamma}};
  for (const auto& [field, given, value] : numbers) {
    if (!given->has_value()) continue;
    // Any number but NaN: FrequencySpectrum::make checks the values and names the fields.
    if (std::isnan(**given)) return require_finite(sea_state_parameter(field).flag, **given);
    *value = **given;
  }
  Result<DepthFactor> depth_factor =
      parse_name("--depth-factor", kDepthFactorNames, in.depth_factor);
  if (!depth_factor.ok()) return depth_factor.status();
  p.depth_factor = depth_factor.value();
  Result<FetchLaw> fetch_law = parse_name("--fetch-law", kFetchLawNames, in.fetch_law);
  if (!fetch_law.ok()) return fetch_law.status();
  p.fetch_law = fetch_law.value();
  Result<JonswapNormalization> normalization =
      parse_name("--normalization", kJonswapNormalizationNames, in.normalization);
  if (!normalization.ok()) return normalization.status();
  p.normalization = normalization.value();
  if (!in.hs && !in.tp && !in.wind_speed) {
    // The default sea state: a fresh breeze over a long fetch.
    p.wind_speed_mps = kDefaultWindSpeedMps;
    if ((p.model == SpectrumModel::jonswap || p.model == SpectrumModel::tma) && !in.fetch)
      p.fetch_m = kDefaultFetchM;
  }
  if (p.model == SpectrumModel::tma && !in.depth) {
    return invalid_argument("tma needs " + std::string(sea_state_parameter("depth_m").flag) +
                            " (water depth, m)");
  }
  return p;
}

}  // namespace ocean
