// Quadtree selection: L_max (eq. 56), hand-computed subdivisions (eqs. 57–58), balancing, culling
// against hand-built cameras (eqs. 59–61), neighbour flags (eqs. 62–64), batching (eq. 70),
// snapping (eq. 69) and the no-allocation contract.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "ocean/lod.hpp"

namespace {

using namespace ocean::lod;

LodParams uncull(double size, Quality q, Vec3 eye) {
  return {.ocean_size_m = size,
          .quality = q,
          .camera_position_m = eye,
          .cull = false,
          .follow_camera = false};
}

TEST(LodQuadtree, MaxLevelFollowsEq56) {
  // ⌊log2(S/64) + 0.5⌋ clamped to [2, 8], values worked by hand.
  EXPECT_EQ(max_level(256.0), 2);  // log2(4) = 2
  EXPECT_EQ(max_level(512.0), 3);
  EXPECT_EQ(max_level(1024.0), 4);
  EXPECT_EQ(max_level(4096.0), 6);
  EXPECT_EQ(max_level(8192.0), 7);  // log2(128) = 7
  EXPECT_EQ(max_level(720.0), 3);   // log2(11.25) = 3.49 -> 3.99 -> 3
  EXPECT_EQ(max_level(730.0), 4);   // log2(11.41) = 3.51 -> 4.01 -> 4
  EXPECT_EQ(max_level(100.0), 2);   // clamped up
  EXPECT_EQ(max_level(1.0e6), 8);   // clamped down
}

TEST(LodQuadtree, PresetsAreTable2) {
  const Quality low = quality_preset(QualityPreset::low);
  EXPECT_EQ(low.vertices, 16);
  EXPECT_EQ(low.lod_scale, 2.0);
  EXPECT_EQ(low.cull_scale, 1.2);
  const Quality ultra = quality_preset(QualityPreset::ultra);
  EXPECT_EQ(ultra.vertices, 64);
  EXPECT_EQ(ultra.lod_scale, 1.0);
  EXPECT_EQ(ultra.cull_scale, 2.0);
  EXPECT_EQ(quality_preset(QualityPreset::medium).vertices, 32);
  EXPECT_EQ(quality_preset(QualityPreset::high).lod_scale, 1.2);
  EXPECT_EQ(parse_preset("high").value(), QualityPreset::high);
  EXPECT_FALSE(parse_preset("extreme").ok());
}

// S = 1024, τ = 2, camera above the centre of a fixed grid. Root: d = h, subdivides if h < 2048.
// Level 1 (s = 512) centres at (±256, ±256): subdivide if 2·256² + h² < 1024², h < 957.9.
// Level 2 (s = 256) nearest centres (±128, ±128): subdivide if 2·128² + h² < 512², h < 479.
TEST(LodQuadtree, HandComputedSubdivisionAboveTheCentre) {
  const Quality low = quality_preset(QualityPreset::low);
  LodSelection sel;
  const struct {
    double h;
    int level;
    std::uint32_t count;
  } cases[] = {{3000.0, 0, 1}, {1000.0, 1, 4}, {900.0, 2, 16}};
  for (const auto& c : cases) {
    ASSERT_TRUE(select_patches(uncull(1024.0, low, {0.0, c.h, 0.0}), sel).ok());
    EXPECT_EQ(sel.instances.size(), c.count) << c.h;
    EXPECT_EQ(sel.patches_per_level[static_cast<std::size_t>(c.level)], c.count) << c.h;
    EXPECT_EQ(sel.patches_per_config[0], c.count) << "uniform grids need no stitching";
    ASSERT_EQ(sel.batches.size(), 1u);
    EXPECT_EQ(sel.batches[0].count, c.count);
  }
  // h = 400: of the 16 level-2 nodes only the inner four subdivide (2·128² + 400² < 512²;
  // (384, 128): 384² + 128² + 400² > 512²); their level-3 children do not (64²·2 + 400² > 256²).
  // So 12 level-2 and 16 level-3 patches; the 12 border ones of the 4×4 level-3 block stitch
  // towards level 2: the corners on two edges, two per side on one.
  ASSERT_TRUE(select_patches(uncull(1024.0, low, {0.0, 400.0, 0.0}), sel).ok());
  EXPECT_EQ(sel.patches_per_level[2], 12u);
  EXPECT_EQ(sel.patches_per_level[3], 16u);
  std::uint32_t flagged = 0;
  for (const PatchInstance& pi : sel.instances) {
    if (pi.level == 3 && pi.config != 0) ++flagged;
    if (pi.level == 2) {
      EXPECT_EQ(pi.config, 0);  // the coarser side never stitches
    }
  }
  EXPECT_EQ(flagged, 12u);  // the 4×4 block's 12 border patches
  EXPECT_EQ(sel.patches_per_config[kWest | kSouth], 1u);
  EXPECT_EQ(sel.patches_per_config[kEast | kNorth], 1u);
  EXPECT_EQ(sel.patches_per_config[kWest], 2u);
}

// A recursive reference of eq. 57 alone, to compare with the balanced selection.
void raw_levels(double size, double tau, Vec3 eye, int lmax, int l, int x, int y,
                std::vector<int>& map) {
  const double s = size / (1 << l);
  const double cx = -0.5 * size + (x + 0.5) * s, cz = -0.5 * size + (y + 0.5) * s;
  const double d2 = (cx - eye.x) * (cx - eye.x) + eye.y * eye.y + (cz - eye.z) * (cz - eye.z);
  if (l < lmax && d2 < (s * tau) * (s * tau)) {
    for (int k = 0; k < 4; ++k)
      raw_levels(size, tau, eye, lmax, l + 1, 2 * x + k % 2, 2 * y + k / 2, map);
    return;
  }
  const int w = 1 << lmax, delta = 1 << (lmax - l);
  for (int j = y * delta; j < (y + 1) * delta; ++j) {
    for (int i = x * delta; i < (x + 1) * delta; ++i) map[static_cast<std::size_t>(j * w + i)] = l;
  }
}

TEST(LodQuadtree, BalancingOnlyRefinesAndIsNeededForSmallTau) {
  const Quality ultra = quality_preset(QualityPreset::ultra);  // τ = 1 < 1.58: unbalanced trees
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2000.0, 2000.0);
  LodSelection sel;
  int refined_cases = 0;
  for (int i = 0; i < 50; ++i) {
    const Vec3 eye{u(rng), 1.0 + std::abs(u(rng)) * 0.05, u(rng)};
    ASSERT_TRUE(select_patches(uncull(4096.0, ultra, eye), sel).ok());
    std::vector<int> raw(sel.subdivision_map.size());
    raw_levels(4096.0, 1.0, eye, sel.max_level, 0, 0, 0, raw);
    bool refined = false;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      ASSERT_GE(sel.subdivision_map[k], raw[k]);
      refined = refined || sel.subdivision_map[k] > raw[k];
    }
    refined_cases += refined ? 1 : 0;
  }
  EXPECT_GT(refined_cases, 0);
}

