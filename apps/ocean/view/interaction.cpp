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

constexpr double kWaypointStep_rad = 5.0 * std::numbers::pi / 180.0;

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

double circling_boat_end(const BoatControls& boat, double t0_s) {
  return t0_s + kBoatLaps * 2.0 * std::numbers::pi * boat.radius_m / boat.speed_mps;
}

Result<std::unique_ptr<waves::LocalLayer>> circling_boat_layer(const BoatControls& boat,
                                                               double t0_s, double choppiness) {
  if (Status s = validate(boat); !s.ok()) return s;
  waves::KelvinWake wake{.speed_mps = boat.speed_mps,
                         .hull_length_m = kBoatHullLength_m,
                         .peak_height_m = kBoatWakePeak_m};
  const int steps =
      static_cast<int>(std::ceil(kBoatLaps * 2.0 * std::numbers::pi / kWaypointStep_rad));
  const double dt = (circling_boat_end(boat, t0_s) - t0_s) / steps;
  wake.path.reserve(static_cast<std::size_t>(steps) + 1);
  for (int i = 0; i <= steps; ++i) {
    const double t = t0_s + i * dt;
    const waves::WakePose p = circling_pose(boat, t0_s, t);
    wake.path.push_back({.time_s = t, .x_m = p.x_m, .z_m = p.z_m});
  }
  const double side = 2.0 * (boat.radius_m + kBoatWakeMargin_m);
  waves::LayerParams params{
      .area = {.origin_m = {boat.centre_m[0] - 0.5 * side, boat.centre_m[1] - 0.5 * side},
               .size_m = side,
               .resolution = kBoatLayerResolution},
      .wakes = {std::move(wake)},
      .choppiness = choppiness};
  return waves::LocalLayer::make(std::move(params));
}

render::ObjectInstance boat_instance(std::uint32_t mesh, const waves::WakePose& pose) {
  return {.mesh = mesh,
          .model = render::model_matrix(
              {pose.x_m, kBoatCentreHeight_m, pose.z_m},
              bodies::orientation_from_heading(pose.heading_rad * 180.0 / std::numbers::pi))};
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
  layer_.reset();
  boat_ = boat;
  if (!boat.on) {
    simulator.set_local_layer(nullptr);
    return Status{};
  }
  Result<std::unique_ptr<waves::LocalLayer>> layer = circling_boat_layer(boat, time_s, choppiness_);
  if (!layer.ok()) return layer.status();
  layer_ = std::move(layer).value();
  simulator.set_local_layer(layer_);
  t0_s_ = time_s;
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
  if (!boat_.on) return Status{};
  // Past the path's end (or before its start: time ran backwards): a new path from the start of
  // the current lap, where the boat is at angle 0 again, so it drives on without a jump.
  if (time_s > circling_boat_end(boat_, t0_s_) || time_s < t0_s_) {
    const double lap_s = 2.0 * std::numbers::pi * boat_.radius_m / boat_.speed_mps;
    const double t0 = t0_s_ + std::floor((time_s - t0_s_) / lap_s) * lap_s;
    if (Status s = set_boat(boat_, t0, simulator); !s.ok()) return s;
  }
  view.objects.push_back(boat_instance(0, circling_pose(boat_, t0_s_, time_s)));
  return Status{};
}

}  // namespace ocean::cli::view
