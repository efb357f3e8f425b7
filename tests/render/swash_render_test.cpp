// The swash in the picture (docs/rendering.md R.67, docs/waves.md W.40–W.43): straight down over
// a planar 1:10 beach built here, over 24 times spread evenly through one peak period, the
// landward-most pixel under the swash's sheet (the normals view's foam alpha, which only the sheet
// carries on land) in each row reaches, at its furthest, R2%/β beyond the shoreline, with R2% of
// Stockdon et al. (2006, eq. 19) computed here from the sea's Hs and the peak period of the
// JONSWAP fetch law (Hasselmann et al. 1973); at every time each row's water line lies where the
// CPU twin (waves::swash_elevation_m, swash_alongshore_phase) puts it, and half a period later it
// has moved. Skips where no Vulkan device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "ocean/plan.hpp"
#include "ocean/scene.hpp"
#include "ocean/waves.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace swash_render_test {

using ocean::render::Scene;
using ocean::render::View;

TEST(SwashRender, TheSheetReachesTheRunupOncePerPeriodAndTheLineMoves) {
  if (ocean::render::testing::graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const ocean::SimulationConfig config = ocean::render::testing::small_config();
  // The peak of the JONSWAP fetch law (Hasselmann et al. 1973): f_p = 3.5·(g/U)·x̃^−0.33,
  // x̃ = g·F/U², for the small sea's U = 12 m/s and F = 100 km.
  const double g = 9.81, u10 = 12.0, fetch = 100e3;
  const double omega_p =
      2.0 * std::numbers::pi * 3.5 * (g / u10) * std::pow(g * fetch / (u10 * u10), -0.33);
  const double period = 2.0 * std::numbers::pi / omega_p;
  auto plan = ocean::SimulationPlan::make(config);
  ASSERT_TRUE(plan.ok()) << plan.status().message();
  EXPECT_NEAR(plan.value().surface().peak_period_s, period, 1e-9 * period);

  // A planar beach: d = β·(x_s − x) on 0.125 m cells over x in [0, 64] m; land beyond x_s.
  const double beta = 0.1, x_shore = 30.0, size = 64.0, z0 = -32.0;
  constexpr int kCells = 512;
  const double cell = size / kCells;
  std::vector<float> weights(ocean::render::kDampingBands * kCells * kCells, 1.0f);
  std::vector<float> depth(kCells * kCells);
  for (int r = 0; r < kCells; ++r)
    for (int c = 0; c < kCells; ++c)
      depth[std::size_t(r) * kCells + c] = float(beta * (x_shore - (c + 0.5) * cell));

  constexpr int kW = 160, kH = 96;
  auto scene = Scene::make({.config = config, .width = kW, .height = kH});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ocean::render::Renderer& r = scene.value()->renderer();
  const double t0 = 20.0;
  ASSERT_TRUE(scene.value()->warm_up(t0, 0.5).ok());
  r.set_calm(true);  // no cascades: on the water no foam at all
  ASSERT_TRUE(r.set_damping({.origin_m = {0.0, z0},
                             .size_m = size,
                             .resolution = kCells,
                             .band_weights = weights,
                             .depth_m = depth})
                  .ok());

  // Stockdon et al. (2006), eqs. 10, 19: the run-up of this sea on this beach, and its reach.
  const double h0 = r.significant_wave_height_m();
  const double l0 = g * period * period / (2.0 * std::numbers::pi);
  const double hl = h0 * l0;
  const double setup = 0.35 * beta * std::sqrt(hl);
  const double swash = std::sqrt(hl * (0.563 * beta * beta + 0.004));
  const double runup2 = 1.1 * (setup + 0.5 * swash);
  const double x_runup = x_shore + runup2 / beta;

  // Straight down from 12 m over x = 36 m: 0.125 m per pixel, screen right −x, up +z.
  const double height = 12.0, x_c = 36.0, half_h = 6.0, half_w = half_h * kW / kH;
  const double pixel = 2.0 * half_w / kW;
  View view;
  view.camera = {.position_m = {x_c, height, 0.0},
                 .target_m = {x_c, 0.0, 0.002},
                 .fov_y_rad = 2.0 * std::atan(half_h / height),
                 .aspect = double(kW) / kH,
                 .near_m = 0.5,
                 .far_m = 1e4};
  view.shading = ocean::render::sky_preset("clear").value();
  view.debug = ocean::render::DebugView::normals;  // the normal in rgb, the foam in alpha
  // Where a pixel's ray meets the beach: at the offset o it has on the sea level, scaled by
  // (H − h)/H where the land stands h = β·(x − x_s) high: x − x_c = o·(H − β·(x − x_s))/H.
  const auto x_of = [&](int col) {
    const double o = -(2.0 * (col + 0.5) / kW - 1.0) * half_w;
    const double x = (x_c + o * (height + beta * x_shore) / height) / (1.0 + o * beta / height);
    return x > x_shore ? x : x_c + o;
  };
  const auto z_of = [&](int row, double x) {
    return (1.0 - 2.0 * (row + 0.5) / kH) * half_h * (height - beta * std::max(x - x_shore, 0.0)) /
           height;
  };

  // The twin's water line in each row at time t: x_s + level/β where the level is above the
  // sea, none (the shoreline) below it.
  const ocean::waves::Runup twin = ocean::waves::stockdon_runup(h0, l0, beta);
  ASSERT_NEAR(twin.runup2_m, runup2, 1e-9);
  const auto twin_reach = [&](int row, double t) {
    double x = x_shore;  // the row's z depends a little on where the line is: two passes
    for (int pass = 0; pass < 2; ++pass) {
      const double phase =
          t / period + ocean::waves::swash_alongshore_phase(x_shore, z_of(row, x) - z0, l0);
      x = x_shore + std::max(ocean::waves::swash_elevation_m(twin, phase), 0.0) / beta;
    }
    return x;
  };

  constexpr int kTimes = 24;
  std::vector<double> furthest(kH, x_shore);
  std::vector<std::vector<double>> reach(kTimes, std::vector<double>(kH, x_shore));
  double worst_twin = 0.0;
  for (int i = 0; i < kTimes; ++i) {
    const double t = t0 + i * period / kTimes;
    ASSERT_TRUE(scene.value()->step(t).ok());
    ASSERT_TRUE(r.draw(view).ok());
    std::vector<float> hdr;
    ASSERT_TRUE(r.read_hdr(hdr).ok());
    if (i == 0) {  // the land (its normal tilted seawards, −x: red below ½) on the left
      EXPECT_LT(hdr[(std::size_t(kH / 2) * kW + 2) * 4], 0.49f);
      EXPECT_NEAR(hdr[(std::size_t(kH / 2) * kW + kW - 3) * 4], 0.5f, 0.01f);
    }
    for (int row = 0; row < kH; ++row) {
      for (int col = 0; col < kW; ++col) {  // the landward-most pixel under the sheet
        if (hdr[(std::size_t(row) * kW + col) * 4 + 3] > 0.05f) {
          reach[i][row] = x_of(col);
          break;
        }
      }
      furthest[row] = std::max(furthest[row], reach[i][row]);
      // A covered pixel's centre lies below the line, the next landward one's above it; where the
      // line runs steeply across the rows, a pixel's height of it either side.
      const double expected = twin_reach(row, t);
      const double slope_rows =
          std::abs(twin_reach(row + 1, t) - twin_reach(row - 1, t)) / 2.0;  // m per row
      const double err = std::abs(reach[i][row] - expected) - (pixel + slope_rows + 0.02);
      worst_twin = std::max(worst_twin, std::abs(reach[i][row] - expected));
      if (expected > x_shore + pixel) {
        EXPECT_LE(err, 0.0) << "row " << row << " at t = " << t << ": drawn " << reach[i][row]
                            << " m, twin " << expected << " m";
      } else if (expected <= x_shore) {  // run down below the sea level: no sheet on the land
        EXPECT_LE(reach[i][row], x_shore + pixel + slope_rows) << "row " << row << " at t = " << t;
      }
    }
  }
  // The furthest reach in each row over the period: R2%/β beyond the shoreline, less a pixel
  // (the last covered pixel's centre), less what 24 samples of the parabola may miss at its top
  // (4·(1/48)² of the swash's range), and 0.02 m for the half floats: a height rounded by up to
  // 2⁻¹¹ m (0.005 m over β) and the slope from two of them 6.5 m apart (≤ 1.5·10⁻⁴, whose
  // dR2%/dβ = 8.7 m makes 0.013 m of reach).
  const double range = runup2 - (setup - 0.5 * swash);
  const double sampling = 4.0 * range / (48.0 * 48.0) / beta;
  double lo = 1e9, hi = -1e9;
  for (int row = 0; row < kH; ++row) {
    lo = std::min(lo, furthest[row]), hi = std::max(hi, furthest[row]);
    EXPECT_LE(furthest[row], x_runup + 0.02) << "row " << row;
    EXPECT_GE(furthest[row], x_runup - pixel - sampling - 0.02) << "row " << row;
  }
  // Half a period apart the water line differs.
  double moved = 0.0;
  for (int row = 0; row < kH; ++row) moved += std::abs(reach[0][row] - reach[kTimes / 2][row]);
  moved /= kH;
  std::printf(
      "H0 %.3f m, T_p %.3f s, L0 %.2f m, beta %.2f: setup %.3f m, S %.3f m, R2 %.3f m -> reach "
      "%.3f m beyond the shore; drawn furthest %.3f-%.3f m (pixel %.3f m, sampling %.3f m); "
      "worst |drawn - twin| %.3f m; mean line shift over half a period %.3f m\n",
      h0, period, l0, beta, setup, swash, runup2, runup2 / beta, lo - x_shore, hi - x_shore, pixel,
      sampling, worst_twin, moved);
  EXPECT_GT(moved, 1.0);
}

}  // namespace swash_render_test
