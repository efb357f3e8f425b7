// The composited local surface in the picture (docs/rendering.md R.19, docs/math.md M.7.9–M.7.10):
// the renderer shades the area from Frame::local. Seen from straight above in the normals debug
// view (the shading normal as colour, the foam in alpha, linear HDR): over a nearly calm sea a
// waveform's pixels carry the normal the simulator computed for the composited surface, and a
// wake's pixels carry its accumulated foam where the sum folded and none where it did not; over a
// wind sea the picture is bit for bit the one without the layer wherever the layer is zero, inside
// the area and outside it. Skips where no Vulkan device exists (fails with
// OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "ocean/lod.hpp"
#include "ocean/scene.hpp"
#include "ocean/waves.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::Scene;
using ocean::render::View;
constexpr int kSurfSide = 192;

// Straight down from `height_m` over (x, z), 50° field of view.
View top_down(double x, double z, double height_m) {
  View view;
  view.camera = {.position_m = {x, height_m, z},
                 .target_m = {x + 1e-3 * height_m, 0.0, z},
                 .fov_y_rad = 50.0 * std::numbers::pi / 180.0,
                 .aspect = 1.0,
                 .near_m = 0.5,
                 .far_m = 1e5};
  view.shading = ocean::render::sky_preset("clear").value();
  return view;
}

// The pixel (col, row) that shows world point (x, y, z), or {−1, −1} off the picture.
std::array<int, 2> pixel_of(const View& view, double x, double y, double z) {
  const auto& m = ocean::lod::view_projection(view.camera).m;  // column-major
  const double cx = m[0] * x + m[4] * y + m[8] * z + m[12];
  const double cy = m[1] * x + m[5] * y + m[9] * z + m[13];
  const double cw = m[3] * x + m[7] * y + m[11] * z + m[15];
  const int col = static_cast<int>((cx / cw + 1.0) * 0.5 * kSurfSide);
  const int row = static_cast<int>((1.0 - cy / cw) * 0.5 * kSurfSide);
  if (col < 0 || col >= kSurfSide || row < 0 || row >= kSurfSide) return {-1, -1};
  return {col, row};
}

// A sea of 0.5 m/s wind: Hs of millimetres, slopes of the order of 10⁻³; slowly decaying foam.
ocean::SimulationConfig nearly_calm() {
  ocean::SimulationConfig c = ocean::render::testing::small_config();
  c.sea.wind_sea.spectrum.wind_speed_mps = 0.5;
  c.foam.source = ocean::FoamSource::ramp;  // the checks name the ramp's start
  c.foam.decay_per_s = 0.2;                 // foam lingers behind a wake for seconds
  return c;
}

// A 48 m square waveform of ridges along z, h = sin(2π·x/16 m), centred at the origin.
ocean::waves::Waveform ridges() {
  auto map = std::make_shared<ocean::waves::HeightMap>();
  map->rows = map->cols = 96;
  for (int r = 0; r < 96; ++r)
    for (int c = 0; c < 96; ++c)
      map->values.push_back(
          static_cast<float>(std::sin(2.0 * std::numbers::pi * (c + 0.5) / 32.0)));
  return {.map = map, .size_m = 48.0, .amplitude_m = 1.0};
}

std::shared_ptr<const ocean::waves::LocalLayer> make_layer(ocean::waves::LayerParams p) {
  auto made = ocean::waves::LocalLayer::make(std::move(p));
  EXPECT_TRUE(made.ok()) << made.status().message();
  return made.ok() ? std::move(made).value() : nullptr;
}

