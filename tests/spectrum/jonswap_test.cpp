// JONSWAP: published values (Hs/Tp/γ form), the DNV-RP-C205 γ rule and normalisation, the
// fetch laws, and the identity γ = 1 ⇒ Pierson–Moskowitz.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/spectrum.hpp"
#include "spectrum/test_util.hpp"

namespace {

using ocean::FrequencySpectrum;
using ocean::SpectrumModel;
using ocean_test::relative_error;

FrequencySpectrum jonswap(double hs, double tp, double gamma,
                          ocean::JonswapNormalization n = ocean::JonswapNormalization::dnv) {
  return FrequencySpectrum::make({.model = SpectrumModel::jonswap,
                                  .significant_wave_height_m = hs,
                                  .peak_period_s = tp,
                                  .gamma = gamma,
                                  .normalization = n})
      .value();
}

// xdyn @4c4db1c, code/environment_models/unit_tests/src/JonswapSpectrumTest.cpp lines 34–50:
// Hs = 1, Tp = 10, γ = 3.3 with Goda's 1 − 0.287·ln γ, σ = 0.07/0.09.
TEST(Jonswap, XdynValues) {
  const FrequencySpectrum s = jonswap(1.0, 10.0, 3.3);
  const double omega[] = {0.4, 0.5, 0.6, 0.7, 0.8};
  const double expected[] = {0.001548977510098, 0.046145520023689, 0.241661465488933,
                             0.144435240716521, 0.061449169843241};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(s(omega[i]), expected[i], 1e-14);
}

// xdyn PiersonMoskowitzSpectrumTest.cpp lines 34–47: JONSWAP(Hs = 10, Tp = 5π/8, γ = 1).
// The first ω is 17/9 (the test prints a truncation of it).
TEST(Jonswap, XdynPiersonMoskowitzAsGammaOne) {
  const FrequencySpectrum s = jonswap(10.0, 5.0 * ocean::kPi / 8.0, 1.0);
  const double omega[] = {17.0 / 9.0, 2.166666666666667, 2.444444444444445, 2.722222222222222, 3.0};
  const double expected[] = {0.004600020635184, 0.179258995153943, 0.955512136348661,
                             2.014925308286375, 2.673499618095267};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(s(omega[i]), expected[i], 1e-13);
}

// WAFO test_models.py lines 21–29: Jonswap(Hm0 = 7, Tp = 11, γ = 1) at ω = 1, 2, 3.
TEST(Jonswap, WafoGammaOneValues) {
  const FrequencySpectrum s = jonswap(7.0, 11.0, 1.0);
  EXPECT_NEAR(s(1.0), 1.42694133, 6e-9);
  EXPECT_NEAR(s(2.0), 0.05051648, 6e-9);
  EXPECT_NEAR(s(3.0), 0.00669692, 6e-9);
}

// xdyn JonswapSpectrumTest.cpp lines 52–76, after DNV-RP-C205 fig. 3.9: Hs = 4, Tp = 8.
TEST(Jonswap, DnvFigureBounds) {
  const double s1 = jonswap(4.0, 8.0, 1.0)(0.8);
  const double s2 = jonswap(4.0, 8.0, 2.0)(0.8);
  const double s5 = jonswap(4.0, 8.0, 5.0)(0.8);
  EXPECT_GT(s1, 1.5);
  EXPECT_LT(s1, 2.0);
  EXPECT_GT(s2, 2.5);
  EXPECT_LT(s2, 3.0);
  EXPECT_GT(s5, 4.5);
  EXPECT_LT(s5, 5.0);
  for (double w = 0.1; w < 3.0; w += 0.01) {
    if (w > 0.6 && w < 1.1) continue;
    EXPECT_LE(jonswap(4.0, 8.0, 5.0)(w), 1.0);
  }
}

// OrcaFlex JONSWAP (Hs = 3.5 m, Tp = 5.5 s, γ = 3) as shipped in 4Subsea/waveresponse-python
// @7bab614 tests/testdata/hs0350_tp0550_gamma3_jonswap.json. OrcaFlex normalises numerically,
// so Goda/DNV's A_γ agrees to ~0.13 % and our exact normalisation to ~0.04 %.
TEST(Jonswap, OrcaFlexReferencePoints) {
  struct Row {
    double omega, s;
  };
  const Row rows[] = {
      {0.7461604173145288, 0.020051454975728453}, {1.1406820172739347, 1.9688906899735168},
      {1.2607538085659278, 1.061749871861047},    {1.7753471998173271, 0.20402487231853153},
      {2.804533982320125, 0.02482701767572792},   {5.37750093857712, 0.0009889304264602717}};
  const FrequencySpectrum dnv = jonswap(3.5, 5.5, 3.0);
  const FrequencySpectrum exact = jonswap(3.5, 5.5, 3.0, ocean::JonswapNormalization::exact);
  for (const Row& r : rows) {
    EXPECT_LT(relative_error(dnv(r.omega), r.s), 2e-3);
    EXPECT_LT(relative_error(exact(r.omega), r.s), 1e-3);
  }
}

// Identity: with γ = 1 the peak factor vanishes and A_γ = 1, so JONSWAP equals the Hs/Tp PM.
TEST(Jonswap, GammaOneEqualsPiersonMoskowitz) {
  const FrequencySpectrum s = jonswap(4.0, 8.0, 1.0);
  for (double w = 0.05; w < 6.0; w *= 1.05) {
    EXPECT_EQ(s(w), ocean::pierson_moskowitz_hs_tp(w, 4.0, 8.0));
  }
}

// DNV-RP-C205 §3.5.5.5: γ = 5 for Tp/√Hs ≤ 3.6, exp(5.75 − 1.15·Tp/√Hs) between, 1 for ≥ 5.
TEST(Jonswap, DnvGammaRule) {
  EXPECT_EQ(ocean::jonswap_gamma_dnv(3.5, 5.5), 5.0);   // Tp/√Hs = 2.94
  EXPECT_EQ(ocean::jonswap_gamma_dnv(2.5, 8.0), 1.0);   // 5.06
  EXPECT_EQ(ocean::jonswap_gamma_dnv(4.0, 10.0), 1.0);  // exactly 5
  EXPECT_NEAR(ocean::jonswap_gamma_dnv(4.0, 8.0), std::exp(5.75 - 1.15 * 4.0), 1e-15);
  // Auto γ is the default of the Hs/Tp form.
  const FrequencySpectrum s =
      FrequencySpectrum::make(
          {.model = SpectrumModel::jonswap, .significant_wave_height_m = 4.0, .peak_period_s = 8.0})
          .value();
  EXPECT_EQ(s.gamma(), ocean::jonswap_gamma_dnv(4.0, 8.0));
}

// DNV-RP-C205 states A_γ = 1 − 0.287 ln γ is an approximation of the exact normaliser: check
// it keeps Hs within 1 % over its validity range 1 ≤ γ ≤ 7, and that "exact" is exact.
TEST(Jonswap, NormalisationPreservesHs) {
  for (double gamma : {1.0, 2.0, 3.3, 5.0, 7.0}) {
    const FrequencySpectrum dnv = jonswap(3.0, 9.0, gamma);
    EXPECT_LT(relative_error(dnv.hs_m(), 3.0), 0.01) << "gamma " << gamma;
    const FrequencySpectrum exact = jonswap(3.0, 9.0, gamma, ocean::JonswapNormalization::exact);
    EXPECT_LT(relative_error(exact.hs_m(), 3.0), 1e-9) << "gamma " << gamma;
  }
}

// Hasselmann et al. (1973): α = 0.076·x̃^−0.22, fp = 3.5·(g/U)·x̃^−0.33, x̃ = gF/U². Vincevičius
// (2024, eq. 1.9) prints ωp = 22·(g²/(U·F))^⅓, i.e. 22/(2π·3.5)·x̃^(0.33−⅓) times Hasselmann's: a
// few percent lower at the fetches of interest.
TEST(Jonswap, FetchLaws) {
  const double g = 9.81;
  const double u = 10.0;
  const double f = 10e3;
  const double x = g * f / (u * u);
  const auto [alpha, wp] = ocean::jonswap_fetch_law(u, f, g, ocean::FetchLaw::hasselmann_1973);
  EXPECT_NEAR(alpha, 0.076 * std::pow(x, -0.22), 1e-15);
  EXPECT_NEAR(wp, 2.0 * ocean::kPi * 3.5 * g / u * std::pow(x, -0.33), 1e-13);
  const double wp_seed = ocean::jonswap_fetch_law(u, f, g, ocean::FetchLaw::cube_root)[1];
  EXPECT_NEAR(wp_seed, 22.0 * std::cbrt(g * g / (u * f)), 1e-13);
  for (double fetch : {1e3, 1e4, 1e5, 1e6}) {
    const double ratio = ocean::jonswap_fetch_law(u, fetch, g, ocean::FetchLaw::cube_root)[1] /
                         ocean::jonswap_fetch_law(u, fetch, g, ocean::FetchLaw::hasselmann_1973)[1];
    EXPECT_LT(ratio, 1.0);
    EXPECT_GT(ratio, 0.95);
  }
}

// The fetch-limited sea grows towards the fully developed Pierson–Moskowitz sea with fetch:
// Hs rises and ωp falls monotonically.
TEST(Jonswap, FetchGrowth) {
  double last_hs = 0.0;
  double last_wp = 1e9;
  for (double fetch : {1e3, 1e4, 1e5, 1e6}) {
    const FrequencySpectrum s =
        FrequencySpectrum::make(
            {.model = SpectrumModel::jonswap, .wind_speed_mps = 15.0, .fetch_m = fetch})
            .value();
    EXPECT_GT(s.hs_m(), last_hs);
    EXPECT_LT(s.peak_omega(), last_wp);
    last_hs = s.hs_m();
    last_wp = s.peak_omega();
    EXPECT_EQ(s.gamma(), 3.3);
  }
}

TEST(Jonswap, RejectsBadInput) {
  using P = ocean::FrequencySpectrumParams;
  const P bad[] = {
      {.model = SpectrumModel::jonswap, .wind_speed_mps = 10.0},                  // no fetch
      {.model = SpectrumModel::jonswap, .wind_speed_mps = 10.0, .fetch_m = 0.0},  // zero fetch
      {.model = SpectrumModel::jonswap, .wind_speed_mps = 10.0, .fetch_m = -1e3},
      {.model = SpectrumModel::jonswap,
       .significant_wave_height_m = 2.0,
       .peak_period_s = 8.0,
       .gamma = 0.5},
      {.model = SpectrumModel::jonswap,
       .significant_wave_height_m = 2.0,
       .peak_period_s = 8.0,
       .gamma = 25.0},
      {.model = SpectrumModel::jonswap, .significant_wave_height_m = -2.0, .peak_period_s = 8.0},
      {.model = SpectrumModel::jonswap, .significant_wave_height_m = 2.0, .peak_period_s = 0.0},
      {.model = SpectrumModel::jonswap,
       .significant_wave_height_m = 2.0,
       .peak_period_s = 8.0,
       .fetch_m = 1e4},
  };
  for (const P& p : bad) EXPECT_FALSE(FrequencySpectrum::make(p).ok());
  EXPECT_NE(FrequencySpectrum::make(bad[1]).status().message().find("fetch_m = 0"),
            std::string::npos);
}

}  // namespace
