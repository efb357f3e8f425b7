// Directional spreading functions D(ω, θ), each normalised so that ∫D dθ = 1 over (−π, π].
//
// This work is based on:
//   - Longuet-Higgins, M. S., Cartwright, D. E. & Smith, N. D. (1963) Observations of the
//     directional spectrum of sea waves using the motions of a floating buoy: cos-2s form and
//     its normaliser Γ(s+1)/(2√π·Γ(s+½)).
//   - Mitsuyasu, H. et al. (1975) Observations of the directional spectrum of ocean waves using a
//     cloverleaf buoy. J. Phys. Oceanogr. 5: s = s_max·(f/fp)^5 (f ≤ fp), s_max·(f/fp)^−2.5
//     (f > fp), s_max = 11.5·(2π·fp·U10/g)^−2.5.
//   - Hasselmann, D. E., Dunckel, M. & Ewing, J. A. (1980) Directional wave spectra observed
//     during JONSWAP 1973. J. Phys. Oceanogr. 10: s = 6.97·(f/fp)^4.06 (f < 1.05·fp),
//     9.77·(f/fp)^μ with μ = −2.33 − 1.45·(U10/cp − 1.17) (f ≥ 1.05·fp).
//   - Donelan, M. A., Hamilton, J. & Hui, W. H. (1985) Directional spectra of wind-generated
//     waves. Phil. Trans. R. Soc. A 315; Banner, M. L. (1990) Equilibrium spectra of wind waves.
//     J. Phys. Oceanogr. 20 (β_s = 10^ε, ε = −0.4 + 0.8393·exp(−0.567·ln((ω/ωp)²)) above 1.6·ωp);
//     Vincevičius 2024, eq. 1.13 (which uses the first branch for all ω/ωp < 0.95).
//   - Aebi, VR Ocean, §3.2.2–3.2.3: power-cosine |cos θ|^s(α), s(α) = 1 + 5α², counter-wave energy
//     σ(α) = 0.01 + 0.49(1 − α)².
// Equations: docs/math.md §4.
#include <cmath>
#include <optional>
#include <string>

#include "ocean/spectrum.hpp"

