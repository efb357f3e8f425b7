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

#include "ocean/spectrum.hpp"

namespace ocean {

namespace {
constexpr double kPmAlpha = 8.1e-3;  // Phillips constant of Pierson & Moskowitz (1964)
constexpr double kPmBeta = 0.74;     // their low-frequency shape constant
}  // namespace

double pierson_moskowitz_wind(double omega, double wind_speed_mps, double gravity_mps2) {
  if (!(omega > 0.0)) return 0.0;
  const double omega0 = gravity_mps2 / wind_speed_mps;
  const double ratio4 = std::pow(omega0 / omega, 4.0);
  return kPmAlpha * gravity_mps2 * gravity_mps2 / std::pow(omega, 5.0) *
         std::exp(-kPmBeta * ratio4);  // (M.3.1)
}

double pierson_moskowitz_hs_tp(double omega, double hs_m, double tp_s) {
  if (!(omega > 0.0)) return 0.0;
  const double omega_p = 2.0 * kPi / tp_s;
  const double ratio4 = std::pow(omega_p / omega, 4.0);
  return 5.0 / 16.0 * hs_m * hs_m * ratio4 / omega * std::exp(-1.25 * ratio4);  // (M.3.3)
}

/// Peak of the wind form: dS/dω = 0 at ω⁴ = 4β/5·ω0⁴   (M.3.2)
double pierson_moskowitz_peak_omega(double wind_speed_mps, double gravity_mps2) {
  return std::pow(0.8 * kPmBeta, 0.25) * gravity_mps2 / wind_speed_mps;
}

double pierson_moskowitz_alpha() { return kPmAlpha; }
double pierson_moskowitz_beta() { return kPmBeta; }

}  // namespace ocean
