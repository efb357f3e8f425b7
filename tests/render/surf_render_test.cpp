// The surf in the picture (docs/rendering.md R.63, docs/waves.md W.25–W.27): straight down over a
// planar beach built here, on a calm sea (no cascades: the foam is the surf's alone), the foam
// coverage the shading draws (the normals view's alpha) is Battjes & Janssen's fraction of
// breaking waves computed here from the closed forms, and full foam begins where H_rms = γ·d.
// Land (R.64): a plateau 8 m high seen from 2 m up stands above the horizon, its top edge at the
// elevation its height and distance give, and is sand-coloured. Skips where no Vulkan device
// exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "ocean/scene.hpp"
#include "ocean/waves.hpp"
#include "render/render_helpers.hpp"
#include "support/depth_law.hpp"
#include "support/require_devices.hpp"

namespace surf_render_test {

using ocean::render::Scene;
using ocean::render::View;
constexpr double kG = 9.81;
constexpr double kGamma = 0.78;

using ocean_test::kitaigorodskii_phi;  // W.12's closed form (support/depth_law.hpp)

// Q_b of Battjes & Janssen (1978): the root of (1 − Q)/ln Q = −b², by bisection on ln Q.
double battjes_janssen(double b) {
  if (b >= 1.0) return 1.0;
  double lo = -1.0 / (b * b), hi = -(1.0 - b * b);  // e^y − 1 − b²y > 0 at lo, < 0 at hi
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::exp(mid) - 1.0 - b * b * mid > 0.0 ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

TEST(SurfRender, TheFoamBandIsTheFractionOfBreakingWavesAndSaturatesAtTheBreakingIndex) {
  if (ocean::render::testing::graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const ocean::SimulationConfig config = ocean::render::testing::small_config();
  const std::vector<double> k = ocean::band_wavenumbers(config);
  const auto variances = ocean::band_variances(config);
  ASSERT_TRUE(variances.ok()) << variances.status().message();
  const std::vector<double> m0 = variances.value();

  // A planar beach, d = x/50 for x in [0, 128] m, on a map of 0.25 m cells.
  const double slope = 1.0 / 50.0, size = 128.0;
  constexpr int kCells = 512;
  const double cell = size / kCells;
  auto map = std::make_shared<ocean::waves::HeightMap>();
  map->rows = map->cols = kCells;
  for (int r = 0; r < kCells; ++r)
    for (int c = 0; c < kCells; ++c) map->values.push_back(float(slope * (c + 0.5) * cell));
  auto damping = ocean::waves::Damping::make(
      {.bathymetry = ocean::waves::PlacedMap{.map = map, .origin_m = {0.0, -64.0}, .size_m = size},
       .band_wavenumbers_radpm = k,
       .band_variances_m2 = m0,
       .breaking_index = kGamma});
  ASSERT_TRUE(damping.ok()) << damping.status().message();

  // The analytic surf: H_rms(d)² = 8·Σ Φ_c(d)·m0_c, b = H_rms/(γ·d), onset where b = 1.
  const auto b_at = [&](double x) {
    const double d = slope * x;
    double v = 0.0;
    for (std::size_t c = 0; c < k.size(); ++c)
      v += kitaigorodskii_phi(std::sqrt(kG * k[c]), d) * m0[c];
    return std::sqrt(8.0 * v) / (kGamma * d);
  };
  double lo = 0.01, hi = size;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (b_at(mid) > 1.0 ? lo : hi) = mid;
  }
  const double x_break = lo;
  ASSERT_GT(x_break, 12.0);
  ASSERT_LT(x_break, 80.0);

  // The grid the renderer reads, sampled at its cells' centres as `ocean render` samples it.
  std::vector<float> weights(ocean::render::kDampingBands * kCells * kCells, 1.0f);
  std::vector<float> depth(kCells * kCells), breaking(kCells * kCells);
  std::vector<double> w(k.size());
  for (int r = 0; r < kCells; ++r) {
    for (int c = 0; c < kCells; ++c) {
      const double x = (c + 0.5) * cell, z = -64.0 + (r + 0.5) * cell;
      const std::size_t i = std::size_t(r) * kCells + c;
      damping.value().band_weights(x, z, w);
      for (std::size_t b = 0; b < k.size(); ++b)
        weights[i * ocean::render::kDampingBands + b] = float(w[b]);
      const ocean::waves::Surf s = damping.value().surf(x, z);
      depth[i] = float(s.depth_m);
      breaking[i] = float(s.breaking_fraction);
    }
  }

  constexpr int kW = 240, kH = 60;
  auto scene = Scene::make({.config = config, .width = kW, .height = kH});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_TRUE(scene.value()->warm_up(2.0, 1.0).ok());
  ocean::render::Renderer& r = scene.value()->renderer();
  r.set_calm(true);  // no cascades: the surf's foam alone
  ASSERT_TRUE(r.set_damping({.origin_m = {0.0, -64.0},
                             .size_m = size,
                             .resolution = kCells,
                             .band_weights = weights,
                             .depth_m = depth,
                             .breaking_fraction = breaking})
                  .ok());
  // Straight down from 12 m over the onset: columns run along x, 0.1 m per pixel.
  const double height = 12.0, fov_y = 2.0 * std::atan(3.0 / height);
  const double half_width = height * std::tan(0.5 * fov_y) * kW / kH;  // 12 m
  View view;
  view.camera = {.position_m = {x_break, height, 0.0},
                 .target_m = {x_break, 0.0, 0.002},
                 .fov_y_rad = fov_y,
                 .aspect = double(kW) / kH,
                 .near_m = 0.5,
                 .far_m = 1e4};
  view.shading = ocean::render::sky_preset("clear").value();
  view.debug = ocean::render::DebugView::normals;  // foam coverage in alpha
  ASSERT_TRUE(r.draw(view).ok());
  std::vector<float> hdr;
  ASSERT_TRUE(r.read_hdr(hdr).ok());
  // The mean alpha of each column over the middle rows.
  std::vector<double> alpha(kW, 0.0);
  for (int col = 0; col < kW; ++col) {
    for (int row = kH / 4; row < 3 * kH / 4; ++row)
      alpha[col] += hdr[(std::size_t(row) * kW + col) * 4 + 3];
    alpha[col] /= kH / 2;
  }
  // Which way x runs across the picture: the shallow (saturated) side.
  const double sign = alpha.front() > alpha.back() ? 1.0 : -1.0;
  const auto x_of = [&](int col) {
    return x_break + sign * (2.0 * (col + 0.5) / kW - 1.0) * half_width;
  };
  double worst = 0.0, onset = -1.0;
  for (int i = 0; i < kW; ++i) {
    const int col = sign > 0 ? i : kW - 1 - i;  // from the shore seawards
    const double x = x_of(col);
    // The rendered value lies within the analytic Q_b over a cell's neighbourhood (the grid is
    // sampled at cell centres and interpolated), and the half float's 2⁻¹¹.
    const double q_lo = battjes_janssen(b_at(x + cell)), q_hi = battjes_janssen(b_at(x - cell));
    const double err = std::max({alpha[col] - q_hi, q_lo - alpha[col], 0.0}) - 1e-3;
    worst = std::max(worst, err);
    EXPECT_LE(err, 0.0) << "x = " << x << ": rendered " << alpha[col] << ", analytic [" << q_lo
                        << ", " << q_hi << "]";
    if (alpha[col] >= 0.999) onset = x;  // the last saturated column, seawards
  }
  std::printf(
      "onset of breaking: analytic x = %.3f m (d = %.3f m), rendered %.3f m; pixel %.3f m, "
      "cell %.3f m; foam at x_b + 5 m: %.3f rendered, %.3f analytic\n",
      x_break, x_break * slope, onset, 2.0 * half_width / kW, cell,
      alpha[std::size_t(std::clamp((sign * 5.0 / half_width + 1.0) * kW / 2.0, 0.0, kW - 1.0))],
      battjes_janssen(b_at(x_break + 5.0)));
  EXPECT_NEAR(onset, x_break, cell + 2.0 * half_width / kW);
}

TEST(SurfRender, LandStandsAtItsHeight) {
  if (ocean::render::testing::graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  // A grid of 0.5 m cells over x in [0, 128] m: water 20 m deep, then from x = 60 m land 8 m
  // high (depth −8). Bilinear between the cell centres at 59.75 and 60.25 m, the shoreline lies
  // at 60.11 m and the plateau is at full height from 60.25 m.
  constexpr int kCells = 256;
  const double size = 128.0, cell = size / kCells, plateau = 8.0;
  std::vector<float> weights(ocean::render::kDampingBands * kCells * kCells, 1.0f);
  std::vector<float> depth(kCells * kCells);
  for (int r = 0; r < kCells; ++r)
    for (int c = 0; c < kCells; ++c)
      depth[std::size_t(r) * kCells + c] = (c + 0.5) * cell >= 60.0 ? float(-plateau) : 20.0f;
  constexpr int kW = 64, kH = 96;
  auto scene =
      Scene::make({.config = ocean::render::testing::small_config(), .width = kW, .height = kH});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_TRUE(scene.value()->warm_up(2.0, 1.0).ok());
  ocean::render::Renderer& r = scene.value()->renderer();
  r.set_calm(true);
  ASSERT_TRUE(r.set_damping({.origin_m = {0.0, -64.0},
                             .size_m = size,
                             .resolution = kCells,
                             .band_weights = weights,
                             .depth_m = depth})
                  .ok());
  // From 2 m up, looking level along +x: the horizon on the middle row.
  const double eye = 2.0, fov_y = 16.0 * std::numbers::pi / 180.0;
  View view;
  view.camera = {.position_m = {0.0, eye, 0.0},
                 .target_m = {100.0, eye, 0.0},
                 .fov_y_rad = fov_y,
                 .aspect = double(kW) / kH,
                 .near_m = 0.5,
                 .far_m = 1e4};
  view.shading = ocean::render::sky_preset("clear").value();
  ASSERT_TRUE(r.draw(view).ok());
  std::vector<float> hdr;
  ASSERT_TRUE(r.read_hdr(hdr).ok());
  // In each of the middle columns the topmost sand pixel (red over blue above 1.2: sand of
  // albedo 0.45/0.30 under a bluish sky light; sky and water are bluer), as tan of its elevation
  // at its top edge.
  const double tan_half = std::tan(0.5 * fov_y), px = 2.0 * tan_half / kH;
  const double top_near = (plateau - eye) / 60.25;  // the plateau's first point at full height
  for (int col = kW / 4; col < 3 * kW / 4; ++col) {
    int top = -1;
    for (int row = 0; row < kH && top < 0; ++row) {
      const float* p = &hdr[(std::size_t(row) * kW + col) * 4];
      if (p[0] > 1.2f * p[2]) top = row;
    }
    ASSERT_GE(top, 0) << "no sand in column " << col;
    const double tan_top = tan_half - top * px;  // the row's upper edge
    // The top edge lies where the mesh's first vertex at full height is: at 60.25 m, or a vertex
    // spacing (under 3 m at 60 m) beyond; a pixel either side for the rasterisation.
    EXPECT_LE(tan_top, top_near + px) << "column " << col;
    EXPECT_GE(tan_top, (plateau - eye) / 63.25 - px) << "column " << col;
    if (col == kW / 2)
      std::printf(
          "plateau's top edge: tan %.4f drawn, %.4f at 60.25 m (%.4f at 63.25 m); pixel %.4f\n",
          tan_top, top_near, (plateau - eye) / 63.25, px);
    // Drawn at the sea level, the land would not rise above the horizon.
    EXPECT_GT(tan_top, 0.5 * top_near);
  }
}

}  // namespace surf_render_test
