// The run-up of the waves on a beach (docs/waves.md W.40–W.43): Stockdon, Holman, Howd &
// Sallenger (2006), "Empirical parameterization of setup, swash, and runup", Coastal Engineering
// 53, eqs. 10–12 and 19, evaluated by hand below at sea states of their field range (H0 1–3 m,
// T_p 8–12 s, foreshores 1:50 to 1:10); the swash's cycle against its closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/waves.hpp"

namespace swash_test {

using ocean::waves::Runup;

TEST(Swash, DeepWaterWavelengthIsGTSquaredOverTwoPi) {
  // L0 = 9.81·10²/(2π) = 156.130999 m.
  EXPECT_NEAR(ocean::waves::deep_water_wavelength_m(10.0, 9.81), 156.130999, 1e-6);
}

struct Case {
  double h0_m, period_s, slope;
  double setup_m, swash_m, runup2_m, rundown_m;  // the closed forms, by hand
};

TEST(Swash, SetupSwashAndRunupAreStockdonsClosedForms) {
  // ⟨η⟩ = 0.35·β·√(H0·L0), S = √(H0·L0·(0.563β² + 0.004)), R2 = 1.1·(⟨η⟩ + S/2), with
  // L0 = 9.81·T²/(2π): e.g. H0 = 2 m, T = 10 s, β = 0.1: √(H0·L0) = 17.6711, ⟨η⟩ = 0.618483,
  // S = 17.6711·√0.00963 = 1.734094, R2 = 1.1·(0.618483 + 0.867047) = 1.634083 m.
  const Case cases[] = {
      {2.0, 10.0, 0.1, 0.618483, 1.734094, 1.634083, -0.248564},
      {1.0, 8.0, 0.05, 0.174933, 0.735077, 0.596719, -0.192605},
      {3.0, 12.0, 0.02, 0.181796, 1.688146, 1.128456, -0.662277},
  };
  for (const Case& c : cases) {
    const double l0 = ocean::waves::deep_water_wavelength_m(c.period_s, 9.81);
    const Runup r = ocean::waves::stockdon_runup(c.h0_m, l0, c.slope);
    EXPECT_NEAR(r.setup_m, c.setup_m, 1e-6) << c.h0_m << " m, " << c.period_s << " s";
    EXPECT_NEAR(r.swash_m, c.swash_m, 1e-6) << c.h0_m << " m, " << c.period_s << " s";
    EXPECT_NEAR(r.runup2_m, c.runup2_m, 1e-6) << c.h0_m << " m, " << c.period_s << " s";
    EXPECT_NEAR(r.rundown_m, c.rundown_m, 1e-6) << c.h0_m << " m, " << c.period_s << " s";
    // Their swash is the incident (eq. 11, 0.75·β·√(H0·L0)) and infragravity (eq. 12,
    // 0.06·√(H0·L0)) bands added in quadrature, 0.5625 and 0.0036 rounded to 0.563 and 0.004.
    const double hl = c.h0_m * l0;
    const double s_inc = 0.75 * c.slope * std::sqrt(hl), s_ig = 0.06 * std::sqrt(hl);
    EXPECT_NEAR(r.swash_m * r.swash_m, s_inc * s_inc + s_ig * s_ig,
                (0.0005 * c.slope * c.slope + 0.0004) * hl + 1e-12);
  }
}

TEST(Swash, TheSlopeIsClampedToTheLawsRangeAndNoWavesGiveNoRunup) {
  const double l0 = 100.0;
  const Runup steep = ocean::waves::stockdon_runup(1.0, l0, 5.0);
  const Runup at_clamp = ocean::waves::stockdon_runup(1.0, l0, ocean::waves::kMaxForeshoreSlope);
  EXPECT_EQ(steep.runup2_m, at_clamp.runup2_m);
  EXPECT_EQ(ocean::waves::stockdon_runup(1.0, l0, -0.05).runup2_m,
            ocean::waves::stockdon_runup(1.0, l0, 0.05).runup2_m);
  // A flat foreshore: no set-up, the infragravity swash alone, R2 = 1.1·√(0.004·H0·L0)/2.
  const Runup flat = ocean::waves::stockdon_runup(1.0, l0, 0.0);
  EXPECT_EQ(flat.setup_m, 0.0);
  EXPECT_NEAR(flat.runup2_m, 0.55 * std::sqrt(0.4), 1e-12);
  EXPECT_EQ(ocean::waves::stockdon_runup(0.0, l0, 0.1).runup2_m, 0.0);
  EXPECT_EQ(ocean::waves::stockdon_runup(1.0, 0.0, 0.1).runup2_m, 0.0);
  EXPECT_EQ(ocean::waves::stockdon_runup(std::nan(""), l0, 0.1).runup2_m, 0.0);
}

TEST(Swash, TheWaterLineRisesToTheRunupAtHalfACycleAlongAParabola) {
  const Runup r = ocean::waves::stockdon_runup(2.0, 156.130999, 0.1);
  const double range = r.runup2_m - r.rundown_m;
  EXPECT_NEAR(ocean::waves::swash_elevation_m(r, 0.0), r.rundown_m, 1e-12);
  EXPECT_NEAR(ocean::waves::swash_elevation_m(r, 0.5), r.runup2_m, 1e-12);
  EXPECT_NEAR(ocean::waves::swash_elevation_m(r, 0.25), r.rundown_m + 0.75 * range, 1e-12);
  for (double p = 0.0; p < 1.0; p += 0.01) {
    const double z = ocean::waves::swash_elevation_m(r, p);
    EXPECT_LE(z, r.runup2_m + 1e-12);
    EXPECT_GE(z, r.rundown_m - 1e-12);
    EXPECT_NEAR(z, ocean::waves::swash_elevation_m(r, 1.0 - p), 1e-12);  // up as it comes down
    EXPECT_NEAR(z, ocean::waves::swash_elevation_m(r, p + 3.0), 1e-12);  // once per period
  }
}

TEST(Swash, ThePhaseVariesAlongTheShoreWithinHalfACycle) {
  const double l0 = 100.0;
  double lo = 1.0, hi = -1.0;
  for (double z = 0.0; z < 2000.0; z += 0.5) {
    const double p = ocean::waves::swash_alongshore_phase(0.0, z, l0);
    lo = std::min(lo, p), hi = std::max(hi, p);
  }
  EXPECT_LE(hi, 0.5);  // |ψ| ≤ 0.35 + 0.15
  EXPECT_GE(lo, -0.5);
  EXPECT_GT(hi - lo, 0.5);  // and it does vary
  EXPECT_EQ(ocean::waves::swash_alongshore_phase(3.0, 4.0, 0.0), 0.0);
}

}  // namespace swash_test
