// TMA depth attenuation: the Kitaigorodskii factor Φ(ω, h) that turns a deep-water JONSWAP
// spectrum into a finite-depth one.
//
// This work is based on:
//   - Kitaigorodskii, S. A., Krasitskii, V. P. & Zaslavskii, M. M. (1975) On Phillips' theory of
//     equilibrium range in the spectra of wind-generated gravity waves. J. Phys. Oceanogr. 5.
//   - Bouws, E., Günther, H., Rosenthal, W. & Vincent, C. L. (1985) Similarity of the wind wave
//     spectrum in finite depth water: 1. Spectral form. J. Geophys. Res. 90(C1).
//   - Hughes, S. A. (1984) The TMA shallow-water spectrum description and applications. CERC
//     Technical Report 84-7.
//   - Thompson, E. F. & Vincent, C. L. (1983) Prediction of wave height in shallow water.
//     Coastal Structures '83 — the piecewise approximation (Vincevičius 2024, eq. 1.11), held at 1
//     for ω_h ≥ 2 where the printed quadratic would fall again.
// Equations: docs/math.md (M.3.9), (M.3.10).
#include <cmath>

#include "ocean/spectrum.hpp"

namespace ocean {

double tma_depth_factor(double omega, double depth_m, double gravity_mps2, DepthFactor factor) {
  if (!(omega > 0.0) || std::isinf(depth_m)) return 1.0;
  const double g = gravity_mps2;
  if (factor == DepthFactor::thompson_vincent) {
    const double omega_h = omega * std::sqrt(depth_m / g);  // (M.3.10)
    if (omega_h <= 1.0) return 0.5 * omega_h * omega_h;
    if (omega_h >= 2.0) return 1.0;
    const double t = 2.0 - omega_h;
    return 1.0 - 0.5 * t * t;
  }
  // Φ = [k_h⁻³·dk_h/dω] / [k_∞⁻³·dk_∞/dω] with dk/dω = 1/c_g   (M.3.9). With k_∞ = ω²/g =
  // k_h·tanh(k_h·h) this is Φ = tanh²(x)/(1 + 2x/sinh 2x), x = k_h·h the root of x·tanh x = ωh²
  // (M.3.9'): a function of ωh alone, free of the overflowing k³ and ω³.
  const double omega_h = omega * std::sqrt(depth_m / g);
  if (omega_h >= 10.0) return 1.0;  // x ≥ 100: tanh² x = 1 and 2x/sinh 2x < 1e-80
  // Below the dispersion domain Φ = ωh²/2·(1 − ωh²/3 + ...) is ωh²/2 in double precision.
  const Dispersion unit = Dispersion::make({.gravity_mps2 = 1.0, .depth_m = 1.0}).value();
  if (omega_h < unit.min_omega()) return 0.5 * omega_h * omega_h;
  const double x = unit.wavenumber(omega_h);
  const double t = std::tanh(x);
  return t * t / (1.0 + 2.0 * x / std::sinh(2.0 * x));
}

}  // namespace ocean