TEST(LodQuadtree, CullingAgainstHandBuiltCameras) {
  const Quality medium = quality_preset(QualityPreset::medium);
  LodSelection all, seen;
  const Vec3 eye{0.0, 10.0, 0.0};
  LodParams p = uncull(1024.0, medium, eye);
  ASSERT_TRUE(select_patches(p, all).ok());
  // Looking along +x, level: everything with its (β-scaled, displacement-padded) box at x < 0
  // is behind the near plane x = 0.5.
  p.cull = true;
  p.frustum = camera_frustum({.position_m = eye, .target_m = {100.0, 10.0, 0.0}});
  ASSERT_TRUE(select_patches(p, seen).ok());
  EXPECT_GT(seen.instances.size(), 0u);
  EXPECT_LT(seen.instances.size(), all.instances.size());
  EXPECT_EQ(seen.subdivision_map, all.subdivision_map);  // culling never changes the tree
  bool ahead = false;
  for (const PatchInstance& pi : seen.instances) {
    const double e = 0.5 * pi.size_m * medium.cull_scale;
    EXPECT_GE(pi.centre_x_m + e, 0.5) << "patch behind the camera";
    if (std::abs(pi.centre_z_m) < pi.size_m && pi.centre_x_m > 200.0 &&
        pi.centre_x_m - 0.5 * pi.size_m < 300.0) {
      ahead = true;
    }
  }
  EXPECT_TRUE(ahead) << "the patch straight ahead at x ≈ 250 m is drawn";
  // Every emitted patch is a leaf of the unculled selection.
  for (const PatchInstance& pi : seen.instances) {
    bool found = false;
    for (const PatchInstance& q : all.instances) {
      found = found || (q.grid_x == pi.grid_x && q.grid_y == pi.grid_y && q.level == pi.level);
    }
    EXPECT_TRUE(found);
  }
  // Looking at the sky from 100 m: the boxes reach y = 0.015·1024 = 15.4 m only.
  p.camera_position_m = {0.0, 100.0, 0.0};
  p.frustum = camera_frustum({.position_m = {0.0, 100.0, 0.0}, .target_m = {0.0, 200.0, 1.0}});
  ASSERT_TRUE(select_patches(p, seen).ok());
  EXPECT_EQ(seen.instances.size(), 0u);
  EXPECT_TRUE(seen.batches.empty());
  // A larger vertical displacement bound brings them back (the boxes reach the camera).
  p.max_vertical_displacement_m = 150.0;
  ASSERT_TRUE(select_patches(p, seen).ok());
  EXPECT_GT(seen.instances.size(), 0u);
  // Far outside a fixed square, looking away from it: nothing.
  p = uncull(1024.0, medium, {5000.0, 20.0, 0.0});
  p.cull = true;
  p.frustum = camera_frustum({.position_m = {5000.0, 20.0, 0.0}, .target_m = {6000.0, 0.0, 0.0}});
  ASSERT_TRUE(select_patches(p, seen).ok());
  EXPECT_EQ(seen.instances.size(), 0u);
  // ... and looking back at it: something.
  p.frustum = camera_frustum({.position_m = {5000.0, 20.0, 0.0}, .target_m = {0.0, 0.0, 0.0}});
  ASSERT_TRUE(select_patches(p, seen).ok());
  EXPECT_GT(seen.instances.size(), 0u);
}