namespace ocean {

std::string_view to_string(SpreadingModel model) { return name_of(kSpreadingModelNames, model); }

Result<SpreadingModel> parse_spreading_model(std::string_view name) {
  if (std::optional<SpreadingModel> m = value_of(kSpreadingModelNames, name)) return *m;
  return invalid_argument("spreading model = '" + excerpt(name) + "' is unknown: must be one of " +
                          name_list(kSpreadingModelNames, ", ", ", "));
}

namespace {
// Γ(x+1)/Γ(x+½) for x ≥ 0. Through log-gamma up to x = 128; beyond, lgamma's rounding (~x·ln x
// ulps) would grow and for x ≥ 2^53 the two arguments round to one number, so the asymptotic
// series √x·(1 + 1/(8x) + 1/(128x²) − 5/(1024x³) − 21/(32768x⁴)) (DLMF §5.11(iii), eq. 5.11.13
// with a = 1, b = ½) takes over: its error is 1.5e-3/x⁵ < 5e-14 there. Finite for every finite x.
double gamma_ratio_half(double x) {
  if (x <= 128.0) return std::exp(std::lgamma(x + 1.0) - std::lgamma(x + 0.5));
  const double u = 1.0 / x;
  return std::sqrt(x) *
         (1.0 + u * (1.0 / 8 + u * (1.0 / 128 + u * (-5.0 / 1024 + u * (-21.0 / 32768)))));
}
}  // namespace

double cos2s_normalization(double s) {
  return gamma_ratio_half(s) / (2.0 * std::sqrt(kPi));  // Γ(s+1)/(2√π·Γ(s+½))   (M.4.3)
}

double power_cosine_integral(double s, double sigma_back) {
  // ∫_{−π/2}^{π/2} cos^s θ dθ = √π·Γ((s+1)/2)/Γ(s/2+1); the back half adds σ times that  (M.4.2)
  return (1.0 + sigma_back) * std::sqrt(kPi) / gamma_ratio_half(0.5 * s);
}

double donelan_banner_beta(double omega_ratio) {
  const double r = omega_ratio;  // (M.4.6)
  if (r < 0.95) return 2.61 * std::pow(r, 1.3);
  if (r < 1.6) return 2.28 * std::pow(r, -1.3);
  const double epsilon = -0.4 + 0.8393 * std::exp(-0.567 * std::log(r * r));
  return std::pow(10.0, epsilon);
}

namespace {

bool is_set(double v) { return !std::isnan(v); }

double wrap_angle(double theta) {
  double t = std::remainder(theta, 2.0 * kPi);  // in [−π, π]
  if (t <= -kPi) t += 2.0 * kPi;
  return t;
}

double cos2s(double s, double theta) {
  return cos2s_normalization(s) * std::pow(std::abs(std::cos(0.5 * theta)), 2.0 * s);  // (M.4.3)
}

}  // namespace

Result<Spreading> Spreading::make(const SpreadingParams& params, const SpreadingContext& context) {
  Spreading d;
  d.params_ = params;
  d.context_ = context;
  const std::string model(to_string(params.model));
  if (is_set(params.s)) {
    if (params.model != SpreadingModel::power_cosine && params.model != SpreadingModel::cos2s) {
      return invalid_argument("s applies only to power-cosine and cos2s spreading (" + model +
                              " derives its exponent from ω/ωp)");
    }
    if (Status s = require_in_range("s", params.s, 0.0, 1000.0); !s.ok()) return s;
  }
  if (Status s = require_in_range("alpha", params.alpha, 0.0, 1.0); !s.ok()) return s;
  const bool needs_peak = params.model == SpreadingModel::mitsuyasu ||
                          params.model == SpreadingModel::hasselmann ||
                          params.model == SpreadingModel::donelan_banner;
  const bool needs_wind =
      params.model == SpreadingModel::mitsuyasu || params.model == SpreadingModel::hasselmann;
  if (needs_peak) {
    if (!is_set(context.omega_p)) {
      return invalid_argument(model + " spreading needs the peak frequency omega_p");
    }
    if (Status s = require_positive("omega_p", context.omega_p); !s.ok()) return s;
  }
  if (needs_wind) {
    if (!is_set(context.wind_speed_mps)) {
      return invalid_argument(model + " spreading needs wind_speed_mps");
    }
    if (Status s = require_in_range("wind_speed_mps", context.wind_speed_mps, 1e-3, 100.0);
        !s.ok()) {
      return s;
    }
    if (Status s = require_in_range("gravity_mps2", context.gravity_mps2, 0.1, 100.0); !s.ok()) {
      return s;
    }
  }
  switch (params.model) {
    case SpreadingModel::power_cosine: {
      const double s = is_set(params.s) ? params.s : 1.0 + 5.0 * params.alpha * params.alpha;
      const double one_minus = 1.0 - params.alpha;
      d.sigma_back_ = params.counter_wave_suppression ? 0.01 + 0.49 * one_minus * one_minus : 1.0;
      d.norm_ = 1.0 / power_cosine_integral(s, d.sigma_back_);  // (M.4.1)
      d.params_.s = s;
      break;
    }
    case SpreadingModel::cos2s:
      if (!is_set(params.s))
        return invalid_argument("cos2s spreading needs s (e.g. 10 to 80 for swell)");
      d.norm_ = cos2s_normalization(params.s);
      break;
    case SpreadingModel::mitsuyasu:
      d.s_max_ = 11.5 * std::pow(context.wind_speed_mps * context.omega_p / context.gravity_mps2,
                                 -2.5);  // (M.4.4)
      break;
    case SpreadingModel::hasselmann:
    case SpreadingModel::donelan_banner: break;
  }
  return d;
}

double Spreading::spread_parameter(double omega) const {
  const double r = omega / context_.omega_p;
  switch (params_.model) {
    case SpreadingModel::power_cosine:
    case SpreadingModel::cos2s: return params_.s;
    case SpreadingModel::mitsuyasu:
      return r <= 1.0 ? s_max_ * std::pow(r, 5.0) : s_max_ * std::pow(r, -2.5);
    case SpreadingModel::hasselmann: {
      if (r < 1.05) return 6.97 * std::pow(r, 4.06);               // (M.4.5)
      const double cp = context_.gravity_mps2 / context_.omega_p;  // deep-water phase speed
      const double mu = -2.33 - 1.45 * (context_.wind_speed_mps / cp - 1.17);
      return 9.77 * std::pow(r, mu);
    }
    case SpreadingModel::donelan_banner: return donelan_banner_beta(r);
  }
  return 0.0;
}

double Spreading::operator()(double omega, double theta) const {
  const double t = wrap_angle(theta);
  switch (params_.model) {
    case SpreadingModel::power_cosine: {
      const double c = std::cos(t);
      const double w = c < 0.0 ? sigma_back_ : 1.0;
      return norm_ * w * std::pow(std::abs(c), params_.s);  // (M.4.1)
    }
    case SpreadingModel::cos2s:
      return norm_ * std::pow(std::abs(std::cos(0.5 * t)), 2.0 * params_.s);
    case SpreadingModel::mitsuyasu:
    case SpreadingModel::hasselmann: return cos2s(spread_parameter(omega), t);
    case SpreadingModel::donelan_banner: {
      const double beta = spread_parameter(omega);
      if (beta < 1e-8) return 1.0 / (2.0 * kPi);  // limit β→0: uniform
      const double sech = 1.0 / std::cosh(beta * t);
      return beta / (2.0 * std::tanh(beta * kPi)) * sech * sech;  // (M.4.6)
    }
  }
  return 0.0;
}

}  // namespace ocean
