// ocean/world.hpp — what moves on and with the sea: objects placed in the world, floating as
// rigid bodies (ocean/bodies.hpp) when asked, driven by their propulsion along a straight course
// or round a circle (B.8–B.11), the Kelvin wakes their tracks leave (W.17), and the local layer
// (ocean/waves.hpp) that holds those wakes with the caller's fixed wakes and waveforms. One call,
// World::advance_to(t), steps it all and hands the layer to the simulator the picture is made of
// (Simulator::set_local_layer); every front end (`ocean render`, `ocean view`, `ocean query`,
// `ocean bake`) drives its objects and its layer through it. The renderer reads the objects'
// poses; their meshes stay the renderer's (ocean/objects.hpp).
//
// Conventions (docs/conventions.md, docs/bodies.md): SI units, world Y up, the mean sea level at
// y = 0; headings in degrees from +x towards +z; quaternions (w, x, y, z). An object's hull is
// given in its own frame (the frame its meshes are drawn in); its pose maps that frame to the
// world: p_world = R(q)·p + x.
//
// Threading: one thread drives a World and the simulator it reads and feeds.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ocean/bodies.hpp"
#include "ocean/core.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace ocean::world {

/// The built-in objects (docs/bodies.md B.6; each metacentrically stable at its density).
enum class Shape : std::uint8_t {
  box,   ///< 2 × 1 × 2 m
  buoy,  ///< a spar buoy of radius 0.8 m, 1 m tall
  boat,  ///< the procedural boat: 8 m long, 3 m beam, 1.2 m deep, bow at +x
};
/// The shape's hull, centred on its centre of volume.
Result<bodies::Hull> shape_hull(Shape shape);
/// The deck, bulwark, cabin and windows of Shape::boat, in its hull's frame (bodies::boat_topside).
Result<bodies::BoatTopside> boat_topside();
/// Densities of the built-in objects and of other hulls (a glTF mesh) when they float, kg/m³.
inline constexpr double kBoxDensity_kgpm3 = 500.0, kBuoyDensity_kgpm3 = 400.0,
                        kBoatDensity_kgpm3 = 350.0, kMeshDensity_kgpm3 = 500.0;
double shape_density_kgpm3(Shape shape);

/// A triangle mesh's positions and indices (3 per triangle), as a renderer holds them.
struct MeshView {
  std::span<const std::array<float, 3>> positions;
  std::span<const std::uint32_t> indices;
};
/// The meshes as one hull: positions merged where they are equal (glTF splits vertices at normal
/// and texture seams), degenerate triangles dropped. Not validated: FloatingBody refuses a hull
/// that is not closed.
bodies::Hull welded_hull(std::span<const MeshView> meshes);

/// The wake's peak height per hull length of a driven object whose hull has no thin-ship
/// description (thin_hull_of finds no draught): a fast motor boat's 0.05·L.
inline constexpr double kDefaultWakePeakPerLength = 0.05;
/// The propulsion of a driven object (B.8–B.10), sized from its body: a thrust of up to half its
/// weight (a fast motor boat's: 200 kW at 7 m/s for the built-in boat) acting at 0.9 of the
/// hull's aft extent, at the height of the centre of mass (the drag alone trims it), the speed
/// loop's τ_u = 2.5 s (98 % of a new speed in 6τ_u = 15 s), a steering moment of up to I_ψ·0.5
/// rad/s² with τ_ψ = 2 s.
bodies::PropulsionParams propulsion_for(const bodies::BodyParams& body, double gravity_mps2 = 9.81);
/// The hull as a thin ship (docs/waves.md W.23): its half-breadth (half its width across z) on a
/// 64 × 16 grid from stern to bow and from the still-water line down to the keel, the line where
/// the water displaced by the level hull weighs mass_kg. nullopt for a hull with no length or
/// that would not float.
std::optional<waves::ThinHull> thin_hull_of(const bodies::Hull& hull, double mass_kg,
                                            double water_density_kgpm3 = 1025.0);
/// The track of a driven object (W.17): its hull's length along x as L, its widest breadth as
/// the foam's beam (W.20–W.21), its thin hull (thin_hull_of) for the wake's height (W.24; without
/// one kDefaultWakePeakPerLength·L), a waypoint every 0.5 s, 8 kept.
waves::WakeTrackParams wake_track_for(const bodies::BodyParams& body,
                                      double water_density_kgpm3 = 1025.0);

