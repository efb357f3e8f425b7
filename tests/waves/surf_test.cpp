// Depth-induced breaking (ocean/waves.hpp, docs/waves.md W.25–W.27): the fraction of breaking
// waves solves Battjes & Janssen's (1978) relation; on a planar beach built here the surf begins
// where the rms height of the damped bands, computed here from the Kitaigorodskii factor's closed
// form, reaches γ·d, within the map's cell; shoreward of it the bands' weights hold H_rms at γ·d,
// and the simulator's queried heights carry exactly that variance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "ocean/backends.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"
#include "support/depth_law.hpp"

namespace surf_test {

using ocean::waves::breaking_fraction;
using ocean::waves::Damping;
using ocean::waves::DampingParams;
using ocean::waves::HeightMap;
using ocean::waves::PlacedMap;
constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;
constexpr double kGamma = 0.78;  // McCowan (1894)

using ocean_test::kitaigorodskii_phi;  // W.12's closed form (support/depth_law.hpp)

// A fetch-limited wind sea on the project's three default-sized cascades at a small grid.
ocean::SimulationConfig beach_sea() {
  ocean::SimulationConfig c;
  c.sea.wind_sea.spectrum = {
      .model = ocean::SpectrumModel::jonswap, .wind_speed_mps = 12.0, .fetch_m = 1e5};
  c.resolution = 64;
  c.cascade_patch_sizes_m = {400.0, 60.0, 12.0};
  c.choppiness = 0.0;
  return c;
}

TEST(Surf, BreakingFractionSolvesBattjesJanssen) {
  EXPECT_EQ(breaking_fraction(0.0), 0.0);
  EXPECT_EQ(breaking_fraction(-1.0), 0.0);
  EXPECT_EQ(breaking_fraction(std::nan("")), 0.0);
  EXPECT_EQ(breaking_fraction(1.0), 1.0);  // the saturated surf zone
  EXPECT_EQ(breaking_fraction(3.0), 1.0);
  double previous = 0.0;
  for (double b = 0.05; b < 0.9999; b += 0.01) {
    const double q = breaking_fraction(b);
    ASSERT_GT(q, previous) << "b = " << b;  // rises with b
    ASSERT_LT(q, 1.0) << "b = " << b;
    // (1 − Q)/ln Q = −b², in the form ln Q = −(1 − Q)/b² that holds where Q underflows
    // (Q ≈ e^{−1/b²}: e^{−400} at b = 0.05).
    EXPECT_NEAR(std::log(q), -(1.0 - q) / (b * b), 1e-9 * (1.0 + 1.0 / (b * b))) << "b = " << b;
    previous = q;
  }
  // Close to saturation, ln Q = −ε − ε²/2 + … with ε = 1 − Q gives ε ≈ 2(1 − b²).
  const double b = 0.9999;
  EXPECT_NEAR(1.0 - breaking_fraction(b), 2.0 * (1.0 - b * b), 1e-6);
}

// A planar beach rising towards −x: d(x) = s·x for x in [0, 200] m, a 4-row map of 0.5 m cells
// whose samples lie on the plane (bilinear sampling is exact on it); the onset of breaking along
// z = 1 m is where H_rms = γ·d.
TEST(Surf, PlanarBeachBreaksWhereTheRmsHeightReachesGammaTimesDepth) {
  const ocean::SimulationConfig c = beach_sea();
  const auto variances = ocean::band_variances(c);
  ASSERT_TRUE(variances.ok()) << variances.status().message();
  const std::vector<double> m0 = variances.value();
  const std::vector<double> k = ocean::band_wavenumbers(c);
  const double slope = 1.0 / 20.0, cell = 0.5;
  const int cols = 400;
  auto map = std::make_shared<HeightMap>();
  map->rows = 4;
  map->cols = cols;
  for (int r = 0; r < 4; ++r)
    for (int col = 0; col < cols; ++col)
      map->values.push_back(static_cast<float>(slope * (col + 0.5) * cell));
  const auto made = Damping::make({.bathymetry = PlacedMap{.map = map, .size_m = cols * cell},
                                   .band_wavenumbers_radpm = k,
                                   .band_variances_m2 = m0,
                                   .breaking_index = kGamma});
  ASSERT_TRUE(made.ok()) << made.status().message();
  const Damping& damping = made.value();

  // The analytic onset: H_rms(d)² = 8·Σ Φ(√(g·k_c), d)·m0_c (W.12, W.25), H_rms(d) = γ·d,
  // bisected on d (H_rms > γ·d in the shallows, where H_rms ∝ √d).
  const auto rms = [&](double d) {
    double s = 0.0;
    for (std::size_t b = 0; b < k.size(); ++b)
      s += kitaigorodskii_phi(std::sqrt(kG * k[b]), d) * m0[b];
    return std::sqrt(8.0 * s);
  };
  double lo = 1e-6, hi = 10.0;
  ASSERT_GT(rms(lo), kGamma * lo);
  ASSERT_LT(rms(hi), kGamma * hi);
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rms(mid) > kGamma * mid ? lo : hi) = mid;
  }
  const double x_break = lo / slope;
  ASSERT_GT(x_break, 4.0 * cell);  // well inside the map, past its clamped edge
  ASSERT_LT(x_break, 150.0);

  // The damping's onset: scanning shoreward in steps of a tenth of a cell, the first point where
  // every wave breaks (Q_b = 1, H_rms ≥ H_max).
  double onset = -1.0;
  for (double x = 150.0; x > 0.0; x -= 0.1 * cell) {
    if (damping.surf(x, 1.0).breaking_fraction >= 1.0) {
      onset = x;
      break;
    }
  }
  std::printf(
      "onset of breaking on a 1:20 beach: analytic x = %.3f m (d = %.4f m), found %.3f m "
      "(cell %.2f m)\n",
      x_break, x_break * slope, onset, cell);
  EXPECT_NEAR(onset, x_break, cell) << "analytic d_b = " << x_break * slope << " m";

  std::vector<double> w(k.size());
  for (double x = 2.0 * cell; x < 150.0; x += 0.37) {
    const double d = slope * x;
    const ocean::waves::Surf s = damping.surf(x, 1.0);
    ASSERT_NEAR(s.depth_m, d, 1e-5 * d);
    EXPECT_NEAR(s.rms_height_m, rms(d), 1e-4 * rms(d)) << "x = " << x;
    EXPECT_NEAR(s.max_height_m, kGamma * d, 1e-5 * d);
    // The bands' weights: H_rms of the weighted variances, √(8 Σ w_c² m0_c), is the unbroken
    // sea's seaward of the onset and γ·d shoreward (W.27).
    damping.band_weights(x, 1.0, w);
    double v = 0.0;
    for (std::size_t b = 0; b < k.size(); ++b) v += w[b] * w[b] * m0[b];
    const double h = std::sqrt(8.0 * v);
    if (x < x_break - cell) {
      EXPECT_NEAR(h, kGamma * d, 1e-5 * d) << "x = " << x;
      EXPECT_EQ(s.breaking_fraction, 1.0) << "x = " << x;
    } else if (x > x_break + cell) {
      EXPECT_NEAR(h, rms(d), 1e-4 * rms(d)) << "x = " << x;
      EXPECT_LT(s.breaking_fraction, 1.0) << "x = " << x;
      EXPECT_NEAR(s.breaking_fraction, breaking_fraction(rms(d) / (kGamma * d)), 1e-3) << x;
    }
    // Never above the index (of the map's float depth, within 1e-7 of the plane's).
    EXPECT_LE(h, kGamma * s.depth_m * (1.0 + 1e-12)) << "x = " << x;
  }
  // Off the map: deep water, nothing breaks.
  EXPECT_EQ(damping.surf(-5.0, 1.0).breaking_fraction, 0.0);
  EXPECT_TRUE(std::isinf(damping.surf(-5.0, 1.0).max_height_m));
}

