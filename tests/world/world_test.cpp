// The World (ocean/world.hpp) against physics and exact identities: a floating box placed at
// Archimedes' draught on a calm sea stays there; a driven boat goes at its commanded speed and
// its Kelvin wake (W.17) lies behind it in the layer the sea is handed, still water ahead; a
// circling boat keeps to its circle (B.11); stepping to a time in one call or in several gives
// the same bodies, bit for bit, where the sub-steps are the same; the circle's course and
// guidance against their geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/world.hpp"

namespace {

using ocean::world::BodySea;
using ocean::world::Circle;
using ocean::world::ObjectDesc;
using ocean::world::World;
using ocean::world::WorldParams;
constexpr double kWorldPi = std::numbers::pi;

ocean::SimulationConfig small_sea() {
  ocean::SimulationConfig c;
  c.resolution = 16;
  c.cascade_patch_sizes_m = {100.0};
  c.sea.wind_sea.spectrum.wind_speed_mps = 1.0;
  return c;
}

// A sea that is exactly calm: a bathymetry of depth 0 over 2 km damps every band to nothing
// (W.12: the depth weight is 0 at d = 0), so its heights are the local layer's alone.
std::unique_ptr<ocean::Simulator> calm_sea() {
  const ocean::SimulationConfig c = small_sea();
  auto sim = ocean::make_simulator(c);
  EXPECT_TRUE(sim.ok()) << sim.status().message();
  auto map = std::make_shared<ocean::waves::HeightMap>();
  map->rows = 2, map->cols = 2, map->values = {0.0f, 0.0f, 0.0f, 0.0f};
  auto damping = ocean::waves::Damping::make(
      {.bathymetry = ocean::waves::PlacedMap{.map = map, .origin_m = {-1e3, -1e3}, .size_m = 2e3},
       .band_wavenumbers_radpm = ocean::band_wavenumbers(c)});
  EXPECT_TRUE(damping.ok()) << damping.status().message();
  sim.value()->set_damping(std::make_shared<const ocean::waves::Damping>(damping.value()));
  sim.value()->step(0.0);
  return std::move(sim).value();
}

ObjectDesc shape(ocean::world::Shape s, std::array<double, 3> at, double heading = 0.0,
                 double speed = 0.0) {
  return {.hull = ocean::world::shape_hull(s).value(),
          .density_kgpm3 = ocean::world::shape_density_kgpm3(s),
          .position_m = at,
          .heading_deg = heading,
          .speed_mps = speed};
}

TEST(World, TheCalmSeaIsCalm) {
  auto sea = calm_sea();
  const std::vector<std::array<double, 2>> xz{{0.0, 0.0}, {13.0, -7.0}, {-40.0, 25.0}};
  std::vector<ocean::HeightSample> h(xz.size());
  sea->heights_at(xz, h);
  for (const auto& s : h) EXPECT_EQ(s.height_m, 0.0);
}

TEST(World, AFloatingBoxAtRestOnACalmSeaStaysAtArchimedesDraught) {
  // The built-in box, 1 m tall, density 500 kg/m³: draught d = (500/1025)·1 m; its centre (and
  // the origin of its frame, the hull being centred) at 0.5 − d.
  const double d = ocean::world::kBoxDensity_kgpm3 / 1025.0 * 1.0;
  auto sea = calm_sea();
  auto world =
      World::make({.objects = {shape(ocean::world::Shape::box, {3.0, 0.5 - d, -2.0}, 30.0)},
                   .floating = true,
                   .body_sea = BodySea::caller},
                  small_sea());
  ASSERT_TRUE(world.ok()) << world.status().message();
  ASSERT_TRUE(world.value()->advance_to(10.0, *sea).ok());
  EXPECT_EQ(world.value()->steps_until(10.0), 0);
  EXPECT_NEAR(world.value()->time_s(), 10.0, 1e-9);
  const ocean::world::Pose pose = world.value()->pose(0);
  EXPECT_NEAR(pose.position_m[0], 3.0, 1e-6);
  EXPECT_NEAR(pose.position_m[1], 0.5 - d, 1e-6);
  EXPECT_NEAR(pose.position_m[2], -2.0, 1e-6);
  const auto level = ocean::bodies::orientation_from_heading(30.0);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(pose.orientation[i], level[i], 1e-6) << i;
  // Nothing is driven: no wake; the layer handed to the sea holds the box's waterline foam
  // (W.20) round it, on its rim and nowhere else.
  const auto& layer = world.value()->local_layer();
  ASSERT_NE(layer, nullptr);
  EXPECT_EQ(sea->local_layer(), layer.get());
  EXPECT_TRUE(layer->params().wakes.empty());
  ASSERT_EQ(layer->params().footprints.size(), 1u);
  const double t = world.value()->time_s();
  EXPECT_NEAR(layer->foam_at(3.0, -2.0, t), ocean::world::kRestFoamCoverage, 1e-9);  // inside
  EXPECT_LT(layer->foam_at(3.0 + 6.0, -2.0, t), 1e-9);                             // 6 m off
  EXPECT_EQ(layer->displacement_at(3.0, -2.0, t)[1], 0.0);                         // no waves
}

TEST(World, ObjectsThatDoNotFloatStayWherePlaced) {
  auto sea = calm_sea();
  auto world = World::make({.objects = {shape(ocean::world::Shape::buoy, {1.0, 2.0, 3.0}, 90.0)}},
                           small_sea());
  ASSERT_TRUE(world.ok()) << world.status().message();
  ASSERT_TRUE(world.value()->advance_to(5.0, *sea).ok());
  EXPECT_EQ(world.value()->body(0), nullptr);
  const ocean::world::Pose pose = world.value()->pose(0);
  EXPECT_EQ(pose.position_m, (std::array<double, 3>{1.0, 2.0, 3.0}));
  EXPECT_EQ(pose.orientation, ocean::bodies::orientation_from_heading(90.0));
  // A speed drives a floating object only.
  auto driven = World::make(
      {.objects = {shape(ocean::world::Shape::boat, {0.0, 0.0, 0.0}, 0.0, 5.0)}}, small_sea());
  ASSERT_FALSE(driven.ok());
  EXPECT_NE(driven.status().message().find("objects[0]"), std::string::npos);
}

TEST(World, ADrivenBoatsWakeLiesBehindItInTheLayerTheSeaIsHanded) {
  // A boat driven at 5 m/s along +z from (10, ·, −20), and a buoy that drifts.
  auto sea = calm_sea();
  auto made = World::make(
      {.objects = {shape(ocean::world::Shape::boat, {10.0, 0.0, -20.0}, 90.0, 5.0),
                   shape(ocean::world::Shape::buoy, {-10.0, 0.0, 0.0})},
       .floating = true,
       .body_sea = BodySea::caller,
       .wake_area = ocean::waves::LocalArea{.origin_m = {-90.0, -90.0}, .size_m = 200.0}},
      small_sea());
  ASSERT_TRUE(made.ok()) << made.status().message();
  World& world = *made.value();
  bool handed = false;
  for (double t = 0.5; t <= 20.0 + 1e-9; t += 0.5) {
    auto advanced = world.advance_to(t, *sea);
    ASSERT_TRUE(advanced.ok()) << advanced.status().message();
    handed = handed || advanced.value();
    sea->step(t);
  }
  EXPECT_TRUE(handed);
  const auto* body = world.body(0);
  ASSERT_NE(body, nullptr);
  // From rest: about 4 s (τ_u) of speeding up, then 5 m/s along +z, heading 90°.
  const auto& x = body->state().position_m;
  EXPECT_NEAR(x[0], 10.0, 1.0);
  EXPECT_GT(x[2], -20.0 + 5.0 * 14.0);
  EXPECT_LT(x[2], -20.0 + 5.0 * 20.0);
  EXPECT_NEAR(ocean::bodies::heading_deg(body->state()), 90.0, 1.0);
  EXPECT_NEAR(std::hypot(body->state().velocity_mps[0], body->state().velocity_mps[2]), 5.0, 0.15);
  std::vector<ocean::waves::KelvinWake> wakes;
  world.driven_wakes(wakes);
  ASSERT_EQ(wakes.size(), 1u);  // the drifting buoy makes none
  EXPECT_DOUBLE_EQ(wakes[0].hull_length_m, 8.0);  // the built-in boat's length
  // Its height from its hull's wave resistance (W.24): a thin hull that displaces its mass.
  EXPECT_FALSE(wakes[0].peak_height_m.has_value());
  ASSERT_NE(wakes[0].thin_hull, nullptr);
  const ocean::waves::ThinHull& thin = *wakes[0].thin_hull;
  double displaced = 0.0;
  for (double f : thin.half_breadth_m)
    displaced += 2.0 * f * thin.length_m / thin.columns * thin.draft_m / thin.rows;
  const auto hull = ocean::world::shape_hull(ocean::world::Shape::boat).value();
  const double mass = ocean::world::kBoatDensity_kgpm3 * ocean::bodies::mass_properties(hull).volume_m3;
  EXPECT_NEAR(displaced * 1025.0, mass, 0.03 * mass);
  EXPECT_NEAR(wakes[0].foam.beam_m, 3.0, 1e-9);
  // The layer the sea holds is the world's, and its wake is at the boat, heading as it heads.
  ASSERT_NE(world.local_layer(), nullptr);
  EXPECT_EQ(sea->local_layer(), world.local_layer().get());
  const ocean::waves::LocalLayer& layer = *world.local_layer();
  const double t = world.time_s();
  const auto pose = ocean::waves::pose_at(layer.params().wakes.at(0), t);
  EXPECT_LT(std::hypot(pose.x_m - x[0], pose.z_m - x[2]), 0.5);
  EXPECT_NEAR(pose.heading_rad * 180.0 / kWorldPi, 90.0, 2.0);
  // Heights along the track: waves behind (transverse, 2πU²/g = 16 m long), still water ahead.
  const auto rms_along = [&](double from, double to) {
    double sum = 0.0;
    int n = 0;
    for (double s = from; s <= to; s += 0.25, ++n) {
      const double h = layer.displacement_at(pose.x_m + s * std::cos(pose.heading_rad),
                                             pose.z_m + s * std::sin(pose.heading_rad), t)[1];
      sum += h * h;
    }
    return std::sqrt(sum / n);
  };
  const double behind = rms_along(-40.0, -10.0), ahead = rms_along(15.0, 45.0);
  EXPECT_GT(behind, 0.02);
  EXPECT_LT(ahead, 0.1 * behind);
}

TEST(World, WithoutASquareTheWakeIsLaidRoundTheFirstDrivenObject) {
  auto sea = calm_sea();
  auto made = World::make(
      {.objects = {shape(ocean::world::Shape::buoy, {-10.0, 0.0, 0.0}),
                   shape(ocean::world::Shape::boat, {0.0, 0.0, 0.0}, 30.0, 5.0)},
       .floating = true,
       .body_sea = BodySea::caller},
      small_sea());
  ASSERT_TRUE(made.ok()) << made.status().message();
  World& world = *made.value();
  // Frame by frame until the first wake: the square is laid then, round the boat as it is.
  double t = 0.0;
  // (The buoy's waterline foam makes a layer of its own from the start.)
  while ((world.local_layer() == nullptr || world.local_layer()->params().wakes.empty()) &&
         t < 10.0) {
    t += 1.0 / 30;
    ASSERT_TRUE(world.advance_to(t, *sea).ok());
  }
  ASSERT_NE(world.local_layer(), nullptr);
  const auto& s = world.body(1)->state();
  const double heading = ocean::bodies::heading_deg(s) * kWorldPi / 180.0;
  const double back = ocean::world::kDrivenArea_m / 6.0;
  const auto& area = world.local_layer()->params().area;
  EXPECT_EQ(area.size_m, ocean::world::kDrivenArea_m);
  EXPECT_EQ(area.resolution, ocean::world::kDrivenAreaResolution);
  // Its corner on whole cells (W.22): within half a cell of the ideal placement.
  const double cell = area.size_m / area.resolution;
  EXPECT_NEAR(area.origin_m[0] + 0.5 * area.size_m, s.position_m[0] - back * std::cos(heading),
              0.5 * cell + 1e-9);
  EXPECT_NEAR(area.origin_m[1] + 0.5 * area.size_m, s.position_m[2] - back * std::sin(heading),
              0.5 * cell + 1e-9);
  EXPECT_NEAR(area.origin_m[0] / cell, std::round(area.origin_m[0] / cell), 1e-6);
}

TEST(World, TheSquareMovesWithTheBoatAndFadesIntoTheSea) {
  // A boat driven straight at 6 m/s for 60 s goes 300 m: the square is laid again as it goes
  // (W.22) and the boat is never nearer its border than the soft edge's inner side.
  auto sea = calm_sea();
  auto made = World::make(
      {.objects = {shape(ocean::world::Shape::boat, {0.0, 0.0, 0.0}, 0.0, 6.0)},
       .floating = true,
       .body_sea = BodySea::caller},
      small_sea());
  ASSERT_TRUE(made.ok()) << made.status().message();
  World& world = *made.value();
  const double band = ocean::world::kDrivenAreaEdgeFraction * ocean::world::kDrivenArea_m;
  int laid = 0;
  std::array<double, 2> last{1e30, 1e30};
  for (double t = 0.5; t <= 60.0; t += 0.5) {
    ASSERT_TRUE(world.advance_to(t, *sea).ok());
    if (world.local_layer() == nullptr) continue;
    const auto& area = world.local_layer()->params().area;
    if (area.origin_m != last) ++laid;
    last = area.origin_m;
    const auto& x = world.body(0)->state().position_m;
    const double inside = std::min({x[0] - area.origin_m[0], area.origin_m[0] + area.size_m - x[0],
                                    x[2] - area.origin_m[1], area.origin_m[1] + area.size_m - x[2]});
    EXPECT_GT(inside, band) << "t = " << t;
  }
  EXPECT_GE(laid, 10);  // 300 m in steps of at most 20 m, after the first
  // No seam: across the soft edge the layer's height changes no faster than the sea's own
  // surface slopes. Cox & Munk (1954, "Measurement of the roughness of the sea surface from
  // photographs of the sun's glitter", JOSA 44(11), eq. 3, a clean surface) give the mean square
  // slope 0.003 + 5.12e-3·W at wind speed W: 0.054 at 10 m/s (the moderate preset), an rms slope
  // along one direction of √(0.054/2) = 0.16. The layer's largest slope anywhere in the edge band
  // (central differences on its own grid) must stay below half of that.
  const ocean::waves::LocalLayer& layer = *world.local_layer();
  ocean::waves::LocalFrame frame;
  layer.evaluate(world.time_s(), frame);
  const auto& area = layer.params().area;
  const int n = area.resolution;
  const double cell = area.size_m / n;
  const auto h = [&](int c, int r) {
    return static_cast<double>(frame.displacement[3 * (static_cast<std::size_t>(r) * n + c) + 1]);
  };
  double band_max = 0.0, inside_max = 0.0;
  for (int r = 1; r + 1 < n; ++r) {
    for (int c = 1; c + 1 < n; ++c) {
      const double g = std::hypot(h(c + 1, r) - h(c - 1, r), h(c, r + 1) - h(c, r - 1)) / (2 * cell);
      const double d = cell * (std::min({c, r, n - 1 - c, n - 1 - r}) + 0.5);
      (d < band ? band_max : inside_max) = std::max(d < band ? band_max : inside_max, g);
    }
  }
  const double sea_slope = std::sqrt((0.003 + 5.12e-3 * 10.0) / 2.0);
  EXPECT_GT(inside_max, sea_slope);  // the wake itself is steep enough to see
  EXPECT_LT(band_max, 0.5 * sea_slope);
}

// The bodies after advancing to each of `times` in turn, on the World's own sea.
std::vector<ocean::bodies::BodyState> states_after(const std::vector<double>& times) {
  auto made = World::make(
      {.objects = {shape(ocean::world::Shape::boat, {0.0, 0.0, 0.0}, 20.0, 4.0),
                   shape(ocean::world::Shape::box, {8.0, 0.0, 5.0})},
       .floating = true},
      small_sea());
  EXPECT_TRUE(made.ok()) << made.status().message();
  auto sea = calm_sea();  // handed the layer only: the bodies ride the World's own sea
  for (double t : times) EXPECT_TRUE(made.value()->advance_to(t, *sea).ok()) << t;
  return {made.value()->body(0)->state(), made.value()->body(1)->state()};
}

TEST(World, OneCallEqualsSeveralWhoseStepsAreEven) {
  // The own sea is simulated at the first of each call's steps and every second one after: calls
  // of an even number of steps (here 60 and 120) simulate it at the same times as one call, so
  // the bodies are the same to the bit.
  const auto once = states_after({3.0});
  const auto split = states_after({1.0, 3.0});
  for (std::size_t b = 0; b < once.size(); ++b) {
    EXPECT_EQ(once[b].position_m, split[b].position_m) << b;
    EXPECT_EQ(once[b].orientation, split[b].orientation) << b;
    EXPECT_EQ(once[b].velocity_mps, split[b].velocity_mps) << b;
    EXPECT_EQ(once[b].angular_velocity_radps, split[b].angular_velocity_radps) << b;
  }
}

TEST(World, StepsAreCountedToWithinHalfAStep) {
  auto made = World::make(
      {.objects = {shape(ocean::world::Shape::buoy, {0.0, 0.0, 0.0})}, .floating = true},
      small_sea());
  ASSERT_TRUE(made.ok()) << made.status().message();
  EXPECT_EQ(made.value()->steps_until(1.0), 60);
  EXPECT_EQ(made.value()->steps_until(1.0 + 0.49 / 60), 60);
  EXPECT_EQ(made.value()->steps_until(1.0 + 0.51 / 60), 61);
  EXPECT_EQ(made.value()->steps_until(-1.0), 0);
  // A cancelled advance stops before its first step.
  std::atomic<bool> cancel{true};
  auto sea = calm_sea();
  auto r = made.value()->advance_to(1.0, *sea, {.cancel = &cancel});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), ocean::ErrorCode::cancelled);
  EXPECT_EQ(made.value()->time_s(), 0.0);
}

