// The wake of a driven floating body (W.17 with B.8–B.10): the track it really went along, fed to
// the local layer's Kelvin wake, has the transverse wavelength 2πU²/g of the body's speed; a
// drifting body makes none; a layer remade with the new track shares its table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "ocean/bodies.hpp"
#include "ocean/waves.hpp"
#include "support/kelvin_measure.hpp"

namespace {

using namespace ocean::bodies;
using ocean::waves::KelvinWake;
using ocean::waves::LayerParams;
using ocean::waves::LocalLayer;
using ocean::waves::WakeTrack;
constexpr double kWakePi = std::numbers::pi;
constexpr double kG = 9.81;

// A box 8 m long (x), 1 m high, 2 m wide, density 500 kg/m³, driven along +x at 3 m/s from rest:
// Fr = U/√(gL) = 0.34, transverse waves 2πU²/g = 5.8 m long.
struct Driven {
  FloatingBody body;
  Propulsion propulsion;
  WakeTrack track;
  double time_s = 0.0;
  void run(double seconds, double speed_mps) {
    const double dt = 1.0 / 60;
    for (int i = 0; i < static_cast<int>(std::lround(seconds / dt)); ++i) {
      auto w = propulsion.control(body, {.speed_mps = speed_mps}, dt);
      ASSERT_TRUE(w.ok());
      ASSERT_TRUE(body.step(calm_surface(), dt, w.value()).ok());
      time_s += dt;
      track.record(time_s, body.state().position_m[0], body.state().position_m[2]);
    }
  }
};
Driven driven_box() {
  auto params = solid_body(box_hull({8.0, 1.0, 2.0}, 4).value(), 500.0).value();
  auto body = FloatingBody::make(params, {.position_m = {0.0, 0.0, 0.0}}).value();
  auto propulsion = Propulsion::make({.max_thrust_n = 2e4, .speed_time_s = 3.0}).value();
  auto track = WakeTrack::make({.hull_length_m = 8.0, .peak_height_m = 0.3}).value();
  track.record(0.0, 0.0, 0.0);
  return {std::move(body), propulsion, std::move(track)};
}

// A layer of 200 m at 512² round the body's wake (0.39 m cells: 15 per transverse wavelength).
LayerParams layer_round(double x_body, const KelvinWake& wake) {
  LayerParams p;
  p.area = {.origin_m = {x_body - 170.0, -100.0}, .size_m = 200.0, .resolution = 512};
  p.wakes = {wake};
  return p;
}

TEST(DrivenWake, TransverseWavelengthIsThatOfTheBodysSpeed) {
  Driven d = driven_box();
  d.run(40.0, 3.0);
  KelvinWake wake;
  ASSERT_TRUE(d.track.wake(wake));
  const double u = d.track.track_speed_mps();  // the body's speed along its recorded track
  EXPECT_NEAR(u, 3.0, 0.03);
  auto layer = LocalLayer::make(layer_round(d.body.state().position_m[0], wake));
  ASSERT_TRUE(layer.ok()) << layer.status().message();
  // Heights on the track behind the wake's apex at the newest waypoint's time.
  const double t = wake.path.back().time_s;
  const ocean::waves::WakePose apex = ocean::waves::pose_at(wake, t);
  EXPECT_NEAR(apex.x_m, d.track.waypoint(d.track.size() - 1).x_m, 1e-9);
  std::vector<double> s, h;
  for (double behind = 5.0; behind <= 150.0; behind += 0.1) {
    s.push_back(behind);
    h.push_back(layer.value()->displacement_at(apex.x_m - behind * std::cos(apex.heading_rad),
                                               apex.z_m - behind * std::sin(apex.heading_rad),
                                               t)[1]);
  }
  const auto waves = ocean_test::transverse_waves(s, h, 10.0, 140.0);
  const double expected = 2.0 * kWakePi * u * u / kG;
  std::printf(
      "transverse wavelength %.4f m from %zu crossings (2 pi U^2/g = %.4f m at the "
      "track's U = %.4f m/s), error %.2f %%\n",
      waves.wavelength_m, waves.crossings, expected, u,
      100.0 * (waves.wavelength_m / expected - 1.0));
  ASSERT_GT(waves.crossings, 20u);
  EXPECT_NEAR(waves.wavelength_m / expected, 1.0, 0.05);
  // The wake trails behind the body along +x; ahead of it the water is still.
  for (double ahead = 1.0; ahead < 20.0; ahead += 1.0)
    EXPECT_EQ(layer.value()->displacement_at(apex.x_m + ahead, apex.z_m, t)[1], 0.0);
}

TEST(DrivenWake, ADriftingBodyMakesNoWake) {
  Driven d = driven_box();
  d.run(20.0, 0.2);  // below the track's 0.5 m/s threshold
  KelvinWake wake;
  EXPECT_LT(d.track.track_speed_mps(), 0.5);
  EXPECT_FALSE(d.track.wake(wake));
  EXPECT_EQ(d.track.wake_speed_mps(), 0.0);
}

TEST(DrivenWake, ALayerRemadeWithTheNewTrackSharesItsTable) {
  Driven d = driven_box();
  d.run(30.0, 3.0);
  KelvinWake wake;
  ASSERT_TRUE(d.track.wake(wake));
  const double x = d.body.state().position_m[0];
  auto first = LocalLayer::make(layer_round(x, wake)).value();
  EXPECT_EQ(first->tables_computed(), 1u);
  d.run(2.0, 3.0);  // four new waypoints, the same speed step
  ASSERT_TRUE(d.track.wake(wake));
  auto second = LocalLayer::make(layer_round(x, wake), first.get()).value();
  EXPECT_EQ(second->tables_computed(), 0u);
  EXPECT_EQ(second->table_count(), 1u);
  // The shared table gives the field a layer that computed its own gives.
  first.reset();
  auto fresh = LocalLayer::make(layer_round(x, wake)).value();
  const double t = wake.path.back().time_s;
  for (double behind = 3.0; behind < 60.0; behind += 7.3) {
    const auto a = second->displacement_at(x - behind, 1.5, t);
    const auto b = fresh->displacement_at(x - behind, 1.5, t);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a[k], b[k]);
  }
}

}  // namespace
