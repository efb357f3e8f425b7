// src/world/objects.cpp — what an object of the world is made of: the built-in shapes' hulls and
// densities, a renderer's meshes welded into one hull, and a driven object's propulsion and wake
// track sized from its body (docs/bodies.md B.6, B.8–B.10; docs/waves.md W.17).
#include <algorithm>
#include <map>

#include "ocean/world.hpp"

namespace ocean::world {

Result<bodies::Hull> shape_hull(Shape shape) {
  switch (shape) {
    case Shape::box:
      return bodies::box_hull({2.0, 1.0, 2.0});
    case Shape::buoy:
      return bodies::buoy_hull(0.8, 1.0);
    case Shape::boat:
      break;
  }
  return bodies::boat_hull(8.0, 3.0, 1.2);
}

double shape_density_kgpm3(Shape shape) {
  switch (shape) {
    case Shape::box:
      return kBoxDensity_kgpm3;
    case Shape::buoy:
      return kBuoyDensity_kgpm3;
    case Shape::boat:
      break;
  }
  return kBoatDensity_kgpm3;
}

bodies::Hull welded_hull(std::span<const MeshView> meshes) {
  bodies::Hull hull;
  std::map<std::array<double, 3>, std::uint32_t> index;
  for (const MeshView& mesh : meshes) {
    std::vector<std::uint32_t> map(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const std::array<double, 3> p{mesh.positions[v][0], mesh.positions[v][1],
                                    mesh.positions[v][2]};
      auto [it, inserted] = index.try_emplace(p, static_cast<std::uint32_t>(hull.vertices.size()));
      if (inserted) hull.vertices.push_back(p);
      map[v] = it->second;
    }
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::array<std::uint32_t, 3> tri{map[mesh.indices[t]], map[mesh.indices[t + 1]],
                                             map[mesh.indices[t + 2]]};
      if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]) hull.triangles.push_back(tri);
    }
  }
  return hull;
}

bodies::PropulsionParams propulsion_for(const bodies::BodyParams& body, double gravity_mps2) {
  double x_min = 0.0;
  for (const auto& v : body.hull.vertices) x_min = std::min(x_min, v[0]);
  // The yaw inertia of the level body: about its vertical (body y) axis.
  const double i_yaw = body.inertia_kgm2[4];
  return {.max_thrust_n = 0.5 * body.mass_kg * gravity_mps2,
          .thrust_point_m = {0.9 * x_min, 0.0, 0.0},
          .speed_time_s = 2.5,
          .max_yaw_moment_nm = 0.5 * i_yaw,
          .heading_time_s = 2.0};
}

waves::WakeTrackParams wake_track_for(const bodies::Hull& hull) {
  double x_min = 0.0, x_max = 0.0;
  for (const auto& v : hull.vertices) {
    x_min = std::min(x_min, v[0]);
    x_max = std::max(x_max, v[0]);
  }
  const double length = std::clamp(x_max - x_min, 0.01, 1000.0);
  return {.hull_length_m = length, .peak_height_m = kWakePeakPerLength * length};
}

}  // namespace ocean::world
