// The tessellated mesh's levels on the CPU (ocean/tessellation.hpp, docs/rendering.md R.40–R.42),
// through the function the tessellation control shader runs: Algorithm 1's printed values, every
// edge two quads share given the same outer level from both sides (no T-junction), the printed
// per-quad levels leaving unequal shared edges, and bad parameters refused.
#include "ocean/tessellation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace ocean::render;

// Algorithm 1, lines 4–5 at points where the sine is known exactly: LOD = N at the projection
// point (Tess = N), LOD = N/2 at d = N·D_span/2 (Tess = N·sin(π/4)), LOD = 0 beyond N·D_span
// (Tess = 0, held at 1: a quad is never less than itself).
TEST(Tessellation, LevelsAreAlgorithmOnesPrintedValues) {
  const float n = 32.0f, span = 10.0f;
  EXPECT_FLOAT_EQ(tessellation_level(0.0f, n, span), 32.0f);
  EXPECT_NEAR(tessellation_level(160.0f, n, span), 32.0 * std::sin(std::numbers::pi / 4.0), 1e-4);
  EXPECT_NEAR(tessellation_level(80.0f, n, span), 32.0 * std::sin(3.0 * std::numbers::pi / 8.0),
              1e-4);
  EXPECT_FLOAT_EQ(tessellation_level(320.0f, n, span), 1.0f);
  EXPECT_FLOAT_EQ(tessellation_level(5000.0f, n, span), 1.0f);
  // Falls monotonically with the distance.
  float previous = tessellation_level(0.0f, n, span);
  for (float d = 1.0f; d < 400.0f; d += 1.0f) {
    const float level = tessellation_level(d, n, span);
    EXPECT_LE(level, previous) << d;
    previous = level;
  }
}

// The inner level is Algorithm 1's InTess = Tess/2 at the quad's centre (line 6).
TEST(Tessellation, InnerLevelIsHalfTheCentresLevel) {
  const TessellationParams params{.mesh = MeshMode::tessellation, .max_level = 16, .span_m = 4};
  const TessellationGrid grid{.corner_m = {-64, -64}, .cell_m = 8, .quads = 16, .eye_m = {3, -5}};
  const std::vector<QuadLevels> levels = tessellation_levels(params, grid);
  for (int j = 0; j < grid.quads; ++j)
    for (int i = 0; i < grid.quads; ++i) {
      const double cx = -64 + 8 * (i + 0.5) - 3, cz = -64 + 8 * (j + 0.5) + 5;
      const float centre = tessellation_level(static_cast<float>(std::hypot(cx, cz)), 16.0f, 4.0f);
      EXPECT_NEAR(levels[static_cast<std::size_t>(j * grid.quads + i)].inner,
                  std::max(0.5f * centre, 1.0f), 1e-4f);
    }
}

// How many edges two quads share with different outer levels from the two sides (compared
// bit for bit: the tessellator puts the same vertices on an edge only for the same level).
int mismatched_shared_edges(const std::vector<QuadLevels>& levels, int quads) {
  int mismatched = 0;
  const auto at = [&](int i, int j) -> const QuadLevels& {
    return levels[static_cast<std::size_t>(j * quads + i)];
  };
  for (int j = 0; j < quads; ++j)
    for (int i = 0; i < quads; ++i) {
      if (i + 1 < quads) mismatched += at(i, j).outer[2] != at(i + 1, j).outer[0];  // x = i + 1
      if (j + 1 < quads) mismatched += at(i, j).outer[3] != at(i, j + 1).outer[1];  // z = j + 1
    }
  return mismatched;
}

// Every shared edge gets one level from both sides, for eyes over the grid, off its corner and
// far away, and grids of odd sizes off the origin (float positions that are not round).
TEST(Tessellation, SharedEdgesHaveEqualLevels) {
  const TessellationGrid grids[] = {
      {.corner_m = {-1024, -1024}, .cell_m = 32, .quads = 64, .eye_m = {0, 0}},
      {.corner_m = {-1024, -1024}, .cell_m = 32, .quads = 64, .eye_m = {517.3f, -211.9f}},
      {.corner_m = {-300.7f, 12.3f}, .cell_m = 7.3f, .quads = 97, .eye_m = {-500, 900}},
      {.corner_m = {-2048, -2048}, .cell_m = 16, .quads = 256, .eye_m = {1.1f, 2.2f}}};
  for (const TessellationGrid& g : grids) {
    for (double span : {0.0, 3.0, 40.0}) {
      const TessellationParams params{
          .mesh = MeshMode::tessellation, .max_level = 24, .span_m = span};
      EXPECT_EQ(mismatched_shared_edges(tessellation_levels(params, g), g.quads), 0)
          << g.quads << " quads, span " << span;
    }
  }
}

// Algorithm 1 as printed (every outer level the quad centre's Tess) gives neighbours of
// different levels different outer levels on the edge they share: the T-junctions the shared
// edges remove, and what the check above would find without them.
TEST(Tessellation, PrintedPerQuadLevelsLeaveUnequalSharedEdges) {
  const TessellationGrid g{.corner_m = {-256, -256}, .cell_m = 8, .quads = 64, .eye_m = {0, 0}};
  const TessellationParams printed{
      .mesh = MeshMode::tessellation, .max_level = 16, .span_m = 8, .shared_edges = false};
  EXPECT_GT(mismatched_shared_edges(tessellation_levels(printed, g), g.quads), 100);
}

TEST(Tessellation, SpanDefaultsToHalfTheSquareOverN) {
  EXPECT_DOUBLE_EQ(tessellation_span_m({.max_level = 32}, 4096.0), 64.0);
  EXPECT_DOUBLE_EQ(tessellation_span_m({.max_level = 32, .span_m = 5.0}, 4096.0), 5.0);
}

TEST(Tessellation, RefusesBadParametersAndNames) {
  EXPECT_TRUE(validate(TessellationParams{}).ok());
  EXPECT_FALSE(validate(TessellationParams{.base_quads = 0}).ok());
  EXPECT_FALSE(validate(TessellationParams{.base_quads = 257}).ok());
  EXPECT_FALSE(validate(TessellationParams{.max_level = 0.5}).ok());
  EXPECT_FALSE(validate(TessellationParams{.max_level = 65}).ok());
  EXPECT_FALSE(validate(TessellationParams{.max_level = std::nan("")}).ok());
  EXPECT_FALSE(validate(TessellationParams{.span_m = INFINITY}).ok());
  EXPECT_EQ(parse_mesh_mode("tessellation").value(), MeshMode::tessellation);
  EXPECT_EQ(parse_mesh_mode("quadtree").value(), MeshMode::quadtree);
  const auto bad = parse_mesh_mode("triangles");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("quadtree or tessellation"), std::string::npos)
      << bad.status().message();
}

}  // namespace
