// src/waves/wake_track.cpp — the track of a moving object, recorded at a fixed interval in a ring
// of waypoints, and the Kelvin wake that follows it (W.17): the track's mean speed, quantised and
// held so that the wake's pattern is recomputed only when the speed really changes.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ocean/waves.hpp"

namespace ocean::waves {

namespace {

constexpr double kMaxWakeSpeed_mps = 100.0;  // KelvinWake's limit

}  // namespace

Status validate(const WakeTrackParams& p) {
  if (Status s = require_in_range("hull_length_m", p.hull_length_m, 0.01, 1000.0); !s.ok())
    return s;
  if (p.peak_height_m) {
    if (Status s = require_non_negative("peak_height_m", *p.peak_height_m); !s.ok()) return s;
  }
  if (Status s = require_non_negative("fade_length_m", p.fade_length_m); !s.ok()) return s;
  if (Status s = validate(p.foam); !s.ok()) return s;
  if (p.thin_hull != nullptr) {
    if (Status s = validate(*p.thin_hull); !s.ok()) return s;
  }
  if (Status s = require_positive("interval_s", p.interval_s); !s.ok()) return s;
  if (Status s = require_in_range("interval_s", p.interval_s, 0.0, 60.0); !s.ok()) return s;
  if (p.waypoints < 2 || p.waypoints > 4096)
    return invalid_argument("waypoints = " + std::to_string(p.waypoints) +
                            " is out of range: must be in [2, 4096]");
  if (Status s = require_non_negative("min_speed_mps", p.min_speed_mps); !s.ok()) return s;
  if (!(p.min_speed_mps < kMaxWakeSpeed_mps))
    return invalid_argument("min_speed_mps = " + format_number(p.min_speed_mps) +
                            " is out of range: must be below 100");
  if (Status s = require_positive("speed_step", p.speed_step); !s.ok()) return s;
  if (Status s = require_in_range("speed_step", p.speed_step, 0.0, 0.1); !s.ok()) return s;
  return require_non_negative("retune_s", p.retune_s);
}

Result<WakeTrack> WakeTrack::make(const WakeTrackParams& params) {
  if (Status s = validate(params); !s.ok()) return s;
  WakeTrack track;
  track.params_ = params;
  track.ring_.resize(static_cast<std::size_t>(params.waypoints));
  return track;
}

void WakeTrack::clear() {
  first_ = 0;
  count_ = 0;
  wake_speed_mps_ = 0.0;
}

const Waypoint& WakeTrack::waypoint(std::size_t i) const {
  return ring_[(first_ + i) % ring_.size()];
}

double WakeTrack::track_speed_mps() const {
  if (count_ < 2) return 0.0;
  double length = 0.0;
  for (std::size_t i = 1; i < count_; ++i) {
    const Waypoint &a = waypoint(i - 1), &b = waypoint(i);
    length += std::hypot(b.x_m - a.x_m, b.z_m - a.z_m);
  }
  return length / (waypoint(count_ - 1).time_s - waypoint(0).time_s);
}

void WakeTrack::record(double time_s, double x_m, double z_m) {
  if (count_ > 0) {
    const double last = waypoint(count_ - 1).time_s;
    if (time_s < last) {
      clear();
    } else if (time_s < last + params_.interval_s * (1.0 - 1e-9)) {
      return;  // not yet: the next waypoint is interval_s after the last
    }
  }
  if (count_ == ring_.size()) {
    first_ = (first_ + 1) % ring_.size();
    --count_;
  }
  ring_[(first_ + count_) % ring_.size()] = {.time_s = time_s, .x_m = x_m, .z_m = z_m};
  ++count_;
  // (W.17) The wake's speed: the track's, in steps of e^{speed_step}, changed only when the track
  // has left the present step by a whole step and retune_s has passed since the last change.
  const double u = track_speed_mps();
  if (!(u >= params_.min_speed_mps) || u <= 0.0 || u > kMaxWakeSpeed_mps) {
    wake_speed_mps_ = 0.0;
    return;
  }
  const double step = params_.speed_step;
  const bool off_step = wake_speed_mps_ == 0.0 || std::abs(std::log(u / wake_speed_mps_)) > step;
  if (off_step && (wake_speed_mps_ == 0.0 || time_s - retuned_s_ >= params_.retune_s)) {
    wake_speed_mps_ = std::min(std::exp(step * std::round(std::log(u) / step)), kMaxWakeSpeed_mps);
    retuned_s_ = time_s;
  }
}

bool WakeTrack::wake(KelvinWake& out) const {
  if (wake_speed_mps_ == 0.0 || count_ < 2) return false;
  out.hull_length_m = params_.hull_length_m;
  out.peak_height_m = params_.peak_height_m;
  out.fade_length_m = params_.fade_length_m;
  out.foam = params_.foam;
  out.thin_hull = params_.thin_hull;
  out.speed_mps = wake_speed_mps_;
  // Newest first, timed back along the track at the wake's speed; a point closer than a
  // millimetre to the one after it is skipped (the times must increase); then oldest first.
  out.path.clear();
  out.path.push_back(waypoint(count_ - 1));
  for (std::size_t i = count_ - 1; i-- > 0;) {
    const Waypoint& w = waypoint(i);
    const Waypoint& next = out.path.back();
    const double d = std::hypot(next.x_m - w.x_m, next.z_m - w.z_m);
    if (d < 1e-3) continue;
    out.path.push_back({.time_s = next.time_s - d / wake_speed_mps_, .x_m = w.x_m, .z_m = w.z_m});
  }
  std::reverse(out.path.begin(), out.path.end());
  if (out.path.size() < 2) return false;
  const Waypoint &a = out.path[out.path.size() - 2], &b = out.path.back();
  out.heading_deg = std::atan2(b.z_m - a.z_m, b.x_m - a.x_m) * 180.0 / std::numbers::pi;
  out.x_m = b.x_m;
  out.z_m = b.z_m;
  return true;
}

}  // namespace ocean::waves
