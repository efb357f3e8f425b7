// src/world/world.cpp — the World: its objects' bodies stepped at a fixed step against the sea,
// driven ones by their helm (B.8–B.11), their tracks recorded (W.17); poses for the renderer.
// The local layer the tracks' wakes make is in layer.cpp.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ocean/backends.hpp"
#include "world_object.hpp"

namespace ocean::world {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Status validate(const Circle& c, const std::string& name) {
  if (!std::isfinite(c.centre_m[0]) || !std::isfinite(c.centre_m[1]))
    return invalid_argument(name + ": the circle's centre must be finite");
  if (!(c.radius_m > 0.0) || !std::isfinite(c.radius_m))
    return invalid_argument(name + ": the circle's radius = " + format_number(c.radius_m) +
                            " m must be finite and > 0");
  if (!(c.look_ahead_m > 0.0) || !std::isfinite(c.look_ahead_m))
    return invalid_argument(name + ": the circle's look_ahead_m = " +
                            format_number(c.look_ahead_m) + " m must be finite and > 0");
  return {};
}

// Puts a circling object on its circle at angle 0 at time_s: its calm-water draught and trim
// turned to the course's heading, moving along it at the commanded speed, the speed loop as if
// it had been going steadily, its track begun there.
void place_on_circle(World::Object& o, double time_s) {
  const waves::WakePose p = circling_pose(*o.circle, o.speed_mps, time_s, time_s);
  const double y = o.settled.position_m[1];
  // The settled trim (a rotation about z) turned to the course's heading.
  const bodies::Quat h = bodies::orientation_from_heading(p.heading_rad / kDegree);
  const bodies::Quat& q = o.settled.orientation;
  const bodies::Quat turned{h[0] * q[0] - h[2] * q[2], h[0] * q[1] + h[2] * q[3],
                            h[0] * q[2] + h[2] * q[0], h[0] * q[3] - h[2] * q[1]};
  const double u = o.speed_mps;
  // A valid state: the settled one, moved and turned.
  (void)o.body->set_state(
      {.position_m = {p.x_m, y, p.z_m},
       .orientation = turned,
       .velocity_mps = {u * std::cos(p.heading_rad), 0.0, u * std::sin(p.heading_rad)}});
  o.propulsion->reset(u);
  o.track->clear();
  o.track->record(time_s, p.x_m, p.z_m);
}

// The body, propulsion and track of a floating object.
Status make_body(World::Object& o, const ObjectDesc& desc, const std::string& name,
                 double gravity_mps2) {
  Result<bodies::BodyParams> params = bodies::solid_body(desc.hull, desc.density_kgpm3);
  if (!params.ok())
    return invalid_argument(name + " cannot float: " + params.status().message());
  o.centre_m = bodies::mass_properties(desc.hull).centroid_m;
  if (!desc.hull.vertices.empty()) {
    std::array<double, 4> box{desc.hull.vertices[0][0], desc.hull.vertices[0][0],
                              desc.hull.vertices[0][2], desc.hull.vertices[0][2]};
    for (const auto& v : desc.hull.vertices)
      box = {std::min(box[0], v[0]), std::max(box[1], v[0]), std::min(box[2], v[2]),
             std::max(box[3], v[2])};
    o.size_m = {box[1] - box[0], box[3] - box[2]};
    o.box_centre_m = {0.5 * (box[0] + box[1]), 0.0, 0.5 * (box[2] + box[3])};
  }
  bodies::BodyState start;
  if (!o.circle) {
    const std::array<double, 3> c = bodies::rotate(o.start.orientation, o.centre_m);
    const auto& x = o.start.position_m;
    start = {.position_m = {x[0] + c[0], x[1] + c[1], x[2] + c[2]},
             .orientation = o.start.orientation};
  }
  Result<bodies::FloatingBody> body = bodies::FloatingBody::make(params.value(), start);
  if (!body.ok()) return body.status();
  o.body = std::make_unique<bodies::FloatingBody>(std::move(body).value());
  if (o.speed_mps > 0.0) {
    Result<bodies::Propulsion> propulsion =
        bodies::Propulsion::make(propulsion_for(params.value(), gravity_mps2));
    if (!propulsion.ok()) return propulsion.status();
    o.propulsion = propulsion.value();
    Result<waves::WakeTrack> track = waves::WakeTrack::make(wake_track_for(params.value()));
    if (!track.ok()) return track.status();
    o.track = std::move(track).value();
  }
  if (o.circle) {  // settled once in calm water, at rest: the draught and trim each start has
    for (double t = 0.0; t < kSettle_s; t += kBodyStep_s) {
      if (Status s = o.body->step(bodies::calm_surface(), kBodyStep_s); !s.ok()) return s;
    }
    o.settled = o.body->state();
  }
  return {};
}

}  // namespace

