// src/waves/michell.cpp — a thin ship's wave resistance by Michell's integral (W.23) and the
// height of the Kelvin pattern that carries it (W.24): the wake's amplitude from the hull's
// beam, draught and length and the Froude number.
//
// This work is based on:
// - J. H. Michell, "The wave resistance of a ship", Phil. Mag. (5) 45, 106–123, 1898, in the form
//   E. O. Tuck, "The wave resistance formula of J. H. Michell (1898) and its significance to
//   recent research in ship hydrodynamics", J. Austral. Math. Soc. B 30, 365–377, 1989:
//   R = (4ρg²/πU²)·∫_1^∞ |I(λ)|²·λ²/√(λ² − 1) dλ, I(λ) = ∫∫ f_x·e^{k0·λ²·z}·e^{i·k0·λ·x} dx dz.
// - T. H. Havelock, "Wave patterns and wave resistance", Trans. INA 76, 430–443, 1934; J. N.
//   Newman, "Marine Hydrodynamics", MIT Press 1977, ch. 6: the resistance of a far field
//   η = ∫ A(θ)·(…) dθ is R = (π/2)·ρ·U²·∫_{−π/2}^{π/2} |A(θ)|²·cos³θ dθ.
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "ocean/waves.hpp"

namespace ocean::waves {

Status validate(const ThinHull& h) {
  if (Status s = require_in_range("thin_hull.length_m", h.length_m, 0.01, 1000.0); !s.ok())
    return s;
  if (Status s = require_in_range("thin_hull.draft_m", h.draft_m, 1e-4, 1000.0); !s.ok()) return s;
  if (h.columns < 2 || h.rows < 1 || h.columns > 4096 || h.rows > 4096 ||
      h.half_breadth_m.size() !=
          static_cast<std::size_t>(h.columns) * static_cast<std::size_t>(h.rows))
    return invalid_argument("thin_hull: " + std::to_string(h.half_breadth_m.size()) +
                            " half-breadths for " + std::to_string(h.columns) + " columns × " +
                            std::to_string(h.rows) + " rows (2–4096 columns, 1–4096 rows)");
  for (double f : h.half_breadth_m)
    if (!(f >= 0.0) || !std::isfinite(f))
      return invalid_argument("thin_hull.half_breadth_m = " + format_number(f) +
                              " must be finite and ≥ 0");
  return {};
}

double michell_resistance_per_density(const ThinHull& h, double speed_mps, double gravity_mps2) {
  const double k0 = gravity_mps2 / (speed_mps * speed_mps);
  const double dx = h.length_m / h.columns, dz = h.draft_m / h.rows;
  const auto cols = static_cast<std::size_t>(h.columns);
  // (W.23) With f piecewise constant on the cells and 0 beyond the ends, f_x is a sum of steps,
  // and by parts I = −i·k0·λ·∫∫ f·e^{−k0λ²d}·e^{ik0λx} dx dd (d the depth), each cell integrated
  // exactly: e^{ik0λx_c}·2·sin(k0λ·dx/2)/(k0λ) along x, (e^{−q·d0} − e^{−q·d1})/q in depth.
  const auto integral = [&](double lambda) {
    const double a = k0 * lambda, q = k0 * lambda * lambda;
    std::complex<double> sum = 0.0;
    for (int r = 0; r < h.rows; ++r) {
      const double depth = (q * dz < 1e-8)
                               ? dz * std::exp(-q * (r + 0.5) * dz)
                               : (std::exp(-q * r * dz) - std::exp(-q * (r + 1) * dz)) / q;
      if (depth < 1e-300) break;
      std::complex<double> row = 0.0;
      for (std::size_t c = 0; c < cols; ++c) {
        const double f = h.half_breadth_m[static_cast<std::size_t>(r) * cols + c];
        if (f == 0.0) continue;
        const double x = -0.5 * h.length_m + (static_cast<double>(c) + 0.5) * dx;
        row += f * std::polar(1.0, a * x);
      }
      sum += row * depth;
    }
    const double along = 2.0 * std::sin(0.5 * a * dx) / a;
    return std::complex<double>(0.0, -a) * along * sum;
  };
  // λ = cosh t near λ = 1 (the integrand λ²/√(λ² − 1)·dλ = cosh²t·dt has no singularity), then λ
  // itself in steps resolving the hull's oscillation e^{ik0λL/2} by 24, to λ = 60 (the rest:
  // |I|² ∝ λ⁻⁴, under 1e-3 of the whole).
  double sum = 0.0;
  const double t_end = 2.0;
  const int t_steps = 400;
  for (int i = 0; i < t_steps; ++i) {
    const double t = (i + 0.5) * t_end / t_steps;
    const double lambda = std::cosh(t);
    sum += std::norm(integral(lambda)) * lambda * lambda * (t_end / t_steps);
  }
  const double period = 2.0 * std::numbers::pi / (k0 * 0.5 * h.length_m);
  const double step = std::min(0.05, period / 24.0);
  for (double lambda = std::cosh(t_end) + 0.5 * step; lambda < 60.0; lambda += step)
    sum += std::norm(integral(lambda)) * lambda * lambda / std::sqrt(lambda * lambda - 1.0) * step;
  return 4.0 * gravity_mps2 * gravity_mps2 / (std::numbers::pi * speed_mps * speed_mps) * sum;
}

}  // namespace ocean::waves
