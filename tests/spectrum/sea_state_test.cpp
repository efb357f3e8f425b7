// Sea state: the ω→k conversion conserves variance, directions point where waves travel,
// swell adds its own energy, and depth is shared between TMA and the dispersion.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/spectrum.hpp"
#include "spectrum/test_util.hpp"

namespace {

using ocean::SeaState;
using ocean::SeaStateParams;
using ocean::SpectrumModel;
using ocean::SpreadingModel;
using ocean_test::relative_error;

// ∫∫F dkx dkz in polar coordinates: ∫∫F(k, θ)·k dθ dk, k on a log grid.
double integrate_k(const SeaState& sea, double k_lo, double k_hi) {
  const double u0 = std::log(k_lo);
  const double u1 = std::log(k_hi);
  return ocean_test::simpson(
      [&](double u) {
        const double k = std::exp(u);
        const double ring = ocean_test::simpson(
            [&](double t) { return sea.wave_vector_spectrum(k * std::cos(t), k * std::sin(t)); },
            -ocean::kPi, ocean::kPi, 720);
        return ring * k * k;  // k dk = k² du
      },
      u0, u1, 1600);
}

SeaStateParams wind_sea(ocean::FrequencySpectrumParams spectrum, ocean::SpreadingParams spreading) {
  SeaStateParams p;
  p.wind_sea = {.spectrum = spectrum, .spreading = spreading, .direction_rad = 0.4};
  return p;
}

// Vincevičius 2024, eq. 1.15 / Horvath (2015): F(k) = S(ω)·D·(dω/dk)/k keeps ∫∫F dk = ∫S dω.
TEST(SeaState, OmegaToKConversionConservesVariance) {
  const SeaStateParams cases[] = {
      wind_sea({.model = SpectrumModel::jonswap, .wind_speed_mps = 10.0, .fetch_m = 1e5},
               {.model = SpreadingModel::donelan_banner}),
      wind_sea(
          {.model = SpectrumModel::tma, .wind_speed_mps = 10.0, .fetch_m = 1e5, .depth_m = 8.0},
          {.model = SpreadingModel::mitsuyasu}),
      wind_sea({.model = SpectrumModel::pierson_moskowitz,
                .significant_wave_height_m = 2.0,
                .peak_period_s = 8.0},
               {.model = SpreadingModel::cos2s, .s = 8.0}),
      wind_sea({.model = SpectrumModel::phillips, .wind_speed_mps = 7.0},
               {.model = SpreadingModel::power_cosine, .alpha = 0.7}),
  };
  for (const SeaStateParams& p : cases) {
    const SeaState sea = SeaState::make(p).value();
    const double wp = sea.systems().front().spectrum().peak_omega();
    const double k_lo = sea.dispersion().wavenumber(0.05 * wp);
    const double k_hi = sea.dispersion().wavenumber(60.0 * wp);
    const double m0_k = integrate_k(sea, k_lo, k_hi);
    // The same band in ω; the conversion must reproduce it, not only the total.
    const auto& s = sea.systems().front().spectrum();
    const double m0_omega =
        ocean_test::simpson([&](double w) { return s(w); }, 0.05 * wp, 60.0 * wp, 200000);
    EXPECT_LT(relative_error(m0_k, m0_omega), 1e-4) << ocean::to_string(p.wind_sea.spectrum.model);
    EXPECT_LT(relative_error(m0_omega, sea.variance_m2()), 2e-3);
  }
}

TEST(SeaState, EnergyTravelsAlongTheMeanDirection) {
  SeaStateParams p =
      wind_sea({.model = SpectrumModel::jonswap, .wind_speed_mps = 10.0, .fetch_m = 1e5},
               {.model = SpreadingModel::cos2s, .s = 10.0});
  p.wind_sea.direction_rad = ocean::kPi / 2.0;  // towards +z
  const SeaState sea = SeaState::make(p).value();
  const double k = sea.dispersion().wavenumber(sea.systems().front().spectrum().peak_omega());
  EXPECT_GT(sea.wave_vector_spectrum(0.0, k), 100.0 * sea.wave_vector_spectrum(k, 0.0));
  EXPECT_GT(sea.wave_vector_spectrum(0.0, k), 100.0 * sea.wave_vector_spectrum(0.0, -k));
  EXPECT_EQ(sea.wave_vector_spectrum(0.0, 0.0), 0.0);
}

TEST(SeaState, SwellAddsItsVariance) {
  SeaStateParams p =
      wind_sea({.model = SpectrumModel::jonswap, .wind_speed_mps = 8.0, .fetch_m = 3e4},
               {.model = SpreadingModel::donelan_banner});
  const double wind_only = SeaState::make(p).value().variance_m2();
  p.has_swell = true;
  p.swell = {.spectrum = {.model = SpectrumModel::jonswap,
                          .significant_wave_height_m = 1.5,
                          .peak_period_s = 13.0,
                          .gamma = 5.0,
                          .normalization = ocean::JonswapNormalization::exact},
             .spreading = {.model = SpreadingModel::cos2s, .s = 40.0},
             .direction_rad = -1.0};
  const SeaState sea = SeaState::make(p).value();
  EXPECT_LT(relative_error(sea.variance_m2(), wind_only + 1.5 * 1.5 / 16.0), 1e-8);
  // The swell's peak shows up along its own direction.
  const double k = sea.dispersion().wavenumber(2.0 * ocean::kPi / 13.0);
  EXPECT_GT(sea.wave_vector_spectrum(k * std::cos(-1.0), k * std::sin(-1.0)),
            10.0 * sea.wave_vector_spectrum(k, 0.0));
}

TEST(SeaState, TmaDepthIsSharedWithDispersion) {
  SeaStateParams p = wind_sea(
      {.model = SpectrumModel::tma, .wind_speed_mps = 10.0, .fetch_m = 1e5, .depth_m = 6.0},
      {.model = SpreadingModel::donelan_banner});
  EXPECT_EQ(SeaState::make(p).value().dispersion().params().depth_m, 6.0);
  p.dispersion.depth_m = 30.0;
  const auto mismatch = SeaState::make(p);
  ASSERT_FALSE(mismatch.ok());
  EXPECT_NE(mismatch.status().message().find("depth"), std::string::npos);
}

TEST(SeaState, ReportsWhichSystemIsBad) {
  SeaStateParams p =
      wind_sea({.model = SpectrumModel::jonswap, .wind_speed_mps = 8.0, .fetch_m = 3e4},
               {.model = SpreadingModel::donelan_banner});
  p.has_swell = true;
  p.swell.spectrum = {
      .model = SpectrumModel::jonswap, .significant_wave_height_m = -1.0, .peak_period_s = 12.0};
  const auto sea = SeaState::make(p);
  ASSERT_FALSE(sea.ok());
  EXPECT_EQ(sea.status().message().rfind("swell: ", 0), 0u);
}

}  // namespace
