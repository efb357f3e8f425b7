// src/waves/hull_foam.cpp — the foam a moving hull makes (docs/waves.md W.20–W.21): along its
// waterline, the rim of its footprint, and in the trail behind it, a turbulent wake that widens
// and whose foam spreads and ages.
//
// This work is based on:
// - H. Tennekes & J. L. Lumley, "A First Course in Turbulence", MIT Press 1972, §4.2: the width
//   of a far wake grows as x^{1/2} behind a two-dimensional body and as x^{1/3} behind an
//   axisymmetric one, while what it carries is conserved across it.
// - J. H. Milgram, R. D. Peltzer & O. M. Griffin, "Suppression of short sea waves in ship wakes:
//   measurements and observations", J. Geophys. Res. 98(C4), 7103–7114, 1993: the turbulent,
//   foam-marked centreline wake of a ship spreads slowly and stays visible far behind it.
#include <algorithm>
#include <cmath>

#include "ocean/waves.hpp"

namespace ocean::waves {

Status validate(const HullFoam& f) {
  if (Status s = require_in_range("foam.beam_m", f.beam_m, 0.0, 1000.0); !s.ok()) return s;
  if (Status s = require_in_range("foam.coverage", f.coverage, 0.0, 1.0); !s.ok()) return s;
  if (Status s = require_in_range("foam.rim_width_m", f.rim_width_m, 0.0, 100.0); !s.ok())
    return s;
  if (Status s = require_positive("foam.lifetime_s", f.lifetime_s); !s.ok()) return s;
  if (Status s = require_in_range("foam.lifetime_s", f.lifetime_s, 0.0, 3600.0); !s.ok())
    return s;
  return require_in_range("foam.spread_exponent", f.spread_exponent, 0.0, 1.0);
}

Status validate(const Footprint& f) {
  if (Status s = require_finite("x_m", f.x_m); !s.ok()) return s;
  if (Status s = require_finite("z_m", f.z_m); !s.ok()) return s;
  if (Status s = require_finite("heading_deg", f.heading_deg); !s.ok()) return s;
  if (Status s = require_positive("length_m", f.length_m); !s.ok()) return s;
  if (Status s = require_in_range("length_m", f.length_m, 0.0, 1000.0); !s.ok()) return s;
  return validate(f.foam);
}

double trail_half_width_m(const HullFoam& f, double hull_length_m, double s_m) {
  return 0.5 * f.beam_m * std::pow(1.0 + std::max(s_m, 0.0) / hull_length_m, f.spread_exponent);
}

double hull_foam_coverage(const HullFoam& f, double hull_length_m, double speed_mps, double s_m,
                          double zeta_m) {
  if (!(f.beam_m > 0.0) || !(f.coverage > 0.0)) return 0.0;
  const double half_b = 0.5 * f.beam_m, half_l = 0.5 * hull_length_m;
  // (W.20) Waterline: full inside the footprint, e^{−(d/w)²} at d = (r − 1)·B/2 outside it, r the
  // footprint's normalised radius (d is the distance along the beam, longer off the ends, where
  // the bow wave breaks and the stern's flow separates).
  const double r = std::hypot(s_m / half_l, zeta_m / half_b);
  const double w = f.rim_width_m > 0.0 ? f.rim_width_m : 0.5 * half_b;
  const double d = std::max(r - 1.0, 0.0) * half_b;
  double c = f.coverage * std::exp(-(d * d) / (w * w));
  // (W.21) Trail: from the centre backwards, half width b(s), the foam spread across it (the
  // section's total kept, C₀·B/2 at the start) and aged by e^{−s/(U·T)}; across the track
  // 2^{−(ζ/b)²}, so b is the half width at half maximum.
  if (s_m > 0.0 && speed_mps > 0.0) {
    const double b = trail_half_width_m(f, hull_length_m, s_m);
    const double q = zeta_m / b;
    const double trail = f.coverage * (half_b / b) * std::exp(-s_m / (speed_mps * f.lifetime_s)) *
                         std::exp2(-q * q);
    c = std::max(c, trail);
  }
  return std::min(c, 1.0);
}

}  // namespace ocean::waves
