// The cube-sphere's mesh is watertight (docs/rendering.md R.36): without culling the six faces'
// stitched patches close into a sphere — every edge shared by exactly two triangles, in
// opposite directions, V − E + F = 2 — for cameras over face centres, edges and corners; with
// culling no edge is shared by more than two triangles. Coordinates are exact integers of the
// finest lattice on the cube, so a vertex on a face's edge is the same point from both faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "ocean/sphere.hpp"

namespace {

using namespace ocean;
using namespace ocean::sphere;
using Point = std::array<std::int64_t, 3>;

struct Soup {
  std::vector<std::array<Point, 3>> triangles;
};

// Triangle soup of a selection on the lattice of 2^L·V cells per face side: cube point
// M·N + (2i − M)·U + (2j − M)·V with M = 2^L·V.
Soup soup(const SphereSelection& sel, const lod::PatchMeshes& meshes) {
  Soup s;
  const std::int64_t vv = meshes.vertices, m = (std::int64_t{1} << sel.max_level) * vv;
  for (const SpherePatch& p : sel.patches) {
    const FaceAxes f = face_axes(p.face);
    const std::int64_t scale = std::int64_t{1} << (sel.max_level - p.level);
    const auto& idx = meshes.indices[p.config];
    for (std::size_t t = 0; t < idx.size(); t += 3) {
      std::array<Point, 3> tri{};
      for (std::size_t k = 0; k < 3; ++k) {
        const std::int64_t a = idx[t + k] % (vv + 1), b = idx[t + k] / (vv + 1);
        const std::int64_t i = (p.x * vv + a) * scale, j = (p.y * vv + b) * scale;
        const std::int64_t cu = 2 * i - m, cv = 2 * j - m;
        tri[k] = {m * static_cast<std::int64_t>(f.n.x) + cu * static_cast<std::int64_t>(f.u.x) +
                      cv * static_cast<std::int64_t>(f.v.x),
                  m * static_cast<std::int64_t>(f.n.y) + cu * static_cast<std::int64_t>(f.u.y) +
                      cv * static_cast<std::int64_t>(f.v.y),
                  m * static_cast<std::int64_t>(f.n.z) + cu * static_cast<std::int64_t>(f.u.z) +
                      cv * static_cast<std::int64_t>(f.v.z)};
      }
      s.triangles.push_back(tri);
    }
  }
  return s;
}

// Empty when watertight (closed: a sphere), else why not.
std::string check(const Soup& s, bool closed) {
  std::map<std::pair<Point, Point>, int> directed;
  std::map<Point, int> vertices;
  for (const auto& t : s.triangles) {
    // Facing outwards: ((b − a) × (c − a))·(a + b + c) > 0.
    const Point e1{t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]};
    const Point e2{t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]};
    const Point n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                  e1[0] * e2[1] - e1[1] * e2[0]};
    const std::int64_t out = n[0] * (t[0][0] + t[1][0] + t[2][0]) +
                             n[1] * (t[0][1] + t[1][1] + t[2][1]) +
                             n[2] * (t[0][2] + t[1][2] + t[2][2]);
    if (out <= 0) return "a triangle faces inwards or is degenerate";
    for (std::size_t k = 0; k < 3; ++k) {
      if (++directed[{t[k], t[(k + 1) % 3]}] > 1) return "a directed edge is used twice";
      vertices[t[k]] = 1;
    }
  }
  std::size_t open = 0;
  for (const auto& [e, count] : directed)
    if (!directed.contains({e.second, e.first})) ++open;
  if (closed) {
    if (open != 0) return std::to_string(open) + " edges have no twin (a crack or T-junction)";
    const auto v = static_cast<std::int64_t>(vertices.size());
    const auto e = static_cast<std::int64_t>(directed.size() / 2);
    const auto f = static_cast<std::int64_t>(s.triangles.size());
    if (v - e + f != 2) return "Euler characteristic " + std::to_string(v - e + f) + " != 2";
  }
  return {};
}

struct Result {
  std::size_t triangles = 0, cross_face_stitches = 0;
};