TEST(LodQuadtree, BatchesGroupInstancesByConfiguration) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1500.0, 1500.0);
  LodSelection sel;
  for (int i = 0; i < 40; ++i) {
    const Vec3 eye{u(rng), 2.0 + std::abs(u(rng)) * 0.2, u(rng)};
    LodParams p{.ocean_size_m = 4096.0,
                .quality = quality_preset(QualityPreset::high),
                .camera_position_m = eye,
                .frustum = camera_frustum({.position_m = eye, .target_m = {0.0, 0.0, 0.0}}),
                .cull = (i % 2) == 0};
    ASSERT_TRUE(select_patches(p, sel).ok());
    ASSERT_LE(sel.batches.size(), 16u);
    std::uint32_t next = 0, prev_config = 0;
    for (std::size_t b = 0; b < sel.batches.size(); ++b) {
      const Batch& batch = sel.batches[b];
      EXPECT_EQ(batch.first, next);
      EXPECT_GT(batch.count, 0u);
      if (b > 0) {
        EXPECT_GT(batch.config, prev_config);
      }
      prev_config = batch.config;
      EXPECT_EQ(batch.count, sel.patches_per_config[batch.config]);
      for (std::uint32_t k = batch.first; k < batch.first + batch.count; ++k) {
        EXPECT_EQ(sel.instances[k].config, batch.config);
      }
      next += batch.count;
    }
    EXPECT_EQ(next, sel.instances.size());
    EXPECT_EQ(std::accumulate(sel.patches_per_level.begin(), sel.patches_per_level.end(), 0u),
              sel.instances.size());
    // Instance geometry matches its grid cell (eq. 58, 70).
    for (const PatchInstance& pi : sel.instances) {
      const double s = 4096.0 / (1 << pi.level);
      EXPECT_FLOAT_EQ(pi.size_m, static_cast<float>(s));
      EXPECT_NEAR(pi.centre_x_m, sel.grid_centre_x_m - 2048.0 + (pi.grid_x + 0.5) * s, 1e-3);
      EXPECT_NEAR(pi.centre_z_m, sel.grid_centre_z_m - 2048.0 + (pi.grid_y + 0.5) * s, 1e-3);
    }
  }
}

