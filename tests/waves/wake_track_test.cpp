// WakeTrack (W.17): waypoints at a fixed interval, the newest kept; the speed along the track; the
// wake's speed quantised and held; the path timed back at that speed so that the object is at its
// newest waypoint then and every segment shares one table; bad parameters refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/waves.hpp"

namespace {

using ocean::waves::KelvinWake;
using ocean::waves::pose_at;
using ocean::waves::WakeTrack;
using ocean::waves::WakeTrackParams;
constexpr double kTrackPi = std::numbers::pi;

TEST(WakeTrack, RecordsAtItsIntervalAndKeepsTheNewest) {
  auto track = WakeTrack::make({.interval_s = 0.5, .waypoints = 4}).value();
  for (int i = 0; i <= 600; ++i) {  // 10 s at 60 Hz, 2 m/s along +x
    const double t = i / 60.0;
    track.record(t, 2.0 * t, 1.0);
  }
  ASSERT_EQ(track.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NEAR(track.waypoint(i).time_s, 8.5 + 0.5 * static_cast<double>(i), 1e-9);
  EXPECT_NEAR(track.track_speed_mps(), 2.0, 1e-9);
  // A time before the newest waypoint starts afresh.
  track.record(1.0, 0.0, 0.0);
  EXPECT_EQ(track.size(), 1u);
  EXPECT_EQ(track.track_speed_mps(), 0.0);
  EXPECT_EQ(track.wake_speed_mps(), 0.0);
}

TEST(WakeTrack, PathEndsAtTheNewestWaypointAndHasOneSpeed) {
  // A quarter circle of radius 50 m at 5 m/s (ω = 0.1 rad/s), recorded every 0.5 s.
  auto track = WakeTrack::make({.hull_length_m = 6.0, .interval_s = 0.5, .waypoints = 8}).value();
  const auto at = [](double t) {
    return std::array<double, 2>{50.0 * std::cos(0.1 * t), 50.0 * std::sin(0.1 * t)};
  };
  for (int i = 0; i <= 15 * 60; ++i) {
    const double t = i / 60.0;
    track.record(t, at(t)[0], at(t)[1]);
  }
  KelvinWake wake;
  ASSERT_TRUE(track.wake(wake));
  ASSERT_EQ(wake.path.size(), 8u);
  EXPECT_TRUE(validate(wake).ok());
  EXPECT_EQ(wake.hull_length_m, 6.0);
  // The chords of 0.05 rad are shorter than the arcs by sin(0.025)/0.025: 0.9999 of 5 m/s, and
  // the wake's speed is that in steps of 1 %.
  const double chord_speed = 5.0 * std::sin(0.025) / 0.025;
  EXPECT_NEAR(track.track_speed_mps(), chord_speed, 1e-9);
  EXPECT_NEAR(std::log(track.wake_speed_mps() / chord_speed), 0.0, 0.005 + 1e-12);
  const double q = std::log(track.wake_speed_mps()) / 0.01;
  EXPECT_NEAR(q, std::round(q), 1e-9);
  const double newest = 15.0;
  const auto pose = pose_at(wake, newest);
  EXPECT_NEAR(pose.x_m, at(newest)[0], 1e-9);
  EXPECT_NEAR(pose.z_m, at(newest)[1], 1e-9);
  EXPECT_NEAR(pose.speed_mps, track.wake_speed_mps(), 1e-9);
  // Heading of the last chord: the tangent 0.025 rad before the newest point.
  EXPECT_NEAR(pose.heading_rad, 0.1 * newest + kTrackPi / 2 - 0.025, 1e-9);
  for (std::size_t i = 1; i < wake.path.size(); ++i) {
    const auto& a = wake.path[i - 1];
    const auto& b = wake.path[i];
    EXPECT_NEAR(std::hypot(b.x_m - a.x_m, b.z_m - a.z_m) / (b.time_s - a.time_s),
                track.wake_speed_mps(), 1e-9);
  }
  // One table for the whole path.
  ocean::waves::LayerParams p;
  p.area = {.origin_m = {-80.0, -80.0}, .size_m = 160.0, .resolution = 128};
  p.wakes = {wake};
  EXPECT_EQ(ocean::waves::LocalLayer::make(p).value()->table_count(), 1u);
}

TEST(WakeTrack, SpeedIsHeldWithinItsStepAndRetunedAtMostOncePerRetuneTime) {
  auto track =
      WakeTrack::make({.interval_s = 0.5, .waypoints = 2, .speed_step = 0.01, .retune_s = 2.0})
          .value();
  double x = 0.0, t = 0.0;
  const auto go = [&](double speed, double seconds) {
    for (int i = 0; i < static_cast<int>(seconds / 0.5); ++i) {
      t += 0.5;
      x += speed * 0.5;
      track.record(t, x, 0.0);
    }
  };
  track.record(0.0, 0.0, 0.0);
  go(4.0, 1.0);
  const double held = track.wake_speed_mps();
  EXPECT_NEAR(held, 4.0, 0.02);
  go(4.0 * std::exp(0.008), 5.0);  // less than a step away: held
  EXPECT_EQ(track.wake_speed_mps(), held);
  // Speeding up by 1 % per waypoint: the wake's speed changes once per 2 s, not per waypoint.
  int changes = 0;
  double last = held;
  double speed = 4.0;
  for (int i = 0; i < 20; ++i) {
    speed *= 1.01;
    go(speed, 0.5);
    if (track.wake_speed_mps() != last) ++changes;
    last = track.wake_speed_mps();
  }
  EXPECT_LE(changes, 6);  // 10 s of speeding up: at most one change per 2 s (and the first)
  EXPECT_GE(changes, 4);
  go(speed, 3.0);  // steady again: caught up within a step
  EXPECT_NEAR(std::log(track.wake_speed_mps() / speed), 0.0, 0.01 + 1e-12);
}

TEST(WakeTrack, BadParametersAreRefusedByName) {
  const auto refused = [](const WakeTrackParams& p, const char* field) {
    const ocean::Status s = validate(p);
    EXPECT_FALSE(s.ok()) << field;
    EXPECT_NE(s.message().find(field), std::string::npos) << s.message();
    EXPECT_FALSE(WakeTrack::make(p).ok());
  };
  refused({.hull_length_m = NAN}, "hull_length_m");
  refused({.hull_length_m = 0.0}, "hull_length_m");
  refused({.peak_height_m = -1.0}, "peak_height_m");
  refused({.fade_length_m = NAN}, "fade_length_m");
  refused({.interval_s = 0.0}, "interval_s");
  refused({.interval_s = NAN}, "interval_s");
  refused({.waypoints = 1}, "waypoints");
  refused({.min_speed_mps = -0.1}, "min_speed_mps");
  refused({.min_speed_mps = NAN}, "min_speed_mps");
  refused({.speed_step = 0.0}, "speed_step");
  refused({.speed_step = 0.5}, "speed_step");
  refused({.retune_s = -1.0}, "retune_s");
  EXPECT_TRUE(validate(WakeTrackParams{}).ok());
}

}  // namespace