World::~World() = default;

Result<std::unique_ptr<World>> World::make(WorldParams params, const SimulationConfig& config) {
  std::unique_ptr<World> world(new World());
  world->gravity_mps2_ = config.sea.dispersion.gravity_mps2;
  for (std::size_t i = 0; i < params.objects.size(); ++i) {
    const ObjectDesc& desc = params.objects[i];
    const std::string name =
        desc.name.empty() ? "objects[" + std::to_string(i) + "]" : desc.name;
    if (!(desc.speed_mps >= 0.0) || !std::isfinite(desc.speed_mps))
      return invalid_argument(name + ": speed_mps = " + format_number(desc.speed_mps) +
                              " must be finite and >= 0");
    if (desc.speed_mps > 0.0 && !params.floating)
      return invalid_argument(name + ": a speed drives a floating object, and the objects do not float");
    Object o;
    o.start = {.position_m = desc.position_m,
               .orientation = bodies::orientation_from_heading(desc.heading_deg)};
    o.heading_deg = desc.heading_deg;
    o.speed_mps = desc.speed_mps;
    if (desc.circle) {
      if (!(desc.speed_mps > 0.0))
        return invalid_argument(name + ": a circle is driven round: give a speed > 0");
      if (Status s = validate(*desc.circle, name); !s.ok()) return s;
      o.circle = desc.circle;
    }
    if (params.floating) {
      if (Status s = make_body(o, desc, name, world->gravity_mps2_); !s.ok()) return s;
    }
    world->objects_.push_back(std::move(o));
  }
  if (params.layer) {
    Result<std::unique_ptr<waves::LocalLayer>> layer = waves::LocalLayer::make(std::move(*params.layer));
    if (!layer.ok()) return layer.status();
    world->given_layer_ = std::move(layer).value();
    params.layer.reset();  // held by the layer
  }
  if (params.wake_area) {
    if (Status s = waves::validate(*params.wake_area); !s.ok()) return s;
  }
  if (params.floating && params.body_sea == BodySea::own && !params.objects.empty()) {
    SimulationConfig surface = config;
    // The displacement is all the queries read: no float maps, and no far-field noise map (a
    // picture's, 512² by default, would cost each step of the bodies' sea about seven times its
    // cascades: 30 ms against 4 ms of CPU for the moderate preset).
    surface.outputs = FrameOutputs::textures();
    surface.far_noise.resolution = 0;
    Result<std::unique_ptr<Simulator>> sim = make_simulator(surface);
    if (!sim.ok()) return sim.status();
    world->own_sea_ = std::move(sim).value();
    world->own_sea_->step(params.start_time_s);
  }
  world->params_ = std::move(params);
  world->time_s_ = world->params_.start_time_s;
  for (Object& o : world->objects_)
    if (o.circle) place_on_circle(o, world->time_s_);
  return world;
}

long long World::steps_until(double time_s) const {
  if (!params_.floating || objects_.empty()) return 0;
  // Counted with the same sums as step_bodies takes them.
  long long steps = 0;
  for (double t = time_s_; t + 0.5 * kBodyStep_s < time_s; t += kBodyStep_s) ++steps;
  return steps;
}