/// A circle a driven object is steered round, from +x towards +z (B.11).
struct Circle {
  std::array<double, 2> centre_m{0.0, 0.0};  ///< (x, z), finite
  double radius_m = 80.0;                    ///< r, finite and > 0
  double look_ahead_m = 40.0;                ///< Δ of the line-of-sight guidance, > 0
};
/// The point on the circle at angle ω·(t − t0), ω = U/r, started at angle 0, (cx + r, cz), at
/// t0, heading along the tangent (angle + 90°): the course a boat at speed U is steered onto.
waves::WakePose circling_pose(const Circle& circle, double speed_mps, double t0_s, double time_s);
/// The heading that steers an object at (x, z) onto the circle (B.11, line-of-sight guidance):
/// the tangent at its angle about the centre, turned inwards by atan((ρ − r)/Δ), ρ its distance
/// from the centre. Degrees from +x towards +z.
double circle_heading_deg(const Circle& circle, double x_m, double z_m);

/// One object.
struct ObjectDesc {
  /// Names the object in messages ("--object boat"); empty: "objects[i]".
  std::string name;
  /// The object's hull in its own frame: closed (bodies::validate) when the world floats; unused
  /// otherwise.
  bodies::Hull hull;
  double density_kgpm3 = kMeshDensity_kgpm3;  ///< of the solid hull when it floats
  /// Where the origin of the object's frame is at the start, m (ignored with `circle`: a
  /// circling object starts on its circle at its calm-water draught).
  std::array<double, 3> position_m{};
  double heading_deg = 0.0;  ///< the object's +x axis, turned from +x towards +z
  /// The commanded speed, m/s, finite and ≥ 0: above 0 the object is driven by its propulsion
  /// (propulsion_for) along heading_deg from rest at the start time, and its track leaves a
  /// Kelvin wake (wake_track_for). Needs WorldParams::floating.
  double speed_mps = 0.0;
  /// Driven round this circle instead (speed_mps > 0): the object starts under way on it, at
  /// angle 0 and the commanded speed, settled to its calm-water draught and trim.
  std::optional<Circle> circle;
};

/// The surface the floating bodies are stepped against.
enum class BodySea : std::uint8_t {
  /// A CPU simulator of the configuration, the World's own (displacement only, no far-field
  /// noise), simulated from the start time at the first of each advance_to's body steps and
  /// every second one after: the bodies see the sea without the local layer.
  own,
  /// The simulator given to advance_to, as it was last published (the caller steps it): the
  /// bodies ride on the sea they are drawn on, local layer (their own wakes) included.
  caller,
};

struct WorldParams {
  std::vector<ObjectDesc> objects;
  /// The objects float as rigid bodies on the sea; otherwise they stay where they are placed.
  bool floating = false;
  BodySea body_sea = BodySea::own;
  /// The caller's local layer: wakes of given paths, waveforms and the square they are drawn in,
  /// built by make() (LocalLayer::make); the driven objects' wakes are added to it. Unset: none.
  std::optional<waves::LayerParams> layer;
  /// The square the driven wakes are drawn in without a `layer`; unset: a kDrivenArea_m square
  /// laid round the first driven object when its first wake appears (its centre a sixth of the
  /// side behind it, so the wake trails into it), laid again whenever the object has gone a
  /// sixteenth of its side from there, its soft edge kDrivenAreaEdgeFraction and the driven wakes
  /// faded over a quarter side behind their objects (docs/waves.md W.22).
  std::optional<waves::LocalArea> wake_area;
  double choppiness = 1.0;  ///< λ of the driven wakes' horizontal displacement without a `layer`
  double start_time_s = 0.0;  ///< the time the objects are at their start
};
/// The waterline foam's coverage round a floating object at rest (docs/waves.md W.20): half of
/// a driven hull's, the foam of waves breaking against it now and then.
inline constexpr double kRestFoamCoverage = 0.5;
/// The side and grid of the square laid round a driven object (WorldParams::wake_area unset):
/// 0.3 m cells, 12 transverse wavelengths of a boat at 5 m/s behind it.
inline constexpr double kDrivenArea_m = 320.0;
inline constexpr int kDrivenAreaResolution = 1024;
/// The soft edge of that square (waves::LocalArea::edge_fraction): a quarter of its side, so the
/// layer fades into the sea over 80 m and no border shows (docs/waves.md W.22).
inline constexpr double kDrivenAreaEdgeFraction = 0.25;
/// The bodies' fixed step, s; the own sea is simulated every second step.
inline constexpr double kBodyStep_s = 1.0 / 60;
/// Calm-water settling of a circling object before it starts, s.
inline constexpr double kSettle_s = 4.0;

/// Where an object's frame is: p_world = R(orientation)·p + position_m.
struct Pose {
  std::array<double, 3> position_m{};
  bodies::Quat orientation{1.0, 0.0, 0.0, 0.0};
};

