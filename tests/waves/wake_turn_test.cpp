// A wake on a turn (docs/waves.md W.21c): its Kelvin pattern is laid along the track's arc
// length, so a circling boat's pattern, read in the frame of the track (s behind along the arc,
// ζ off it), is the straight-course pattern at the same (s, ζ); the pattern swung rigidly with
// the present heading, as before, puts its centreline s²/(2R) off the track.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "ocean/waves.hpp"

namespace {

using namespace ocean::waves;

constexpr double kPi = std::numbers::pi;
// A 10 m boat at 4 m/s (Fr = 0.40, transverse wavelength 2πU²/g = 10.25 m) on a circle of 80 m,
// its path recorded every 0.5 s as a WakeTrack records it (2 m chords, 1.43° turns).
constexpr double kU = 4.0, kL = 10.0, kR = 80.0, kDt = 0.5, kNow = 50.0, kPeak = 0.5;
// One square and grid for both layers, so both wakes have the same table (cell 0.3125 m).
constexpr LocalArea kArea{
    .origin_m = {-160.0, -160.0}, .size_m = 320.0, .resolution = 1024, .edge_fraction = 0.0};

// Anticlockwise seen from +y, from (0, 0) heading +x: the heading turns towards +z.
std::array<double, 2> on_circle(double t) {
  const double a = kU / kR * t;
  return {kR * std::sin(a), kR * (1.0 - std::cos(a))};
}

std::unique_ptr<LocalLayer> make(const KelvinWake& w) {
  LayerParams p;
  p.area = kArea;
  p.wakes.push_back(w);
  auto layer = LocalLayer::make(std::move(p));
  EXPECT_TRUE(layer.ok()) << layer.status().message();
  return std::move(layer).value();
}

TEST(KelvinWake, OnATurnThePatternFollowsTheTrack) {
  KelvinWake circling{.hull_length_m = kL, .peak_height_m = kPeak};
  for (double t = 0.0; t <= kNow + 1.0; t += kDt) {
    const auto q = on_circle(t);
    circling.path.push_back({.time_s = t, .x_m = q[0], .z_m = q[1]});
  }
  const WakePose pose = pose_at(circling, kNow);
  // The straight course at the same speed, heading +x from the origin: s = −x, ζ = z.
  const KelvinWake straight{
      .heading_deg = 0.0, .speed_mps = pose.speed_mps, .hull_length_m = kL, .peak_height_m = kPeak};
  // Swung rigidly: the straight pattern at the present pose and heading (the model before W.21c).
  const KelvinWake swung{.x_m = pose.x_m,
                         .z_m = pose.z_m,
                         .heading_deg = pose.heading_rad * 180.0 / kPi,
                         .speed_mps = pose.speed_mps,
                         .hull_length_m = kL,
                         .peak_height_m = kPeak};
  const auto turn = make(circling), line = make(straight), rigid = make(swung);
  // The circle's point s metres of arc behind the object now, at time t(s) = kNow − s/U, and the
  // unit normal to the left of the travel there. The object now lies on the chord of its last two
  // waypoints (pose_at), within U²Δt²/(8R) = 0.5 mm of the circle.
  //
  // What the recorded track may differ by: its chords lie within δζ = R·(1 − cos(Δθ/2)) = 6.3 mm
  // of the circle (Δθ = U·Δt/R = 0.025 rad between waypoints), their normals within Δθ/2 of the
  // circle's, so a point ζ off the circle is read up to δs = |ζ|·tan(Δθ/2) + 1 mm along the track
  // from its arc length (on the outside of a waypoint the nearest point is the waypoint itself
  // over a fan of Δθ, where s stands still), and its horizontal displacement turned by the
  // chord's direction, up to Δθ/2 from the circle's. Each component must lie within the straight
  // pattern's own change over s ± δs, ζ ± δζ and that turn (1.5 times it, for the pattern's
  // curvature over so short a step, and 1e-4 m).
  const double dtheta = kU * kDt / kR, dzeta = kR * (1.0 - std::cos(0.5 * dtheta));
  double worst = 0.0, worst_rigid = 0.0, largest = 0.0, axis_rigid = 0.0, worst_s = 0.0,
         worst_zeta = 0.0;
  int outside_bound = 0, points = 0;
  for (double s = 10.0; s <= 80.0; s += 2.5) {
    const double a = kU / kR * (kNow - s / kU);
    const double px = kR * std::sin(a), pz = kR * (1.0 - std::cos(a));
    const double ux = std::cos(a), uz = std::sin(a);  // travel direction
    const double half = 0.4 * s;                      // beyond Kelvin's 19.5° (tan = 0.354)
    for (double zeta = -half; zeta <= half; zeta += 0.37) {
      const double x = px - zeta * uz, z = pz + zeta * ux;
      const auto got = turn->displacement_at(x, z, kNow);
      const auto want = line->displacement_at(-s, zeta, 0.0);
      const auto old = rigid->displacement_at(x, z, kNow);
      // Heights, and the horizontal displacement turned into the track's frame (D_s, D_ζ).
      const std::array<double, 3> g{-(got[0] * ux + got[2] * uz), got[1],
                                    -got[0] * uz + got[2] * ux};
      const std::array<double, 3> w{-want[0], want[1], want[2]};
      const double ds = std::abs(zeta) * std::tan(0.5 * dtheta) + 1e-3;
      std::array<double, 3> bound{0.0, 0.0, 0.0};
      for (int i = -1; i <= 1; ++i) {
        for (int j = -1; j <= 1; ++j) {
          const auto v = line->displacement_at(-(s + i * ds), zeta + j * dzeta, 0.0);
          const std::array<double, 3> n{-v[0], v[1], v[2]};
          for (int k = 0; k < 3; ++k) bound[k] = std::max(bound[k], std::abs(n[k] - w[k]));
        }
      }
      // The chord's direction, by which D is turned, differs from the circle's by up to Δθ/2.
      const double turn_by = std::tan(0.5 * dtheta), b0 = bound[0];
      bound[0] += turn_by * (std::abs(w[2]) + bound[2]);
      bound[2] += turn_by * (std::abs(w[0]) + b0);
      ++points;
      for (int k = 0; k < 3; ++k) {
        const double diff = std::abs(g[k] - w[k]);
        if (diff > 1.5 * bound[k] + 1e-4) ++outside_bound;
        if (diff > worst) worst = diff, worst_s = s, worst_zeta = zeta;
      }
      worst_rigid = std::max(worst_rigid, std::abs(old[1] - want[1]));
      largest = std::max(largest, std::abs(want[1]));
    }
    // The swung pattern's centreline at s: straight behind the object, off the circle.
    const double cx = pose.x_m - s * std::cos(pose.heading_rad),
                 cz = pose.z_m - s * std::sin(pose.heading_rad);
    axis_rigid = std::max(axis_rigid, std::abs(std::hypot(cx, cz - kR) - kR));
  }
  std::printf(
      "on the circle: %d of %d points outside the bound; largest |difference| from the "
      "straight pattern %.4f m at s = %.1f m, zeta = %.2f m (swung rigidly: %.3f m) of a "
      "largest height %.3f m; the swung centreline %.1f m off the track\n",
      outside_bound, points, worst, worst_s, worst_zeta, worst_rigid, largest, axis_rigid);
  EXPECT_GT(largest, 0.5 * kPeak);  // the comparison saw the wake
  EXPECT_EQ(outside_bound, 0);
  // Swung rigidly the pattern misses: its centreline lies √(s² + R²) − R off the track (33 m at
  // s = 80; s²/(2R) for s ≪ R), and its heights there differ by as much as the pattern's own.
  EXPECT_GT(axis_rigid, 30.0);
  EXPECT_GT(worst_rigid, 0.5 * kPeak);
}

// On a straight path the pattern laid along the track is the pattern of the heading.
TEST(KelvinWake, OnAStraightPathTheTrackFrameIsTheHeadingsFrame) {
  KelvinWake path{.hull_length_m = kL, .peak_height_m = kPeak};
  const double c = std::cos(0.6), sn = std::sin(0.6);
  for (double t = 0.0; t <= 40.0; t += 0.5)
    path.path.push_back({.time_s = t, .x_m = kU * t * c - 100.0, .z_m = kU * t * sn - 80.0});
  const WakePose pose = pose_at(path, 30.0);
  const KelvinWake heading{.x_m = pose.x_m,
                           .z_m = pose.z_m,
                           .heading_deg = pose.heading_rad * 180.0 / kPi,
                           .speed_mps = pose.speed_mps,
                           .hull_length_m = kL,
                           .peak_height_m = kPeak};
  const auto a = make(path), b = make(heading);
  double worst = 0.0, largest = 0.0;
  for (double x = -150.0; x <= 50.0; x += 1.7) {
    for (double z = -120.0; z <= 80.0; z += 1.9) {
      const auto u = a->displacement_at(x, z, 30.0), v = b->displacement_at(x, z, 0.0);
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(u[k] - v[k]));
      largest = std::max(largest, std::abs(v[1]));
    }
  }
  EXPECT_GT(largest, 0.5 * kPeak);
  // Rounding of two ways to the same (s, ζ) and heading (1e-13 m at 100 m) through the table's
  // bilinear lookup.
  EXPECT_LT(worst, 1e-8);
}

}  // namespace