Status World::step_bodies(double time_s, Simulator& sea, const AdvanceHooks& hooks) {
  const long long steps = steps_until(time_s);
  if (steps == 0) return {};
  const bodies::SurfaceQuery surface = bodies::surface_of(own_sea_ ? *own_sea_ : sea);
  for (long long i = 0; i < steps; ++i) {
    if (hooks.cancel != nullptr && hooks.cancel->load(std::memory_order_relaxed))
      return {ErrorCode::cancelled, "stopped at t = " + format_number(time_s_) + " s"};
    if (own_sea_ && i % 2 == 0) own_sea_->step(time_s_);
    for (Object& o : objects_) {
      bodies::Wrench thrust;
      if (o.propulsion) {
        const auto& x = o.body->state().position_m;
        const bodies::HelmCommand helm =
            o.circle ? bodies::HelmCommand{.speed_mps = o.speed_mps,
                                           .heading_deg = circle_heading_deg(*o.circle, x[0], x[2]),
                                           .turn_rate_degps =
                                               o.speed_mps / o.circle->radius_m / kDegree}
                     : bodies::HelmCommand{.speed_mps = o.speed_mps, .heading_deg = o.heading_deg};
        Result<bodies::Wrench> w = o.propulsion->control(*o.body, helm, kBodyStep_s);
        if (!w.ok()) return w.status();
        thrust = w.value();
      }
      if (Status s = o.body->step(surface, kBodyStep_s, thrust); !s.ok()) return s;
      if (o.track) {
        const auto& x = o.body->state().position_m;
        o.track->record(time_s_ + kBodyStep_s, x[0], x[2]);
      }
    }
    time_s_ += kBodyStep_s;
    if (hooks.on_step) hooks.on_step(i + 1);
  }
  return {};
}

Result<bool> World::advance_to(double time_s, Simulator& sea, const AdvanceHooks& hooks) {
  if (Status s = step_bodies(time_s, sea, hooks); !s.ok()) return s;
  if (Status s = update_layer(sea); !s.ok()) return s;
  const std::shared_ptr<const waves::LocalLayer>& layer = local_layer();
  if (layer.get() == sea.local_layer()) return false;
  sea.set_local_layer(layer);
  return true;
}

void World::restart(double time_s) {
  for (Object& o : objects_)
    if (o.circle) place_on_circle(o, time_s);
  driven_layer_.reset();
  time_s_ = time_s;
}

Status World::set_course(std::size_t index, double speed_mps, const Circle& circle) {
  if (index >= objects_.size() || !objects_[index].circle)
    return invalid_argument("object " + std::to_string(index) + " does not circle");
  const std::string name = "objects[" + std::to_string(index) + "]";
  if (!(speed_mps > 0.0) || !std::isfinite(speed_mps))
    return invalid_argument(name + ": speed_mps = " + format_number(speed_mps) +
                            " must be finite and > 0");
  if (Status s = validate(circle, name); !s.ok()) return s;
  objects_[index].speed_mps = speed_mps;
  objects_[index].circle = circle;
  return {};
}

Status World::set_wake_area(const waves::LocalArea& area) {
  if (Status s = waves::validate(area); !s.ok()) return s;
  const bool moved = !params_.wake_area || area.origin_m != params_.wake_area->origin_m ||
                     area.size_m != params_.wake_area->size_m;
  params_.wake_area = area;
  if (moved && given_layer_ == nullptr) driven_layer_.reset();  // tables for the old cells
  return {};
}

std::size_t World::object_count() const { return objects_.size(); }

Pose World::pose(std::size_t index) const {
  const Object& o = objects_.at(index);
  if (o.body == nullptr) return o.start;
  // The body's centre is the object frame's point centre_m: origin = x − R·c.
  const bodies::BodyState& s = o.body->state();
  const std::array<double, 3> c = bodies::rotate(s.orientation, o.centre_m);
  return {.position_m = {s.position_m[0] - c[0], s.position_m[1] - c[1], s.position_m[2] - c[2]},
          .orientation = s.orientation};
}

const bodies::FloatingBody* World::body(std::size_t index) const {
  return objects_.at(index).body.get();
}

const bodies::Propulsion* World::propulsion(std::size_t index) const {
  const Object& o = objects_.at(index);
  return o.propulsion ? &*o.propulsion : nullptr;
}

}  // namespace ocean::world
