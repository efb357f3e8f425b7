// The interaction scenes of `ocean view` (see interaction.hpp).
#include "view/interaction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "object_flags.hpp"
#include "ocean/bodies.hpp"
#include "wave_flags.hpp"

namespace ocean::cli::view {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kSettle_s = 4.0;    // calm-water settling before the boat starts
constexpr double kMaxJump_s = 10.0;  // a longer jump in time restarts the boat on the circle

// A square map of side `size` and `n` samples per side, centred on `centre`, whose value is
// f(distance from the centre).
template <typename F>
waves::PlacedMap radial_map(std::array<double, 2> centre, double size, int n, F f) {
  auto map = std::make_shared<waves::HeightMap>();
  map->rows = n, map->cols = n;
  map->values.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  const double cell = size / n;
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      const double dx = (c + 0.5) * cell - 0.5 * size, dz = (r + 0.5) * cell - 0.5 * size;
      map->values[static_cast<std::size_t>(r) * static_cast<std::size_t>(n) +
                  static_cast<std::size_t>(c)] = static_cast<float>(f(std::hypot(dx, dz)));
    }
  }
  return {.map = std::move(map),
          .origin_m = {centre[0] - 0.5 * size, centre[1] - 0.5 * size},
          .size_m = size};
}

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The square the boat's wake is drawn in: centred on the circle, kBoatWakeMargin_m beyond it.
waves::LocalArea wake_area(const BoatControls& boat) {
  const double side = 2.0 * (boat.radius_m + kBoatWakeMargin_m);
  return {.origin_m = {boat.centre_m[0] - 0.5 * side, boat.centre_m[1] - 0.5 * side},
          .size_m = side,
          .resolution = kBoatLayerResolution};
}

}  // namespace

Status validate(const BoatControls& boat) {
  if (!(boat.speed_mps > 0.0 && boat.speed_mps <= 20.0))
    return invalid_argument("boat speed = " + std::to_string(boat.speed_mps) +
                            " m/s: must be in (0, 20]");
  if (!(boat.radius_m >= 10.0 && boat.radius_m <= 500.0))
    return invalid_argument("boat circle radius = " + std::to_string(boat.radius_m) +
                            " m: must be in [10, 500]");
  if (!std::isfinite(boat.centre_m[0]) || !std::isfinite(boat.centre_m[1]))
    return invalid_argument("boat circle centre: must be finite");
  return Status{};
}

waves::WakePose circling_pose(const BoatControls& boat, double t0_s, double time_s) {
  const double angle = boat.speed_mps / boat.radius_m * (time_s - t0_s);
  return {.x_m = boat.centre_m[0] + boat.radius_m * std::cos(angle),
          .z_m = boat.centre_m[1] + boat.radius_m * std::sin(angle),
          .heading_rad = angle + 0.5 * std::numbers::pi,
          .speed_mps = boat.speed_mps};
}

double circle_heading_deg(const BoatControls& boat, double x_m, double z_m) {
  // (B.11) Line-of-sight guidance onto the circle: the tangent at the boat's angle φ about the
  // centre (motion from +x towards +z), turned inwards when the boat is outside the circle.
  const double dx = x_m - boat.centre_m[0], dz = z_m - boat.centre_m[1];
  const double phi = std::atan2(dz, dx), rho = std::hypot(dx, dz);
  return (phi + 0.5 * std::numbers::pi + std::atan((rho - boat.radius_m) / kBoatLookAhead_m)) /
         kDegree;
}

