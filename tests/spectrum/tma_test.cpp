// TMA: the Kitaigorodskii depth factor against WAFO, its deep and shallow limits, and the
// Thompson–Vincent approximation.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/spectrum.hpp"
#include "spectrum/test_util.hpp"

namespace {

using ocean::DepthFactor;
using ocean::FrequencySpectrum;
using ocean::SpectrumModel;
using ocean_test::relative_error;

// WAFO (pywafo @c831ec8) src/wafo/spectrum/tests/test_models.py lines 31–35:
// Tmaspec(Hm0 = 7, Tp = 11, γ = 1, h = 10) at ω = 1, 2, 3 (decimal = 5, 8 digits printed).
TEST(Tma, WafoTmaspecValues) {
  const FrequencySpectrum s = FrequencySpectrum::make({.model = SpectrumModel::tma,
                                                       .significant_wave_height_m = 7.0,
                                                       .peak_period_s = 11.0,
                                                       .gamma = 1.0,
                                                       .depth_m = 10.0})
                                  .value();
  EXPECT_NEAR(s(1.0), 0.70106233, 6e-9);
  EXPECT_NEAR(s(2.0), 0.05022433, 6e-9);
  EXPECT_NEAR(s(3.0), 0.00669692, 6e-9);
}

// WAFO phi1(w, h): the doctest `Jonswap()(w)*phi1(w, 30)` (models.py lines 685–689) and the
// Tmaspec test above imply Φ(1, 30) = 0.9659327465, Φ(1, 10) = 0.49130424, Φ(2, 10) = 0.99421674.
TEST(Tma, WafoExactFactor) {
  EXPECT_NEAR(ocean::tma_depth_factor(1.0, 30.0, 9.81, DepthFactor::exact), 0.9659327465, 1e-9);
  // The h = 10 values are ratios of 8-digit printed numbers: good to ~1e-7 relative.
  EXPECT_NEAR(ocean::tma_depth_factor(1.0, 10.0, 9.81, DepthFactor::exact), 0.49130424, 1e-7);
  EXPECT_NEAR(ocean::tma_depth_factor(2.0, 10.0, 9.81, DepthFactor::exact), 0.99421674, 2e-7);
}

// Identities: Φ → 1 in deep water, Φ → ωh²/2 in the shallow limit (Kitaigorodskii et al. 1975).
TEST(Tma, DeepAndShallowLimits) {
  const double g = 9.81;
  for (double omega : {0.5, 1.0, 3.0}) {
    EXPECT_NEAR(ocean::tma_depth_factor(omega, 5000.0, g, DepthFactor::exact), 1.0, 1e-12);
    EXPECT_EQ(ocean::tma_depth_factor(omega, ocean::kInfiniteDepth, g, DepthFactor::exact), 1.0);
  }
  for (double omega_h : {1e-3, 1e-2, 3e-2}) {
    const double depth = 10.0;
    const double omega = omega_h * std::sqrt(g / depth);
    const double phi = ocean::tma_depth_factor(omega, depth, g, DepthFactor::exact);
    EXPECT_LT(relative_error(phi, 0.5 * omega_h * omega_h), 2.0 * omega_h * omega_h);
  }
}

// TMA tends to JONSWAP in deep water.
TEST(Tma, TendsToJonswapInDeepWater) {
  const FrequencySpectrum deep =
      FrequencySpectrum::make(
          {.model = SpectrumModel::tma, .wind_speed_mps = 12.0, .fetch_m = 5e4, .depth_m = 3000.0})
          .value();
  const FrequencySpectrum j =
      FrequencySpectrum::make(
          {.model = SpectrumModel::jonswap, .wind_speed_mps = 12.0, .fetch_m = 5e4})
          .value();
  for (double w = 0.3; w < 5.0; w *= 1.1) EXPECT_LT(relative_error(deep(w), j(w)), 1e-10);
}

// Thompson & Vincent (1983): ωh²/2 up to 1, 1 − (2 − ωh)²/2 up to 2, then 1; continuous, and
// within 0.025 of the exact factor everywhere (worst near ωh ≈ 1.2).
TEST(Tma, ThompsonVincentApproximation) {
  const double g = 9.81;
  const double depth = 10.0;
  const auto tv = [&](double omega_h) {
    return ocean::tma_depth_factor(omega_h * std::sqrt(g / depth), depth, g,
                                   DepthFactor::thompson_vincent);
  };
  EXPECT_NEAR(tv(0.5), 0.125, 1e-12);
  EXPECT_NEAR(tv(1.0), 0.5, 1e-12);
  EXPECT_NEAR(tv(1.5), 0.875, 1e-12);
  EXPECT_NEAR(tv(2.0), 1.0, 1e-12);
  EXPECT_EQ(tv(3.0), 1.0);
  double max_diff = 0.0;
  for (double omega_h = 0.01; omega_h < 4.0; omega_h += 0.01) {
    const double exact =
        ocean::tma_depth_factor(omega_h * std::sqrt(g / depth), depth, g, DepthFactor::exact);
    max_diff = std::max(max_diff, std::abs(exact - tv(omega_h)));
    EXPECT_LE(exact, 1.0 + 1e-12);
  }
  EXPECT_LT(max_diff, 0.025);
}

TEST(Tma, RejectsBadDepth) {
  for (double depth : {0.0, -5.0, std::nan("")}) {
    EXPECT_FALSE(
        FrequencySpectrum::make(
            {.model = SpectrumModel::tma, .wind_speed_mps = 10.0, .fetch_m = 1e4, .depth_m = depth})
            .ok());
  }
}

}  // namespace
