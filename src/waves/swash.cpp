// src/waves/swash.cpp — the run-up of the waves on a beach (W.40–W.43): the wave set-up, the swash
// and the 2 % exceedance run-up of Stockdon et al. (2006), and the elevation of the instantaneous
// water line that a renderer draws over the beach (its GLSL twin is src/render/shaders/swash.glsl).
//
// This work is based on:
// - Stockdon, Holman, Howd & Sallenger (2006), "Empirical parameterization of setup, swash, and
//   runup", Coastal Engineering 53: set-up ⟨η⟩ = 0.35·β_f·√(H0·L0) (eq. 10), swash
//   S = √(H0·L0·(0.563·β_f² + 0.004)) (eq. 19's swash term: incident 0.75·β_f·√(H0·L0), eq. 11,
//   and infragravity 0.06·√(H0·L0), eq. 12, added in quadrature and rounded), and the run-up
//   exceeded by 2 % of the swash maxima R2% = 1.1·(⟨η⟩ + S/2) (eq. 19), fitted to ten field
//   experiments on sandy beaches; H0 the deep-water significant height, L0 = g·T_p²/(2π).
// - Shen & Meyer (1963), "Climb of a bore on a beach. Part 3. Run-up", J. Fluid Mech. 16: after the
//   bore collapses at the shore the tip of the swash moves as a particle under the down-slope
//   pull of gravity, a parabola in time — the shape (not the height) of the drawn cycle (W.42).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ocean/waves.hpp"

namespace ocean::waves {

double deep_water_wavelength_m(double period_s, double gravity_mps2) {
  return gravity_mps2 * period_s * period_s / (2.0 * std::numbers::pi);  // (W.40)
}

Runup stockdon_runup(double h0_m, double l0_m, double foreshore_slope) {
  Runup r;
  if (!(h0_m > 0.0) || !(l0_m > 0.0)) return r;  // NaN too: no waves, no run-up
  const double beta = std::isfinite(foreshore_slope)
                          ? std::clamp(std::abs(foreshore_slope), 0.0, kMaxForeshoreSlope)
                          : kMaxForeshoreSlope;
  const double hl = h0_m * l0_m;
  r.setup_m = 0.35 * beta * std::sqrt(hl);                    // (W.41), eq. 10
  r.swash_m = std::sqrt(hl * (0.563 * beta * beta + 0.004));  // (W.41), eq. 19
  r.runup2_m = 1.1 * (r.setup_m + 0.5 * r.swash_m);           // (W.41), eq. 19
  r.rundown_m = r.setup_m - 0.5 * r.swash_m;                  // (W.41)
  return r;
}

double swash_elevation_m(const Runup& runup, double phase) {
  const double p = phase - std::floor(phase);
  return runup.rundown_m + (runup.runup2_m - runup.rundown_m) * 4.0 * p * (1.0 - p);  // (W.42)
}

double swash_alongshore_phase(double x_m, double z_m, double l0_m) {
  if (!(l0_m > 0.0)) return 0.0;
  // (W.43): two slow waves of phase along the shore, 1.7·L0 and 1.1·L0 long, in directions
  // 37° and 120° from +x: chosen values, so that the swash of neighbouring stretches of beach
  // arrives at different times (a cycle apart over about L0/2, as obliquely incident waves
  // reach the shore) without one period of the pattern showing.
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return 0.35 * std::sin(kTwoPi * (0.8 * x_m + 0.6 * z_m) / (1.7 * l0_m)) +
         0.15 * std::sin(kTwoPi * (-0.5 * x_m + 0.866 * z_m) / (1.1 * l0_m) + 1.9);
}

}  // namespace ocean::waves