TEST(WorldCircle, TheCourseRunsRoundTheCircleAtItsSpeedAlongTheTangent) {
  const Circle circle{.centre_m = {10, -20}, .radius_m = 40.0};
  const double t0 = 3.0;
  for (double t : {3.0, 7.5, 20.0, 100.0}) {
    const auto p = ocean::world::circling_pose(circle, 5.0, t0, t);
    EXPECT_NEAR(std::hypot(p.x_m - 10.0, p.z_m + 20.0), 40.0, 1e-9) << t;
    // The heading is perpendicular to the radius, and a small step moves along it.
    const auto q = ocean::world::circling_pose(circle, 5.0, t0, t + 1e-3);
    const double dx = (q.x_m - p.x_m) / 1e-3, dz = (q.z_m - p.z_m) / 1e-3;
    EXPECT_NEAR(std::hypot(dx, dz), 5.0, 1e-3) << t;
    EXPECT_NEAR(dx, 5.0 * std::cos(p.heading_rad), 1e-3) << t;
    EXPECT_NEAR(dz, 5.0 * std::sin(p.heading_rad), 1e-3) << t;
  }
  // One lap takes 2πr/U.
  const auto start = ocean::world::circling_pose(circle, 5.0, t0, t0);
  const auto lap = ocean::world::circling_pose(circle, 5.0, t0, t0 + 2 * kWorldPi * 8.0);
  EXPECT_NEAR(start.x_m, lap.x_m, 1e-9);
  EXPECT_NEAR(start.z_m, lap.z_m, 1e-9);
}

