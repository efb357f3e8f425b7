// The 16 index buffers (eqs. 65–68) and the skirt (§5.7).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "ocean/lod.hpp"

namespace {

using namespace ocean::lod;

TEST(LodStitching, EveryConfigurationIsAValidWatertightPatch) {
  for (int v : {2, 4, 16, 32, 64}) {
    auto meshes = build_patch_meshes(v);
    ASSERT_TRUE(meshes.ok());
    const int row = v + 1;
    ASSERT_EQ(meshes.value().positions_xz.size(), static_cast<std::size_t>(2 * row * row));
    EXPECT_EQ(meshes.value().positions_xz[0], -0.5f);
    EXPECT_EQ(meshes.value().positions_xz.back(), 0.5f);
    for (int c = 0; c < kConfigurations; ++c) {
      const auto& idx = meshes.value().indices[static_cast<std::size_t>(c)];
      const int cells = v / 2;
      // L.8: 8 triangles per cell, one less per stitched cell edge.
      ASSERT_EQ(idx.size(), static_cast<std::size_t>(
                                3 * (8 * cells * cells - cells * std::popcount(unsigned(c)))))
          << "V " << v << " config " << c;
      std::map<std::pair<int, int>, int> edges;
      long area2 = 0;
      std::vector<bool> used(static_cast<std::size_t>(row * row), false);
      for (std::size_t t = 0; t < idx.size(); t += 3) {
        int x[3], z[3];
        for (int k = 0; k < 3; ++k) {
          const int id = idx[t + static_cast<std::size_t>(k)];
          ASSERT_LT(id, row * row);
          used[static_cast<std::size_t>(id)] = true;
          x[k] = id % row;
          z[k] = id / row;
        }
        const int a2 = (z[1] - z[0]) * (x[2] - x[0]) - (x[1] - x[0]) * (z[2] - z[0]);
        ASSERT_GT(a2, 0) << "degenerate or facing down";
        area2 += a2;
        for (int k = 0; k < 3; ++k) {
          const int p = idx[t + static_cast<std::size_t>(k)];
          const int q = idx[t + static_cast<std::size_t>((k + 1) % 3)];
          ++edges[{std::min(p, q), std::max(p, q)}];
        }
      }
      EXPECT_EQ(area2, 2L * v * v);  // covers the patch exactly once
      for (const auto& [e, n] : edges) {
        const int x0 = e.first % row, z0 = e.first / row, x1 = e.second % row, z1 = e.second / row;
        const bool boundary =
            (x0 == x1 && (x0 == 0 || x0 == v)) || (z0 == z1 && (z0 == 0 || z0 == v));
        EXPECT_EQ(n, boundary ? 1 : 2);
        if (boundary) {  // a stitched side spans two quads, an unstitched one
          const int len = std::abs(x1 - x0) + std::abs(z1 - z0);
          const int bit = x0 == x1 ? (x0 == 0 ? kWest : kEast) : (z0 == 0 ? kSouth : kNorth);
          EXPECT_EQ(len, (c & bit) ? 2 : 1);
        }
      }
      // The odd vertices of a stitched side are not used; an unstitched side uses them all.
      for (int k = 1; k < v; k += 2) {
        EXPECT_EQ(used[static_cast<std::size_t>(v + k * row)], (c & kEast) == 0);
        EXPECT_EQ(used[static_cast<std::size_t>(k * row)], (c & kWest) == 0);
        EXPECT_EQ(used[static_cast<std::size_t>(k + v * row)], (c & kNorth) == 0);
        EXPECT_EQ(used[static_cast<std::size_t>(k)], (c & kSouth) == 0);
      }
    }
  }
  // Aebi, VR Ocean, eq. 66: one cell (V = 2): 8 triangles full, 7 with one side, 4 with all four.
  EXPECT_EQ(build_patch_indices(2, 0).size(), 24u);
  EXPECT_EQ(build_patch_indices(2, kEast).size(), 21u);
  EXPECT_EQ(build_patch_indices(2, 15).size(), 12u);
  EXPECT_FALSE(build_patch_meshes(3).ok());
  EXPECT_FALSE(build_patch_meshes(256).ok());
}

TEST(LodSkirt, FourRotatedStripsTileTheRingToTheHorizon) {
  auto skirt = build_skirt(1024.0);
  ASSERT_TRUE(skirt.ok());
  const SkirtMesh& m = skirt.value();
  ASSERT_EQ(m.positions_xz.size(), 12u);
  EXPECT_EQ(m.strip.size(), 6u);
  ASSERT_EQ(m.triangles.size(), 12u);
  const double inner = 512.0, outer = 10240.0;
  double area = 0.0;
  for (const auto& r : m.rotations) {
    for (std::size_t t = 0; t < 12; t += 3) {
      double x[3], z[3];
      for (std::size_t k = 0; k < 3; ++k) {
        const double px = m.positions_xz[2 * m.triangles[t + k]];
        const double pz = m.positions_xz[2 * m.triangles[t + k] + 1];
        x[k] = r[0] * px + r[1] * pz;
        z[k] = -r[1] * px + r[0] * pz;
        EXPECT_GE(std::max(std::abs(x[k]), std::abs(z[k])), inner);  // outside the ocean square
        EXPECT_LE(std::max(std::abs(x[k]), std::abs(z[k])), outer);
      }
      const double a2 = (z[1] - z[0]) * (x[2] - x[0]) - (x[1] - x[0]) * (z[2] - z[0]);
      EXPECT_GT(a2, 0.0);  // faces +y in every rotation
      area += 0.5 * a2;
    }
  }
  EXPECT_DOUBLE_EQ(area, (2 * outer) * (2 * outer) - (2 * inner) * (2 * inner));
  EXPECT_TRUE(build_skirt(1024.0, 2000.0).ok());
  EXPECT_FALSE(build_skirt(1024.0, 2000.0, {.segments = 3, .rings = 4}).ok());
  EXPECT_FALSE(build_skirt(1024.0, 2000.0, {.segments = 64, .rings = 0}).ok());
  EXPECT_FALSE(build_skirt(1024.0, 2000.0, {.segments = 254, .rings = 64}).ok());  // > 16 bits
  EXPECT_FALSE(build_skirt(1024.0, 300.0).ok());
  EXPECT_FALSE(build_skirt(10.0).ok());
}

TEST(LodSkirt, ATessellatedSkirtTilesTheSameRingWithGeometricRings) {
  const double inner = 512.0, outer = 80000.0;
  auto skirt = build_skirt(1024.0, outer, {.segments = 8, .rings = 6});
  ASSERT_TRUE(skirt.ok());
  const SkirtMesh& m = skirt.value();
  ASSERT_EQ(m.positions_xz.size(), 2u * 9 * 7);
  ASSERT_EQ(m.triangles.size(), 3u * 2 * 8 * 6);
  EXPECT_TRUE(m.strip.empty());
  // Ring k at inner·(outer/inner)^(k/6): consecutive rings stand in one ratio.
  for (int k = 0; k <= 6; ++k) {
    const double d = m.positions_xz[static_cast<std::size_t>(2 * 9 * k + 1)];
    EXPECT_NEAR(d, inner * std::pow(outer / inner, k / 6.0), 1e-6 * d) << "ring " << k;
  }
  double area = 0.0;
  for (const auto& r : m.rotations) {
    for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
      double x[3], z[3];
      for (std::size_t k = 0; k < 3; ++k) {
        const double px = m.positions_xz[2 * m.triangles[t + k]];
        const double pz = m.positions_xz[2 * m.triangles[t + k] + 1];
        x[k] = r[0] * px + r[1] * pz;
        z[k] = -r[1] * px + r[0] * pz;
      }
      const double a2 = (z[1] - z[0]) * (x[2] - x[0]) - (x[1] - x[0]) * (z[2] - z[0]);
      EXPECT_GT(a2, 0.0);
      area += 0.5 * a2;
    }
  }
  EXPECT_NEAR(area, (2 * outer) * (2 * outer) - (2 * inner) * (2 * inner), 1e-6 * outer * outer);
}

}  // namespace
