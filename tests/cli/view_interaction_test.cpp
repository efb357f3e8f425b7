// The interaction scenes of `ocean view` (view/interaction.hpp): the boat's world (the floating
// boat driven round its circle by its propulsion on the view's sea, and the wake its track leaves,
// measured from the layer's field), and the shallows' damping against the depth law and the mask
// they are built from.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/lod.hpp"
#include "ocean/sim.hpp"
#include "view/interaction.hpp"

namespace {

using ocean::cli::view::BoatControls;
using ocean::cli::view::make_boat_world;
using ocean::cli::view::Shallows;
using ocean::cli::view::shallows_damping;

ocean::SimulationConfig view_sea() {
  ocean::SimulationConfig c;
  c.resolution = 16;
  c.cascade_patch_sizes_m = {100.0};
  return c;
}

// The view's sea made exactly calm: a bathymetry of depth 0 damps every band to nothing (W.12),
// so that the boat rides on its own wake alone.
std::unique_ptr<ocean::Simulator> calm_view_sea() {
  const ocean::SimulationConfig c = view_sea();
  auto sim = ocean::make_simulator(c).value();
  auto map = std::make_shared<ocean::waves::HeightMap>();
  map->rows = 2, map->cols = 2, map->values = {0.0f, 0.0f, 0.0f, 0.0f};
  auto damping = ocean::waves::Damping::make(
      {.bathymetry = ocean::waves::PlacedMap{.map = map, .origin_m = {-1e3, -1e3}, .size_m = 2e3},
       .band_wavenumbers_radpm = ocean::band_wavenumbers(c)});
  sim->set_damping(std::make_shared<const ocean::waves::Damping>(damping.value()));
  sim->step(0.0);
  return sim;
}

// The view's frames: the boat's world advanced every 1/30 s.
void run(ocean::world::World& boat, ocean::Simulator& sea, double from, double to) {
  for (double t = from; t <= to + 1e-9; t += 1.0 / 30)
    ASSERT_TRUE(boat.advance_to(t, sea).ok()) << t;
}

TEST(ViewBoat, FloatingBoatIsDrivenRoundTheCircleAndItsWakeTrailsBehindIt) {
  const BoatControls controls{.on = true, .speed_mps = 7.0, .radius_m = 80.0, .centre_m = {0, 0}};
  const double t0 = 10.0;
  auto made = make_boat_world(controls, t0, view_sea());
  ASSERT_TRUE(made.ok()) << made.status().message();
  ocean::world::World& boat = *made.value();
  auto sea = calm_view_sea();
  run(boat, *sea, t0, t0 + 15.0);  // settling onto the circle
  // Most of a lap (the lap is 2π·80/7 = 72 s): on the circle within 10 % of its radius (the
  // line-of-sight guidance holds the boat a little outside, where its inward turn equals the
  // hull's drift angle on the turn, B.11), at the commanded speed within 3 %.
  double farthest = 0.0;
  for (double t = t0 + 15.0; t < t0 + 60.0; t += 5.0) {
    run(boat, *sea, t, t + 5.0);
    const auto& s = boat.body(0)->state();
    const double rho = std::hypot(s.position_m[0], s.position_m[2]);
    farthest = std::max(farthest, std::abs(rho - 80.0));
    EXPECT_NEAR(std::hypot(s.velocity_mps[0], s.velocity_mps[2]), 7.0, 0.21) << t;
  }
  std::printf("largest distance from the circle %.2f m (radius 80 m), %zu wake tables\n", farthest,
              boat.tables_computed());
  EXPECT_LT(farthest, 8.0);
  // The layer was remade at every waypoint (2 per second, 130 times) but computed a table only
  // for the few 1 % speed steps the boat passed while it settled into the turn.
  EXPECT_LE(boat.tables_computed(), 6u);
  ASSERT_NE(boat.local_layer(), nullptr);
  EXPECT_EQ(sea->local_layer(), boat.local_layer().get());  // handed to the view's sea
  const ocean::waves::LocalLayer& layer = *boat.local_layer();
  EXPECT_EQ(layer.table_count(), 1u);
  // The square centred on the circle, kBoatWakeMargin_m beyond it.
  EXPECT_EQ(layer.params().area.size_m, 2.0 * (80.0 + ocean::cli::view::kBoatWakeMargin_m));
  EXPECT_EQ(layer.params().area.resolution, ocean::cli::view::kBoatLayerResolution);
  const double t = boat.time_s();
  const auto wake = ocean::waves::pose_at(layer.params().wakes.at(0), t);
  const auto& x = boat.body(0)->state().position_m;
  EXPECT_LT(std::hypot(wake.x_m - x[0], wake.z_m - x[2]), 1.0);  // the wake is at the boat
  // Heights along the boat's track: waves behind it (the transverse waves, 2πU²/g = 31 m long),
  // still water ahead of it (a Kelvin wake has none).
  const auto rms_along = [&](double from, double to) {
    double sum = 0.0;
    int n = 0;
    for (double s = from; s <= to; s += 0.5, ++n) {
      const double h = layer.displacement_at(wake.x_m + s * std::cos(wake.heading_rad),
                                             wake.z_m + s * std::sin(wake.heading_rad), t)[1];
      sum += h * h;
    }
    return std::sqrt(sum / n);
  };
  const double behind = rms_along(-45.0, -10.0), ahead = rms_along(15.0, 50.0);
  EXPECT_GT(behind, 0.02);
  EXPECT_LT(ahead, 0.1 * behind);
}

TEST(ViewBoat, NewControlsDriveTheRunningBoat) {
  auto made = make_boat_world({.on = true, .speed_mps = 5.0, .radius_m = 150.0}, 0.0, view_sea());
  ASSERT_TRUE(made.ok()) << made.status().message();
  ocean::world::World& boat = *made.value();
  auto sea = calm_view_sea();
  run(boat, *sea, 0.0, 5.0);
  ASSERT_TRUE(boat.set_course(0, 8.0, {.radius_m = 150.0}).ok());
  run(boat, *sea, 5.0, 35.0);
  const auto& v = boat.body(0)->state().velocity_mps;
  EXPECT_NEAR(std::hypot(v[0], v[2]), 8.0, 0.24);
  EXPECT_FALSE(boat.set_course(0, NAN, {.radius_m = 150.0}).ok());
}

TEST(ViewBoat, BadControlsAreRefused) {
  EXPECT_FALSE(make_boat_world({.on = true, .speed_mps = -1.0}, 0.0, view_sea()).ok());
  EXPECT_FALSE(make_boat_world({.on = true, .speed_mps = NAN}, 0.0, view_sea()).ok());
  EXPECT_FALSE(make_boat_world({.on = true, .radius_m = 5.0}, 0.0, view_sea()).ok());
  EXPECT_FALSE(make_boat_world({.on = true, .speed_mps = 25.0}, 0.0, view_sea()).ok());
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
  // On the island (land 4 m high) every band is gone; at r = 140 m (inside the reef at 150 m)
  // the depth is (140 − 50)/5 = 18 m, and each band's weight is the depth law's at 18 m.
  lagoon.value()->band_weights(centre[0], centre[1], w);
  for (double v : w) EXPECT_NEAR(v, 0.0, 1e-12);
  lagoon.value()->band_weights(centre[0] + 140.0, centre[1], w);
  for (std::size_t c = 0; c < k.size(); ++c)
    EXPECT_NEAR(w[c], ocean::waves::depth_band_weight(k[c], 18.0, 9.81), 1e-3) << c;
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

// `ocean view --boat --shallows lagoon` starts framed on its scenes: every point of the disc the
// scenes occupy (the boat's circle and hull, 90 m; the lagoon's shoal, 100 m) lies inside the
// picture, and the disc spans at least 80 % of the narrower of its two angles (its centre's
// chord does), for the view's default 55° at 16:9 and a square 40° picture; with no scene there is
// nothing to frame.
TEST(ViewFraming, TheScenesStartInThePicture) {
  using ocean::cli::view::framing_camera;
  using ocean::cli::view::scene_radius_m;
  EXPECT_EQ(scene_radius_m({.on = false}, Shallows::none), 0.0);
  EXPECT_EQ(scene_radius_m({.on = true}, Shallows::none), 90.0);
  EXPECT_EQ(scene_radius_m({.on = true}, Shallows::lagoon), 100.0);
  const std::array<double, 2> centre = {300.0, 60.0};
  for (const auto& [fov_deg, aspect] : {std::pair{55.0, 16.0 / 9.0}, std::pair{40.0, 1.0}}) {
    const double radius = scene_radius_m({.on = true}, Shallows::lagoon);
    const double fov = fov_deg * std::numbers::pi / 180.0;
    const auto [eye, target] = framing_camera(centre, radius, {300.0, 60.0}, fov, aspect);
    const ocean::lod::Camera camera{.position_m = {eye[0], eye[1], eye[2]},
                                    .target_m = {target[0], target[1], target[2]},
                                    .fov_y_rad = fov,
                                    .aspect = aspect,
                                    .near_m = 0.5,
                                    .far_m = 1e5};
    ASSERT_TRUE(ocean::lod::validate(camera).ok());
    const ocean::lod::Mat4 vp = ocean::lod::view_projection(camera);
    double left = 1.0, right = -1.0;
    for (int i = 0; i < 64; ++i) {
      const double a = 2.0 * std::numbers::pi * i / 64.0;
      const double p[4] = {centre[0] + radius * std::cos(a), 0.0, centre[1] + radius * std::sin(a),
                           1.0};
      double clip[4] = {};
      for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 4; ++k) clip[r] += vp.m[static_cast<std::size_t>(k * 4 + r)] * p[k];
      ASSERT_GT(clip[3], 0.0) << "point " << i << " behind the eye";
      const double x = clip[0] / clip[3], y = clip[1] / clip[3];
      EXPECT_LE(std::abs(x), 1.0) << "point " << i << ", fov " << fov_deg;
      EXPECT_LE(std::abs(y), 1.0) << "point " << i << ", fov " << fov_deg;
      left = std::min(left, x), right = std::max(right, x);
    }
    const double half = std::tan(0.5 * fov) * aspect;  // tan of half the horizontal angle
    const double span = std::atan(right * half) - std::atan(left * half);
    const double narrower = std::min(fov, 2.0 * std::atan(half));
    std::printf(
        "fov %.0f°, aspect %.2f: eye %.0f m up, the disc spans %.0f %% of the narrower "
        "angle\n",
        fov_deg, aspect, eye[1], 100.0 * span / narrower);
    // The chord through the centre spans 80 %; the nearer chords, seen from closer, more.
    EXPECT_GE(span / narrower, 0.8 - 1e-9) << "fov " << fov_deg;
  }
}