TEST(WorldCircle, GuidanceSteersAlongTheCircleAndBackOntoIt) {
  const Circle circle{.centre_m = {10, -20}, .radius_m = 40.0};
  // On the circle: the tangent (motion from +x towards +z).
  EXPECT_NEAR(ocean::world::circle_heading_deg(circle, 50.0, -20.0), 90.0, 1e-9);
  EXPECT_NEAR(ocean::world::circle_heading_deg(circle, 10.0, 20.0), 180.0, 1e-9);
  // Outside it turns inwards, inside outwards, by atan(offset / look-ahead).
  const double turn = std::atan(10.0 / circle.look_ahead_m) * 180 / kWorldPi;
  EXPECT_NEAR(ocean::world::circle_heading_deg(circle, 60.0, -20.0), 90.0 + turn, 1e-9);
  EXPECT_NEAR(ocean::world::circle_heading_deg(circle, 40.0, -20.0), 90.0 - turn, 1e-9);
}

TEST(WorldCircle, ACirclingBoatStartsOnItsCircleUnderWayAndRestarts) {
  ObjectDesc boat = shape(ocean::world::Shape::boat, {0.0, 0.0, 0.0}, 0.0, 6.0);
  boat.circle = Circle{.centre_m = {5.0, 5.0}, .radius_m = 50.0};
  auto made = World::make({.objects = {boat}, .floating = true, .body_sea = BodySea::caller,
                           .start_time_s = 7.0},
                          small_sea());
  ASSERT_TRUE(made.ok()) << made.status().message();
  World& world = *made.value();
  const auto& s = world.body(0)->state();
  EXPECT_NEAR(s.position_m[0], 55.0, 1e-12);
  EXPECT_NEAR(s.position_m[2], 5.0, 1e-12);
  EXPECT_NEAR(s.velocity_mps[2], 6.0, 1e-12);  // along the tangent, +z
  EXPECT_NEAR(ocean::bodies::heading_deg(s), 90.0, 0.1);  // the settled trim's yaw
  auto sea = calm_sea();
  ASSERT_TRUE(world.advance_to(12.0, *sea).ok());
  EXPECT_GT(std::hypot(world.body(0)->state().position_m[0] - 55.0,
                       world.body(0)->state().position_m[2] - 5.0),
            20.0);
  world.restart(30.0);
  EXPECT_EQ(world.time_s(), 30.0);
  EXPECT_NEAR(world.body(0)->state().position_m[0], 55.0, 1e-12);
  EXPECT_NEAR(world.body(0)->state().position_m[2], 5.0, 1e-12);
  EXPECT_EQ(world.local_layer(), nullptr);  // the track begins again: no wake yet
  EXPECT_FALSE(world.set_course(0, -1.0, *boat.circle).ok());
  EXPECT_FALSE(world.set_course(0, 5.0, {.radius_m = 0.0}).ok());
}

}  // namespace
