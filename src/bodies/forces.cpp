// The forces on a floating body (FloatingBody::evaluate): one batched height query at the hull's
// vertices, each triangle clipped where its depth below the surface changes sign, the
// hydrostatic pressure integrated exactly over the submerged parts, drag against still water,
// gravity. Equations (B.2)–(B.4): docs/bodies.md.
//
// This work is based on:
//   J. Kerner, "Water interaction model for boats in video games", Game Developer (Gamasutra),
//   2015 — hull triangles split at the waterline, the hydrostatic force per submerged triangle.
//   Pressure p = ρ·g·depth is linear over a triangle when the depth is, so its force and moment
//   are exact with the linear-function integrals ∫λ_i λ_j dA = A/12·(1 + δ_ij) (B.3); over a
//   closed hull in calm water their sum is Archimedes' ρ·g·V_submerged by the divergence theorem.
#include <cmath>

#include "body_math.hpp"
#include "ocean/bodies.hpp"

namespace ocean::bodies {

namespace {

struct Accumulator {
  Vec3 pressure{}, pressure_torque{}, drag{}, drag_torque{};
  double wetted_area = 0.0;
};

// A submerged triangle: points r relative to the centre of mass, depths h ≥ 0, the unit outward
// normal n and the area A.
void integrate(const std::array<Vec3, 3>& r, const std::array<double, 3>& h, const Vec3& n,
               double area, const BodyState& state, const BodyParams& body, const Water& water,
               Accumulator& acc) {
  const double rho_g = water.density_kgpm3 * water.gravity_mps2;
  const double sum_h = h[0] + h[1] + h[2];
  // (B.2) F = −ρg·∫h dA·n, ∫h dA = A·(h0 + h1 + h2)/3.
  acc.pressure = add(acc.pressure, scale(n, -rho_g * area * sum_h / 3.0));
  // (B.3) τ = −ρg·(∫h·r dA) × n, ∫h·r dA = A/12·(Σ h_j r_j + Σh_j·Σr_j).
  const Vec3 sum_r = add(add(r[0], r[1]), r[2]);
  Vec3 moment = scale(sum_r, sum_h);
  for (std::size_t j = 0; j < 3; ++j) moment = add(moment, scale(r[j], h[j]));
  acc.pressure_torque = add(acc.pressure_torque, scale(cross(moment, n), -rho_g * area / 12.0));
  // (B.4) Drag at the centroid against still water, along the normal.
  const Vec3 c = scale(sum_r, 1.0 / 3.0);
  const Vec3 v = add(state.velocity_mps, cross(state.angular_velocity_radps, c));
  const double vn = dot(v, n);
  const double magnitude =
      water.density_kgpm3 * area *
      (body.drag.linear_mps * vn + 0.5 * body.drag.quadratic * std::abs(vn) * vn);
  const Vec3 drag = scale(n, -magnitude);
  acc.drag = add(acc.drag, drag);
  acc.drag_torque = add(acc.drag_torque, cross(c, drag));
  acc.wetted_area += area;
}

}  // namespace

Forces FloatingBody::evaluate(const SurfaceQuery& surface) {
  world_vertices(world_);
  const std::size_t count = world_.size();
  xz_.resize(count);
  heights_.resize(count);
  for (std::size_t i = 0; i < count; ++i) xz_[i] = {world_[i][0], world_[i][2]};
  surface(xz_, heights_);

  Accumulator acc;
  const Vec3& x = state_.position_m;
  for (const auto& t : params_.hull.triangles) {
    std::array<Vec3, 3> p{};
    std::array<double, 3> depth{};
    for (std::size_t k = 0; k < 3; ++k) {
      p[k] = sub(world_[t[k]], x);
      depth[k] = heights_[t[k]].height_m - world_[t[k]][1];
    }
    const Vec3 area_vector = scale(cross(sub(p[1], p[0]), sub(p[2], p[0])), 0.5);
    const double area = norm(area_vector);
    if (!(area > 0.0)) continue;
    const Vec3 n = scale(area_vector, 1.0 / area);
    // Clip the triangle to depth ≥ 0 (one plane, Sutherland–Hodgman in the depth): 0, 3 or 4
    // points, the depth linear along each edge, 0 where an edge crosses the surface.
    std::array<Vec3, 4> poly{};
    std::array<double, 4> poly_depth{};
    int m = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t j = (k + 1) % 3;
      if (depth[k] >= 0.0) {
        poly[static_cast<std::size_t>(m)] = p[k];
        poly_depth[static_cast<std::size_t>(m++)] = depth[k];
      }
      if ((depth[k] >= 0.0) != (depth[j] >= 0.0)) {
        const double s = depth[k] / (depth[k] - depth[j]);
        poly[static_cast<std::size_t>(m)] = add(p[k], scale(sub(p[j], p[k]), s));
        poly_depth[static_cast<std::size_t>(m++)] = 0.0;
      }
    }
    for (int k = 1; k + 1 < m; ++k) {  // fan
      const auto a = static_cast<std::size_t>(k), b = static_cast<std::size_t>(k + 1);
      const std::array<Vec3, 3> r{poly[0], poly[a], poly[b]};
      const double sub_area = 0.5 * norm(cross(sub(r[1], r[0]), sub(r[2], r[0])));
      integrate(r, {poly_depth[0], poly_depth[a], poly_depth[b]}, n, sub_area, state_, params_,
                water_, acc);
    }
  }
  Forces f;
  f.buoyancy_n = acc.pressure;
  f.drag_n = acc.drag;
  f.submerged_volume_m3 = acc.pressure[1] / (water_.density_kgpm3 * water_.gravity_mps2);
  f.wetted_area_m2 = acc.wetted_area;
  const Vec3 gravity{0.0, -params_.mass_kg * water_.gravity_mps2, 0.0};
  f.force_n = add(add(acc.pressure, acc.drag), gravity);
  f.torque_nm = add(acc.pressure_torque, acc.drag_torque);
  forces_ = f;
  return f;
}

}  // namespace ocean::bodies
