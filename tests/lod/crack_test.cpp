// The selected mesh is watertight: for many cameras every interior edge is shared by exactly two
// triangles, the boundary of the ocean square is the only boundary, and no vertex lies inside
// another triangle's edge (no T-junctions). Coordinates are exact integers on the finest lattice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "lod/lod_test_util.hpp"
#include "ocean/lod.hpp"

namespace {

using namespace ocean::lod;
using lod_test::LatticeTriangle;

struct CaseResult {
  std::size_t triangles = 0;
  bool ok = true;
  std::string why;
};

// Checks the soup; `full` means the selection must cover the whole square (no culling).
CaseResult check_watertight(const LodSelection& sel, const PatchMeshes& meshes, bool full) {
  CaseResult r;
  const std::vector<LatticeTriangle> soup = lod_test::triangle_soup(sel, meshes);
  r.triangles = soup.size();
  const std::int64_t m = (std::int64_t{1} << sel.max_level) * meshes.vertices;  // lattice side
  auto key = [&](std::int64_t x, std::int64_t z) {
    return static_cast<std::uint64_t>(x * (m + 1) + z);
  };
  std::vector<std::pair<std::uint64_t, std::uint64_t>> edges;
  std::vector<std::uint64_t> points;
  edges.reserve(soup.size() * 3);
  std::int64_t area = 0;
  for (const LatticeTriangle& t : soup) {
    const std::int64_t a = lod_test::twice_area_up(t);
    if (a <= 0) {
      r.ok = false;
      r.why = "degenerate or downward triangle";
      return r;
    }
    area += a;
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t p = key(t.x[k], t.z[k]), q = key(t.x[(k + 1) % 3], t.z[(k + 1) % 3]);
      edges.emplace_back(std::min(p, q), std::max(p, q));
      points.push_back(p);
    }
  }
  if (full && area != 2 * m * m) {
    r.ok = false;
    r.why = "area " + std::to_string(area) + " != " + std::to_string(2 * m * m);
    return r;
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::sort(edges.begin(), edges.end());
  auto unpack = [&](std::uint64_t k) {
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(k) / (m + 1),
                                                 static_cast<std::int64_t>(k) % (m + 1)};
  };
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    const std::size_t count = j - i;
    const auto [x0, z0] = unpack(edges[i].first);
    const auto [x1, z1] = unpack(edges[i].second);
    const bool on_boundary =
        (x0 == x1 && (x0 == 0 || x0 == m)) || (z0 == z1 && (z0 == 0 || z0 == m));
    const std::size_t expected = on_boundary ? 1 : 2;
    if (count > 2 || (full && count != expected)) {
      r.ok = false;
      r.why = "edge (" + std::to_string(x0) + "," + std::to_string(z0) + ")-(" +
              std::to_string(x1) + "," + std::to_string(z1) + ") shared by " +
              std::to_string(count);
      return r;
    }
    // T-junction: a vertex strictly inside this edge (axis-aligned or diagonal lattice steps).
    const std::int64_t dx = x1 - x0, dz = z1 - z0;
    const std::int64_t steps = std::max(std::abs(dx), std::abs(dz));
    for (std::int64_t s = 1; s < steps; ++s) {
      if (dx % steps != 0 || dz % steps != 0) break;  // not a lattice line: no interior points
      const std::uint64_t p = key(x0 + dx / steps * s, z0 + dz / steps * s);
      if (std::binary_search(points.begin(), points.end(), p)) {
        r.ok = false;
        r.why = "T-junction on edge (" + std::to_string(x0) + "," + std::to_string(z0) + ")-(" +
                std::to_string(x1) + "," + std::to_string(z1) + ")";
        return r;
      }
    }
    i = j;
  }
  // 2:1 balance of the subdivision map, which the stitching relies on.
  const int w = sel.map_width;
  for (int y = 0; y < w; ++y) {
    for (int x = 0; x + 1 < w; ++x) {
      const auto at = [&](int cx, int cy) {
        return static_cast<int>(sel.subdivision_map[static_cast<std::size_t>(cy * w + cx)]);
      };
      if (std::abs(at(x, y) - at(x + 1, y)) > 1 || std::abs(at(y, x) - at(y, x + 1)) > 1) {
        r.ok = false;
        r.why = "subdivision map not 2:1 balanced";
        return r;
      }
    }
  }
  return r;
}

