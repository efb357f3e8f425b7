// Pierson–Moskowitz (wind form) and Bretschneider (Hs/Tp form): published values and
// closed-form moments.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/spectrum.hpp"
#include "spectrum/test_util.hpp"

namespace {

using ocean::FrequencySpectrum;
using ocean::SpectrumModel;
using ocean_test::relative_error;

// xdyn (sirehna/xdyn @4c4db1c), code/environment_models/unit_tests/src/
// BretschneiderSpectrumTest.cpp lines 30–39: S(ω) in m²·s/rad, Tp = peak period.
TEST(PiersonMoskowitz, XdynBretschneiderValues) {
  struct Row {
    double hs, tp, omega, s;
  };
  const Row rows[] = {{1.0, 5.0, 1.0, 0.034510725921325},
                      {2.0, 5.0, 1.0, 0.138042903685298},
                      {2.0, 5.0, 10.0, 0.000031161194389},
                      {2.0, 10.0, 0.5, 0.276085807370596}};
  for (const Row& r : rows) {
    EXPECT_NEAR(ocean::pierson_moskowitz_hs_tp(r.omega, r.hs, r.tp), r.s, 1e-14);
    const FrequencySpectrum s = FrequencySpectrum::make({.model = SpectrumModel::pierson_moskowitz,
                                                         .significant_wave_height_m = r.hs,
                                                         .peak_period_s = r.tp})
                                    .value();
    EXPECT_NEAR(s(r.omega), r.s, 1e-14);
  }
}

// WAFO (pywafo @c831ec8) src/wafo/spectrum/tests/test_models.py lines 15–19:
// Bretschneider(Hm0 = 6.5, Tp = 10) at ω = 0, 1, 2, 3 (decimal = 5; 8 digits printed).
TEST(PiersonMoskowitz, WafoBretschneiderValues) {
  const double omega[] = {0.0, 1.0, 2.0, 3.0};
  const double expected[] = {0.0, 1.69350993, 0.06352698, 0.00844783};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(ocean::pierson_moskowitz_hs_tp(omega[i], 6.5, 10.0), expected[i], 6e-9);
  }
}

// Stewart, R. H. (2008) Introduction to Physical Oceanography, ch. 16 eqs. 16.30–16.33, for the
// wind form with U19.5: ωp = 0.877·g/U, ⟨ζ²⟩ = 2.74e-3·U⁴/g², H1/3 = 0.21·U²/g.
TEST(PiersonMoskowitz, StewartPublishedConstants) {
  const double g = 9.81;
  for (double u : {5.0, 10.0, 20.0, 30.0}) {
    const FrequencySpectrum s =
        FrequencySpectrum::make({.model = SpectrumModel::pierson_moskowitz, .wind_speed_mps = u})
            .value();
    EXPECT_LT(relative_error(s.peak_omega(), 0.877 * g / u), 5e-4);
    EXPECT_LT(relative_error(s.moment(0), 2.74e-3 * u * u * u * u / (g * g)), 2e-3);
    EXPECT_LT(relative_error(s.hs_m(), 0.21 * u * u / g), 5e-3);
    // The peak really is the maximum.
    EXPECT_GT(s(s.peak_omega()), s(s.peak_omega() * 1.01));
    EXPECT_GT(s(s.peak_omega()), s(s.peak_omega() * 0.99));
  }
}

// Exact identity: m0 = α·U⁴/(4β·g²) for the wind form (α = 0.0081, β = 0.74), so that
// Hs = 4·√(α/(4β))·U²/g = 0.2093·U²/g.
TEST(PiersonMoskowitz, WindFormVarianceClosedForm) {
  const double g = 9.81;
  for (double u : {3.0, 12.0, 25.0}) {
    const FrequencySpectrum s =
        FrequencySpectrum::make({.model = SpectrumModel::pierson_moskowitz, .wind_speed_mps = u})
            .value();
    EXPECT_LT(relative_error(s.moment(0), 0.0081 * std::pow(u, 4) / (4.0 * 0.74 * g * g)), 1e-9);
  }
}

// Exact identity: the Hs/Tp form integrates to Hs²/16 and peaks at 2π/Tp.
TEST(PiersonMoskowitz, HsTpFormVarianceAndPeak) {
  for (double hs : {0.5, 3.0, 12.0}) {
    for (double tp : {4.0, 9.0, 16.0}) {
      const FrequencySpectrum s =
          FrequencySpectrum::make({.model = SpectrumModel::pierson_moskowitz,
                                   .significant_wave_height_m = hs,
                                   .peak_period_s = tp})
              .value();
      EXPECT_LT(relative_error(s.moment(0), hs * hs / 16.0), 1e-9);
      const double wp = 2.0 * ocean::kPi / tp;
      EXPECT_GT(s(wp), s(wp * 1.001));
      EXPECT_GT(s(wp), s(wp * 0.999));
    }
  }
}

// The two forms describe the same sea when Hs = 4√(α/4β)·U²/g and ωp = (4β/5)^¼·g/U.
TEST(PiersonMoskowitz, WindAndHsTpFormsAgree) {
  const double g = 9.81;
  const double u = 20.0;
  const double hs = 4.0 * std::sqrt(0.0081 / (4.0 * 0.74)) * u * u / g;
  const double tp = 2.0 * ocean::kPi / (std::pow(0.8 * 0.74, 0.25) * g / u);
  for (double w = 0.2; w < 3.0; w += 0.05) {
    const double a = ocean::pierson_moskowitz_wind(w, u, g);
    const double b = ocean::pierson_moskowitz_hs_tp(w, hs, tp);
    EXPECT_LT(relative_error(a, b), 1e-12) << "omega " << w;
  }
}

TEST(PiersonMoskowitz, RejectsBadInput) {
  using P = ocean::FrequencySpectrumParams;
  const P bad[] = {
      {.model = SpectrumModel::pierson_moskowitz, .wind_speed_mps = -3.0},
      {.model = SpectrumModel::pierson_moskowitz, .wind_speed_mps = std::nan("")},
      {.model = SpectrumModel::pierson_moskowitz, .wind_speed_mps = 10.0, .fetch_m = 1e4},
      {.model = SpectrumModel::pierson_moskowitz, .significant_wave_height_m = 2.0},
      {.model = SpectrumModel::pierson_moskowitz,
       .significant_wave_height_m = 2.0,
       .peak_period_s = 8.0,
       .wind_speed_mps = 10.0},
      {.model = SpectrumModel::pierson_moskowitz},
      {.model = SpectrumModel::pierson_moskowitz, .wind_speed_mps = 10.0, .gamma = 3.3},
      {.model = SpectrumModel::pierson_moskowitz, .wind_speed_mps = 10.0, .depth_m = 20.0},
  };
  for (const P& p : bad) EXPECT_FALSE(FrequencySpectrum::make(p).ok());
  const auto status = FrequencySpectrum::make(bad[0]).status();
  EXPECT_EQ(status.code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(status.message().find("wind_speed_mps = -3"), std::string::npos);
}

}  // namespace
