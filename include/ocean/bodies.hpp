// ocean/bodies.hpp — rigid bodies floating on the simulated sea: a closed triangle hull moved by
// gravity, the hydrostatic pressure of the water over its submerged part (Archimedes, integrated
// exactly over the hull clipped at the surface) and drag, integrated at a fixed step. The water
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

/// The forces of one evaluation.
struct Forces {
  Vec3 force_n{};                    ///< total: gravity + pressure + drag, world
  Vec3 torque_nm{};                  ///< about the centre of mass, world
  Vec3 buoyancy_n{};                 ///< the pressure force alone
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
  Status step(const SurfaceQuery& surface, double dt_s);

  [[nodiscard]] const BodyState& state() const { return state_; }
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

}  // namespace ocean::bodies