Result<std::unique_ptr<CirclingBoat>> CirclingBoat::make(const BoatControls& boat, double time_s,
                                                         double choppiness) {
  if (Status s = validate(boat); !s.ok()) return s;
  Result<bodies::Hull> hull = bodies::boat_hull(8.0, 3.0, 1.2);
  if (!hull.ok()) return hull.status();
  Result<bodies::BodyParams> params = bodies::solid_body(hull.value(), kBoatDensity);
  if (!params.ok()) return params.status();
  std::unique_ptr<CirclingBoat> b(new CirclingBoat());
  b->controls_ = boat;
  b->choppiness_ = choppiness;
  b->centre_m_ = bodies::mass_properties(hull.value()).centroid_m;
  Result<bodies::Propulsion> propulsion = bodies::Propulsion::make(propulsion_for(params.value()));
  if (!propulsion.ok()) return propulsion.status();
  b->propulsion_ = propulsion.value();
  Result<waves::WakeTrack> track = waves::WakeTrack::make(wake_track_for(params.value().hull));
  if (!track.ok()) return track.status();
  b->track_ = std::move(track).value();
  // Settled once in calm water, at rest: the draught and trim it starts each lap from.
  Result<bodies::FloatingBody> body = bodies::FloatingBody::make(params.value(), {});
  if (!body.ok()) return body.status();
  b->body_ = std::make_unique<bodies::FloatingBody>(std::move(body).value());
  for (double t = 0.0; t < kSettle_s; t += kBoatStep_s) {
    if (Status s = b->body_->step(bodies::calm_surface(), kBoatStep_s); !s.ok()) return s;
  }
  b->settled_ = b->body_->state();
  b->params_ = {.area = wake_area(boat), .choppiness = choppiness};
  b->restart(time_s);
  return b;
}

Status CirclingBoat::set_controls(const BoatControls& boat) {
  if (Status s = validate(boat); !s.ok()) return s;
  controls_ = boat;
  const waves::LocalArea area = wake_area(boat);
  if (area.origin_m != params_.area.origin_m || area.size_m != params_.area.size_m) {
    params_.area = area;
    layer_.reset();  // its tables were made for the old square's cells
  }
  return Status{};
}

void CirclingBoat::restart(double time_s) {
  const waves::WakePose p = circling_pose(controls_, time_s, time_s);
  const double y = settled_.position_m[1];
  // The settled trim (a rotation about z) turned to the course's heading.
  const bodies::Quat h = bodies::orientation_from_heading(p.heading_rad / kDegree);
  const bodies::Quat& q = settled_.orientation;
  const bodies::Quat turned{h[0] * q[0] - h[2] * q[2], h[0] * q[1] + h[2] * q[3],
                            h[0] * q[2] + h[2] * q[0], h[0] * q[3] - h[2] * q[1]};
  const double u = controls_.speed_mps;
  // A valid state: the settled one, moved and turned.
  (void)body_->set_state(
      {.position_m = {p.x_m, y, p.z_m},
       .orientation = turned,
       .velocity_mps = {u * std::cos(p.heading_rad), 0.0, u * std::sin(p.heading_rad)}});
  propulsion_->reset(u);
  track_->clear();
  track_->record(time_s, p.x_m, p.z_m);
  layer_.reset();
  time_s_ = time_s;
}

Status CirclingBoat::advance(double time_s, const bodies::SurfaceQuery& surface) {
  if (time_s < time_s_ || time_s > time_s_ + kMaxJump_s) {
    restart(time_s);
    return Status{};
  }
  const double newest = track_->size() == 0 ? -1.0 : track_->waypoint(track_->size() - 1).time_s;
  while (time_s_ + 0.5 * kBoatStep_s < time_s) {
    const auto& x = body_->state().position_m;
    const bodies::HelmCommand helm{
        .speed_mps = controls_.speed_mps,
        .heading_deg = circle_heading_deg(controls_, x[0], x[2]),
        .turn_rate_degps = controls_.speed_mps / controls_.radius_m / kDegree};
    Result<bodies::Wrench> thrust = propulsion_->control(*body_, helm, kBoatStep_s);
    if (!thrust.ok()) return thrust.status();
    if (Status s = body_->step(surface, kBoatStep_s, thrust.value()); !s.ok()) return s;
    time_s_ += kBoatStep_s;
    const auto& moved = body_->state().position_m;
    track_->record(time_s_, moved[0], moved[2]);
  }
  if (track_->size() == 0 || track_->waypoint(track_->size() - 1).time_s == newest) return {};
  // A new waypoint: the layer remade with the new path, sharing the previous one's table.
  waves::KelvinWake wake;
  if (!track_->wake(wake)) {
    layer_.reset();
    return Status{};
  }
  waves::LayerParams params = params_;
  params.wakes.push_back(std::move(wake));
  Result<std::unique_ptr<waves::LocalLayer>> layer =
      waves::LocalLayer::make(std::move(params), layer_.get());
  if (!layer.ok()) return layer.status();
  layer_ = std::move(layer).value();
  tables_computed_ += layer_->tables_computed();
  return Status{};
}

