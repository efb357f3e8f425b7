// The depth law's closed form, computed independently of the library for the tests that check
// the damping and the surf against it (docs/waves.md W.12).
#pragma once

#include <cmath>

namespace ocean_test {

/// Φ(ω, d) of Kitaigorodskii et al. 1975 / Bouws et al. 1985 in closed form: tanh²x/(1 + 2x/sinh
/// 2x) with x = k_d·d the root of x·tanh x = ω²d/g, found here by bisection.
inline double kitaigorodskii_phi(double omega, double depth, double g = 9.81) {
  const double y = omega * omega * depth / g;
  double lo = 0.0, hi = y + 1.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid * std::tanh(mid) < y ? lo : hi) = mid;
  }
  const double x = 0.5 * (lo + hi);
  return std::pow(std::tanh(x), 2) / (1.0 + 2.0 * x / std::sinh(2.0 * x));
}

}  // namespace ocean_test