// A single 300 m band over a constant depth in its surf zone: the heights queried at the band's
// texel centres (choppiness 0: the texels themselves, weighted) have the mean square (γ·d)²/8
// when the damping is given the realisation's own texel variance as the band's variance.
TEST(Surf, QueriedHeightsInTheSurfZoneHaveTheIndexesRmsHeight) {
  ocean::SimulationConfig c = beach_sea();
  c.cascade_patch_sizes_m = {300.0};
  auto made = ocean::make_simulator(c);
  ASSERT_TRUE(made.ok()) << made.status().message();
  auto& sim = *made.value();
  sim.step(4.0);
  const auto& disp = sim.frame().cascades[0].displacement;
  double texel = 0.0;
  for (std::size_t i = 1; i < disp.size(); i += 3) texel += double(disp[i]) * disp[i];
  texel /= static_cast<double>(disp.size() / 3);
  const double depth = 0.1;
  auto floor = std::make_shared<HeightMap>();
  floor->rows = floor->cols = 4;
  floor->values.assign(16, static_cast<float>(depth));
  const double k = ocean::band_wavenumbers(c)[0];
  const double unbroken = std::sqrt(8.0 * kitaigorodskii_phi(std::sqrt(kG * k), depth) * texel);
  ASSERT_GT(unbroken, 1.2 * kGamma * depth);  // the depth is in the surf zone
  auto damping = Damping::make(
      {.bathymetry = PlacedMap{.map = floor, .origin_m = {-500, -500}, .size_m = 1000.0},
       .band_wavenumbers_radpm = {k},
       .band_variances_m2 = {texel},
       .breaking_index = kGamma});
  ASSERT_TRUE(damping.ok()) << damping.status().message();
  sim.set_damping(std::make_shared<const Damping>(std::move(damping).value()));
  std::vector<std::array<double, 2>> at;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) at.push_back({-150.0 + 300.0 * i / 64, -150.0 + 300.0 * j / 64});
  std::vector<ocean::HeightSample> out(at.size());
  sim.heights_at(at, out);
  double ms = 0.0;
  for (const auto& s : out) ms += s.height_m * s.height_m;
  ms /= static_cast<double>(out.size());
  // Float texels, double sums: 0.1 %.
  EXPECT_NEAR(std::sqrt(8.0 * ms), kGamma * depth, 1e-3 * kGamma * depth);
}

