// src/world/circle.cpp — the circle a driven object is steered round: the course on it and the
// line-of-sight guidance that steers onto it (docs/bodies.md B.11).
#include <cmath>
#include <numbers>

#include "ocean/world.hpp"

namespace ocean::world {

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;
}  // namespace

waves::WakePose circling_pose(const Circle& circle, double speed_mps, double t0_s, double time_s) {
  const double angle = speed_mps / circle.radius_m * (time_s - t0_s);
  return {.x_m = circle.centre_m[0] + circle.radius_m * std::cos(angle),
          .z_m = circle.centre_m[1] + circle.radius_m * std::sin(angle),
          .heading_rad = angle + 0.5 * std::numbers::pi,
          .speed_mps = speed_mps};
}

double circle_heading_deg(const Circle& circle, double x_m, double z_m) {
  // (B.11) The tangent at the object's angle φ about the centre (motion from +x towards +z),
  // turned inwards when the object is outside the circle.
  const double dx = x_m - circle.centre_m[0], dz = z_m - circle.centre_m[1];
  const double phi = std::atan2(dz, dx), rho = std::hypot(dx, dz);
  return (phi + 0.5 * std::numbers::pi + std::atan((rho - circle.radius_m) / circle.look_ahead_m)) /
         kDegree;
}

}  // namespace ocean::world
