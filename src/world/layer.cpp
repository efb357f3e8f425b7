// src/world/layer.cpp — the World's local layer: the caller's layer with the Kelvin wakes of the
// driven objects' tracks (docs/waves.md W.17). A track's wake changes only when it records a
// waypoint (every 0.5 s), so the layer is remade then, sharing the previous layer's wake tables
// while the speeds hold (LocalLayer::make with tables_from): a copy of the parameters, not a
// table, per waypoint.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "world_object.hpp"

namespace ocean::world {

namespace {

// Whether two lists of wakes are the same objects on the same paths.
bool same_wakes(const std::vector<waves::KelvinWake>& a, const std::vector<waves::KelvinWake>& b) {
  const auto same = [](const waves::KelvinWake& u, const waves::KelvinWake& v) {
    const auto same_point = [](const waves::Waypoint& p, const waves::Waypoint& q) {
      return p.time_s == q.time_s && p.x_m == q.x_m && p.z_m == q.z_m;
    };
    return u.x_m == v.x_m && u.z_m == v.z_m && u.heading_deg == v.heading_deg &&
           u.speed_mps == v.speed_mps && u.hull_length_m == v.hull_length_m &&
           u.peak_height_m == v.peak_height_m && u.fade_length_m == v.fade_length_m &&
           std::equal(u.path.begin(), u.path.end(), v.path.begin(), v.path.end(), same_point);
  };
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), same);
}

}  // namespace

void World::driven_wakes(std::vector<waves::KelvinWake>& out) const {
  for (const Object& o : objects_) {
    if (!o.track) continue;
    waves::KelvinWake wake;
    if (o.track->wake(wake)) out.push_back(std::move(wake));
  }
}

const std::shared_ptr<const waves::LocalLayer>& World::local_layer() const {
  return driven_layer_ != nullptr ? driven_layer_ : given_layer_;
}

Status World::update_layer() {
  wakes_.clear();
  driven_wakes(wakes_);
  if (wakes_.empty()) {
    driven_layer_.reset();
    return {};
  }
  const waves::LocalLayer* given = given_layer_.get();
  waves::LayerParams p;
  p.choppiness = params_.choppiness;
  if (given != nullptr) {
    p = given->params();
  } else if (params_.wake_area) {
    p.area = *params_.wake_area;
  } else {
    // Round the first driven object: its centre a sixth of a side behind it, so the wake trails
    // into it and the object stays clear of the soft edge; laid again, whole cells over, once the
    // object has gone a sixteenth of a side from where that puts it, so the area moves with it
    // (docs/waves.md W.22).
    const Object& first = *std::find_if(objects_.begin(), objects_.end(),
                                        [](const Object& o) { return o.propulsion.has_value(); });
    const auto& x = first.body->state().position_m;
    const double back = kDrivenArea_m / 6.0, half = 0.5 * kDrivenArea_m;
    const double heading = bodies::heading_deg(first.body->state()) * std::numbers::pi / 180.0;
    const std::array<double, 2> want{x[0] - back * std::cos(heading) - half,
                                     x[2] - back * std::sin(heading) - half};
    if (!driven_area_ || std::hypot(want[0] - driven_area_->origin_m[0],
                                    want[1] - driven_area_->origin_m[1]) > kDrivenArea_m / 16.0) {
      const double cell = kDrivenArea_m / kDrivenAreaResolution;
      driven_area_ = {.origin_m = {cell * std::round(want[0] / cell),
                                   cell * std::round(want[1] / cell)},
                      .size_m = kDrivenArea_m,
                      .resolution = kDrivenAreaResolution,
                      .edge_fraction = kDrivenAreaEdgeFraction};
    }
    p.area = *driven_area_;
    // The waves fade behind the object before the area's border (W.22): e^{−s/(side/4)}, 4 % of
    // their height at the back edge, two thirds of a side behind.
    for (waves::KelvinWake& w : wakes_)
      if (w.fade_length_m == 0.0) w.fade_length_m = 0.25 * kDrivenArea_m;
  }
  for (waves::KelvinWake& w : wakes_) p.wakes.push_back(std::move(w));
  if (driven_layer_ != nullptr && same_wakes(driven_layer_->params().wakes, p.wakes)) return {};
  const waves::LocalLayer* previous = driven_layer_ != nullptr ? driven_layer_.get() : given;
  Result<std::unique_ptr<waves::LocalLayer>> made = waves::LocalLayer::make(std::move(p), previous);
  if (!made.ok()) return made.status();
  tables_computed_ += made.value()->tables_computed();
  driven_layer_ = std::move(made).value();
  return {};
}

}  // namespace ocean::world