render::ObjectInstance CirclingBoat::instance(std::uint32_t mesh) const {
  // The body's centre is the mesh frame's point centre_m: origin = x − R·c.
  const bodies::BodyState& s = body_->state();
  const std::array<double, 3> c = bodies::rotate(s.orientation, centre_m_);
  return {
      .mesh = mesh,
      .model = render::model_matrix(
          {s.position_m[0] - c[0], s.position_m[1] - c[1], s.position_m[2] - c[2]}, s.orientation)};
}

std::optional<Shallows> parse_shallows(std::string_view name) {
  if (name == "none") return Shallows::none;
  if (name == "lily-pads") return Shallows::lily_pads;
  if (name == "lagoon") return Shallows::lagoon;
  return std::nullopt;
}

Result<std::optional<waves::Damping>> shallows_damping(Shallows scene,
                                                       std::array<double, 2> centre_m,
                                                       const SimulationConfig& config) {
  if (scene == Shallows::none) return std::optional<waves::Damping>{};
  waves::DampingParams params{.band_wavenumbers_radpm = band_wavenumbers(config),
                              .gravity_mps2 = config.sea.dispersion.gravity_mps2};
  if (scene == Shallows::lily_pads) {
    params.mask =
        radial_map(centre_m, 200.0, 256, [](double r) { return smoothstep(40.0, 60.0, r); });
  } else {
    params.bathymetry = radial_map(
        centre_m, 400.0, 256, [](double r) { return std::clamp((r - 50.0) / 5.0, 0.0, 40.0); });
  }
  Result<waves::Damping> made = waves::Damping::make(std::move(params));
  if (!made.ok()) return made.status();
  return std::optional<waves::Damping>(std::move(made).value());
}

Result<std::unique_ptr<InteractionScene>> InteractionScene::make(render::Renderer& renderer,
                                                                 const SimulationConfig& config) {
  Result<std::unique_ptr<SceneObjects>> boat =
      SceneObjects::make({ObjectSpec{.kind = "boat"}}, false, config);
  if (!boat.ok()) return boat.status();
  if (Status s = renderer.set_meshes(boat.value()->meshes()); !s.ok()) return s;
  std::unique_ptr<InteractionScene> scene(new InteractionScene);
  scene->choppiness_ = config.choppiness;
  return scene;
}

Status InteractionScene::set_boat(const BoatControls& boat, double time_s, Simulator& simulator) {
  if (boat.on && boat_ != nullptr) return boat_->set_controls(boat);
  boat_.reset();
  simulator.set_local_layer(nullptr);
  if (!boat.on) return Status{};
  Result<std::unique_ptr<CirclingBoat>> made = CirclingBoat::make(boat, time_s, choppiness_);
  if (!made.ok()) return made.status();
  boat_ = std::move(made).value();
  return Status{};
}

Status InteractionScene::set_shallows(Shallows scene, std::array<double, 2> centre_m,
                                      const SimulationConfig& config, render::Renderer& renderer) {
  Result<std::optional<waves::Damping>> damping = shallows_damping(scene, centre_m, config);
  if (!damping.ok()) return damping.status();
  if (!damping.value().has_value()) return renderer.set_damping({});
  const DampingSamples d = sample_damping(*damping.value(), 256, render::kDampingBands);
  return renderer.set_damping({.origin_m = d.origin_m,
                               .size_m = d.size_m,
                               .resolution = d.resolution,
                               .band_weights = d.band_weights,
                               .depth_m = d.depth_m});
}

Status InteractionScene::update(double time_s, Simulator& simulator, render::View& view) {
  view.objects.clear();
  if (boat_ == nullptr) return Status{};
  if (Status s = boat_->advance(time_s, bodies::surface_of(simulator)); !s.ok()) return s;
  view.objects.push_back(boat_->instance(0));
  if (boat_->layer().get() != simulator.local_layer()) simulator.set_local_layer(boat_->layer());
  return Status{};
}

}  // namespace ocean::cli::view
