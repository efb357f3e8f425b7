// view/interaction.hpp — the interaction scenes of `ocean view`: a boat that floats on the sea,
// driven round a circle by its propulsion and steering (docs/bodies.md B.8–B.11), leaving a
// Kelvin wake from its track in the local layer (docs/waves.md W.1–W.9, W.17, docs/rendering.md
// R.19) — a world of ocean/world.hpp made from the panel's controls — and shallows that damp
// the sea's short bands (W.12–W.14, R.24; shallows.hpp): lily pads (a damping mask) and a lagoon
// (a bathymetry that shoals to an island, with its surf and beach). Plain data and the library's
// types; no window, no ImGui.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "ocean/objects.hpp"
#include "ocean/render.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"
#include "ocean/world.hpp"
#include "shallows.hpp"

namespace ocean::cli::view {

/// The layer's grid: 512 cells over a square of side 2·radius + 2·kBoatWakeMargin_m.
inline constexpr int kBoatLayerResolution = 512;
inline constexpr double kBoatWakeMargin_m = 60.0;
/// A longer jump of the view's time than this, s, or one backwards, restarts the boat on its
/// circle (World::restart).
inline constexpr double kBoatMaxJump_s = 10.0;

/// A boat driving round a circle, from +x towards +z.
struct BoatControls {
  bool on = false;
  double speed_mps = 7.0;  ///< commanded U, (0, 20]
  double radius_m = 80.0;  ///< of the circle, [10, 500] (round the lagoon's island)
  std::array<double, 2> centre_m{0.0, 0.0};
};
/// invalid_argument naming the control for a speed or radius outside its range or NaN.
Status validate(const BoatControls& boat);

/// The world of the boat: the built-in boat (world::Shape::boat) floating on the sea the view
/// draws (world::BodySea::caller), driven round the circle by its propulsion (the propulsion of
/// `ocean render --object boat,...,SPEED --float`), starting on it at time_s, and its Kelvin
/// wake in a layer over a square centred on the circle. Errors: validate(boat).
Result<std::unique_ptr<world::World>> make_boat_world(const BoatControls& boat, double time_s,
                                                      const SimulationConfig& config);

using cli::kShallowsLabels;
using cli::parse_shallows;
using cli::Shallows;
using cli::shallows_damping;

/// The radius about the scene's centre that shows what the scenes hold, m: the boat's circle and
/// its hull (radius + 10 m), the lily pads' disc and its edge (60 m), the lagoon's island and its
/// shoal to 10 m of depth (100 m); the largest of those on, 0 for none.
double scene_radius_m(const BoatControls& boat, Shallows shallows);

/// A camera that frames the disc of `radius_m` on the sea about `centre_m`, seen along the
/// horizontal direction `look` (x, z; not both 0): looking down 25° at the centre from the
/// distance at which the disc spans 80 % of the narrower of the picture's two angles, for a
/// vertical field of view `fov_y_rad` and width/height `aspect`. {eye, target}, world metres.
std::array<std::array<double, 3>, 2> framing_camera(std::array<double, 2> centre_m, double radius_m,
                                                    std::array<double, 2> look, double fov_y_rad,
                                                    double aspect);

/// The scenes in a running view: the floating boat and its wake, and the shallows' damping,
/// handed to a renderer.
class InteractionScene {
 public:
  /// Uploads the built-in boat's mesh with renderer.set_meshes (the view's only mesh).
  static Result<std::unique_ptr<InteractionScene>> make(render::Renderer& renderer,
                                                        const SimulationConfig& config);
  /// The boat from time_s on (a running boat takes the new controls where it is), or no boat
  /// and no layer on the simulator.
  Status set_boat(const BoatControls& boat, double time_s, Simulator& simulator);
  /// A shallows scene centred at `centre` for the cascades of `config` (none removes it).
  Status set_shallows(Shallows scene, std::array<double, 2> centre_m,
                      const SimulationConfig& config, render::Renderer& renderer);
  /// Before each draw: the boat's world advanced to time_s on the simulator's surface (its last
  /// published frame; restarted on the circle after a jump in time, kBoatMaxJump_s), a new layer
  /// with its wake set on the simulator (whose composited local surface Scene::step hands to the
  /// renderer from the next step on), the boat's instance in view.objects (cleared without a
  /// boat).
  Status update(double time_s, Simulator& simulator, render::View& view);

 private:
  InteractionScene() = default;
  SimulationConfig config_;
  std::uint32_t boat_meshes_ = 1;  ///< the boat's meshes, 0 … boat_meshes_ − 1 (built_in_meshes)
  std::unique_ptr<world::World> boat_;
};

}  // namespace ocean::cli::view
