// `--object FILE.glb|box|buoy|boat,X,Y,Z[,HEADING_DEG[,SPEED_MPS]]` (repeatable) and `--float`
// of `ocean render`: the objects' meshes for the renderer, their placement, and with --float the
// floating-body simulation (ocean/bodies.hpp) on a CPU simulator of the same sea from t = 0, so
// that each object sits on the waves at the time of each frame; an object given a speed is driven
// by its propulsion (B.8–B.10) along its heading and leaves a Kelvin wake from its track (W.17).
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ocean/bodies.hpp"
#include "ocean/render.hpp"
#include "ocean/waves.hpp"

namespace ocean::cli {

/// One parsed --object.
struct ObjectSpec {
  std::string kind;  ///< box, buoy, boat or a .glb/.gltf path
  std::array<double, 3> position_m{};
  double heading_deg = 0.0;
  double speed_mps = 0.0;  ///< commanded speed with --float; 0: drifts
};
/// "KIND,X,Y,Z[,HEADING_DEG[,SPEED_MPS]]": X, Z in [-1e5, 1e5] m, Y in [-1e4, 1e4] m, heading in
/// [-360, 360], speed in [0, 30] m/s; a file name ends in .glb or .gltf and holds no comma.
/// invalid_argument naming --object and the part at fault (ocean::excerpt of the text).
Result<ObjectSpec> parse_object_spec(const std::string& text);

/// Densities of the built-in objects and of glTF meshes when they float, kg/m³.
inline constexpr double kBoxDensity = 500.0, kBuoyDensity = 400.0, kBoatDensity = 350.0,
                        kMeshDensity = 500.0;
/// The wake's peak height per hull length of a driven object: a fast motor boat's 0.05·L (above
/// the library's 0.02·L for displacement hulls), so the wake shows in a moderate sea.
inline constexpr double kWakePeakPerLength = 0.05;

/// The propulsion of a driven object (B.8–B.10), sized from its body: a thrust of up to half its
/// weight (a fast motor boat's: 200 kW at 7 m/s for the built-in boat) acting at 0.9 of the
/// hull's aft extent, at the height of the centre of mass (the drag alone trims it), the speed
/// loop's τ_u = 2.5 s (98 % of a new speed in 6τ_u = 15 s), a steering moment of up to I_ψ·0.5
/// rad/s² with τ_ψ = 2 s.
bodies::PropulsionParams propulsion_for(const bodies::BodyParams& body, double gravity_mps2 = 9.81);
/// The track of a driven object (W.17): its hull's length along x as L, a peak of
/// kWakePeakPerLength·L, a waypoint every 0.5 s, 8 kept.
waves::WakeTrackParams wake_track_for(const bodies::Hull& hull);

/// The latest time `ocean render --float` integrates the objects to, s: --time of the last
/// frame (--time + (--frames − 1)/--fps) beyond it is a usage error. The bodies start at t = 0
/// and step 1/60 s, the sea under them simulated every second step: 600 s is 36 000 body steps
/// and 18 000 steps of the sea, whose cost dominates. Measured with a box on the moderate
/// preset's four 256² cascades: about 4 ms of CPU per step of the sea, so the longest span is
/// about 80 s of CPU (a minute or two on two cores), and four times that on 512² grids; beyond
/// it a picture would be a wait of many minutes. The same bound as --warmup's.
inline constexpr double kMaxFloatTime_s = 600.0;
/// The shortest integration that shows its progress (a bar on a terminal, a summary line in a
/// log), s of simulated time: a minute, about 8 s of CPU on the moderate preset. Shorter spans,
/// the default --time 20 among them, print nothing.
inline constexpr double kFloatProgressSpan_s = 60.0;

/// The objects of a render: meshes for Renderer::set_meshes and, per object, its instances.
class SceneObjects {
 public:
  /// Builds the meshes (loading glTF files) and, with `floating`, a body per object and a CPU
  /// simulator of `config` for the surface. Errors: the file's (load_gltf), a glTF that is not
  /// a closed mesh with --float, a bad configuration.
  static Result<std::unique_ptr<SceneObjects>> make(const std::vector<ObjectSpec>& specs,
                                                    bool floating, const SimulationConfig& config);
  [[nodiscard]] const std::vector<render::Mesh>& meshes() const { return meshes_; }
  /// Advances the bodies (with --float) to time_s from where they are (from t = 0 on the first
  /// call) at a fixed step of 1/60 s, the surface simulated every second step, then writes the
  /// instances of every object at their poses into `out`. A span of kFloatProgressSpan_s or more
  /// shows a progress bar on stderr ("floating bodies (1/60 s steps)"). When `cancel` is set (by
  /// a signal handler, StopSignals) it stops between two steps with ErrorCode::cancelled and
  /// `out` untouched; the bodies keep the pose they reached.
  Status place(double time_s, std::vector<render::ObjectInstance>& out,
               const std::atomic<bool>* cancel = nullptr);
  /// Appends the Kelvin wake of every driven object that moves fast enough (W.17) to `out`.
  void wakes(std::vector<waves::KelvinWake>& out) const;
  /// Where the first driven object is (x, z) and which way it heads (degrees), or nullopt.
  [[nodiscard]] std::optional<std::array<double, 3>> first_driven() const;

 private:
  struct Object {
    std::vector<std::uint32_t> meshes;
    std::array<double, 3> position_m{};
    std::array<double, 4> orientation{1, 0, 0, 0};
    std::array<double, 3> centre_m{};  // the mesh frame's point that is the body's centre
    std::unique_ptr<bodies::FloatingBody> body;
    std::optional<bodies::Propulsion> propulsion;  // a driven object
    bodies::HelmCommand helm;
    std::optional<waves::WakeTrack> track;
  };
  std::vector<render::Mesh> meshes_;
  std::vector<Object> objects_;
  std::unique_ptr<Simulator> surface_;  // with --float
  double time_s_ = 0.0;
};

}  // namespace ocean::cli
