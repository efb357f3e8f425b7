// The slope variance of the waves shorter than a grid resolves, from the unified directional
// spectrum of Elfouhaily, Chapron, Katsaros & Vandemark (1997), J. Geophys. Res. 102(C7),
// 15781–15796 (docs/math.md §9). Equation numbers are the paper's.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ocean/spectrum.hpp"

namespace ocean {

namespace {

constexpr double kCapillaryWavenumber = 370.0;  // k_m, rad/m: the gravity–capillary minimum
constexpr double kCapillaryPhaseSpeed = 0.23;   // c_m, m/s

double phase_speed(double k, double g) { return capillary_gravity_phase_speed(k, g); }

// Friction velocity u* = √C_D·U10 with Wu's drag coefficient C_D = (0.8 + 0.065·U10)·10⁻³ (Wu
// 1982, "Wind-stress coefficients over sea surface from breeze to hurricane", J. Geophys. Res.
// 87(C12), eq. 5).
double friction_velocity(double u10) { return std::sqrt((0.8 + 0.065 * u10) * 1e-3) * u10; }

// The quantile q ∈ [0, 1) of the spreading over the half circle, φ ∈ [−π/2, π/2): the root of
// F(φ) = (φ + π/2)/π + Δ·sin 2φ/(2π) = q. F is increasing (F' = (1 + Δ·cos 2φ)/π > 0 for Δ < 1):
// bisection to double precision.
double spreading_quantile(double q, double delta) {
  double lo = -0.5 * kPi, hi = 0.5 * kPi;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double f = (mid + 0.5 * kPi) / kPi + delta * std::sin(2.0 * mid) / (2.0 * kPi);
    (f < q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

// Phase speed of gravity–capillary waves in deep water, c = √(g/k·(1 + (k/k_m)²)) (eq. 4).
double capillary_gravity_phase_speed(double k, double g) {
  const double r = k / kCapillaryWavenumber;
  return std::sqrt(g / k * (1.0 + r * r));
}

double ShortWaveComponent::slope_variance() const {
  const double ak = amplitude_m * std::hypot(kx_radpm, kz_radpm);
  return 0.5 * ak * ak;
}

CurvatureSample elfouhaily_curvature(double k, const ShortWaveParams& p) {
  const double g = p.gravity_mps2;
  const double u10 = p.wind_speed_mps;
  const double omega = p.inverse_wave_age;
  const double kp = g * omega * omega / (u10 * u10);  // k_p = k0·Ω², k0 = g/U10² (eq. 3)
  const double cp = phase_speed(kp, g);
  const double c = phase_speed(k, g);
  const double us = friction_velocity(u10);
  // The long waves' peak: the Pierson–Moskowitz shape L_PM and JONSWAP's enhancement J_p.
  const double l_pm = std::exp(-1.25 * (kp / k) * (kp / k));                // eq. 2
  const double gamma = omega <= 1.0 ? 1.7 : 1.7 + 6.0 * std::log10(omega);  // eq. 3
  const double sigma = 0.08 * (1.0 + 4.0 / (omega * omega * omega));        // eq. 3
  const double x = std::sqrt(k / kp) - 1.0;
  const double j_p = std::pow(gamma, std::exp(-x * x / (2.0 * sigma * sigma)));  // eq. 3
  // Long waves: B_l = ½·α_p·(c_p/c)·F_p, α_p = 6·10⁻³·√Ω (eqs. 31–34).
  const double f_p = l_pm * j_p * std::exp(-omega / std::sqrt(10.0) * x);
  const double b_l = 0.5 * 6e-3 * std::sqrt(omega) * (cp / c) * f_p;
  // Short waves: B_h = ½·α_m·(c_m/c)·F_m, α_m from u*/c_m (eqs. 40–44).
  const double r = k / kCapillaryWavenumber - 1.0;
  const double f_m = l_pm * j_p * std::exp(-0.25 * r * r);
  const double ratio = us / kCapillaryPhaseSpeed;
  const double alpha_m =
      0.01 * (ratio <= 1.0 ? 1.0 + std::log(ratio) : 1.0 + 3.0 * std::log(ratio));
  const double b_h = 0.5 * alpha_m * (kCapillaryPhaseSpeed / c) * f_m;
  // Spreading: Δ = tanh(a0 + a_p·(c/c_p)^2.5 + a_m·(c_m/c)^2.5), a0 = ln 2/4, a_p = 4,
  // a_m = 0.13·u*/c_m (eqs. 57, 59).
  const double delta = std::tanh(std::log(2.0) / 4.0 + 4.0 * std::pow(c / cp, 2.5) +
                                 0.13 * ratio * std::pow(kCapillaryPhaseSpeed / c, 2.5));
  return {.curvature = std::max(b_l + b_h, 0.0), .spreading = delta};
}

Result<SlopeVariance> short_wave_slope_variance(const ShortWaveParams& p) {
  if (Status s = require_in_range("wind_speed_mps", p.wind_speed_mps, 0.5, 60.0); !s.ok()) return s;
  if (Status s = require_non_negative("grid_nyquist_radpm", p.grid_nyquist_radpm); !s.ok())
    return s;
  if (Status s = require_finite("wind_direction_rad", p.wind_direction_rad); !s.ok()) return s;
  if (Status s = require_in_range("inverse_wave_age", p.inverse_wave_age, 0.84, 5.0); !s.ok())
    return s;
  if (Status s = require_positive("gravity_mps2", p.gravity_mps2); !s.ok()) return s;

  // ⟨s_u²⟩ = ∫∫ k²·F(k)·cos²φ, F(k, φ) = k⁻⁴·B(k)·Φ(k, φ): over ln k the integrand is B(k) times
  // the share of the direction integral that lies outside the grid's square (eq. 49's
  // Φ = (1 + Δ·cos 2φ)/2π; over a whole circle ∫cos²φ·Φ dφ = ½ + Δ/4).
  const double a = p.grid_nyquist_radpm;
  const double k_lo = a > 0.0 ? a : 1e-4;
  const double k_hi = std::max(2e4, 4.0 * k_lo);  // F_m is below e⁻³⁰⁰ of its peak beyond
  constexpr int kSteps = 2000;                    // Simpson over ln k, even
  constexpr int kAngles = 360;                    // midpoints over φ, where the square cuts
  const double h = std::log(k_hi / k_lo) / kSteps;
  SlopeVariance out;
  for (int i = 0; i <= kSteps; ++i) {
    const double k = k_lo * std::exp(h * i);
    const CurvatureSample b = elfouhaily_curvature(k, p);
    double up = 0.0, cross = 0.0;
    if (a == 0.0 || k >= std::sqrt(2.0) * a) {
      up = 0.5 + 0.25 * b.spreading;
      cross = 0.5 - 0.25 * b.spreading;
    } else {
      for (int j = 0; j < kAngles; ++j) {
        const double phi = (j + 0.5) * 2.0 * kPi / kAngles;  // from the wind
        const double on_grid = phi + p.wind_direction_rad;
        if (std::max(std::abs(std::cos(on_grid)), std::abs(std::sin(on_grid))) * k <= a) continue;
        const double w = (1.0 + b.spreading * std::cos(2.0 * phi)) / kAngles;
        up += w * std::cos(phi) * std::cos(phi);
        cross += w * std::sin(phi) * std::sin(phi);
      }
    }
    const double simpson = (i == 0 || i == kSteps) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    out.upwind += simpson * b.curvature * up;
    out.crosswind += simpson * b.curvature * cross;
  }
  out.upwind *= h / 3.0;
  out.crosswind *= h / 3.0;
  return out;
}

Result<std::vector<ShortWaveComponent>> short_wave_components(const ShortWaveComponentParams& p) {
  const ShortWaveParams& w = p.waves;
  if (Status s = require_in_range("wind_speed_mps", w.wind_speed_mps, 0.5, 60.0); !s.ok()) return s;
  if (Status s = require_finite("wind_direction_rad", w.wind_direction_rad); !s.ok()) return s;
  if (Status s = require_in_range("inverse_wave_age", w.inverse_wave_age, 0.84, 5.0); !s.ok())
    return s;
  if (Status s = require_positive("gravity_mps2", w.gravity_mps2); !s.ok()) return s;
  if (Status s = require_in_range("k_min_radpm", p.k_min_radpm, 1e-3, 2e4); !s.ok()) return s;
  if (Status s = require_in_range("k_max_radpm", p.k_max_radpm, 1e-3, 2e4); !s.ok()) return s;
  if (!(p.k_max_radpm > p.k_min_radpm))
    return invalid_argument("k_max_radpm = " + format_number(p.k_max_radpm) +
                            " must exceed k_min_radpm = " + format_number(p.k_min_radpm));
  if (p.bins < 1 || p.bins > 64)
    return invalid_argument("bins = " + std::to_string(p.bins) + " is outside [1, 64]");
  if (p.per_bin < 1 || p.per_bin > 16)
    return invalid_argument("per_bin = " + std::to_string(p.per_bin) + " is outside [1, 16]");

  const double step = std::log(p.k_max_radpm / p.k_min_radpm) / p.bins;
  constexpr int kSubSteps = 32;  // Simpson over each bin's ln k, even
  std::vector<ShortWaveComponent> out;
  out.reserve(static_cast<std::size_t>(p.bins * p.per_bin));
  std::uint64_t draw = 0;
  for (int b = 0; b < p.bins; ++b) {
    const double ln_lo = std::log(p.k_min_radpm) + b * step;
    double variance = 0.0;  // ∫ B(k) d ln k over the bin: every direction's slopes
    for (int i = 0; i <= kSubSteps; ++i) {
      const double k = std::exp(ln_lo + step * i / kSubSteps);
      const double simpson = (i == 0 || i == kSubSteps) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      variance += simpson * elfouhaily_curvature(k, w).curvature;
    }
    variance *= step / kSubSteps / 3.0;
    const double slope_amplitude = std::sqrt(2.0 * variance / p.per_bin);  // a·k of each wave
    const double offset = uniform_draw(p.seed, draw++);
    for (int j = 0; j < p.per_bin; ++j) {
      const double k = std::exp(ln_lo + step * uniform_draw(p.seed, draw++));
      const double phi = spreading_quantile((j + offset) / p.per_bin,
                                            elfouhaily_curvature(k, w).spreading);
      const double heading = w.wind_direction_rad + phi;
      out.push_back({.kx_radpm = k * std::cos(heading),
                     .kz_radpm = k * std::sin(heading),
                     .amplitude_m = slope_amplitude / k,
                     .omega_radps = k * capillary_gravity_phase_speed(k, w.gravity_mps2),
                     .phase_rad = 2.0 * kPi * uniform_draw(p.seed, draw++)});
    }
  }
  std::sort(out.begin(), out.end(), [](const ShortWaveComponent& a, const ShortWaveComponent& b) {
    return std::hypot(a.kx_radpm, a.kz_radpm) < std::hypot(b.kx_radpm, b.kz_radpm);
  });
  return out;
}

}  // namespace ocean