/// What advance_to watches while it steps.
struct AdvanceHooks {
  /// Set (by a signal handler): advance_to stops between two body steps with
  /// ErrorCode::cancelled; the objects keep the time and poses they reached.
  const std::atomic<bool>* cancel = nullptr;
  /// Called after each body step with the number taken so far in this call.
  std::function<void(long long steps)> on_step;
};

class World {
 public:
  /// Builds a body per object (floating), their propulsion and wake tracks (driven ones), the
  /// caller's layer and, with BodySea::own, a CPU simulator of `config` at start_time_s. Errors,
  /// naming the object: a hull that cannot float (" cannot float: ..."), a speed without
  /// floating, a bad circle; LocalLayer::make's for the layer; the simulator's for a bad
  /// configuration.
  static Result<std::unique_ptr<World>> make(WorldParams params, const SimulationConfig& config);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// The body steps advance_to(time_s) takes from time_s(): one per kBodyStep_s, the last
  /// within half a step of time_s; 0 without floating bodies or for an earlier time.
  [[nodiscard]] long long steps_until(double time_s) const;
  /// Steps the floating bodies from time_s() to time_s (steps_until) against the BodySea, driven
  /// ones by their helm (the straight course or the circle guidance) recording their tracks;
  /// then the local layer: the driven wakes added to the caller's layer, remade (sharing its
  /// wake tables) when a wake changed, the caller's layer again when no driven object makes a
  /// wake. Hands `sea` the layer when it holds another (set_local_layer) and returns true then
  /// (a caller that already simulated this frame simulates it again to composite it).
  Result<bool> advance_to(double time_s, Simulator& sea, const AdvanceHooks& hooks = {});
  /// Puts every circling object back on its circle at angle 0 at time_s, under way, its track
  /// restarted and its wake gone; the others keep their state. The World's time becomes time_s.
  void restart(double time_s);
  /// A new speed and circle for the circling object `index`: it speeds up, slows down or steers
  /// onto the new circle from where it is. invalid_argument for a speed that is not finite and
  /// positive, a bad circle or an object that does not circle.
  Status set_course(std::size_t index, double speed_mps, const Circle& circle);
  /// A new square for the driven wakes (WorldParams::wake_area): the layer is remade at the next
  /// advance_to when it differs. invalid_argument from waves::validate(LocalArea).
  Status set_wake_area(const waves::LocalArea& area);

  [[nodiscard]] double time_s() const { return time_s_; }
  [[nodiscard]] bool floating() const { return params_.floating; }
  [[nodiscard]] std::size_t object_count() const;
  /// The pose of object `index`'s frame at time_s().
  [[nodiscard]] Pose pose(std::size_t index) const;
  /// The body of a floating object, or null.
  [[nodiscard]] const bodies::FloatingBody* body(std::size_t index) const;
  /// The propulsion of a driven object, or null.
  [[nodiscard]] const bodies::Propulsion* propulsion(std::size_t index) const;
  /// Appends the Kelvin wake of every driven object whose track is fast and long enough (W.17).
  void driven_wakes(std::vector<waves::KelvinWake>& out) const;
  /// Appends the waterline foam (docs/waves.md W.20) of every floating object that is not
  /// driven, at its present position and heading: its hull's length along x and breadth across z.
  void rest_footprints(std::vector<waves::Footprint>& out) const;
  /// The layer the sea is handed: the caller's with the driven wakes, or the caller's, or null.
  [[nodiscard]] const std::shared_ptr<const waves::LocalLayer>& local_layer() const;
  /// How many wake tables the driven layers made so far computed (the rest were shared).
  [[nodiscard]] std::size_t tables_computed() const { return tables_computed_; }

  struct Object;

 private:
  World() = default;
  Status step_bodies(double time_s, Simulator& sea, const AdvanceHooks& hooks);
  Status update_layer(const Simulator& sea);
  WorldParams params_;
  double gravity_mps2_ = 9.81;
  std::vector<Object> objects_;
  std::unique_ptr<Simulator> own_sea_;
  double time_s_ = 0.0;
  std::shared_ptr<const waves::LocalLayer> given_layer_;   // built from params_.layer
  std::shared_ptr<const waves::LocalLayer> driven_layer_;  // given_layer_ + the driven wakes
  std::optional<waves::LocalArea> driven_area_;            // laid round the first driven object
  std::vector<waves::KelvinWake> wakes_;                   // scratch
  std::vector<waves::Footprint> footprints_;               // scratch
  std::size_t tables_computed_ = 0;
};

}  // namespace ocean::world
