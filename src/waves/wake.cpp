// src/waves/wake.cpp — a wake's parameters and its object's motion: validation, and the pose
// (position, heading, speed) at a time from a straight course or a path of timed waypoints.
#include <cmath>
#include <numbers>
#include <string>

#include "ocean/waves.hpp"

namespace ocean::waves {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Status check_path(const std::vector<Waypoint>& path) {
  for (std::size_t i = 0; i < path.size(); ++i) {
    const std::string name = "path[" + std::to_string(i) + "]";
    if (Status s = require_finite(name + ".time_s", path[i].time_s); !s.ok()) return s;
    if (Status s = require_finite(name + ".x_m", path[i].x_m); !s.ok()) return s;
    if (Status s = require_finite(name + ".z_m", path[i].z_m); !s.ok()) return s;
    if (i > 0 && !(path[i].time_s > path[i - 1].time_s)) {
      return invalid_argument(name + ".time_s = " + format_number(path[i].time_s) +
                              " is out of order: waypoint times must increase");
    }
  }
  return {};
}

WakePose along_segment(const Waypoint& a, const Waypoint& b, double t) {
  const double dt = b.time_s - a.time_s;
  const double vx = (b.x_m - a.x_m) / dt, vz = (b.z_m - a.z_m) / dt;
  return {.x_m = a.x_m + vx * (t - a.time_s),
          .z_m = a.z_m + vz * (t - a.time_s),
          .heading_rad = std::atan2(vz, vx),
          .speed_mps = std::hypot(vx, vz)};
}

}  // namespace

Status validate(const KelvinWake& w) {
  if (Status s = require_finite("x_m", w.x_m); !s.ok()) return s;
  if (Status s = require_finite("z_m", w.z_m); !s.ok()) return s;
  if (Status s = require_finite("heading_deg", w.heading_deg); !s.ok()) return s;
  if (Status s = require_positive("speed_mps", w.speed_mps); !s.ok()) return s;
  if (Status s = require_in_range("speed_mps", w.speed_mps, 1e-3, 100.0); !s.ok()) return s;
  if (Status s = require_positive("hull_length_m", w.hull_length_m); !s.ok()) return s;
  if (Status s = require_in_range("hull_length_m", w.hull_length_m, 0.01, 1000.0); !s.ok())
    return s;
  if (w.peak_height_m) {
    if (Status s = require_non_negative("peak_height_m", *w.peak_height_m); !s.ok()) return s;
  }
  if (Status s = require_non_negative("fade_length_m", w.fade_length_m); !s.ok()) return s;
  if (Status s = validate(w.foam); !s.ok()) return s;
  if (w.thin_hull != nullptr) {
    if (Status s = validate(*w.thin_hull); !s.ok()) return s;
  }
  if (Status s = check_path(w.path); !s.ok()) return s;
  // Every segment's speed becomes a table of its own: the same limits apply.
  for (std::size_t i = 1; i < w.path.size(); ++i) {
    const double speed = along_segment(w.path[i - 1], w.path[i], w.path[i].time_s).speed_mps;
    if (Status s =
            require_in_range("path[" + std::to_string(i) + "] speed_mps", speed, 1e-3, 100.0);
        !s.ok()) {
      return s;
    }
  }
  return {};
}

WakePose pose_at(const KelvinWake& w, double t) {
  const std::vector<Waypoint>& p = w.path;
  if (p.empty()) {
    const double heading = w.heading_deg * kDegree;
    return {.x_m = w.x_m + w.speed_mps * t * std::cos(heading),
            .z_m = w.z_m + w.speed_mps * t * std::sin(heading),
            .heading_rad = heading,
            .speed_mps = w.speed_mps};
  }
  if (p.size() == 1) {
    return {.x_m = p[0].x_m,
            .z_m = p[0].z_m,
            .heading_rad = w.heading_deg * kDegree,
            .speed_mps = w.speed_mps};
  }
  std::size_t i = 1;
  while (i + 1 < p.size() && t > p[i].time_s) ++i;
  return along_segment(p[i - 1], p[i], t);
}

}  // namespace ocean::waves