TEST(Surf, BadBreakingParametersAreRefusedNamingTheField) {
  const auto fails = [](DampingParams p, const std::string& expected) {
    p.band_wavenumbers_radpm = {0.1, 1.0};
    const auto made = Damping::make(std::move(p));
    ASSERT_FALSE(made.ok());
    EXPECT_NE(made.status().message().find(expected), std::string::npos) << made.status().message();
  };
  fails({.band_variances_m2 = {1.0}}, "1 band variances for 2 band wavenumbers");
  fails({.band_variances_m2 = {1.0, -0.5}}, "band_variances_m2[1]");
  fails({.band_variances_m2 = {1.0, std::nan("")}}, "band_variances_m2[1]");
  fails({.breaking_index = 0.1}, "breaking_index");
  fails({.breaking_index = std::nan("")}, "breaking_index");
}

TEST(Surf, BandVariancesSumToTheSpectrumsVarianceOverTheBands) {
  // The three bands tile the wave vectors from cascade 0's fundamental to the last Nyquist; a
  // 12 m/s sea's variance lies almost wholly within (its peak at ≈ 100 m).
  const ocean::SimulationConfig c = beach_sea();
  const auto m0 = ocean::band_variances(c);
  ASSERT_TRUE(m0.ok());
  ASSERT_EQ(m0.value().size(), 3u);
  const auto sea = ocean::SeaState::make(c.sea);
  ASSERT_TRUE(sea.ok());
  const double total = m0.value()[0] + m0.value()[1] + m0.value()[2];
  EXPECT_GT(total, 0.9 * sea.value().variance_m2());
  EXPECT_LT(total, 1.05 * sea.value().variance_m2());
}

}  // namespace surf_test
