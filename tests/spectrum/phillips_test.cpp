// Phillips: closed-form moments of the wave-vector form, the default amplitude, and the
// VR-Ocean variant's published constants (Aebi, VR Ocean, §3.2).
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/spectrum.hpp"
#include "spectrum/test_util.hpp"

namespace {

using ocean::FrequencySpectrum;
using ocean::SpectrumModel;
using ocean_test::relative_error;

FrequencySpectrum phillips(double u, double amplitude, double cutoff = 0.0) {
  return FrequencySpectrum::make({.model = SpectrumModel::phillips,
                                  .wind_speed_mps = u,
                                  .phillips_amplitude = amplitude,
                                  .small_wave_cutoff_m = cutoff})
      .value();
}

// m0 = ∫A·e^(−1/(kL)²)/k³ dk = A·L²/2 (substitute u = 1/(kL)²).
TEST(Phillips, VarianceClosedForm) {
  for (double u : {5.0, 10.0, 25.0}) {
    const double big_l = u * u / 9.81;
    EXPECT_LT(relative_error(phillips(u, 1e-3).moment(0), 1e-3 * big_l * big_l / 2.0), 1e-8);
  }
}

// With the small-wave factor e^(−k²l²): m0 = A·l·L·K1(2l/L)   (docs/math.md M.3.12;
// Gradshteyn & Ryzhik 3.471.9).
TEST(Phillips, VarianceWithCutoffUsesBesselK1) {
  const double u = 8.0;
  const double big_l = u * u / 9.81;
  for (double l : {0.1, 1.0, 3.0}) {
    const double expected = 1e-3 * l * big_l * std::cyl_bessel_k(1.0, 2.0 * l / big_l);
    EXPECT_LT(relative_error(phillips(u, 1e-3, l).moment(0), expected), 1e-7) << "l " << l;
  }
}

// The default amplitude α/(2β) reproduces the Pierson–Moskowitz Hs = 0.2093·U²/g.
TEST(Phillips, DefaultAmplitudeMatchesPiersonMoskowitzHs) {
  const FrequencySpectrum s =
      FrequencySpectrum::make({.model = SpectrumModel::phillips, .wind_speed_mps = 12.0}).value();
  const double hs_pm = 4.0 * std::sqrt(0.0081 / (4.0 * 0.74)) * 144.0 / 9.81;
  EXPECT_LT(relative_error(s.hs_m(), hs_pm), 1e-8);
  EXPECT_GT(s(s.peak_omega()), s(s.peak_omega() * 1.01));
  EXPECT_GT(s(s.peak_omega()), s(s.peak_omega() * 0.99));
}

// Aebi, VR Ocean, eqs. 6–8 and 11: s(1) = 6 (|cos 60°|^6 = 1/64), σ(1) = 1 %, σ(0) = 50 %,
// l_cutoff(0) = l_min = 0.001 m, l_cutoff(1) = L_patch/4.
TEST(Phillips, VrOceanConstants) {
  const ocean::SpectrumGrid grid{.resolution = 256, .patch_size_m = 200.0};
  const double k = 0.3;
  const auto power = [&](double alpha, double theta) {
    return ocean::vr_ocean_phillips_power(k * std::cos(theta), k * std::sin(theta),
                                          {.wind_speed_mps = 10.0, .alpha = alpha}, grid);
  };
  EXPECT_NEAR(power(1.0, ocean::kPi / 3.0) / power(1.0, 0.0), 1.0 / 64.0, 1e-12);
  EXPECT_NEAR(power(1.0, ocean::kPi) / power(1.0, 0.0), 0.01, 1e-12);
  EXPECT_NEAR(power(0.0, ocean::kPi) / power(0.0, 0.0), 0.5, 1e-12);
  EXPECT_NEAR(power(0.0, ocean::kPi / 3.0) / power(0.0, 0.0), 0.5, 1e-12);  // s(0) = 1
  EXPECT_EQ(ocean::vr_ocean_phillips_power(0.0, 0.0, {}, grid), 0.0);       // DC guard
  EXPECT_NEAR(ocean::vr_ocean_cutoff_length(0.0, 200.0), 0.001, 1e-15);
  EXPECT_NEAR(ocean::vr_ocean_cutoff_length(1.0, 200.0), 50.0, 1e-12);
  // Eqs. 4–5: A = N^(−1/2)·(e/L)²; along the wind with no cutoff P = A·e^(−1/(kL)²)/k⁴.
  const double big_l = 100.0 / 9.81;
  const double expected = std::pow(256.0, -0.5) * std::pow(std::exp(1.0) / 200.0, 2) *
                          std::exp(-1.0 / (k * k * big_l * big_l)) / std::pow(k, 4);
  EXPECT_LT(relative_error(power(1.0, 0.0), expected), 1e-13);
}

TEST(Phillips, RejectsBadInput) {
  using P = ocean::FrequencySpectrumParams;
  const P bad[] = {
      {.model = SpectrumModel::phillips, .significant_wave_height_m = 2.0, .peak_period_s = 8.0},
      {.model = SpectrumModel::phillips, .wind_speed_mps = 10.0, .phillips_amplitude = -1.0},
      {.model = SpectrumModel::phillips, .wind_speed_mps = 10.0, .small_wave_cutoff_m = -0.1},
      {.model = SpectrumModel::phillips, .wind_speed_mps = 10.0, .fetch_m = 1e4},
      {.model = SpectrumModel::jonswap,
       .wind_speed_mps = 10.0,
       .fetch_m = 1e4,
       .small_wave_cutoff_m = 0.5},
  };
  for (const P& p : bad) EXPECT_FALSE(FrequencySpectrum::make(p).ok());
}

}  // namespace
