// Driven objects of `ocean render --object KIND,X,Y,Z,HEADING,SPEED --float` (object_flags.hpp):
// the speed field, the propulsion sized from the body, and the wake the object's track leaves
// (docs/bodies.md B.8-B.10, docs/waves.md W.17), on a sea of 1 m/s wind (waves of centimetres).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "object_flags.hpp"

namespace {

using ocean::cli::ObjectSpec;
using ocean::cli::parse_object_spec;
using ocean::cli::SceneObjects;

ocean::SimulationConfig small_sea() {
  ocean::SimulationConfig c;
  c.resolution = 32;
  c.cascade_patch_sizes_m = {100.0};
  c.sea.wind_sea.spectrum.wind_speed_mps = 1.0;
  return c;
}

TEST(DrivenObjects, TheSpeedFieldIsParsedAndChecked) {
  auto spec = parse_object_spec("boat,1,0,2,30,5.5");
  ASSERT_TRUE(spec.ok()) << spec.status().message();
  EXPECT_EQ(spec.value().speed_mps, 5.5);
  EXPECT_EQ(spec.value().heading_deg, 30.0);
  EXPECT_EQ(parse_object_spec("boat,1,0,2,30").value().speed_mps, 0.0);
  for (const char* bad : {"boat,0,0,0,0,-1", "boat,0,0,0,0,31", "boat,0,0,0,0,nan"}) {
    auto r = parse_object_spec(bad);
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_NE(r.status().message().find("--object speed"), std::string::npos)
        << r.status().message();
  }
  EXPECT_FALSE(parse_object_spec("boat,0,0,0,0,1,2").ok());
  // A speed drives a floating object only.
  auto not_floating = SceneObjects::make({spec.value()}, false, small_sea());
  ASSERT_FALSE(not_floating.ok());
  EXPECT_NE(not_floating.status().message().find("--float"), std::string::npos);
}

TEST(DrivenObjects, ADrivenBoatGoesAtItsSpeedAndLeavesItsTracksWake) {
  // A boat driven at 5 m/s heading 90° (+z) from (10, 0, -20), and a buoy that drifts.
  const std::vector<ObjectSpec> specs{
      {.kind = "boat", .position_m = {10.0, 0.0, -20.0}, .heading_deg = 90.0, .speed_mps = 5.0},
      {.kind = "buoy", .position_m = {-10.0, 0.0, 0.0}}};
  auto objects = SceneObjects::make(specs, true, small_sea());
  ASSERT_TRUE(objects.ok()) << objects.status().message();
  std::vector<ocean::render::ObjectInstance> instances;
  ASSERT_TRUE(objects.value()->place(20.0, instances).ok());
  const auto driven = objects.value()->first_driven();
  ASSERT_TRUE(driven.has_value());
  // From rest: about 4 s (τ_u) of speeding up, then 5 m/s along +z.
  EXPECT_NEAR((*driven)[0], 10.0, 1.0);
  EXPECT_GT((*driven)[1], -20.0 + 5.0 * 14.0);
  EXPECT_LT((*driven)[1], -20.0 + 5.0 * 20.0);
  EXPECT_NEAR((*driven)[2], 90.0, 1.0);
  std::vector<ocean::waves::KelvinWake> wakes;
  objects.value()->wakes(wakes);
  ASSERT_EQ(wakes.size(), 1u);  // the drifting buoy makes none
  const ocean::waves::KelvinWake& w = wakes[0];
  EXPECT_TRUE(ocean::waves::validate(w).ok());
  EXPECT_NEAR(w.speed_mps, 5.0, 0.1);
  EXPECT_DOUBLE_EQ(w.hull_length_m, 8.0);  // the built-in boat's length
  EXPECT_NEAR(w.peak_height_m.value(), ocean::cli::kWakePeakPerLength * 8.0, 1e-12);
  // The wake is where the boat is, heading as it heads.
  const auto pose = ocean::waves::pose_at(w, 20.0);
  EXPECT_LT(std::hypot(pose.x_m - (*driven)[0], pose.z_m - (*driven)[1]), 0.5);
  EXPECT_NEAR(pose.heading_rad * 180.0 / std::numbers::pi, 90.0, 2.0);
}

}  // namespace
