// ocean/bodies.hpp — rigid bodies floating on the simulated sea: a closed triangle hull moved by
// gravity, the hydrostatic pressure of the water over its submerged part (Archimedes, integrated
// exactly over the hull clipped at the surface), drag and, for a driven body, a propeller's thrust
// and a steering moment (Propulsion, B.8–B.10), integrated at a fixed step. The water
// surface comes from batched height queries (Simulator::heights_at: the displaced surface the
// renderer draws, found by inverting the horizontal displacement), on the CPU: no GPU read-back.
//
// Conventions (docs/conventions.md, docs/bodies.md): SI units, world Y up, the mean sea level at
// y = 0. A hull is given in the body frame, whose origin is the body's centre of mass; the pose
// maps it to the world: p_world = R(q)·p_body + x. Quaternions are (w, x, y, z), unit length.
// Headings are degrees from +x towards +z (as ocean/waves.hpp). Equations (B.n): docs/bodies.md.
//
// Threading: a FloatingBody is driven from one thread; the surface query it calls must be safe to
// call from that thread (Simulator's queries are, while no step is being published).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/sim.hpp"

namespace ocean::bodies {

using Vec3 = std::array<double, 3>;
using Quat = std::array<double, 4>;  ///< (w, x, y, z)
using Mat3 = std::array<double, 9>;  ///< row-major

/// A closed, consistently oriented triangle mesh: counter-clockwise seen from outside (normals
/// point out of the body), every edge shared by exactly two triangles. Metres.
struct Hull {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};
/// invalid_argument for an empty hull, a non-finite vertex, an index out of range, a degenerate
/// hull (volume ≤ 0: inside out or open), or more than 1e6 triangles.
Status validate(const Hull& hull);

/// Volume, centre and inertia of the hull as a solid of uniform density 1 kg/m³ (B.1): the
/// signed tetrahedra from the origin to each triangle (Tonon 2004).
struct MassProperties {
  double volume_m3 = 0.0;
  Vec3 centroid_m{};  ///< centre of volume
  Mat3 inertia{};     ///< about the centroid, for density 1 (multiply by the density), kg·m²
};
MassProperties mass_properties(const Hull& hull);
/// The hull moved so that `origin` becomes (0, 0, 0).
Hull translated(Hull hull, const Vec3& origin);

/// Built-in hulls, centred on their centre of volume. invalid_argument for sizes that are not
/// finite and positive (and a segment count outside [3, 256] for the buoy).
/// A box of sides (x, y, z), each face split into n×n squares so that height queries sample the
/// surface every side/n (n in [1, 64]).
Result<Hull> box_hull(const Vec3& size_m, int subdivisions = 4);
/// A spar buoy: a vertical cylinder of radius r and height h, closed by flat caps.
Result<Hull> buoy_hull(double radius_m, double height_m, int segments = 24);
/// A procedural boat: length L along +x (bow at +x), beam B, depth D; a wall-sided hull whose
/// half-breadth is B/2·(1 − |2x/L|^p) at the deck, narrowing towards the keel (B.6).
Result<Hull> boat_hull(double length_m, double beam_m, double depth_m);
/// What stands on that boat's deck, in the frame boat_hull returns (centred on the hull's centre
/// of volume): deck planking, a bulwark along the sheer and across the transom, a cabin amidships
/// with a raked windscreen, and its windows — closed meshes to draw with the hull. They stay
/// above the water as the boat floats, so the buoyancy and its mass (the hull's alone) do not
/// see them. invalid_argument as boat_hull.
struct BoatTopside {
  Hull deck;
  Hull bulwark;
  Hull cabin;
  Hull windows;
};
Result<BoatTopside> boat_topside(double length_m, double beam_m, double depth_m);

/// The water the bodies float in.
struct Water {
  double density_kgpm3 = 1025.0;  ///< ρ, sea water; (0, 1e5]
  double gravity_mps2 = 9.81;     ///< g, (0, 100]
};
Status validate(const Water& water);

/// Drag on each submerged facet against still water (B.4): a force along the facet's normal of
/// −ρ·A·(linear_mps·v_n + ½·quadratic·|v_n|·v_n), v_n the facet's velocity along its normal.
struct DragParams {
  double linear_mps = 0.5;  ///< k_l ≥ 0; heave damping ratio k_l/(2√(g·draught)) (B.4)
  double quadratic = 1.0;   ///< C_d ≥ 0, a flat plate's order of magnitude
};
Status validate(const DragParams& drag);

/// The pose and motion of a body.
struct BodyState {
  Vec3 position_m{};               ///< x: the centre of mass, world
  Quat orientation{1.0, 0, 0, 0};  ///< q: body → world, unit
  Vec3 velocity_mps{};             ///< v of the centre of mass
  Vec3 angular_velocity_radps{};   ///< ω, world frame
};
/// invalid_argument for non-finite values or an orientation whose norm is not 1 within 1e-6.
Status validate(const BodyState& state);
/// The orientation of a heading (degrees from +x towards +z), level.
Quat orientation_from_heading(double heading_deg);
/// R(q)·v.
Vec3 rotate(const Quat& q, const Vec3& v);

/// What a body is made of. The hull's origin is the centre of mass.
struct BodyParams {
  Hull hull;
  double mass_kg = 1.0;  ///< > 0, finite
  Mat3 inertia_kgm2{};   ///< about the centre of mass, body frame: symmetric, positive definite
  DragParams drag;
};
/// invalid_argument naming the field.
Status validate(const BodyParams& params);
/// A solid of uniform density: the hull moved to its centroid, mass ρ_b·V and the solid's
/// inertia (B.1). invalid_argument for a bad hull or a density that is not finite and positive.
Result<BodyParams> solid_body(const Hull& hull, double density_kgpm3, const DragParams& drag = {});

/// The batched height query the bodies read the surface from: out[i] for xz[i], as
/// Simulator::heights_at (the surface height above world (x, z) after displacement).
using SurfaceQuery =
    std::function<void(std::span<const std::array<double, 2>> xz, std::span<HeightSample> out)>;
/// The simulator's heights_at (the surface of its last published frame). The simulator must
/// outlive the query.
SurfaceQuery surface_of(const Simulator& simulator);
/// Calm water: height 0 everywhere.
SurfaceQuery calm_surface();

/// A force and a moment applied to a body besides the water and gravity (propulsion, a tow),
/// world frame, the moment about the centre of mass.
struct Wrench {
  Vec3 force_n{};
  Vec3 torque_nm{};
};

/// The forces of one evaluation.
struct Forces {
  Vec3 force_n{};                    ///< total: gravity + pressure + drag, world
  Vec3 torque_nm{};                  ///< about the centre of mass, world
  Vec3 buoyancy_n{};                 ///< the pressure force alone
  Vec3 drag_n{};                     ///< the drag force alone (B.4)
  double submerged_volume_m3 = 0.0;  ///< buoyancy_n.y/(ρg): the volume Archimedes weighs
  double wetted_area_m2 = 0.0;       ///< area of the hull below the surface
};

class FloatingBody {
 public:
  /// Validates the parameters and the initial state (invalid_argument naming the field).
  static Result<FloatingBody> make(BodyParams params, const BodyState& initial,
                                   const Water& water = {});

