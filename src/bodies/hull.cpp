// Hulls: validation (closed, outward, finite), mass properties of the solid and translation.
//
// This work is based on:
//   F. Tonon, "Explicit exact formulas for the 3-D tetrahedron inertia tensor in terms of its
//   vertex coordinates", J. Math. Stat. 1(1), 2004 — the covariance of a tetrahedron (B.1).
//   D. Eberly, "Polyhedral Mass Properties (Revisited)", Geometric Tools, 2002 — the sum over
//   signed tetrahedra from the origin, exact for any closed oriented mesh.
#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "body_math.hpp"
#include "ocean/bodies.hpp"

namespace ocean::bodies {

namespace {

constexpr std::size_t kMaxTriangles = 1'000'000;

// Every directed edge must appear once and its reverse once: a closed two-manifold whose
// triangles all wind the same way.
bool closed_and_consistent(const Hull& hull) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges, reversed;
  edges.reserve(3 * hull.triangles.size());
  reversed.reserve(3 * hull.triangles.size());
  for (const auto& t : hull.triangles) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = t[static_cast<std::size_t>(e)];
      const std::uint32_t b = t[static_cast<std::size_t>((e + 1) % 3)];
      edges.emplace_back(a, b);
      reversed.emplace_back(b, a);
    }
  }
  std::sort(edges.begin(), edges.end());
  std::sort(reversed.begin(), reversed.end());
  return std::adjacent_find(edges.begin(), edges.end()) == edges.end() && edges == reversed;
}

}  // namespace

Status validate(const Hull& hull) {
  if (hull.vertices.empty() || hull.triangles.empty())
    return invalid_argument("hull: the mesh has no triangles");
  if (hull.triangles.size() > kMaxTriangles)
    return invalid_argument("hull: " + std::to_string(hull.triangles.size()) +
                            " triangles are more than the limit of 1000000");
  for (const Vec3& v : hull.vertices)
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
      return invalid_argument("hull: a vertex is not finite");
  for (const auto& t : hull.triangles)
    for (std::uint32_t i : t)
      if (i >= hull.vertices.size())
        return invalid_argument("hull: vertex index " + std::to_string(i) + " is out of range (" +
                                std::to_string(hull.vertices.size()) + " vertices)");
  if (!closed_and_consistent(hull))
    return invalid_argument(
        "hull: the mesh is not closed and consistently wound (every edge must join exactly two "
        "triangles that run through it in opposite directions)");
  if (!(mass_properties(hull).volume_m3 > 0.0))
    return invalid_argument("hull: the mesh encloses no volume (inside out or flat)");
  return {};
}

MassProperties mass_properties(const Hull& hull) {
  // Tetrahedron (0, a, b, c): volume det/6, first moment det/24·(a + b + c), second moments
  // ∫x_i x_j dV = det/120·(Σ_k a_i a_j ... ) written as the canonical covariance
  // det/120·(Σ_p p_i p_j + (Σ_p p_i)(Σ_p p_j)) over p ∈ {a, b, c} (Tonon 2004) (B.1).
  double volume = 0.0;
  Vec3 first{};
  Mat3 second{};
  for (const auto& t : hull.triangles) {
    const Vec3& a = hull.vertices[t[0]];
    const Vec3& b = hull.vertices[t[1]];
    const Vec3& c = hull.vertices[t[2]];
    const double det = dot(a, cross(b, c));
    volume += det / 6.0;
    const Vec3 s = add(add(a, b), c);
    for (std::size_t i = 0; i < 3; ++i) first[i] += det / 24.0 * s[i];
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        second[3 * i + j] += det / 120.0 * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
  }
  MassProperties m;
  m.volume_m3 = volume;
  if (!(volume > 0.0)) return m;
  m.centroid_m = scale(first, 1.0 / volume);
  // Covariance about the centroid, then the inertia tensor I = tr(C)·1 − C.
  Mat3 c{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      c[3 * i + j] = second[3 * i + j] - volume * m.centroid_m[i] * m.centroid_m[j];
  const double trace = c[0] + c[4] + c[8];
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      m.inertia[3 * i + j] = (i == j ? trace : 0.0) - c[3 * i + j];
  return m;
}

Hull translated(Hull hull, const Vec3& origin) {
  for (Vec3& v : hull.vertices) v = sub(v, origin);
  return hull;
}

Result<BodyParams> solid_body(const Hull& hull, double density_kgpm3, const DragParams& drag) {
  if (Status s = require_positive("density_kgpm3", density_kgpm3); !s.ok()) return s;
  if (Status s = validate(hull); !s.ok()) return s;
  if (Status s = validate(drag); !s.ok()) return s;
  const MassProperties m = mass_properties(hull);
  BodyParams p;
  p.hull = translated(hull, m.centroid_m);
  p.mass_kg = density_kgpm3 * m.volume_m3;
  for (std::size_t i = 0; i < 9; ++i) p.inertia_kgm2[i] = density_kgpm3 * m.inertia[i];
  p.drag = drag;
  if (Status s = validate(p); !s.ok()) return s;
  return p;
}

}  // namespace ocean::bodies
