// JONSWAP: the fetch-limited wind sea, as a peak-enhanced Pierson–Moskowitz spectrum.
//
// This work is based on:
//   - Hasselmann, K. et al. (1973) Measurements of wind-wave growth and swell decay during the
//     Joint North Sea Wave Project (JONSWAP). Dtsch. Hydrogr. Z. A8(12): α = 0.076·x̃^−0.22,
//     fp = 3.5·(g/U10)·x̃^−0.33 with x̃ = gF/U10², γ = 3.3, σa = 0.07, σb = 0.09.
//   - Vincevičius 2024, eq. 1.9: ωp = 22·(g²/(U10·F))^(1/3) (selectable as FetchLaw::cube_root).
//   - DNV-RP-C205 (2010) §3.5.5: Hs/Tp form with A_γ = 1 − 0.287·ln γ and the rule
//     γ = 5 (Tp/√Hs ≤ 3.6), exp(5.75 − 1.15·Tp/√Hs) (3.6 < Tp/√Hs < 5), 1 (Tp/√Hs ≥ 5).
// Equations: docs/math.md (M.3.4)–(M.3.8).
#include <cmath>

#include "ocean/spectrum.hpp"

namespace ocean {

double jonswap_gamma_dnv(double hs_m, double tp_s) {
  const double ratio = tp_s / std::sqrt(hs_m);  // (M.3.6), Hs in m, Tp in s
  if (ratio <= 3.6) return 5.0;
  if (ratio >= 5.0) return 1.0;
  return std::exp(5.75 - 1.15 * ratio);
}

std::array<double, 2> jonswap_fetch_law(double wind_speed_mps, double fetch_m, double gravity_mps2,
                                        FetchLaw law) {
  const double g = gravity_mps2;
  const double u = wind_speed_mps;
  const double fetch_nd = g * fetch_m / (u * u);           // dimensionless fetch x̃ = gF/U²
  const double alpha = 0.076 * std::pow(fetch_nd, -0.22);  // (M.3.7)
  double omega_p = 0.0;
  if (law == FetchLaw::hasselmann_1973) {
    omega_p = 2.0 * kPi * 3.5 * (g / u) * std::pow(fetch_nd, -0.33);  // (M.3.8)
  } else {
    omega_p = 22.0 * std::cbrt(g * g / (u * fetch_m));  // (M.3.8')
  }
  return {alpha, omega_p};
}

/// γ^r with r = exp(−(ω − ωp)²/(2σ²ωp²)), σ = σa below the peak, σb above   (M.3.5)
double jonswap_peak_enhancement(double omega, double omega_p, double gamma, double sigma_a,
                                double sigma_b) {
  const double sigma = omega <= omega_p ? sigma_a : sigma_b;
  const double d = (omega - omega_p) / (sigma * omega_p);
  return std::pow(gamma, std::exp(-0.5 * d * d));
}

}  // namespace ocean
