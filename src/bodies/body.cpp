// FloatingBody: validation of the parameters and states, the pose helpers, the surface queries
// and the semi-implicit (symplectic) Euler step (B.5).
//
// This work is based on:
//   E. Hairer, C. Lubich, G. Wanner, "Geometric Numerical Integration", 2nd ed., Springer 2006,
//   §I.1.2 — the symplectic Euler method: velocities first, positions from the new velocities;
//   its energy error stays bounded (oscillates, O(dt)) instead of drifting.
//   D. Baraff, "Physically Based Modeling: Rigid Body Simulation", SIGGRAPH course notes, 2001 —
//   the world-frame inertia R·I·Rᵀ, the gyroscopic term ω × Iω, q̇ = ½(0, ω)·q.
#include <cmath>
#include <numbers>
#include <string>

#include "body_math.hpp"
#include "ocean/bodies.hpp"

namespace ocean::bodies {

namespace {

Status finite3(const std::string& name, const Vec3& v) {
  for (double x : v)
    if (!std::isfinite(x)) return invalid_argument(name + " is not finite");
  return {};
}

}  // namespace

Status validate(const Water& water) {
  if (Status s = require_in_range("water density_kgpm3", water.density_kgpm3, 1e-9, 1e5); !s.ok())
    return s;
  return require_in_range("water gravity_mps2", water.gravity_mps2, 1e-9, 100.0);
}

Status validate(const DragParams& drag) {
  if (Status s = require_non_negative("drag linear_mps", drag.linear_mps); !s.ok()) return s;
  return require_non_negative("drag quadratic", drag.quadratic);
}

Status validate(const BodyState& state) {
  if (Status s = finite3("body position_m", state.position_m); !s.ok()) return s;
  if (Status s = finite3("body velocity_mps", state.velocity_mps); !s.ok()) return s;
  if (Status s = finite3("body angular_velocity_radps", state.angular_velocity_radps); !s.ok())
    return s;
  const Quat& q = state.orientation;
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(std::abs(n - 1.0) <= 1e-6))
    return invalid_argument("body orientation: the quaternion's norm " + format_number(n) +
                            " is not 1");
  return {};
}

Status validate(const BodyParams& params) {
  if (Status s = validate(params.hull); !s.ok()) return s;
  if (Status s = require_positive("body mass_kg", params.mass_kg); !s.ok()) return s;
  if (Status s = validate(params.drag); !s.ok()) return s;
  const Mat3& i = params.inertia_kgm2;
  for (double v : i)
    if (!std::isfinite(v)) return invalid_argument("body inertia_kgm2 is not finite");
  const bool symmetric = std::abs(i[1] - i[3]) <= 1e-9 * (std::abs(i[1]) + std::abs(i[0])) &&
                         std::abs(i[2] - i[6]) <= 1e-9 * (std::abs(i[2]) + std::abs(i[0])) &&
                         std::abs(i[5] - i[7]) <= 1e-9 * (std::abs(i[5]) + std::abs(i[4]));
  // Sylvester's criterion: the leading principal minors are positive.
  const bool positive = i[0] > 0.0 && i[0] * i[4] - i[1] * i[3] > 0.0 && determinant(i) > 0.0;
  if (!symmetric || !positive)
    return invalid_argument("body inertia_kgm2 is not symmetric positive definite");
  return {};
}

Quat orientation_from_heading(double heading_deg) {
  // A heading turns +x towards +z: a rotation by −heading about +y (right-handed, Y up).
  const double half = -0.5 * heading_deg * std::numbers::pi / 180.0;
  return {std::cos(half), 0.0, std::sin(half), 0.0};
}

Vec3 rotate(const Quat& q, const Vec3& v) { return mul(rotation(q), v); }

SurfaceQuery surface_of(const Simulator& simulator) {
  return [&simulator](std::span<const std::array<double, 2>> xz, std::span<HeightSample> out) {
    simulator.heights_at(xz, out);
  };
}

SurfaceQuery calm_surface() {
  return [](std::span<const std::array<double, 2>> xz, std::span<HeightSample> out) {
    for (std::size_t i = 0; i < xz.size() && i < out.size(); ++i)
      out[i] = {.height_m = 0.0, .source_xz = xz[i]};
  };
}

