// The interaction scenes of `ocean view` (see interaction.hpp).
#include "view/interaction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "object_flags.hpp"
#include "wave_flags.hpp"

namespace ocean::cli::view {
namespace {

// The square the boat's wake is drawn in: centred on the circle, kBoatWakeMargin_m beyond it.
waves::LocalArea wake_area(const BoatControls& boat) {
  const double side = 2.0 * (boat.radius_m + kBoatWakeMargin_m);
  return {.origin_m = {boat.centre_m[0] - 0.5 * side, boat.centre_m[1] - 0.5 * side},
          .size_m = side,
          .resolution = kBoatLayerResolution};
}

world::Circle circle_of(const BoatControls& boat) {
  return {.centre_m = boat.centre_m, .radius_m = boat.radius_m};
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

Result<std::unique_ptr<world::World>> make_boat_world(const BoatControls& boat, double time_s,
                                                      const SimulationConfig& config) {
  if (Status s = validate(boat); !s.ok()) return s;
  Result<bodies::Hull> hull = world::shape_hull(world::Shape::boat);
  if (!hull.ok()) return hull.status();
  return world::World::make({.objects = {{.name = "boat",
                                          .hull = std::move(hull).value(),
                                          .density_kgpm3 = world::kBoatDensity_kgpm3,
                                          .speed_mps = boat.speed_mps,
                                          .circle = circle_of(boat)}},
                             .floating = true,
                             .body_sea = world::BodySea::caller,
                             .wake_area = wake_area(boat),
                             .choppiness = config.choppiness,
                             .start_time_s = time_s},
                            config);
}

double scene_radius_m(const BoatControls& boat, Shallows shallows) {
  double r = boat.on ? boat.radius_m + 10.0 : 0.0;
  if (shallows == Shallows::lily_pads) r = std::max(r, 60.0);
  if (shallows == Shallows::lagoon) r = std::max(r, 100.0);
  return r;
}

std::array<std::array<double, 3>, 2> framing_camera(std::array<double, 2> centre_m, double radius_m,
                                                    std::array<double, 2> look, double fov_y_rad,
                                                    double aspect) {
  const double horizontal_fov = 2.0 * std::atan(std::tan(0.5 * fov_y_rad) * aspect);
  const double narrower = std::min(fov_y_rad, horizontal_fov);
  const double distance = radius_m / std::tan(0.4 * narrower);
  constexpr double kDown = 25.0 * std::numbers::pi / 180.0;
  const double len = std::hypot(look[0], look[1]);
  const double lx = look[0] / len, lz = look[1] / len;
  const double back = distance * std::cos(kDown);
  return {{{centre_m[0] - back * lx, distance * std::sin(kDown), centre_m[1] - back * lz},
           {centre_m[0], 0.0, centre_m[1]}}};
}

Result<std::unique_ptr<InteractionScene>> InteractionScene::make(render::Renderer& renderer,
                                                                 const SimulationConfig& config) {
  Result<std::vector<render::Mesh>> boat = built_in_meshes("boat");
  if (!boat.ok()) return boat.status();
  if (Status s = renderer.set_meshes(boat.value()); !s.ok()) return s;
  const auto parts = static_cast<std::uint32_t>(boat.value().size());
  std::unique_ptr<InteractionScene> scene(new InteractionScene);
  scene->config_ = config;
  scene->boat_meshes_ = parts;
  return scene;
}

Status InteractionScene::set_boat(const BoatControls& boat, double time_s, Simulator& simulator) {
  if (boat.on && boat_ != nullptr) {  // the running boat takes the new controls where it is
    if (Status s = validate(boat); !s.ok()) return s;
    if (Status s = boat_->set_course(0, boat.speed_mps, circle_of(boat)); !s.ok()) return s;
    return boat_->set_wake_area(wake_area(boat));
  }
  boat_.reset();
  simulator.set_local_layer(nullptr);
  if (!boat.on) return Status{};
  Result<std::unique_ptr<world::World>> made = make_boat_world(boat, time_s, config_);
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
                               .depth_m = d.depth_m,
                               .breaking_fraction = d.breaking_fraction});
}

Status InteractionScene::update(double time_s, Simulator& simulator, render::View& view) {
  view.objects.clear();
  if (boat_ == nullptr) return Status{};
  if (time_s < boat_->time_s() || time_s > boat_->time_s() + kBoatMaxJump_s) boat_->restart(time_s);
  if (Result<bool> advanced = boat_->advance_to(time_s, simulator); !advanced.ok())
    return advanced.status();
  const world::Pose pose = boat_->pose(0);
  const std::array<double, 16> model = render::model_matrix(pose.position_m, pose.orientation);
  for (std::uint32_t m = 0; m < boat_meshes_; ++m) view.objects.push_back({.mesh = m, .model = model});
  return Status{};
}

}  // namespace ocean::cli::view
