// Linear water-wave dispersion: gravity–capillary waves on water of finite depth.
//
// This work is based on:
//   - Lamb, H. (1932) Hydrodynamics, 6th ed., §228 and §267 (ω² = (gk + σk³/ρ)·tanh kh).
//   - Eckart, C. (1952) The propagation of gravity waves from deep to shallow water, for the
//     explicit starting guess k ≈ (ω²/g)/√tanh(ω²h/g).
//   - Press, W. H. et al. (2007) Numerical Recipes, 3rd ed., §9.4 (rtsafe: Newton–Raphson that
//     bisects whenever a step leaves the bracket or fails to halve the step before last).
//   - Tessendorf, J. (2001) Simulating Ocean Water, §3.2, and Aebi, VR Ocean, eq. 16 (loop
//     quantisation).
// Equations: docs/math.md §2 (M.2.1–M.2.5).
#include <algorithm>
#include <cassert>
#include <cmath>

#include "internal.hpp"

namespace ocean {

Status require_depth(double depth_m) {
  if (depth_m >= 1e-100) return {};  // the lower end of the domain, M.2.5; ∞ = deep water
  return invalid_argument("depth_m = " + format_number(depth_m) +
                          " is out of range: must be in [1e-100, inf] (inf for deep water)");
}

Result<Dispersion> Dispersion::make(const DispersionParams& params) {
  if (Status s = require_in_range("gravity_mps2", params.gravity_mps2, 0.1, 100.0); !s.ok()) {
    return s;
  }
  if (Status s = require_depth(params.depth_m); !s.ok()) return s;
  if (Status s = require_in_range("capillarity_m3ps2", params.capillarity_m3ps2, 0.0, 1.0);
      !s.ok()) {
    return s;
  }
  Dispersion d;
  d.params_ = params;
  return d;
}

namespace {

// The phase velocity c = ω/k and the ratio n = c_g/c = d ln ω / d ln k at one wavenumber k > 0,
// written so that no intermediate overflows or underflows on the domain (M.2.5):
//   c = √(g + T·k²)·√(tanh(kh)/k),  n = ½·[1 + 2·Tk²/(g + Tk²) + 2kh/sinh(2kh)]   (M.2.3)
struct Wave {
  double c;
  double n;
};

Wave wave(const DispersionParams& p, double k) {
  const double g = p.gravity_mps2;
  const double tension = p.capillarity_m3ps2;
  // √(g + T·k²) as a hypotenuse: T·k² alone overflows for k > 1e154.
  const double stiffness = std::hypot(std::sqrt(g), std::sqrt(tension) * k);
  const double tk2 = tension * k * k;
  const double capillary_share = tk2 < 1e300 ? tk2 / (g + tk2) : 1.0;  // Tk²/(g + Tk²) ∈ [0, 1)
  const double kh = k * p.depth_m;                                     // inf in deep water
  double c = 0.0;
  double depth_term = 0.0;  // 2kh/sinh(2kh) ∈ (0, 1]
  if (kh > 1.0) {
    c = stiffness * std::sqrt(std::tanh(kh)) / std::sqrt(k);
    depth_term = kh < 350.0 ? 2.0 * kh / std::sinh(2.0 * kh) : 0.0;  // < 1e-300 beyond
  } else {
    // tanh(x)/x and 2x/sinh(2x) tend to 1 as x → 0; below 1e-8 they are 1 in double precision.
    const double tanh_ratio = kh > 1e-8 ? std::tanh(kh) / kh : 1.0;
    c = stiffness * std::sqrt(p.depth_m * tanh_ratio);
    depth_term = kh > 1e-8 ? 2.0 * kh / std::sinh(2.0 * kh) : 1.0;
  }
  return {c, 0.5 * (1.0 + 2.0 * capillary_share + depth_term)};
}

[[maybe_unused]] bool in_domain(double k) {
  return k >= Dispersion::kMinWavenumber && k <= Dispersion::kMaxWavenumber;
}

}  // namespace

double Dispersion::omega(double k) const {
  if (k == 0.0) return 0.0;
  assert(in_domain(k));
  return k * wave(params_, k).c;  // (M.2.1)
}

double Dispersion::phase_velocity(double k) const {
  if (k == 0.0) {
    assert(std::isfinite(params_.depth_m));  // deep water has no finite long-wave limit
    return std::sqrt(params_.gravity_mps2 * params_.depth_m);
  }
  assert(in_domain(k));
  return wave(params_, k).c;
}

double Dispersion::group_velocity(double k) const {
  if (k == 0.0) return phase_velocity(0.0);  // long waves are not dispersive: c_g = c = √(gh)
  assert(in_domain(k));
  const Wave w = wave(params_, k);
  return w.n * w.c;  // (M.2.3)
}

double Dispersion::wavenumber(double omega_rad) const {
  if (omega_rad == 0.0) return 0.0;
  assert(omega_rad >= min_omega() && omega_rad <= max_omega());
  const DispersionParams& p = params_;
  // Solve F(u) = ln ω(e^u) − ln ω_target = 0 for u = ln k. F' = n = c_g/c ∈ [½, 2] everywhere
  // (M.2.3), so F is strictly increasing and the root lies between |F|/2 and 2·|F| from any
  // point, on the side F's sign says: a bracket that provably holds it (M.2.2).
  const double log_target = std::log(omega_rad);
  // Start (M.2.2): the smaller of the deep gravity and capillary roots (the deep gravity–capillary
  // root lies below it by at most a factor 2), then Eckart's depth correction.
  const double k_gravity = (omega_rad / std::sqrt(p.gravity_mps2)) *
                           (omega_rad / std::sqrt(p.gravity_mps2));  // ω²/g (inf when huge)
  const double k_capillary = p.capillarity_m3ps2 > 0.0
                                 ? std::pow(omega_rad / std::sqrt(p.capillarity_m3ps2), 2.0 / 3.0)
                                 : kMaxWavenumber;
  double k = std::clamp(std::min(k_gravity, k_capillary), kMinWavenumber, kMaxWavenumber);
  if (std::isfinite(p.depth_m)) {
    k = std::clamp(k / std::sqrt(std::tanh(k * p.depth_m)), kMinWavenumber, kMaxWavenumber);
  }
  // ln(ω(k)/ω_target) from the ratio where it is a normal number: near the root that is exact
  // to an ulp, where ln ω − ln ω_target would carry ln ω's rounding (1e-13 at ω = 1e300).
  const auto log_mismatch = [&](double at_k, double c) {
    const double ratio = at_k * c / omega_rad;
    return std::isnormal(ratio) ? std::log(ratio) : std::log(at_k * c) - log_target;
  };
  Wave w = wave(p, k);
  double f = log_mismatch(k, w.c);
  // The bracket [lo, hi] from the slope bounds, within the domain; rounding in F is a few 1e-16,
  // the reach gets that much slack.
  const double reach = 2.0 * std::abs(f) + 1e-14;
  double lo = std::max(f > 0.0 ? k * std::exp(-reach) : k, kMinWavenumber);
  double hi = std::min(f > 0.0 ? k : k * std::exp(reach), kMaxWavenumber);
  double last_step = std::log(hi / lo);
  double step_before_last = last_step;
  // Newton steps are taken while they stay inside the bracket, shrink fast (at most half the step
  // before last, as rtsafe) and the bracket has halved within the last two iterations; otherwise
  // bisect. So ln(hi/lo) ≤ ln(kMax/kMin) ≈ 921 halves at least every three iterations and falls
  // below 1e-15 within 3·log2(921e15) ≈ 180 of them: the loop always ends by converging.
  double width_mark = last_step;
  int since_halved = 0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (f == 0.0) return k;
    const double newton = -f / w.n;  // Newton step in u = ln k
    double next = k * std::exp(newton);
    double step = std::abs(newton);
    if (!(next > lo && next < hi) || step > 0.5 * step_before_last || since_halved >= 2) {
      next = std::sqrt(lo) * std::sqrt(hi);  // bisect in ln k
      step = 0.5 * std::log(hi / lo);
    }
    if (step <= 1e-15) return next;
    step_before_last = last_step;
    last_step = step;
    k = next;
    w = wave(p, k);
    f = log_mismatch(k, w.c);
    (f > 0.0 ? hi : lo) = k;
    const double width = std::log(hi / lo);
    if (width <= 0.5 * width_mark) {
      width_mark = width;
      since_halved = 0;
    } else {
      ++since_halved;
    }
  }
  assert(false && "the safeguarded Newton iteration converges within 200 steps");
  return k;
}

Status Dispersion::check_wavenumber(std::string_view name, double k) {
  return require_in_range(name, k, kMinWavenumber, kMaxWavenumber);
}

Status Dispersion::check_omega(std::string_view name, double omega_rad) const {
  return require_in_range(name, omega_rad, min_omega(), max_omega());
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
// ω' is an exact multiple j of ω0: keep the integer so the phase stays exact (M.7.3). std::round,
// not lround: j beyond the range of long would make lround's result unspecified.
double harmonic(double omega, double omega0) { return std::round(omega / omega0); }
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
