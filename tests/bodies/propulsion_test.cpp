// Propulsion and steering of floating bodies (B.8–B.10): a propelled box in calm water reaches
// the commanded speed with the thrust equal to its resistance, the facet drag B.4 integrated over
// its wetted ends (closed form), or, thrust-limited, the speed where that resistance equals the
// limit; the heading loop turns a boat to a commanded heading the short way round; a driven boat
// in steep waves stays bounded and upright; bad parameters are refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "ocean/bodies.hpp"

namespace {

using namespace ocean::bodies;
constexpr double kPropPi = std::numbers::pi;
const Water kPropWater{};

// A box of length 4 (x), height 1, beam 2 m and density 500 kg/m³: draught d = (500/1025)·1 m.
constexpr double kLength = 4.0, kPropHeight = 1.0, kBeam = 2.0, kPropDensity = 500.0;
constexpr DragParams kDrag{.linear_mps = 0.5, .quadratic = 1.0};

double draught() { return kPropDensity / kPropWater.density_kgpm3 * kPropHeight; }

// (B.9) The resistance of the box moving along x at U in calm water, from B.4: the bow and the
// stern faces (area B·d each, normals ±x) both meet v_n = ±U, the sides and the bottom none, so
// R(U) = 2·ρ·B·d·(k_l·U + ½·C_d·U²).
double box_resistance(double u) {
  return 2.0 * kPropWater.density_kgpm3 * kBeam * draught() *
         (kDrag.linear_mps * u + 0.5 * kDrag.quadratic * u * u);
}

FloatingBody box_at_rest() {
  auto params = solid_body(box_hull({kLength, kPropHeight, kBeam}, 4).value(), kPropDensity, kDrag);
  EXPECT_TRUE(params.ok()) << params.status().message();
  // The box's centre of mass is at its middle: at the draught it lies kPropHeight/2 − d above the
  // surface.
  auto body = FloatingBody::make(params.value(), {.position_m = {0, kPropHeight / 2 - draught(), 0}});
  EXPECT_TRUE(body.ok()) << body.status().message();
  return std::move(body).value();
}

// Drives `body` for `seconds` at 1/60 s on `surface`; returns the mean forward speed and thrust
// over the last `average_s` seconds.
struct Driving {
  double speed_mps = 0.0, thrust_n = 0.0;
};
Driving drive(FloatingBody& body, Propulsion& propulsion, const HelmCommand& helm,
              const SurfaceQuery& surface, double seconds, double average_s) {
  const double dt = 1.0 / 60;
  const int steps = static_cast<int>(std::lround(seconds / dt));
  const int averaged = static_cast<int>(std::lround(average_s / dt));
  Driving mean;
  for (int i = 0; i < steps; ++i) {
    auto w = propulsion.control(body, helm, dt);
    EXPECT_TRUE(w.ok()) << w.status().message();
    if (!w.ok()) return mean;
    EXPECT_TRUE(body.step(surface, dt, w.value()).ok()) << i;
    if (i >= steps - averaged) {
      const double h = heading_deg(body.state()) * kPropPi / 180;
      const Vec3& v = body.state().velocity_mps;
      mean.speed_mps += (v[0] * std::cos(h) + v[2] * std::sin(h)) / averaged;
      mean.thrust_n += propulsion.thrust_n() / averaged;
    }
  }
  return mean;
}

TEST(Propulsion, ReachesTheCommandedSpeedWithTheThrustOfItsResistance) {
  // The speed loop's integral settles where the thrust equals the resistance R(U_c), at U_c.
  // The thrust acts at the centre of mass; the small trim the drag's moment gives changes R only
  // at second order (cos² of a trim below 1°).
  FloatingBody body = box_at_rest();
  auto propulsion =
      Propulsion::make({.max_thrust_n = 2e4, .speed_time_s = 3.0, .max_yaw_moment_nm = 1e4})
          .value();
  const double u_c = 2.0;
  const Driving run = drive(body, propulsion, {.speed_mps = u_c}, calm_surface(), 60.0, 5.0);
  std::printf("speed %.5f m/s (commanded %.1f), thrust %.1f N (R(U_c) = %.1f N)\n", run.speed_mps,
              u_c, run.thrust_n, box_resistance(u_c));
  EXPECT_NEAR(run.speed_mps / u_c, 1.0, 0.002);
  EXPECT_NEAR(run.thrust_n / box_resistance(u_c), 1.0, 0.01);
  EXPECT_NEAR(heading_deg(body.state()), 0.0, 0.1);
}

TEST(Propulsion, ThrustLimitedBodyGoesAtTheSpeedWhereResistanceEqualsTheLimit) {
  // T_max below R(U_c): terminal speed from ½ρA_eC_d·U² + ρA_e·k_l·U = T_max, A_e = 2·B·d.
  FloatingBody body = box_at_rest();
  const double t_max = 3000.0;
  auto propulsion = Propulsion::make({.max_thrust_n = t_max, .speed_time_s = 3.0}).value();
  ASSERT_LT(t_max, box_resistance(2.0));
  const double a = 2.0 * kPropWater.density_kgpm3 * kBeam * draught();
  const double expected =
      (-a * kDrag.linear_mps +
       std::sqrt(a * a * kDrag.linear_mps * kDrag.linear_mps + 2.0 * a * kDrag.quadratic * t_max)) /
      (a * kDrag.quadratic);
  const Driving run = drive(body, propulsion, {.speed_mps = 2.0}, calm_surface(), 40.0, 5.0);
  std::printf("thrust-limited speed %.4f m/s (closed form %.4f)\n", run.speed_mps, expected);
  EXPECT_NEAR(run.speed_mps / expected, 1.0, 0.01);
  EXPECT_DOUBLE_EQ(run.thrust_n, t_max);
  // The integral did not wind up: a command the body can reach is reached soon after.
  const Driving slower = drive(body, propulsion, {.speed_mps = 1.0}, calm_surface(), 30.0, 5.0);
  EXPECT_NEAR(slower.speed_mps, 1.0, 0.01);
}

// The built-in boat, with a thrust of a third of its weight aft and low, as the CLI sizes it.
struct Boat {
  FloatingBody body;
  Propulsion propulsion;
};
Boat boat(double heading, double speed) {
  auto params = solid_body(boat_hull(8.0, 3.0, 1.2).value(), 350.0).value();
  const PropulsionParams p{.max_thrust_n = params.mass_kg * kPropWater.gravity_mps2 / 3.0,
                           .thrust_point_m = {-3.5, -0.3, 0.0},
                           .max_yaw_moment_nm = 0.5 * params.inertia_kgm2[4]};
  const double h = heading * kPropPi / 180;
  auto body =
      FloatingBody::make(params, {.position_m = {0.0, 0.2, 0.0},
                                  .orientation = orientation_from_heading(heading),
                                  .velocity_mps = {speed * std::cos(h), 0.0, speed * std::sin(h)}});
  EXPECT_TRUE(body.ok()) << body.status().message();
  Propulsion propulsion = Propulsion::make(p).value();
  propulsion.reset(speed);  // going steadily at `speed`
  return {std::move(body).value(), propulsion};
}

TEST(Propulsion, SteersToACommandedHeadingTheShortWayRound) {
  // From 170° to −170°: 20° through ±180°, not 340° back through 0.
  Boat b = boat(170.0, 3.0);
  const HelmCommand helm{.speed_mps = 3.0, .heading_deg = -170.0};
  double smallest = 180.0;
  for (int i = 0; i < 30 * 60; ++i) {
    auto w = b.propulsion.control(b.body, helm, 1.0 / 60);
    ASSERT_TRUE(w.ok());
    ASSERT_TRUE(b.body.step(calm_surface(), 1.0 / 60, w.value()).ok());
    smallest = std::min(smallest, std::abs(heading_deg(b.body.state())));
  }
  const double final_heading = heading_deg(b.body.state());
  std::printf("heading %.3f deg (commanded -170), smallest |heading| on the way %.2f\n",
              final_heading, smallest);
  EXPECT_NEAR(final_heading, -170.0, 1.0);
  EXPECT_GT(smallest, 150.0);  // the long way round would pass 0°
  // The course follows the heading (the hull's sides resist sway).
  const Vec3& v = b.body.state().velocity_mps;
  EXPECT_NEAR(std::atan2(v[2], v[0]) * 180 / kPropPi, -170.0, 2.0);
  EXPECT_NEAR(std::hypot(v[0], v[2]), 3.0, 0.05);
}

TEST(Propulsion, DrivenBoatInSteepWavesStaysBoundedAndUpright) {
  // A 2 m, 7 s wave (λ = 76 m, steepness ak = 0.08) from 60° off the boat's course: the boat
  // heaves, pitches and rolls; the speed loop holds the mean speed against the waves' surge.
  const double a = 1.0, omega = 2 * kPropPi / 7.0, k = omega * omega / kPropWater.gravity_mps2;
  const double dir = 60.0 * kPropPi / 180;
  double t = 0.0;
  const SurfaceQuery surface = [&](std::span<const std::array<double, 2>> xz,
                                   std::span<ocean::HeightSample> out) {
    for (std::size_t i = 0; i < xz.size(); ++i)
      out[i].height_m =
          a * std::cos(k * (xz[i][0] * std::cos(dir) + xz[i][1] * std::sin(dir)) - omega * t);
  };
  const double u_c = 5.0;
  Boat b = boat(0.0, u_c);
  const HelmCommand helm{.speed_mps = u_c, .heading_deg = 0.0};
  const double m = b.body.params().mass_kg;
  double mean_speed = 0.0, largest_roll = 0.0, largest_heave = 0.0, mean_heading = 0.0,
         largest_yaw = 0.0;
  const int steps = 90 * 60, averaged = 45 * 60;
  for (int i = 0; i < steps; ++i) {
    auto w = b.propulsion.control(b.body, helm, 1.0 / 60);
    ASSERT_TRUE(w.ok());
    ASSERT_TRUE(b.body.step(surface, 1.0 / 60, w.value()).ok()) << i;
    t += 1.0 / 60;
    const BodyState& s = b.body.state();
    ASSERT_LT(b.body.kinetic_energy_j(), 0.5 * m * (2 * u_c) * (2 * u_c)) << t;
    ASSERT_LT(std::abs(s.position_m[1]), 2.0 * a + 1.2) << t;
    const Vec3 up = rotate(s.orientation, {0.0, 1.0, 0.0});
    ASSERT_GT(up[1], std::cos(0.5)) << t;  // never more than 29° from upright
    if (i >= steps - averaged) {
      mean_speed += s.velocity_mps[0] / averaged;
      largest_roll = std::max(largest_roll, std::acos(std::min(1.0, up[1])));
      largest_heave = std::max(largest_heave, std::abs(s.position_m[1]));
      mean_heading += heading_deg(s) / averaged;
      largest_yaw = std::max(largest_yaw, std::abs(heading_deg(s)));
    }
  }
  std::printf(
      "mean speed %.3f m/s (commanded %.1f), largest tilt %.1f deg, heave %.2f m, "
      "heading %.2f deg on average, at most %.2f\n",
      mean_speed, u_c, largest_roll * 180 / kPropPi, largest_heave, mean_heading, largest_yaw);
  EXPECT_NEAR(mean_speed / u_c, 1.0, 0.05);
  EXPECT_GT(largest_roll, 0.01);  // the waves did move it
  EXPECT_NEAR(mean_heading, 0.0, 5.0);
}

TEST(Propulsion, BadParametersAreRefusedByName) {
  const auto message = [](const ocean::Status& s) { return s.message(); };
  EXPECT_NE(message(validate(PropulsionParams{.max_thrust_n = NAN})).find("max_thrust_n"),
            std::string::npos);
  EXPECT_NE(message(validate(PropulsionParams{.max_thrust_n = -1.0})).find("max_thrust_n"),
            std::string::npos);
  EXPECT_NE(
      message(validate(PropulsionParams{.thrust_point_m = {0.0, NAN, 0.0}})).find("thrust_point_m"),
      std::string::npos);
  EXPECT_NE(message(validate(PropulsionParams{.speed_time_s = 0.0})).find("speed_time_s"),
            std::string::npos);
  EXPECT_NE(
      message(validate(PropulsionParams{.max_yaw_moment_nm = -5.0})).find("max_yaw_moment_nm"),
      std::string::npos);
  EXPECT_NE(message(validate(PropulsionParams{.heading_time_s = NAN})).find("heading_time_s"),
            std::string::npos);
  EXPECT_FALSE(Propulsion::make({.speed_time_s = -1.0}).ok());
  EXPECT_NE(message(validate(HelmCommand{.speed_mps = -1.0})).find("speed_mps"), std::string::npos);
  EXPECT_NE(message(validate(HelmCommand{.heading_deg = NAN})).find("heading_deg"),
            std::string::npos);
  EXPECT_NE(message(validate(HelmCommand{.turn_rate_degps = INFINITY})).find("turn_rate_degps"),
            std::string::npos);
  FloatingBody body = box_at_rest();
  auto propulsion = Propulsion::make({}).value();
  EXPECT_FALSE(propulsion.control(body, {.speed_mps = NAN}, 1.0 / 60).ok());
  EXPECT_FALSE(propulsion.control(body, {}, 0.0).ok());
  EXPECT_FALSE(body.step(calm_surface(), 1.0 / 60, {.force_n = {NAN, 0.0, 0.0}}).ok());
}

}  // namespace
