// SimulationPlan (ocean/plan.hpp): what it resolves equals what each derivation gives on its own,
// its errors are validate's and the sea state's, and a simulator configured from it keeps it.
#include "ocean/plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/backends.hpp"

namespace {

using ocean::SimulationConfig;
using ocean::SimulationPlan;

SimulationConfig swell_and_sea() {
  SimulationConfig c;
  c.resolution = 64;
  c.cascade_patch_sizes_m = {800.0, 190.0, 41.0};
  c.sea.has_swell = true;
  c.sea.swell.spectrum = {.model = ocean::SpectrumModel::jonswap,
                          .significant_wave_height_m = 1.5,
                          .peak_period_s = 13.0};
  c.sea.swell.direction_rad = 0.7;
  return c;
}

TEST(SimulationPlan, ResolvesWhatEachDerivationGives) {
  const SimulationConfig c = swell_and_sea();
  const SimulationPlan plan = SimulationPlan::make(c).value();
  const auto bands = ocean::cascade_bands(c);
  const auto band_k = ocean::band_wavenumbers(c);
  ASSERT_EQ(plan.cascades().size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const ocean::CascadePlan& k = plan.cascades()[i];
    EXPECT_EQ(k.patch_size_m, c.cascade_patch_sizes_m[i]);
    EXPECT_EQ(k.band_radpm, bands[i]);
    EXPECT_EQ(k.band_wavenumber_radpm, band_k[i]);
    const ocean::InitialSpectrumParams p = ocean::cascade_spectrum_params(c, i);
    EXPECT_EQ(k.spectrum.seed, p.seed);
    EXPECT_EQ(k.spectrum.k_min_radpm, p.k_min_radpm);
    EXPECT_EQ(k.spectrum.k_max_radpm, p.k_max_radpm);
    EXPECT_EQ(k.spectrum.grid.patch_size_m, p.grid.patch_size_m);
    // The tiling wavelength lies between four texels and the band's longest wave.
    EXPECT_GE(k.tiling_wavelength_m, 4.0 * k.patch_size_m / c.resolution);
    const double longest = i == 0 ? k.patch_size_m : 2.0 * std::numbers::pi / k.band_radpm[0];
    EXPECT_LE(k.tiling_wavelength_m, longest);
  }
  // Hs = 4√m0 of both systems together (M.1).
  const double m0 = plan.sea().variance_m2();
  EXPECT_EQ(plan.significant_wave_height_m(), 4.0 * std::sqrt(m0));
  // The swell's peak (13 s, deep water: λ = gT²/2π ≈ 264 m) is longer than the wind sea's, so the
  // shortest peak wavelength is the wind sea's.
  EXPECT_LT(plan.peak_wavelength_m(), 9.81 * 13.0 * 13.0 / (2.0 * std::numbers::pi));
  // The lazily fitted noise is fit_far_field_noise's, bit for bit, and shared by copies.
  const ocean::FarFieldNoise direct = ocean::fit_far_field_noise(c).value();
  const SimulationPlan copy = plan;
  const ocean::FarFieldNoise& fitted = copy.far_noise();
  EXPECT_EQ(fitted.cell_m, direct.cell_m);
  EXPECT_EQ(fitted.amplitude_m, direct.amplitude_m);
  EXPECT_EQ(fitted.velocity_mps, direct.velocity_mps);
  EXPECT_EQ(&plan.far_noise(), &fitted);
}

// The swash's period (docs/waves.md W.40): the peak of the system with the most variance.
TEST(SimulationPlan, ThePeakPeriodIsThatOfTheLargestSystem) {
  SimulationConfig c = swell_and_sea();
  c.sea.wind_sea.spectrum.wind_speed_mps = 10.0;
  c.sea.wind_sea.spectrum.fetch_m = 100e3;
  c.sea.swell.spectrum.significant_wave_height_m = 6.0;  // above the wind sea's 2 m or so
  EXPECT_NEAR(SimulationPlan::make(c).value().surface().peak_period_s, 13.0, 1e-9);
  c.sea.swell.spectrum.significant_wave_height_m = 0.2;
  // The wind sea's: JONSWAP's fetch law (Hasselmann et al. 1973), f_p = 3.5·(g/U)·(gF/U²)^−0.33.
  const double f_p = 3.5 * (9.81 / 10.0) * std::pow(9.81 * 100e3 / 100.0, -0.33);
  EXPECT_NEAR(SimulationPlan::make(c).value().surface().peak_period_s, 1.0 / f_p, 1e-9);
}

TEST(SimulationPlan, SurfaceBoundsFollowHs) {
  SimulationConfig c = swell_and_sea();
  c.choppiness = 1.4;
  const SimulationPlan plan = SimulationPlan::make(c).value();
  const ocean::SurfaceDescription s = plan.surface();
  const double hs = plan.significant_wave_height_m();
  EXPECT_EQ(s.significant_wave_height_m, hs);
  EXPECT_EQ(s.crest_bound_m, ocean::kCrestHeightPerHs * hs + ocean::kCrestMarginM);
  EXPECT_EQ(s.horizontal_reach_m, 1.4 * hs);
  EXPECT_EQ(s.resolution, 64);
  ASSERT_EQ(s.patch_sizes_m.size(), 3u);
  ASSERT_EQ(s.tiling_wavelengths_m.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(s.tiling_wavelengths_m[i], plan.cascades()[i].tiling_wavelength_m);
  EXPECT_EQ(s.foam_ramp[0], c.foam.jacobian_start);
  EXPECT_EQ(s.foam_ramp[1], c.foam.jacobian_full);
}

TEST(SimulationPlan, ErrorsAreValidatesAndTheSeaStates) {
  SimulationConfig bad = swell_and_sea();
  bad.resolution = 100;
  EXPECT_EQ(SimulationPlan::make(bad).status().message(), ocean::validate(bad).message());
  SimulationConfig no_sea = swell_and_sea();
  no_sea.sea.wind_sea.spectrum.wind_speed_mps = -3.0;
  const auto made = SimulationPlan::make(no_sea);
  ASSERT_FALSE(made.ok());
  EXPECT_EQ(made.status().message(), ocean::SeaState::make(no_sea.sea).status().message());
}

TEST(SimulationPlan, SimulatorKeepsThePlanItWasConfiguredWith) {
  const SimulationConfig c = swell_and_sea();
  auto sim = ocean::make_simulator(c, "cpu");
  ASSERT_TRUE(sim.ok()) << sim.status().message();
  const SimulationPlan& plan = sim.value()->plan();
  EXPECT_EQ(plan.config().cascade_patch_sizes_m, c.cascade_patch_sizes_m);
  const double hs = plan.significant_wave_height_m();
  EXPECT_EQ(hs, SimulationPlan::make(c).value().significant_wave_height_m());
  SimulationConfig rougher = c;
  rougher.sea.wind_sea.spectrum.wind_speed_mps = 16.0;
  ASSERT_TRUE(sim.value()->reconfigure(rougher).ok());
  // A stronger wind over the same fetch raises the wind sea's Hs (JONSWAP: Hs ∝ U·√F).
  EXPECT_GT(sim.value()->plan().significant_wave_height_m(), hs);
  EXPECT_EQ(sim.value()->plan().config().sea.wind_sea.spectrum.wind_speed_mps, 16.0);
}

}  // namespace