  /// Forces and torque on the body in its present state: one batched query at the hull's
  /// vertices, each triangle clipped at the surface (the depth linear along it), the pressure
  /// ρ·g·depth integrated exactly over the submerged parts (B.2, B.3), drag (B.4) and gravity.
  /// Allocates only on the first call (the scratch arrays are kept).
  Forces evaluate(const SurfaceQuery& surface);
  /// One step of dt seconds by semi-implicit (symplectic) Euler (B.5): velocities from the
  /// forces of the present state, then positions and orientation from the new velocities. The
  /// surface should be the one at the present time. dt must be finite and positive
  /// (invalid_argument), and a few times shorter than the body's heave period 2π·√(m/(ρgA_w)).
  /// `external` is added to the forces of the present state (B.8–B.10's propulsion).
  Status step(const SurfaceQuery& surface, double dt_s, const Wrench& external = {});

  [[nodiscard]] const BodyState& state() const { return state_; }
  /// Puts the body at a new pose and motion (validate(BodyState): invalid_argument).
  Status set_state(const BodyState& state);
  [[nodiscard]] const BodyParams& params() const { return params_; }
  [[nodiscard]] const Water& water() const { return water_; }
  /// The forces of the last step (or evaluate).
  [[nodiscard]] const Forces& forces() const { return forces_; }
  /// Kinetic energy ½m|v|² + ½ω·Iω, J.
  [[nodiscard]] double kinetic_energy_j() const;
  /// The hull's vertices in the world at the present pose.
  void world_vertices(std::vector<Vec3>& out) const;

