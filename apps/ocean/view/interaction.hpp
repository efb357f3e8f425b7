// view/interaction.hpp — the interaction scenes of `ocean view`: a boat that floats on the sea,
// driven round a circle by its propulsion and steering (docs/bodies.md B.8–B.11), leaving a
// Kelvin wake from its track in the local layer (docs/waves.md W.1–W.9, W.17, docs/rendering.md
// R.19), and shallows that damp the sea's short bands (W.12–W.14, R.24): lily pads (a damping
// mask) and a lagoon (a bathymetry that shoals to an island). Plain data and the library's
// types; no window, no ImGui.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "ocean/bodies.hpp"
#include "ocean/objects.hpp"
#include "ocean/render.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace ocean::cli::view {

/// The layer's grid: 512 cells over a square of side 2·radius + 2·kBoatWakeMargin_m.
inline constexpr int kBoatLayerResolution = 512;
inline constexpr double kBoatWakeMargin_m = 60.0;
/// The boat's body step, s.
inline constexpr double kBoatStep_s = 1.0 / 60;
/// The circle guidance's look-ahead distance, m (B.11).
inline constexpr double kBoatLookAhead_m = 40.0;

/// A boat driving round a circle, from +x towards +z.
struct BoatControls {
  bool on = false;
  double speed_mps = 7.0;  ///< commanded U, (0, 20]
  double radius_m = 80.0;  ///< of the circle, [10, 500] (round the lagoon's island)
  std::array<double, 2> centre_m{0.0, 0.0};
};
/// invalid_argument naming the control for a speed or radius outside its range or NaN.
Status validate(const BoatControls& boat);

/// The point on the circle at angle ω·(t − t0), ω = U/r, started at angle 0, (cx + r, cz), at
/// t0, heading along the tangent (angle + 90°, degrees from +x towards +z): the course the boat
/// is steered onto.
waves::WakePose circling_pose(const BoatControls& boat, double t0_s, double time_s);

/// The heading that steers a boat at (x, z) onto the circle (B.11, line-of-sight guidance): the
/// tangent at the boat's angle about the centre, turned inwards by atan((ρ − r)/Δ), ρ its distance
/// from the centre and Δ = kBoatLookAhead_m. Degrees from +x towards +z.
double circle_heading_deg(const BoatControls& boat, double x_m, double z_m);

/// The built-in boat (object_flags.cpp: boat_hull(8, 3, 1.2), density 350 kg/m³) floating on a
/// surface, driven round the circle by its propulsion (B.8–B.10, the propulsion of
/// `ocean render --object boat,...,SPEED --float`) steered by circle_heading_deg, and its Kelvin
/// wake from its recorded track (W.17) in a local layer over a square centred on the circle.
class CirclingBoat {
 public:
  /// The boat on the circle at angle 0 at time_s, heading along it at the commanded speed,
  /// settled to its calm-water draught. Errors: validate(boat).
  static Result<std::unique_ptr<CirclingBoat>> make(const BoatControls& boat, double time_s,
                                                    double choppiness);
  /// Steps the body from its time towards time_s at kBoatStep_s on `surface` (the surface held
  /// for the steps of one call), recording its track; the layer is remade (sharing its table)
  /// when the track has a new waypoint. A time before the boat's, or more than 10 s after it,
  /// puts the boat back on the circle at time_s.
  Status advance(double time_s, const bodies::SurfaceQuery& surface);
  /// New controls for the running boat: it speeds up, slows down or steers onto the new circle
  /// (the layer's square follows the circle). Errors: validate(boat).
  Status set_controls(const BoatControls& boat);
  [[nodiscard]] const bodies::FloatingBody& body() const { return *body_; }
  [[nodiscard]] const bodies::Propulsion& propulsion() const { return *propulsion_; }
  [[nodiscard]] double time_s() const { return time_s_; }
  /// The layer with the boat's wake; null until the track is fast and long enough.
  [[nodiscard]] const std::shared_ptr<const waves::LocalLayer>& layer() const { return layer_; }
  /// How many wake tables the layers made so far computed (the rest were shared).
  [[nodiscard]] std::size_t tables_computed() const { return tables_computed_; }
  /// The boat's instance at its pose (the mesh frame is the hull's).
  [[nodiscard]] render::ObjectInstance instance(std::uint32_t mesh) const;

 private:
  CirclingBoat() = default;
  void restart(double time_s);
  BoatControls controls_;
  double choppiness_ = 1.0;
  std::unique_ptr<bodies::FloatingBody> body_;
  std::optional<bodies::Propulsion> propulsion_;
  std::optional<waves::WakeTrack> track_;
  std::array<double, 3> centre_m_{};  // the mesh frame's point that is the body's centre
  bodies::BodyState settled_;         // at rest in calm water, heading 0
  double time_s_ = 0.0;
  std::shared_ptr<const waves::LocalLayer> layer_;
  waves::LayerParams params_;
  std::size_t tables_computed_ = 0;
};

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
  /// Before each draw: the boat advanced to time_s on the simulator's surface (its last
  /// published frame), a new layer with its wake set on the simulator (whose composited local
  /// surface Scene::step hands to the renderer from the next step on), the boat's instance in
  /// view.objects (cleared without a boat).
  Status update(double time_s, Simulator& simulator, render::View& view);

 private:
  InteractionScene() = default;
  double choppiness_ = 1.0;
  std::unique_ptr<CirclingBoat> boat_;
};

}  // namespace ocean::cli::view
