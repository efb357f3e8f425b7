// Meshes as plain data (ocean/objects.hpp): validation, flat-shaded meshes of triangle lists and
// the rigid model matrix of a pose.
#include <cmath>
#include <string>

#include "ocean/objects.hpp"

namespace ocean::render {

namespace {

bool finite3(const std::array<float, 3>& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

}  // namespace

Status validate(const Mesh& mesh) {
  if (mesh.positions.empty() || mesh.indices.empty()) return invalid_argument("mesh: no triangles");
  if (mesh.positions.size() > kMaxMeshElements || mesh.indices.size() > kMaxMeshElements)
    return invalid_argument("mesh: " + std::to_string(mesh.positions.size()) + " vertices and " +
                            std::to_string(mesh.indices.size()) +
                            " indices exceed the limit of 16777216 each");
  if (mesh.normals.size() != mesh.positions.size())
    return invalid_argument("mesh: " + std::to_string(mesh.normals.size()) + " normals for " +
                            std::to_string(mesh.positions.size()) + " positions");
  if (mesh.indices.size() % 3 != 0)
    return invalid_argument("mesh: " + std::to_string(mesh.indices.size()) +
                            " indices are not whole triangles");
  for (std::uint32_t i : mesh.indices)
    if (i >= mesh.positions.size())
      return invalid_argument("mesh: index " + std::to_string(i) + " is out of range");
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!finite3(mesh.positions[i]) || !finite3(mesh.normals[i]))
      return invalid_argument("mesh: a position or normal is not finite");
  const Material& m = mesh.material;
  for (double c : m.base_colour)
    if (Status s = require_in_range("material base_colour", c, 0.0, 1.0); !s.ok()) return s;
  if (Status s = require_in_range("material metallic", m.metallic, 0.0, 1.0); !s.ok()) return s;
  return require_in_range("material roughness", m.roughness, 0.02, 1.0);
}

Mesh flat_mesh(std::span<const std::array<double, 3>> vertices,
               std::span<const std::array<std::uint32_t, 3>> triangles, const Material& material) {
  Mesh mesh;
  mesh.material = material;
  for (const auto& t : triangles) {
    const auto& a = vertices[t[0]];
    const auto& b = vertices[t[1]];
    const auto& c = vertices[t[2]];
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (!(len > 0.0)) continue;
    nx /= len, ny /= len, nz /= len;
    for (const auto* p : {&a, &b, &c}) {
      mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
      mesh.positions.push_back(
          {static_cast<float>((*p)[0]), static_cast<float>((*p)[1]), static_cast<float>((*p)[2])});
      mesh.normals.push_back(
          {static_cast<float>(nx), static_cast<float>(ny), static_cast<float>(nz)});
    }
  }
  return mesh;
}

Status validate(const Seabed& s) {
  if (Status st = require_in_range("seabed depth_m", s.depth_m, 1e-3, 1e4); !st.ok()) return st;
  if (Status st = require_in_range("seabed period_m", s.period_m, 1e-3, 1e4); !st.ok()) return st;
  for (double c : s.albedo)
    if (Status st = require_in_range("seabed albedo", c, 0.0, 1.0); !st.ok()) return st;
  for (double a : s.absorption_per_m)
    if (Status st = require_in_range("seabed absorption_per_m", a, 0.0, 100.0); !st.ok()) return st;
  return {};
}

std::array<double, 16> model_matrix(const std::array<double, 3>& position_m,
                                    const std::array<double, 4>& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  // Column-major: columns are the images of the axes, the last the translation.
  return {1 - 2 * (y * y + z * z), 2 * (x * y + w * z),     2 * (x * z - w * y),     0.0,
          2 * (x * y - w * z),     1 - 2 * (x * x + z * z), 2 * (y * z + w * x),     0.0,
          2 * (x * z + w * y),     2 * (y * z - w * x),     1 - 2 * (x * x + y * y), 0.0,
          position_m[0],           position_m[1],           position_m[2],           1.0};
}

}  // namespace ocean::render