 private:
  FloatingBody() = default;
  BodyParams params_;
  Water water_;
  BodyState state_;
  Mat3 inverse_inertia_{};  // body frame
  Forces forces_;
  std::vector<Vec3> world_;
  std::vector<std::array<double, 2>> xz_;
  std::vector<HeightSample> heights_;
};

/// The body's heading: its +x axis (the bow of the built-in boat) projected on the horizontal,
/// degrees from +x towards +z in (−180, 180]; 0 for a body standing on its bow.
double heading_deg(const BodyState& state);

/// A propeller and a steering moment that drive a floating body (B.8–B.10). The thrust pushes
/// along the body's heading, horizontally, at thrust_point_m; the steering moment turns it about
/// the vertical. Gains scale with the body's mass and yaw inertia, so the time constants hold
/// for any size.
struct PropulsionParams {
  double max_thrust_n = 1e4;  ///< T_max > 0: the largest forward thrust (the thrust is ≥ 0)
  /// Where the thrust acts, body frame, m (finite): e.g. the propeller, aft and below the
  /// waterline; the centre of mass (0, 0, 0) gives no pitching moment.
  Vec3 thrust_point_m{};
  double speed_time_s = 4.0;       ///< τ_u > 0: the speed loop's time constant (B.9)
  double max_yaw_moment_nm = 1e4;  ///< N_max > 0: the largest steering moment
  double heading_time_s = 2.0;     ///< τ_ψ > 0: the heading loop's time constant (B.10)
};
/// invalid_argument naming the field ("propulsion max_thrust_n = -1 ...").
Status validate(const PropulsionParams& params);

/// What the helm asks for.
struct HelmCommand {
  double speed_mps = 0.0;    ///< U_c ≥ 0, forward speed over the ground, finite
  double heading_deg = 0.0;  ///< ψ_c, degrees from +x towards +z, finite
  /// ψ̇_c, degrees per second (finite): the rate ψ_c itself turns at, 0 on a straight course;
  /// on a turn it spares the heading loop the error a pure damping of ψ̇ would need.
  double turn_rate_degps = 0.0;
};
/// invalid_argument naming the field.
Status validate(const HelmCommand& command);

/// The speed and heading loops of one body (B.9, B.10): plain state (the loops' integrals), no
/// allocation, one thread.
class Propulsion {
 public:
  static Result<Propulsion> make(const PropulsionParams& params);
  /// The thrust and steering moment for the body's present state and the command, advancing the
  /// speed loop's integral by dt_s (call once per body step, before FloatingBody::step). The
  /// thrust compensates the drag of the body's last step (FloatingBody::forces).
  /// invalid_argument for a bad command or dt.
  Result<Wrench> control(const FloatingBody& body, const HelmCommand& command, double dt_s);
  /// The thrust of the last control, N (≥ 0).
  [[nodiscard]] double thrust_n() const { return thrust_n_; }
  /// The steering moment of the last control about the vertical (turning +x towards +z), N·m.
  [[nodiscard]] double yaw_moment_nm() const { return yaw_moment_nm_; }
  [[nodiscard]] const PropulsionParams& params() const { return params_; }
  /// The loops as if the body had been going steadily at speed_mps (forward) on its course: the
  /// speed loop's integral 2τ_u·speed_mps, the heading loop's 0. Start a body that is already
  /// moving with it; a body at rest starts from reset(0), as made.
  void reset(double speed_mps = 0.0);

 private:
  Propulsion() = default;
  PropulsionParams params_;
  double integral_mps_s_ = 0.0;          // ∫(U_c − u) dt
  double heading_integral_rad_s_ = 0.0;  // ∫(ψ_c − ψ) dt
  double thrust_n_ = 0.0, yaw_moment_nm_ = 0.0;
};

}  // namespace ocean::bodies
