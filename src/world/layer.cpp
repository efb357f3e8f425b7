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

// Whether two lists of footprints are within 2 cm and 1° of each other (a floating object's
// heave and sway move its foam by less than the grid shows).
bool same_footprints(const std::vector<waves::Footprint>& a,
                     const std::vector<waves::Footprint>& b) {
  const auto same = [](const waves::Footprint& u, const waves::Footprint& v) {
    return std::hypot(u.x_m - v.x_m, u.z_m - v.z_m) < 0.02 &&
           std::abs(u.heading_deg - v.heading_deg) < 1.0 && u.length_m == v.length_m &&
           u.foam.beam_m == v.foam.beam_m;
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

void World::rest_footprints(std::vector<waves::Footprint>& out) const {
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    const Object& o = objects_[i];
    if (o.body == nullptr || o.track) continue;
    // The footprint's centre: the middle of the hull's extent (a transom puts the centre of
    // volume abaft it), where the pose puts it.
    const Pose p = pose(i);
    const std::array<double, 3> c = bodies::rotate(p.orientation, o.box_centre_m);
    out.push_back({.x_m = p.position_m[0] + c[0],
                   .z_m = p.position_m[2] + c[2],
                   .heading_deg = bodies::heading_deg(o.body->state()),
                   .length_m = o.size_m[0],
                   .foam = {.beam_m = o.size_m[1], .coverage = kRestFoamCoverage}});
  }
}

Status World::update_layer(const Simulator& sea) {
  wakes_.clear();
  driven_wakes(wakes_);
  footprints_.clear();
  rest_footprints(footprints_);
  // The layer's cells are undisplaced points (W.9) that the sea's choppy displacement moves: the
  // waterline foam of an object at rest is laid at the point that lands on it (M.7.7), so the
  // rim stays round the hull as the sea sways it.
  if (!footprints_.empty()) {
    std::array<std::array<double, 2>, 1> at{};
    std::array<HeightSample, 1> got{};
    for (waves::Footprint& f : footprints_) {
      at[0] = {f.x_m, f.z_m};
      sea.heights_at(at, got);
      if (std::isfinite(got[0].source_xz[0]) && std::isfinite(got[0].source_xz[1])) {
        f.x_m = got[0].source_xz[0];
        f.z_m = got[0].source_xz[1];
      }
    }
  }
  if (wakes_.empty() && footprints_.empty()) {
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
  } else if (wakes_.empty()) {
    // Only objects at rest: a square round them on 0.125 m cells, fine enough for a buoy's rim,
    // on a 4 m lattice so that drifting moves it seldom (W.20).
    double lo_x = footprints_[0].x_m, hi_x = lo_x, lo_z = footprints_[0].z_m, hi_z = lo_z;
    double reach = 0.0;
    for (const waves::Footprint& f : footprints_) {
      lo_x = std::min(lo_x, f.x_m);
      hi_x = std::max(hi_x, f.x_m);
      lo_z = std::min(lo_z, f.z_m);
      hi_z = std::max(hi_z, f.z_m);
      reach = std::max(reach, std::max(f.length_m, f.foam.beam_m));
    }
    const double side =
        std::min(16.0 * std::ceil((std::max(hi_x - lo_x, hi_z - lo_z) + 4.0 * reach + 8.0) / 16.0),
                 kDrivenArea_m);
    const double lattice = 4.0;
    p.area = {.origin_m = {lattice * std::round((0.5 * (lo_x + hi_x) - 0.5 * side) / lattice),
                           lattice * std::round((0.5 * (lo_z + hi_z) - 0.5 * side) / lattice)},
              .size_m = side,
              .resolution = std::min(static_cast<int>(side / 0.125), 2048),
              .edge_fraction = 0.05};
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
    // The waves fade behind the object before the area's border (W.22): e^{−s/(side/4)}, 7 % of
    // their height at the back edge, two thirds of a side behind.
    for (waves::KelvinWake& w : wakes_)
      if (w.fade_length_m == 0.0) w.fade_length_m = 0.25 * kDrivenArea_m;
  }
  for (waves::KelvinWake& w : wakes_) p.wakes.push_back(std::move(w));
  for (const waves::Footprint& f : footprints_) p.footprints.push_back(f);
  if (driven_layer_ != nullptr && same_wakes(driven_layer_->params().wakes, p.wakes) &&
      same_footprints(driven_layer_->params().footprints, p.footprints) &&
      driven_layer_->params().area.origin_m == p.area.origin_m &&
      driven_layer_->params().area.size_m == p.area.size_m)
    return {};
  const waves::LocalLayer* previous = driven_layer_ != nullptr ? driven_layer_.get() : given;
  Result<std::unique_ptr<waves::LocalLayer>> made = waves::LocalLayer::make(std::move(p), previous);
  if (!made.ok()) return made.status();
  tables_computed_ += made.value()->tables_computed();
  driven_layer_ = std::move(made).value();
  return {};
}

}  // namespace ocean::world