Result run(Vec3 eye, bool cull, double radius) {
  SphereLodParams p{.radius_m = radius,
                    .quality = {.vertices = 8, .lod_scale = 1.5, .cull_scale = 1.5},
                    .camera_position_m = eye,
                    .cull = cull,
                    .finest_patch_m = radius / 40.0,
                    .max_vertical_displacement_m = 2.0};
  const double r = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  const lod::Camera cam{
      .position_m = eye, .target_m = {0, 0, 0}, .fov_y_rad = 1.0, .near_m = 1.0, .far_m = 4 * r};
  p.frustum = lod::camera_frustum(cam);
  SphereSelection sel;
  EXPECT_TRUE(select_sphere_patches(p, sel).ok());
  const lod::PatchMeshes meshes = lod::build_patch_meshes(8).value();
  const Soup s = soup(sel, meshes);
  const std::string why = check(s, !cull);
  EXPECT_TRUE(why.empty()) << why << " (eye " << eye.x << "," << eye.y << "," << eye.z << ")";
  Result res{.triangles = s.triangles.size()};
  for (const SpherePatch& sp : sel.patches) {  // stitched edges that lie on a face's edge
    const double h = sp.size / 2;
    if (((sp.config & lod::kEast) && sp.centre_u + h == 1.0) ||
        ((sp.config & lod::kWest) && sp.centre_u - h == -1.0) ||
        ((sp.config & lod::kNorth) && sp.centre_v + h == 1.0) ||
        ((sp.config & lod::kSouth) && sp.centre_v - h == -1.0))
      ++res.cross_face_stitches;
  }
  return res;
}

TEST(SphereCrack, ClosedSphereForCamerasOverCentresEdgesAndCorners) {
  const double radius = 5000.0;
  std::size_t stitches = 0;
  for (double alt : {30.0, 400.0, 6000.0}) {
    const double r = radius + alt;
    for (Vec3 d : {Vec3{0, 1, 0}, Vec3{1, 1, 0}, Vec3{1, 1, 1}, Vec3{0.3, -1, 0.99},
                   Vec3{-1, 0.2, 0.1}, Vec3{0.2, 0.7, -1}}) {
      const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
      stitches +=
          run({r * d.x / len, r * d.y / len, r * d.z / len}, false, radius).cross_face_stitches;
    }
  }
  EXPECT_GT(stitches, 0u);  // the faces' edges did see neighbours of another level
}

TEST(SphereCrack, CulledSelectionsStayManifoldAndCullBehindTheHorizon) {
  const double radius = 5000.0;
  for (Vec3 eye : {Vec3{0, radius + 50, 0}, Vec3{3600, 3600, 100}, Vec3{radius + 3000, 0, 0}}) {
    const Result culled = run(eye, true, radius), full = run(eye, false, radius);
    EXPECT_LT(culled.triangles, full.triangles);
  }
  // From 50 m over the pole the horizon is √(2Rh) ≈ 0.7 km away: the far side is culled there.
  SphereLodParams p{.radius_m = radius,
                    .camera_position_m = {0, radius + 50, 0},
                    .cull = true,
                    .finest_patch_m = 100.0,
                    .max_vertical_displacement_m = 2.0};
  p.frustum =
      lod::camera_frustum({.position_m = p.camera_position_m, .target_m = {100, radius, 0}});
  SphereSelection sel;
  ASSERT_TRUE(select_sphere_patches(p, sel).ok());
  EXPECT_GT(sel.culled_horizon, 0u);
  for (const SpherePatch& sp : sel.patches) EXPECT_NE(sp.face, 3) << "the −y face is out of sight";
}

TEST(SphereCrack, BadInputIsRefused) {
  SphereSelection sel;
  SphereLodParams p{.radius_m = 5000.0, .camera_position_m = {0, 4000, 0}};
  EXPECT_FALSE(select_sphere_patches(p, sel).ok());  // inside the planet
  p.camera_position_m = {0, 6000, 0};
  p.radius_m = -1.0;
  EXPECT_FALSE(select_sphere_patches(p, sel).ok());
  p.radius_m = std::nan("");
  EXPECT_FALSE(select_sphere_patches(p, sel).ok());
  EXPECT_TRUE(sel.patches.empty());
}

}  // namespace
