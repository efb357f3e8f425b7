// view/interaction.hpp — the interaction scenes of `ocean view`: a boat that circles and leaves
// a Kelvin wake in the local layer (docs/waves.md W.1–W.9, docs/rendering.md R.19), and shallows
// that damp the sea's short bands (W.12–W.14, R.24): lily pads (a damping mask) and a lagoon (a
// bathymetry that shoals to an island). Plain data and the library's types; no window, no ImGui.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "ocean/objects.hpp"
#include "ocean/render.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace ocean::cli::view {

/// The built-in boat's hull length (object_flags.cpp: boat_hull(8, 3, 1.2)), the wake's L.
inline constexpr double kBoatHullLength_m = 8.0;
/// How many laps one layer's path covers; the layer is made again after them.
inline constexpr int kBoatLaps = 6;
/// The layer's grid: 512 cells over a square of side 2·radius + 2·kBoatWakeMargin_m.
inline constexpr int kBoatLayerResolution = 512;
inline constexpr double kBoatWakeMargin_m = 60.0;
inline constexpr double kBoatCentreHeight_m = 0.1;
/// The wake's peak height: a fast 8 m motor boat's (0.05·L, above the library's 0.02·L default
/// for displacement hulls), so the wake shows in a moderate sea.
inline constexpr double kBoatWakePeak_m = 0.4;

/// A boat driving round a circle, from +x towards +z (circling_pose).
struct BoatControls {
  bool on = false;
  double speed_mps = 7.0;  ///< U, (0, 20]
  double radius_m = 80.0;  ///< of the circle, [10, 500] (round the lagoon's island)
  std::array<double, 2> centre_m{0.0, 0.0};
};
/// invalid_argument naming the control for a speed or radius outside its range or NaN.
Status validate(const BoatControls& boat);

/// Where the circling boat is at time t (started at angle 0, (cx + r, cz), at t0): position on
/// the circle at angle ω·(t − t0), ω = U/r, heading along the tangent (angle + 90°, degrees from
/// +x towards +z).
waves::WakePose circling_pose(const BoatControls& boat, double t0_s, double time_s);

/// The local layer of the boat from t0 for kBoatLaps laps: one Kelvin wake of hull length
/// kBoatHullLength_m whose path has a waypoint every 5° of the circle (the pattern is the steady
/// wake of the current chord, swung rigidly round the turn), over a square area centred on the
/// circle. Errors: validate(boat), and LocalLayer::make's.
Result<std::unique_ptr<waves::LocalLayer>> circling_boat_layer(const BoatControls& boat,
                                                               double t0_s, double choppiness);
/// The time the layer's path ends: t0 + kBoatLaps·2πr/U.
double circling_boat_end(const BoatControls& boat, double t0_s);

/// The boat's instance at a pose: the built-in boat's mesh frame (bow along +x, centred on its
/// centre of volume) turned to the heading, its centre kBoatCentreHeight_m above the mean sea
/// level (about where it floats in calm water).
render::ObjectInstance boat_instance(std::uint32_t mesh, const waves::WakePose& pose);

/// The shallows scenes.
enum class Shallows : int { none = 0, lily_pads = 1, lagoon = 2 };
inline constexpr std::array<const char*, 3> kShallowsLabels = {"none", "lily pads", "lagoon"};
/// "none", "lily-pads" or "lagoon"; nullopt otherwise.
std::optional<Shallows> parse_shallows(std::string_view name);

/// The damping of a scene centred at `centre` for the cascades of `config`, or nullopt for
/// Shallows::none:
/// - lily pads: a 200 m mask, 0 (the low band only) inside a disc of radius 40 m, 1 beyond 60 m,
///   smoothstep between;
/// - lagoon: a 400 m depth map, 0 m (an island) inside a radius of 50 m, deepening 1 m per 5 m
///   to 40 m (the scene of docs/images/lagoon_render.png).
Result<std::optional<waves::Damping>> shallows_damping(Shallows scene,
                                                       std::array<double, 2> centre_m,
                                                       const SimulationConfig& config);

/// The scenes in a running view: the boat's layer (made again after kBoatLaps laps or an edit)
/// and the shallows' damping, handed to a renderer.
class InteractionScene {
 public:
  /// Uploads the built-in boat's mesh with renderer.set_meshes (the view's only mesh).
  static Result<std::unique_ptr<InteractionScene>> make(render::Renderer& renderer,
                                                        const SimulationConfig& config);
  /// The boat from time_s on (its layer made now, about 0.1 s, and set on the simulator, whose
  /// composited local surface Scene::step hands to the renderer), or no boat and no layer.
  Status set_boat(const BoatControls& boat, double time_s, Simulator& simulator);
  /// A shallows scene centred at `centre` for the cascades of `config` (none removes it).
  Status set_shallows(Shallows scene, std::array<double, 2> centre_m,
                      const SimulationConfig& config, render::Renderer& renderer);
  /// Before each draw: the boat's instance in view.objects (cleared without a boat), its layer
  /// made again on the simulator past the end of its laps.
  Status update(double time_s, Simulator& simulator, render::View& view);

 private:
  InteractionScene() = default;
  double choppiness_ = 1.0;
  BoatControls boat_;
  double t0_s_ = 0.0;
  std::shared_ptr<const waves::LocalLayer> layer_;
};

}  // namespace ocean::cli::view