struct Scenario {
  Quality quality;
  double size_m;
};

// Random cameras: positions inside and outside the square, heights from 0.5 m to 3 km, random
// directions, straight down and grazing; the grid following the camera or fixed.
TEST(LodCracks, NoCracksOrTJunctionsForManyCameras) {
  const Scenario scenarios[] = {
      {quality_preset(QualityPreset::low), 1024.0},
      {quality_preset(QualityPreset::medium), 512.0},
      {{.vertices = 4, .lod_scale = 1.2, .cull_scale = 1.5}, 4096.0},
      {{.vertices = 2, .lod_scale = 3.0, .cull_scale = 1.0}, 8192.0},
      {{.vertices = 8, .lod_scale = 0.8, .cull_scale = 1.2}, 2048.0},
  };
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int cases = 0, with_stitches = 0;
  std::array<int, kConfigurations> seen{};
  for (const Scenario& sc : scenarios) {
    auto meshes = build_patch_meshes(sc.quality.vertices);
    ASSERT_TRUE(meshes.ok());
    LodSelection sel;
    ASSERT_TRUE(reserve_selection(sel, sc.size_m).ok());
    for (int i = 0; i < 24; ++i) {
      const double s = sc.size_m;
      const double height = 0.5 * std::pow(6000.0, unit(rng));  // 0.5 m .. 3 km
      const Vec3 eye{(unit(rng) - 0.5) * 1.6 * s, height, (unit(rng) - 0.5) * 1.6 * s};
      Vec3 target;
      switch (i % 4) {
        case 0: target = {eye.x, 0.0, eye.z}; break;                           // straight down
        case 1: target = {eye.x + 1000.0, eye.y - 1.0, eye.z + 300.0}; break;  // grazing
        default: target = {eye.x + (unit(rng) - 0.5) * s, 0.0, eye.z + (unit(rng) - 0.5) * s};
      }
      for (bool cull : {false, true}) {
        LodParams p{.ocean_size_m = s,
                    .quality = sc.quality,
                    .camera_position_m = eye,
                    .frustum = camera_frustum({.position_m = eye, .target_m = target}),
                    .cull = cull,
                    .follow_camera = (i % 3) != 0,
                    .fixed_centre_x_m = 0.0,
                    .fixed_centre_z_m = 0.0};
        ASSERT_TRUE(select_patches(p, sel).ok());
        const CaseResult r = check_watertight(sel, meshes.value(), !cull);
        ASSERT_TRUE(r.ok) << r.why << " (size " << s << ", V " << sc.quality.vertices << ", eye "
                          << eye.x << "," << eye.y << "," << eye.z << ", cull " << cull << ")";
        ++cases;
        for (const PatchInstance& pi : sel.instances) {
          ++seen[pi.config];
          if (pi.config != 0) ++with_stitches;
        }
      }
    }
  }
  EXPECT_EQ(cases, 240);
  EXPECT_GT(with_stitches, 100);  // the stitching was exercised, not just uniform grids
  for (int c : {0, 1, 2, 4, 8, 3, 6, 9, 12}) EXPECT_GT(seen[static_cast<std::size_t>(c)], 0) << c;
}

// A camera close to the water with τ < √2 ... the raw distance test would leave two-level jumps;
// the balancing pass must remove them (checked by check_watertight's map test).
TEST(LodCracks, LowCameraOnLargeOceanIsWatertight) {
  for (QualityPreset q :
       {QualityPreset::low, QualityPreset::medium, QualityPreset::high, QualityPreset::ultra}) {
    auto meshes = build_patch_meshes(quality_preset(q).vertices);
    ASSERT_TRUE(meshes.ok());
    LodSelection sel;
    LodParams p{.ocean_size_m = 8192.0,
                .quality = quality_preset(q),
                .camera_position_m = {37.0, 2.0, -81.0},
                .cull = false};
    ASSERT_TRUE(select_patches(p, sel).ok());
    EXPECT_EQ(sel.max_level, 7);
    const CaseResult r = check_watertight(sel, meshes.value(), true);
    EXPECT_TRUE(r.ok) << preset_name(q) << ": " << r.why;
  }
}

}  // namespace
