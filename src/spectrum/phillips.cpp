// Phillips spectrum: Tessendorf's wave-vector form, and the variant of Aebi, VR Ocean, with
// its grid normalisation, alignment-dependent spreading and counter-wave suppression.
//
// This work is based on:
//   - Phillips, O. M. (1958) The equilibrium range in the spectrum of wind-generated waves.
//     J. Fluid Mech. 4(4).
//   - Tessendorf, J. (2001) Simulating Ocean Water, SIGGRAPH course notes, eqs. 40–42:
//     P(k) = A·exp(−1/(kL)²)/k⁴·|k̂·ŵ|², L = V²/g, and the small-wave factor exp(−k²l²).
//   - Aebi, VR Ocean, §3.2, eqs. 3–11: A = N^(−1/2)·(e/L_patch)², s(α) = 1 + 5α²,
//     σ(α) = 0.01 + 0.49(1 − α)², l_cutoff(β) = 0.001·(0.25·L_patch/0.001)^β.
// Equations: docs/math.md (M.3.11)–(M.3.14), (M.6.6).
#include <cmath>

#include "internal.hpp"

namespace ocean {

double phillips_k_density(double k, double amplitude, double wind_speed_mps, double gravity_mps2,
                          double small_wave_cutoff_m) {
  if (!(k > 0.0) || std::isinf(k)) return 0.0;  // the limits k → 0 and k → ∞
  const double big_l = wind_speed_mps * wind_speed_mps / gravity_mps2;  // largest wave, L = V²/g
  const double inv_kl = 1.0 / (k * big_l);                              // inf when k·L underflows
  const double kl_cut = k * small_wave_cutoff_m;
  // Both terms are ≤ 0, so their sum is never inf − inf.
  const double exponent = -(inv_kl * inv_kl) - kl_cut * kl_cut;  // (M.3.11), (M.3.12)
  if (k >= 1e-75 && k <= 1e75) {
    const double k2 = k * k;
    return amplitude * std::exp(exponent) / (k2 * k2);
  }
  // k⁴ would overflow or underflow: join it to the exponent (0 through the denormals).
  return amplitude * std::exp(exponent - 4.0 * std::log(k));
}

double phillips_omega_density(double omega, double amplitude, double wind_speed_mps,
                              double gravity_mps2, double small_wave_cutoff_m) {
  if (!(omega > 0.0)) return 0.0;
  const double g = gravity_mps2;
  const double omega0 = g / wind_speed_mps;
  // e^(−k²l²) with k = ω²/g = q², q = ω/√g; without a cutoff the factor is 1 (q² may be ∞).
  const double q = omega / std::sqrt(g);
  const double kl = q * q * small_wave_cutoff_m;
  const double cutoff = small_wave_cutoff_m > 0.0 ? std::exp(-kl * kl) : 1.0;
  return pm_spectrum(2.0 * amplitude * g * g / std::pow(omega0, 5.0), omega0 / omega, 1.0) * cutoff;
}

double phillips_default_amplitude() {
  // m0 = ∫∫A·e^(−1/(kL)²)/k⁴·D dk = A·L²/2 and m0_PM = α·U⁴/(4β·g²)  ⇒  A = α/(2β)   (M.3.13)
  return pierson_moskowitz_alpha() / (2.0 * pierson_moskowitz_beta());
}

double vr_ocean_cutoff_length(double beta, double patch_size_m) {
  constexpr double l_min = 0.001;                              // Aebi, VR Ocean, §3.2.4
  return l_min * std::pow(patch_size_m * 0.25 / l_min, beta);  // Aebi, VR Ocean, eq. 11
}

double vr_ocean_phillips_power(double kx, double kz, const VrOceanPhillipsParams& p,
                               const SpectrumGrid& grid) {
  const double k = std::hypot(kx, kz);          // kx² + kz² would overflow beyond 1e154
  if (!(k > 0.0) || std::isinf(k)) return 0.0;  // DC guard (Aebi, VR Ocean, eq. 14); k → ∞
  const double n = static_cast<double>(grid.resolution);
  const double a_fft = std::pow(n, -0.25);                         // eq. 5
  const double a_spatial = std::exp(1.0) / grid.patch_size_m;      // eq. 5
  const double amplitude = a_fft * a_fft * a_spatial * a_spatial;  // eq. 4
  const double cos_theta =
      (kx * std::cos(p.wind_direction_rad) + kz * std::sin(p.wind_direction_rad)) / k;
  const double s = 1.0 + 5.0 * p.alpha * p.alpha;         // eq. 6
  double directional = std::pow(std::abs(cos_theta), s);  // eq. 7
  if (cos_theta < 0.0) {
    const double one_minus = 1.0 - p.alpha;
    directional *= 0.01 + 0.49 * one_minus * one_minus;  // eqs. 8–9, in the power domain
  }
  return phillips_k_density(k, amplitude, p.wind_speed_mps, p.gravity_mps2,
                            p.small_wave_cutoff_m) *
         directional;  // eqs. 3, 10  (M.6.6)
}

}  // namespace ocean
