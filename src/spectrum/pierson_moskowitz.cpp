// Pierson–Moskowitz spectrum: the fully developed sea, in its wind form and its Hs/Tp
// (Bretschneider, ITTC/IEC) form.
//
// This work is based on:
//   - Pierson, W. J. & Moskowitz, L. (1964) A proposed spectral form for fully developed wind
//     seas based on the similarity theory of S. A. Kitaigorodskii. J. Geophys. Res. 69(24).
//     α = 8.1e-3, β = 0.74, ω0 = g/U19.5.
//   - Bretschneider, C. L. (1959); ITTC (1978); IEC TS 62600-2 / DNV-RP-C205 §3.5.5.1:
//     S(ω) = 5/16·Hs²·ωp⁴·ω⁻⁵·exp(−5/4·(ωp/ω)⁴).
// Equations: docs/math.md (M.3.1)–(M.3.3).
#include <cmath>

#include "internal.hpp"

namespace ocean {

namespace {
constexpr double kPmAlpha = 8.1e-3;  // Phillips constant of Pierson & Moskowitz (1964)
constexpr double kPmBeta = 0.74;     // their low-frequency shape constant
}  // namespace

double pm_spectrum(double scale, double r, double beta) {
  if (!(r > 0.0)) return 0.0;  // ω = ∞
  const double r4 = (r * r) * (r * r);
  // Beyond β·r⁴ = 2000 the value is below 1e-800 for every scale < 1e20 (and β > 1e-100): 0 in
  // double precision. This also covers r⁴ = ∞ (ω → 0), where r⁵·e^(−β·r⁴) would be ∞·0.
  if (beta * r4 > 2000.0) return 0.0;
  // Near the peak, the plain product (r⁵ ≥ 1e-300 and e^(−β·r⁴) ≥ 1e-304 are normal numbers).
  if (r >= 1e-60 && beta * r4 <= 700.0) return scale * (r4 * r) * std::exp(-beta * r4);
  // Far out on either side one factor would underflow before the product does: join them in
  // one exponent so that S reaches 0 through the denormals.
  return std::exp(std::log(scale) + 5.0 * std::log(r) - beta * r4);
}

double pierson_moskowitz_wind(double omega, double wind_speed_mps, double gravity_mps2) {
  if (!(omega > 0.0)) return 0.0;
  // α·g²/ω⁵·exp(−β(ω0/ω)⁴) = α·g²/ω0⁵ · r⁵·exp(−β·r⁴), r = ω0/ω   (M.3.1)
  const double omega0 = gravity_mps2 / wind_speed_mps;
  const double g2 = gravity_mps2 * gravity_mps2;
  return pm_spectrum(kPmAlpha * g2 / std::pow(omega0, 5.0), omega0 / omega, kPmBeta);
}

double pierson_moskowitz_hs_tp(double omega, double hs_m, double tp_s) {
  if (!(omega > 0.0)) return 0.0;
  // 5/16·Hs²·ωp⁴/ω⁵·exp(−5/4·(ωp/ω)⁴) = 5/16·Hs²/ωp · r⁵·exp(−5/4·r⁴), r = ωp/ω   (M.3.3)
  const double omega_p = 2.0 * kPi / tp_s;
  return pm_spectrum(5.0 / 16.0 * hs_m * hs_m / omega_p, omega_p / omega, 1.25);
}

/// Peak of the wind form: dS/dω = 0 at ω⁴ = 4β/5·ω0⁴   (M.3.2)
double pierson_moskowitz_peak_omega(double wind_speed_mps, double gravity_mps2) {
  return std::pow(0.8 * kPmBeta, 0.25) * gravity_mps2 / wind_speed_mps;
}

double pierson_moskowitz_alpha() { return kPmAlpha; }
double pierson_moskowitz_beta() { return kPmBeta; }

}  // namespace ocean
