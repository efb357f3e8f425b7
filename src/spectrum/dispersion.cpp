// Linear water-wave dispersion: gravity–capillary waves on water of finite depth.
//
// This work is based on:
//   - Lamb, H. (1932) Hydrodynamics, 6th ed., §228 and §267 (ω² = (gk + σk³/ρ)·tanh kh).
//   - Eckart, C. (1952) The propagation of gravity waves from deep to shallow water, for the
//     explicit starting guess k ≈ (ω²/g)/√tanh(ω²h/g).
//   - Tessendorf, J. (2001) Simulating Ocean Water, §3.2, and Aebi, VR Ocean, eq. 16 (loop
//     quantisation).
// Equations: docs/math.md §2 (M.2.1–M.2.4).
#include <cmath>

#include "ocean/spectrum.hpp"

namespace ocean {

Result<Dispersion> Dispersion::make(const DispersionParams& params) {
  if (Status s = require_positive("gravity_mps2", params.gravity_mps2); !s.ok()) return s;
  if (!(params.depth_m > 0.0)) {
    return invalid_argument("depth_m = " + format_number(params.depth_m) +
                            " is out of range: must be > 0 (inf for deep water)");
  }
  if (Status s = require_non_negative("capillarity_m3ps2", params.capillarity_m3ps2); !s.ok()) {
    return s;
  }
  Dispersion d;
  d.params_ = params;
  return d;
}

namespace {
// tanh(kh) and kh·sech²(kh) with the deep-water limits taken exactly.
struct DepthTerms {
  double tanh_kh;
  double kh_sech2_kh;
};
DepthTerms depth_terms(double k, double depth_m) {
  if (std::isinf(depth_m)) return {1.0, 0.0};
  const double kh = k * depth_m;
  if (kh > 40.0) return {1.0, 0.0};  // tanh = 1 and kh·sech² < 1e-32 in double precision
  const double c = std::cosh(kh);
  return {std::tanh(kh), kh / (c * c)};
}
}  // namespace

double Dispersion::omega(double k) const {
  if (k <= 0.0) return 0.0;
  const double g = params_.gravity_mps2;
  const double tension = params_.capillarity_m3ps2;
  const DepthTerms d = depth_terms(k, params_.depth_m);
  return std::sqrt((g * k + tension * k * k * k) * d.tanh_kh);  // (M.2.1)
}

double Dispersion::group_velocity(double k) const {
  const double g = params_.gravity_mps2;
  const double tension = params_.capillarity_m3ps2;
  if (k <= 0.0) {
    // Long-wave limit: √(g·h) in finite depth; unbounded in deep water.
    return std::isinf(params_.depth_m) ? std::numeric_limits<double>::infinity()
                                       : std::sqrt(g * params_.depth_m);
  }
  const DepthTerms d = depth_terms(k, params_.depth_m);
  const double w = omega(k);
  // d(ω²)/dk = (g + 3Tk²)·tanh kh + (g + Tk²)·kh·sech² kh;  dω/dk = that / 2ω   (M.2.3)
  const double dw2 =
      (g + 3.0 * tension * k * k) * d.tanh_kh + (g + tension * k * k) * d.kh_sech2_kh;
  return dw2 / (2.0 * w);
}

double Dispersion::wavenumber(double omega_rad) const {
  if (!(omega_rad > 0.0)) return 0.0;
  const double g = params_.gravity_mps2;
  const double target = omega_rad * omega_rad;
  const auto residual = [&](double k) {
    const double w = omega(k);
    return w * w - target;
  };
  // Starting guess (M.2.2): Eckart's explicit form for gravity waves.
  const double k_deep = target / g;
  double k = k_deep;
  if (std::isfinite(params_.depth_m)) k = k_deep / std::sqrt(std::tanh(k_deep * params_.depth_m));
  // ω²(k) is strictly increasing: bracket the root, then Newton steps kept inside the bracket.
  double lo = k;
  double hi = k;
  while (residual(lo) > 0.0) lo *= 0.5;
  while (residual(hi) < 0.0) hi *= 2.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double f = residual(k);
    if (f == 0.0) return k;
    if (f < 0.0)
      lo = k;
    else
      hi = k;
    const double slope = 2.0 * omega(k) * group_velocity(k);  // d(ω²)/dk
    double next = k - f / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::abs(next - k) <= 1e-15 * k) return next;
    k = next;
  }
  return k;
}

double quantize_omega(double omega, double loop_period_s) {
  const double omega0 = 2.0 * kPi / loop_period_s;  // (M.2.4)
  return std::floor(omega / omega0) * omega0;
}

EvolutionPhase::EvolutionPhase(double time_s, double loop_period_s) : time_s_(time_s) {
  if (loop_period_s > 0.0) {
    omega0_ = 2.0 * kPi / loop_period_s;
    const double cycles = time_s / loop_period_s;
    tau_ = cycles - std::floor(cycles);
  }
}

namespace {
// ω' is an exact multiple j of ω0: keep the integer so the phase stays exact (M.7.3).
double harmonic(double omega, double omega0) {
  return static_cast<double>(std::lround(omega / omega0));
}
}  // namespace

double EvolutionPhase::rate(double omega, double loop_period_s) {
  return loop_period_s > 0.0 ? harmonic(omega, 2.0 * kPi / loop_period_s) : omega / (2.0 * kPi);
}

double EvolutionPhase::operator()(double omega) const {
  if (omega0_ > 0.0) {
    const double turns = harmonic(omega, omega0_) * tau_;
    return 2.0 * kPi * (turns - std::floor(turns));
  }
  return std::fmod(omega * time_s_, 2.0 * kPi);
}

}  // namespace ocean
