// The window-free parts of `ocean view`: the free camera's conventions (yaw from +x towards +z,
// right = forward × up, never below 1000 m under the sea), the panel's sea controls ⇄
// SimulationConfig, and the frame-time median.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "view/frame_times.hpp"
#include "view/free_camera.hpp"
#include "view/sea_controls.hpp"

namespace {

using ocean::cli::view::CameraInput;
using ocean::cli::view::FrameTimes;
using ocean::cli::view::FreeCamera;
using ocean::cli::view::SeaControls;
using ocean::lod::Vec3;

double distance(Vec3 a, Vec3 b) { return std::hypot(a.x - b.x, a.y - b.y, a.z - b.z); }

TEST(FreeCamera, StartsLookingAtTheTarget) {
  const FreeCamera cam({0, 6, 0}, {300, -2, 60});
  const Vec3 f = cam.forward();
  const double n = std::hypot(300.0, -8.0, 60.0);
  EXPECT_NEAR(f.x, 300.0 / n, 1e-12);
  EXPECT_NEAR(f.y, -8.0 / n, 1e-12);
  EXPECT_NEAR(f.z, 60.0 / n, 1e-12);
  const ocean::lod::Camera c = cam.camera(1.0, 1.5);
  EXPECT_TRUE(ocean::lod::validate(c).ok());
  EXPECT_NEAR((c.target_m.x - c.position_m.x) / distance(c.target_m, c.position_m), f.x, 1e-12);
}

TEST(FreeCamera, MovesAtItsSpeedAndShiftIsFaster) {
  FreeCamera cam({0, 10, 0}, {1, 10, 0});  // looking along +x
  cam.update({.forward = true}, 1.0);
  EXPECT_NEAR(cam.position().x, cam.params().speed_mps, 1e-12);
  cam.update({.back = true, .fast = true}, 1.0);
  EXPECT_NEAR(cam.position().x, cam.params().speed_mps * (1.0 - cam.params().fast_factor), 1e-9);
  // Diagonal movement is not faster than straight movement.
  FreeCamera diag({0, 10, 0}, {1, 10, 0});
  diag.update({.forward = true, .right = true}, 1.0);
  EXPECT_NEAR(distance(diag.position(), {0, 10, 0}), diag.params().speed_mps, 1e-9);
}

TEST(FreeCamera, RightIsPlusZAtYawZeroAndTheMouseTurnsThatWay) {
  FreeCamera cam({0, 10, 0}, {1, 10, 0});
  cam.update({.right = true}, 1.0);
  EXPECT_NEAR(cam.position().x, 0.0, 1e-12);
  EXPECT_GT(cam.position().z, 0.0);
  FreeCamera turn({0, 10, 0}, {1, 10, 0});
  turn.update({.looking = true, .mouse_dx_px = 100.0, .mouse_dy_px = 100.0}, 0.016);
  EXPECT_GT(turn.forward().z, 0.0);  // mouse right: towards the right
  EXPECT_LT(turn.forward().y, 0.0);  // mouse down: looks down
  // Without the button held the mouse does nothing.
  FreeCamera still({0, 10, 0}, {1, 10, 0});
  still.update({.mouse_dx_px = 100.0}, 0.016);
  EXPECT_EQ(still.yaw_rad(), 0.0);
}

TEST(FreeCamera, DivesNoDeeperThanItsFloorAndNeverFlips) {
  FreeCamera cam({0, -3.0, 0}, {10, -3.0, 0});
  EXPECT_EQ(cam.position().y, -3.0);  // under the sea: the view from below (R.50)
  cam.update({.down = true, .fast = true}, 100.0);
  EXPECT_EQ(cam.position().y, cam.params().min_height_m);
  EXPECT_EQ(cam.params().min_height_m, -1000.0);
  cam.update({.looking = true, .mouse_dy_px = -1e6}, 0.016);
  EXPECT_LE(cam.pitch_rad(), cam.params().max_pitch_rad);
  EXPECT_TRUE(ocean::lod::validate(cam.camera(1.0, 1.0)).ok());
  cam.update({.forward = true}, 10.0);  // straight up: moves up, not sideways much
  EXPECT_GT(cam.position().y, -1000.0 + 100.0);
}

TEST(SeaControls, RoundTripTheDefaultConfiguration) {
  const ocean::SimulationConfig base;
  const SeaControls s = ocean::cli::view::sea_controls(base);
  EXPECT_EQ(s.model, static_cast<int>(ocean::SpectrumModel::jonswap));
  EXPECT_TRUE(s.from_wind);
  EXPECT_EQ(s.cascades, 3);
  auto back = ocean::cli::view::to_config(s, base);
  ASSERT_TRUE(back.ok()) << back.status().message();
  const auto& p = back.value().sea.wind_sea.spectrum;
  EXPECT_EQ(p.wind_speed_mps, 10.0);
  EXPECT_EQ(p.fetch_m, 100e3);
  EXPECT_EQ(back.value().cascade_patch_sizes_m, base.cascade_patch_sizes_m);
  EXPECT_EQ(back.value().resolution, base.resolution);
}

TEST(SeaControls, EveryModelAndFormGivesAValidConfiguration) {
  const ocean::SimulationConfig base;
  for (int model = 0; model < 4; ++model) {
    for (bool wind : {true, false}) {
      SeaControls s = ocean::cli::view::sea_controls(base);
      s.model = model;
      s.from_wind = wind;
      s.deep_water = model != static_cast<int>(ocean::SpectrumModel::tma);
      s.depth_m = 15.0;
      auto c = ocean::cli::view::to_config(s, base);
      ASSERT_TRUE(c.ok()) << model << " " << wind << ": " << c.status().message();
      const auto& p = c.value().sea.wind_sea.spectrum;
      const bool phillips = model == static_cast<int>(ocean::SpectrumModel::phillips);
      EXPECT_EQ(std::isnan(p.wind_speed_mps), !wind && !phillips);  // Phillips: wind only
      EXPECT_EQ(ocean::cli::view::sea_controls(c.value()).from_wind, wind || phillips);
      if (model == static_cast<int>(ocean::SpectrumModel::tma)) {
        EXPECT_EQ(p.depth_m, 15.0);
        EXPECT_EQ(c.value().sea.dispersion.depth_m, 15.0);
      }
    }
  }
}

TEST(SeaControls, GridEditsApplyAndBadOnesAreRejected) {
  const ocean::SimulationConfig base;
  SeaControls s = ocean::cli::view::sea_controls(base);
  s.resolution = 64;
  s.cascades = 4;  // the fourth size continues the ratio: valid
  s.seed = 7;
  s.loop_period_s = 0.0;
  s.direction_deg = 90.0;
  auto c = ocean::cli::view::to_config(s, base);
  ASSERT_TRUE(c.ok()) << c.status().message();
  EXPECT_EQ(c.value().resolution, 64);
  EXPECT_EQ(c.value().cascade_patch_sizes_m.size(), 4u);
  EXPECT_EQ(c.value().seed, 7u);
  EXPECT_NEAR(c.value().sea.wind_sea.direction_rad, std::numbers::pi / 2.0, 1e-15);
  s.cascade_sizes_m[1] = 5000.0;  // not smaller than the first
  auto bad = ocean::cli::view::to_config(s, base);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(bad.status().message().find("patch_size_m[1]"), std::string::npos);
}

TEST(FrameTimes, MedianOfTheLastSixty) {
  FrameTimes t;
  EXPECT_EQ(t.median_ms(), 0.0);
  for (double ms : {5.0, 1.0, 4.0, 2.0, 3.0}) t.add(ms);
  EXPECT_EQ(t.median_ms(), 3.0);
  for (int i = 0; i < 100; ++i) t.add(i < 50 ? 1000.0 : 10.0);  // the last 60: 10 × 1000, 50 × 10
  EXPECT_EQ(t.count(), FrameTimes::kWindow);
  EXPECT_EQ(t.median_ms(), 10.0);
}

}  // namespace