Result<FloatingBody> FloatingBody::make(BodyParams params, const BodyState& initial,
                                        const Water& water) {
  if (Status s = validate(params); !s.ok()) return s;
  if (Status s = validate(initial); !s.ok()) return s;
  if (Status s = validate(water); !s.ok()) return s;
  FloatingBody body;
  body.inverse_inertia_ = inverse(params.inertia_kgm2);
  body.params_ = std::move(params);
  body.state_ = initial;
  body.water_ = water;
  return body;
}

void FloatingBody::world_vertices(std::vector<Vec3>& out) const {
  const Mat3 r = rotation(state_.orientation);
  out.resize(params_.hull.vertices.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = add(mul(r, params_.hull.vertices[i]), state_.position_m);
}

double FloatingBody::kinetic_energy_j() const {
  const Mat3 r = rotation(state_.orientation);
  const Mat3 inertia_world = mul(mul(r, params_.inertia_kgm2), transpose(r));
  const Vec3& w = state_.angular_velocity_radps;
  return 0.5 * params_.mass_kg * dot(state_.velocity_mps, state_.velocity_mps) +
         0.5 * dot(w, mul(inertia_world, w));
}

Status FloatingBody::set_state(const BodyState& state) {
  if (Status s = validate(state); !s.ok()) return s;
  state_ = state;
  return {};
}

double heading_deg(const BodyState& state) {
  const Vec3 forward = rotate(state.orientation, {1.0, 0.0, 0.0});
  if (forward[0] == 0.0 && forward[2] == 0.0) return 0.0;
  return std::atan2(forward[2], forward[0]) * 180.0 / std::numbers::pi;
}

Status FloatingBody::step(const SurfaceQuery& surface, double dt_s, const Wrench& external) {
  if (Status s = require_positive("dt_s", dt_s); !s.ok()) return s;
  if (Status s = finite3("external force_n", external.force_n); !s.ok()) return s;
  if (Status s = finite3("external torque_nm", external.torque_nm); !s.ok()) return s;
  Forces f = evaluate(surface);
  f.force_n = add(f.force_n, external.force_n);
  f.torque_nm = add(f.torque_nm, external.torque_nm);
  // (B.5) Symplectic Euler: v' = v + dt·F/m, ω' = ω + dt·I_w⁻¹(τ − ω × I_w ω); then
  // x' = x + dt·v', q' = normalize(q + dt/2·(0, ω')·q).
  BodyState& s = state_;
  s.velocity_mps = add(s.velocity_mps, scale(f.force_n, dt_s / params_.mass_kg));
  const Mat3 r = rotation(s.orientation);
  const Mat3 inertia_world = mul(mul(r, params_.inertia_kgm2), transpose(r));
  const Mat3 inverse_world = mul(mul(r, inverse_inertia_), transpose(r));
  const Vec3& w = s.angular_velocity_radps;
  const Vec3 gyro = cross(w, mul(inertia_world, w));
  s.angular_velocity_radps = add(w, scale(mul(inverse_world, sub(f.torque_nm, gyro)), dt_s));
  s.position_m = add(s.position_m, scale(s.velocity_mps, dt_s));
  const Vec3& o = s.angular_velocity_radps;
  const Quat& q = s.orientation;
  // (0, ω)·q, the quaternion product.
  const Quat dq{-(o[0] * q[1] + o[1] * q[2] + o[2] * q[3]), o[0] * q[0] + o[1] * q[3] - o[2] * q[2],
                o[1] * q[0] + o[2] * q[1] - o[0] * q[3], o[2] * q[0] + o[0] * q[2] - o[1] * q[1]};
  Quat next{};
  double n2 = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    next[k] = q[k] + 0.5 * dt_s * dq[k];
    n2 += next[k] * next[k];
  }
  for (double& c : next) c /= std::sqrt(n2);
  s.orientation = next;
  for (double v : s.position_m)
    if (!std::isfinite(v))
      return invalid_argument("the body's motion is not finite: dt_s = " + format_number(dt_s) +
                              " is too long for its stiffness, or the surface is not finite");
  return {};
}

}  // namespace ocean::bodies