TEST(LodQuadtree, SelectionDoesNotAllocateAfterReserve) {
  LodSelection sel;
  ASSERT_TRUE(reserve_selection(sel, 8192.0).ok());
  const auto* instances = sel.instances.data();
  const auto* map = sel.subdivision_map.data();
  const auto* split = sel.split.data();
  const auto* stack = sel.stack.data();
  const auto* batches = sel.batches.data();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-5000.0, 5000.0);
  for (int i = 0; i < 100; ++i) {
    const Vec3 eye{u(rng), 0.5 + std::abs(u(rng)) * 0.1, u(rng)};
    LodParams p = uncull((i % 2) ? 8192.0 : 300.0, quality_preset(QualityPreset::ultra), eye);
    p.follow_camera = true;
    ASSERT_TRUE(select_patches(p, sel).ok());
  }
  EXPECT_EQ(sel.instances.data(), instances);
  EXPECT_EQ(sel.subdivision_map.data(), map);
  EXPECT_EQ(sel.split.data(), split);
  EXPECT_EQ(sel.stack.data(), stack);
  EXPECT_EQ(sel.batches.data(), batches);
}

TEST(LodQuadtree, SnappingKeepsEveryLevelOnAFixedLattice) {
  EXPECT_EQ(snap_step_m(1024.0, 32), 32.0);
  EXPECT_EQ(snap(70.0, 32.0), 64.0);
  EXPECT_EQ(snap(-1.0, 32.0), -32.0);
  EXPECT_EQ(snap(64.0, 32.0), 64.0);
  const Quality medium = quality_preset(QualityPreset::medium);
  LodSelection sel;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3000.0, 3000.0);
  for (int i = 0; i < 30; ++i) {
    const Vec3 eye{u(rng), 40.0, u(rng)};
    LodParams p = uncull(1024.0, medium, eye);
    p.follow_camera = true;
    ASSERT_TRUE(select_patches(p, sel).ok());
    EXPECT_EQ(sel.grid_centre_x_m, std::floor(eye.x / 32.0) * 32.0);
    EXPECT_EQ(sel.grid_centre_z_m, std::floor(eye.z / 32.0) * 32.0);
    EXPECT_LE(eye.x - sel.grid_centre_x_m, 32.0);
    // Every patch corner is a multiple of its own vertex spacing s_l/V in world space, so
    // vertices of a level land on the same world points whatever the camera.
    for (const PatchInstance& pi : sel.instances) {
      const double s = 1024.0 / (1 << pi.level);
      const double corner_x = sel.grid_centre_x_m - 512.0 + pi.grid_x * s;
      const double spacing = s / medium.vertices;
      EXPECT_EQ(std::fmod(corner_x, spacing), 0.0) << corner_x << " " << spacing;
    }
  }
}

TEST(LodQuadtree, InvalidParametersAreRejected) {
  LodSelection sel;
  LodParams p = uncull(1024.0, quality_preset(QualityPreset::low), {0.0, 10.0, 0.0});
  p.ocean_size_m = 100.0;
  ocean::Status s = select_patches(p, sel);
  EXPECT_EQ(s.code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(s.message().find("ocean_size_m"), std::string::npos);
  EXPECT_TRUE(sel.instances.empty());
  p.ocean_size_m = 1024.0;
  p.quality.vertices = 15;
  EXPECT_NE(select_patches(p, sel).message().find("quality.vertices"), std::string::npos);
  p.quality = quality_preset(QualityPreset::low);
  p.quality.cull_scale = 0.5;
  EXPECT_NE(select_patches(p, sel).message().find("quality.cull_scale"), std::string::npos);
  p.quality = quality_preset(QualityPreset::low);
  p.camera_position_m.y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(select_patches(p, sel).message().find("camera_position_m"), std::string::npos);
  p.camera_position_m.y = 10.0;
  p.max_horizontal_displacement_m = -1.0;
  EXPECT_FALSE(select_patches(p, sel).ok());
  EXPECT_FALSE(reserve_selection(sel, 1e5).ok());
}

}  // namespace
