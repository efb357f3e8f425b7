// The interaction scenes of `ocean view` (view/interaction.hpp): the circling boat's path and
// the wake it leaves, measured from the layer's field, and the shallows' damping against the
// depth law and the mask they are built from.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "ocean/sim.hpp"
#include "view/interaction.hpp"

namespace {

using ocean::cli::view::BoatControls;
using ocean::cli::view::circling_boat_layer;
using ocean::cli::view::circling_pose;
using ocean::cli::view::Shallows;
using ocean::cli::view::shallows_damping;

constexpr double kPi = std::numbers::pi;

TEST(ViewBoat, CirclesAtItsSpeedAlongTheTangent) {
  const BoatControls boat{.on = true, .speed_mps = 5.0, .radius_m = 40.0, .centre_m = {10, -20}};
  const double t0 = 3.0;
  for (double t : {3.0, 7.5, 20.0, 100.0}) {
    const auto p = circling_pose(boat, t0, t);
    EXPECT_NEAR(std::hypot(p.x_m - 10.0, p.z_m + 20.0), 40.0, 1e-9) << t;
    // The heading is perpendicular to the radius, and a small step moves the boat along it.
    const auto q = circling_pose(boat, t0, t + 1e-3);
    const double dx = (q.x_m - p.x_m) / 1e-3, dz = (q.z_m - p.z_m) / 1e-3;
    EXPECT_NEAR(std::hypot(dx, dz), 5.0, 1e-3) << t;
    EXPECT_NEAR(dx, 5.0 * std::cos(p.heading_rad), 1e-3) << t;
    EXPECT_NEAR(dz, 5.0 * std::sin(p.heading_rad), 1e-3) << t;
  }
  // One lap takes 2πr/U.
  const auto start = circling_pose(boat, t0, t0), lap = circling_pose(boat, t0, t0 + 2 * kPi * 8.0);
  EXPECT_NEAR(start.x_m, lap.x_m, 1e-9);
  EXPECT_NEAR(start.z_m, lap.z_m, 1e-9);
}

TEST(ViewBoat, TheLayerFollowsTheBoatAndTheWakeTrailsBehindIt) {
  const BoatControls boat{.on = true, .speed_mps = 7.0, .radius_m = 60.0, .centre_m = {0, 0}};
  const double t0 = 10.0;
  auto made = circling_boat_layer(boat, t0, 1.0);
  ASSERT_TRUE(made.ok()) << made.status().message();
  const ocean::waves::LocalLayer& layer = *made.value();
  // Every chord of the circle is driven at the same speed: one wake table, not one per chord.
  EXPECT_EQ(layer.table_count(), 1u);
  const ocean::waves::KelvinWake& wake = layer.params().wakes.at(0);
  for (double t : {t0, t0 + 11.0, t0 + 95.0}) {
    // The path's chords (5° each) stay within r·(1 − cos 2.5°) of the circle.
    const auto want = circling_pose(boat, t0, t);
    const auto got = ocean::waves::pose_at(wake, t);
    EXPECT_LT(std::hypot(got.x_m - want.x_m, got.z_m - want.z_m),
              60.0 * (1.0 - std::cos(2.5 * kPi / 180.0)) + 1e-9)
        << t;
    // Heights along the boat's track: waves behind it (the transverse waves, 2πU²/g = 31 m
    // long), still water ahead of it (a Kelvin wake has none).
    const auto rms_along = [&](double from, double to) {
      double sum = 0.0;
      int n = 0;
      for (double s = from; s <= to; s += 0.5, ++n) {
        const double x = got.x_m + s * std::cos(got.heading_rad);
        const double z = got.z_m + s * std::sin(got.heading_rad);
        const double h = layer.displacement_at(x, z, t)[1];
        sum += h * h;
      }
      return std::sqrt(sum / n);
    };
    const double behind = rms_along(-45.0, -10.0), ahead = rms_along(15.0, 50.0);
    EXPECT_GT(behind, 0.02) << t;
    EXPECT_LT(ahead, 0.1 * behind) << t;
  }
}

TEST(ViewBoat, BadControlsAreRefused) {
  EXPECT_FALSE(circling_boat_layer({.on = true, .speed_mps = -1.0}, 0.0, 1.0).ok());
  EXPECT_FALSE(circling_boat_layer({.on = true, .speed_mps = NAN}, 0.0, 1.0).ok());
  EXPECT_FALSE(circling_boat_layer({.on = true, .radius_m = 5.0}, 0.0, 1.0).ok());
}

TEST(ViewShallows, LagoonFollowsTheDepthLawAndLilyPadsTheMask) {
  ocean::SimulationConfig config;
  config.cascade_patch_sizes_m = {1000.0, 233.0, 57.0};
  const std::vector<double> k = ocean::band_wavenumbers(config);
  const std::array<double, 2> centre{30.0, -40.0};

  auto lagoon = shallows_damping(Shallows::lagoon, centre, config);
  ASSERT_TRUE(lagoon.ok()) << lagoon.status().message();
  ASSERT_TRUE(lagoon.value().has_value());
  std::vector<double> w(k.size());
  // On the island (depth 0) every band is gone; at r = 150 m the depth is (150 − 50)/5 = 20 m,
  // and each band's weight is the depth law's at 20 m.
  lagoon.value()->band_weights(centre[0], centre[1], w);
  for (double v : w) EXPECT_NEAR(v, 0.0, 1e-12);
  lagoon.value()->band_weights(centre[0] + 150.0, centre[1], w);
  for (std::size_t c = 0; c < k.size(); ++c)
    EXPECT_NEAR(w[c], ocean::waves::depth_band_weight(k[c], 20.0, 9.81), 1e-3) << c;
  EXPECT_LT(w[0], w.back());  // the longest band feels the bottom most

  auto pads = shallows_damping(Shallows::lily_pads, centre, config);
  ASSERT_TRUE(pads.ok()) << pads.status().message();
  pads.value()->band_weights(centre[0] + 10.0, centre[1] - 10.0, w);  // inside the pads
  EXPECT_DOUBLE_EQ(w[0], 1.0);
  for (std::size_t c = 1; c < w.size(); ++c) EXPECT_NEAR(w[c], 0.0, 1e-6) << c;
  pads.value()->band_weights(centre[0] + 70.0, centre[1], w);  // beyond the pads' edge
  for (double v : w) EXPECT_NEAR(v, 1.0, 1e-6);

  auto none = shallows_damping(Shallows::none, centre, config);
  ASSERT_TRUE(none.ok());
  EXPECT_FALSE(none.value().has_value());
}

}  // namespace
