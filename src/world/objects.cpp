// src/world/objects.cpp — what an object of the world is made of: the built-in shapes' hulls and
// densities, a renderer's meshes welded into one hull, and a driven object's propulsion and wake
// track sized from its body (docs/bodies.md B.6, B.8–B.10; docs/waves.md W.17).
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "ocean/world.hpp"

namespace ocean::world {

namespace {

constexpr double kBoatLength_m = 8.0, kBoatBeam_m = 3.0, kBoatDepth_m = 1.2;  // Shape::boat

}  // namespace

Result<bodies::Hull> shape_hull(Shape shape) {
  switch (shape) {
    case Shape::box:
      return bodies::box_hull({2.0, 1.0, 2.0});
    case Shape::buoy:
      return bodies::buoy_hull(0.8, 1.0);
    case Shape::boat:
      break;
  }
  return bodies::boat_hull(kBoatLength_m, kBoatBeam_m, kBoatDepth_m);
}

Result<bodies::BoatTopside> boat_topside() {
  return bodies::boat_topside(kBoatLength_m, kBoatBeam_m, kBoatDepth_m);
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

namespace {

// The hull's width across z along the line through (x, y) parallel to z: the extent of the
// triangles it crosses (0 where it misses the hull).
double width_at(const bodies::Hull& hull, double x, double y) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& tri : hull.triangles) {
    const auto& a = hull.vertices[tri[0]];
    const auto& b = hull.vertices[tri[1]];
    const auto& c = hull.vertices[tri[2]];
    // Barycentric coordinates of (x, y) in the triangle's projection on the x–y plane.
    const double d = (b[1] - c[1]) * (a[0] - c[0]) + (c[0] - b[0]) * (a[1] - c[1]);
    if (std::abs(d) < 1e-12) continue;
    const double u = ((b[1] - c[1]) * (x - c[0]) + (c[0] - b[0]) * (y - c[1])) / d;
    const double v = ((c[1] - a[1]) * (x - c[0]) + (a[0] - c[0]) * (y - c[1])) / d;
    if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
    const double z = u * a[2] + v * b[2] + (1.0 - u - v) * c[2];
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  return hi > lo ? hi - lo : 0.0;
}

}  // namespace

std::optional<waves::ThinHull> thin_hull_of(const bodies::Hull& hull, double mass_kg,
                                            double water_density_kgpm3) {
  constexpr int kColumns = 64, kRows = 16, kLevels = 64;
  if (hull.vertices.empty() || !(mass_kg > 0.0)) return std::nullopt;
  std::array<double, 2> x{hull.vertices[0][0], hull.vertices[0][0]};
  std::array<double, 2> y{hull.vertices[0][1], hull.vertices[0][1]};
  for (const auto& v : hull.vertices) {
    x = {std::min(x[0], v[0]), std::max(x[1], v[0])};
    y = {std::min(y[0], v[1]), std::max(y[1], v[1])};
  }
  const double length = x[1] - x[0], height = y[1] - y[0];
  if (!(length > 0.01) || !(height > 0.0)) return std::nullopt;
  const double dx = length / kColumns, dy = height / kLevels;
  // The section areas of horizontal slices from the keel up, then the level of the still-water
  // line where the displaced water weighs the hull's mass (Archimedes; level trim).
  std::vector<double> slice(kLevels, 0.0);
  for (int j = 0; j < kLevels; ++j)
    for (int i = 0; i < kColumns; ++i)
      slice[static_cast<std::size_t>(j)] +=
          width_at(hull, x[0] + (i + 0.5) * dx, y[0] + (j + 0.5) * dy) * dx * dy;
  const double volume = mass_kg / water_density_kgpm3;
  double below = 0.0, waterline = y[1];
  for (int j = 0; j < kLevels; ++j) {
    const double v = slice[static_cast<std::size_t>(j)];
    if (below + v >= volume) {
      waterline = y[0] + (j + (v > 0.0 ? (volume - below) / v : 0.0)) * dy;
      break;
    }
    below += v;
  }
  waves::ThinHull thin{.length_m = length,
                       .draft_m = waterline - y[0],
                       .columns = kColumns,
                       .rows = kRows,
                       .half_breadth_m = std::vector<double>(kColumns * kRows, 0.0)};
  if (!(thin.draft_m > 1e-4)) return std::nullopt;
  for (int r = 0; r < kRows; ++r)
    for (int i = 0; i < kColumns; ++i)
      thin.half_breadth_m[static_cast<std::size_t>(r * kColumns + i)] =
          0.5 * width_at(hull, x[0] + (i + 0.5) * dx, waterline - (r + 0.5) * thin.draft_m / kRows);
  return thin;
}

waves::WakeTrackParams wake_track_for(const bodies::BodyParams& body, double water_density_kgpm3) {
  const bodies::Hull& hull = body.hull;
  double x_min = 0.0, x_max = 0.0, z_min = 0.0, z_max = 0.0;
  for (const auto& v : hull.vertices) {
    x_min = std::min(x_min, v[0]);
    x_max = std::max(x_max, v[0]);
    z_min = std::min(z_min, v[2]);
    z_max = std::max(z_max, v[2]);
  }
  const double length = std::clamp(x_max - x_min, 0.01, 1000.0);
  waves::WakeTrackParams p{.hull_length_m = length,
                           // The waterline and trail foam (docs/waves.md W.20–W.21) of the
                           // hull's widest breadth.
                           .foam = {.beam_m = std::clamp(z_max - z_min, 0.0, 1000.0)}};
  // The wake's height from the hull's own wave resistance (W.23–W.24).
  if (std::optional<waves::ThinHull> thin = thin_hull_of(hull, body.mass_kg, water_density_kgpm3);
      thin && validate(*thin).ok()) {
    p.thin_hull = std::make_shared<const waves::ThinHull>(std::move(*thin));
  } else {
    p.peak_height_m = kDefaultWakePeakPerLength * length;
  }
  return p;
}

}  // namespace ocean::world