TEST(LocalSurfaceRender, PixelsCarryTheCompositedNormalAndAccumulatedFoam) {
  if (ocean::render::testing::graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto scene = Scene::make({.config = nearly_calm(), .width = kSurfSide, .height = kSurfSide});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  Scene& s = *scene.value();
  ocean::render::Renderer& r = s.renderer();
  std::vector<float> hdr;

  // The waveform: pixel normal against the simulator's normal of the sum at the cell centres.
  ocean::waves::LayerParams p;
  p.area = {.origin_m = {-32.0, -32.0}, .size_m = 64.0, .resolution = 128};
  p.waveforms.push_back(ridges());
  s.simulator().set_local_layer(make_layer(p));
  ASSERT_TRUE(s.step(2.0).ok());
  View view = top_down(0.0, 0.0, 70.0);
  view.debug = ocean::render::DebugView::normals;
  ASSERT_TRUE(r.draw(view).ok());
  ASSERT_TRUE(r.read_hdr(hdr).ok());
  const ocean::LocalSurfaceFrame& local = s.simulator().frame().local;
  double worst = 0.0, tilt = 0.0;
  int compared = 0;
  for (int row = 40; row < 88; row += 3) {
    for (int col = 40; col < 88; col += 3) {
      const auto [x, z] = ocean::waves::cell_centre(p.area, col, row);
      const std::size_t i = static_cast<std::size_t>(row) * 128 + static_cast<std::size_t>(col);
      const auto [pc, pr] = pixel_of(view, x, local.displacement[3 * i + 1], z);
      ASSERT_GE(pc, 0);
      const float* px = &hdr[(static_cast<std::size_t>(pr) * kSurfSide + pc) * 4];
      for (int k = 0; k < 3; ++k) {
        const double drawn = 2.0 * px[k] - 1.0;
        worst = std::max(worst, std::abs(drawn - local.normal[3 * i + k]));
      }
      tilt = std::max(tilt, std::abs(static_cast<double>(local.normal[3 * i])));
      ++compared;
    }
  }
  std::printf("waveform: %d pixels, largest |N_drawn - N_local| %.4f, largest |n_x| %.3f\n",
              compared, worst, tilt);
  EXPECT_GT(tilt, 0.3);  // the ridges tilt the normal by up to atan(2π/16) = 21°
  // Half-float texels, a pixel's 0.36 m footprint against 0.5 m cells on a ridge whose normal
  // turns by 0.2 per metre, and the sea's own slopes of ~1e-3.
  EXPECT_LT(worst, 0.06);

  // A wake: foam in the picture where the composited surface's accumulated foam exceeds the
  // sea's, none where the layer adds none; some of it where the sum no longer folds (accumulated).
  // Steep enough to fold over blocks of 5×5 cells (Fr = 0.38): the slender pressure's crests
  // (docs/waves.md W.4) are narrower than an 8 m hull's at 1 m made.
  p.waveforms.clear();
  // A hard edge: the hull, 8 m from the border, keeps its whole wake (W.9b's edge would fade it).
  p.area.edge_fraction = 0.0;
  p.wakes.push_back({.x_m = 24.0,
                     .heading_deg = 180.0,
                     .speed_mps = 4.5,
                     .hull_length_m = 14.0,
                     .peak_height_m = 1.6});
  s.simulator().set_local_layer(make_layer(p));
  ASSERT_TRUE(s.warm_up(3.0, 2.0).ok());
  ASSERT_TRUE(r.draw(view).ok());
  ASSERT_TRUE(r.read_hdr(hdr).ok());
  const ocean::LocalSurfaceFrame& wake = s.simulator().frame().local;
  const ocean::FoamParams& foam = s.simulator().config().foam;
  const auto added = [&](int c, int rr) {
    const std::size_t i = static_cast<std::size_t>(rr) * 128 + static_cast<std::size_t>(c);
    return wake.foam[i] - wake.sea_foam[i];
  };
  // The drawn foam (alpha) over the cell's centre, displaced as the surface is.
  const auto drawn = [&](int col, int row) {
    const std::size_t i = static_cast<std::size_t>(row) * 128 + static_cast<std::size_t>(col);
    const auto [x, z] = ocean::waves::cell_centre(p.area, col, row);
    const auto [pc, pr] =
        pixel_of(view, x + wake.layer_displacement[3 * i], wake.displacement[3 * i + 1],
                 z + wake.layer_displacement[3 * i + 2]);
    return pc < 0 ? -1.0f : hdr[(static_cast<std::size_t>(pr) * kSurfSide + pc) * 4 + 3];
  };
  // The least and most foam the layer adds over the (2r + 1)² cells around (col, row).
  const auto around = [&](int col, int row, int reach) {
    float lo = 1.0f, hi = 0.0f;
    for (int dr = -reach; dr <= reach; ++dr)
      for (int dc = -reach; dc <= reach; ++dc)
        lo = std::min(lo, added(col + dc, row + dr)), hi = std::max(hi, added(col + dc, row + dr));
    return std::array<float, 2>{lo, hi};
  };
  int foamy = 0, clear = 0, trail = 0, foamy_drawn = 0, clear_drawn = 0, trail_drawn = 0;
  for (int row = 2; row < 126; ++row) {
    for (int col = 2; col < 126; ++col) {
      const float alpha = drawn(col, row);
      if (alpha < 0.0f) continue;
      const auto [lo, hi] = around(col, row, 2);
      if (lo >= 0.8f) ++foamy, foamy_drawn += alpha > 0.7f;
      if (hi <= 0.0f) ++clear, clear_drawn += alpha > 0.05f;
      // Foam that stays where the sum no longer folds (J above the ramp's start): accumulated.
      const std::size_t i = static_cast<std::size_t>(row) * 128 + static_cast<std::size_t>(col);
      if (around(col, row, 1)[0] >= 0.5f &&
          wake.jacobian[i] > static_cast<float>(foam.jacobian_start))
        ++trail, trail_drawn += alpha > 0.4f;
    }
  }
  std::printf(
      "wake: %d foamy cells (%d drawn with foam), %d foamy and not folding now (%d drawn), "
      "%d clear (%d drawn with foam)\n",
      foamy, foamy_drawn, trail, trail_drawn, clear, clear_drawn);
  ASSERT_GT(foamy, 10);
  ASSERT_GT(trail, 10);
  ASSERT_GT(clear, 1000);
  EXPECT_GE(foamy_drawn, foamy * 9 / 10);
  EXPECT_GE(trail_drawn, trail * 9 / 10);
  EXPECT_LE(clear_drawn, clear / 100);
}

TEST(LocalSurfaceRender, TheSeaIsUnchangedWhereTheLayerIsZero) {
  if (ocean::render::testing::graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto scene = Scene::make(
      {.config = ocean::render::testing::small_config(), .width = kSurfSide, .height = kSurfSide});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  Scene& s = *scene.value();
  ocean::render::Renderer& r = s.renderer();
  // A 96 m area whose waveform covers only its middle 24 m: the layer is exactly 0 elsewhere.
  ocean::waves::LayerParams p;
  p.area = {.origin_m = {-48.0, -48.0}, .size_m = 96.0, .resolution = 192};
  ocean::waves::Waveform w = ridges();
  w.size_m = 24.0;
  p.waveforms.push_back(w);
  s.simulator().set_local_layer(make_layer(p));
  ASSERT_TRUE(s.warm_up(3.0, 1.0).ok());
  const View view = top_down(0.0, 0.0, 120.0);
  std::vector<std::uint8_t> with, without;
  ASSERT_TRUE(r.draw(view).ok());
  ASSERT_TRUE(r.read_srgb(with).ok());
  ASSERT_TRUE(r.set_local_surface({}).ok());  // removed
  ASSERT_TRUE(r.draw(view).ok());
  ASSERT_TRUE(r.read_srgb(without).ok());
  // Pixels over world points more than 3 m (the sea's horizontal displacement, a cell's
  // differences and a pixel) from the waveform's square, inside the area and out: identical.
  int outside = 0, changed_outside = 0, inside = 0, changed_inside = 0;
  for (double x = -54.0; x <= 54.0; x += 0.5) {
    for (double z = -54.0; z <= 54.0; z += 0.5) {
      const auto [col, row] = pixel_of(view, x, 0.0, z);
      if (col < 0) continue;
      const double beyond = std::max(std::abs(x), std::abs(z)) - 12.0;
      const std::size_t i = (static_cast<std::size_t>(row) * kSurfSide + col) * 4;
      const bool same =
          with[i] == without[i] && with[i + 1] == without[i + 1] && with[i + 2] == without[i + 2];
      if (beyond > 3.0) ++outside, changed_outside += !same;
      if (beyond < -3.0) ++inside, changed_inside += !same;
    }
  }
  std::printf("%d points away from the waveform (%d changed), %d over it (%d changed)\n", outside,
              changed_outside, inside, changed_inside);
  ASSERT_GT(outside, 10000);
  EXPECT_EQ(changed_outside, 0);
  EXPECT_GT(changed_inside, inside / 2);
}

}  // namespace
