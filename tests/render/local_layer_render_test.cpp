// The local layer in the picture (docs/rendering.md R.19): a Kelvin wake (ocean/waves.hpp)
// handed to the renderer changes the rendered sea inside the wake's wedge behind the object and
// leaves it alone elsewhere. Seen from above, the picture with the wake minus the picture
// without it is compared inside Kelvin's 19.47° half-angle (with a margin) and outside 35°.
// Skips where no Vulkan device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "ocean/scene.hpp"
#include "ocean/waves.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::Scene;
using ocean::render::View;

TEST(LocalLayerRender, AKelvinWakeShowsInsideItsWedgeOnly) {
  if (ocean::render::testing::graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  constexpr int kLayerSide = 256;
  constexpr double kTime = 20.0;
  // A 40 m hull at 6 m/s heading +x, at the origin at t = 20 s; the layer covers 400 m behind.
  ocean::waves::LayerParams p;
  p.area = {.origin_m = {-350.0, -200.0}, .size_m = 400.0, .resolution = 512};
  p.wakes.push_back({.x_m = -6.0 * kTime,
                     .z_m = 0.0,
                     .heading_deg = 0.0,
                     .speed_mps = 6.0,
                     .hull_length_m = 40.0,
                     .peak_height_m = 1.0});
  auto layer = ocean::waves::LocalLayer::make(p);
  ASSERT_TRUE(layer.ok()) << layer.status().message();
  ocean::waves::LocalFrame frame;
  layer.value()->evaluate(kTime, frame);

  auto scene = Scene::make(
      {.config = ocean::render::testing::small_config(), .width = kLayerSide, .height = kLayerSide});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_TRUE(scene.value()->warm_up(kTime, 2.0).ok());
  ocean::render::Renderer& r = scene.value()->renderer();
  View view;
  view.camera = {.position_m = {-150.0, 400.0, 0.0},
                 .target_m = {-149.0, 0.0, 0.0},
                 .fov_y_rad = 55.0 * std::numbers::pi / 180.0,
                 .aspect = 1.0,
                 .near_m = 0.5,
                 .far_m = 1e5};
  view.shading = ocean::render::sky_preset("clear").value();
  view.shading.sun_elevation_deg = 60.0;
  std::vector<std::uint8_t> with, without;
  ASSERT_TRUE(r.set_local_layer({.origin_m = frame.area.origin_m,
                                 .size_m = frame.area.size_m,
                                 .resolution = frame.area.resolution,
                                 .displacement = frame.displacement})
                  .ok());
  ASSERT_TRUE(r.draw(view).ok());
  ASSERT_TRUE(r.read_srgb(with).ok());
  ASSERT_TRUE(r.set_local_layer({}).ok());  // removed
  ASSERT_TRUE(r.draw(view).ok());
  ASSERT_TRUE(r.read_srgb(without).ok());

  // World points on the sea behind the object (s metres behind, ζ to the side), projected into
  // the picture: mean |difference| of the green channel inside and outside the wedge.
  const ocean::lod::Mat4 vp = ocean::lod::view_projection(view.camera);
  double inside = 0.0, outside = 0.0;
  int n_in = 0, n_out = 0;
  for (double s = 30.0; s <= 330.0; s += 2.0) {
    for (double zeta = -180.0; zeta <= 180.0; zeta += 2.0) {
      const double x = -s, z = zeta;
      const auto& m = vp.m;  // column-major: clip_i = Σ_j m[4j + i]·v_j, v = (x, 0, z, 1)
      const double cx = m[0] * x + m[8] * z + m[12], cy = m[1] * x + m[9] * z + m[13];
      const double cw = m[3] * x + m[11] * z + m[15];
      const int col = static_cast<int>((cx / cw + 1.0) * 0.5 * kLayerSide);
      const int row = static_cast<int>((1.0 - cy / cw) * 0.5 * kLayerSide);
      if (col < 0 || col >= kLayerSide || row < 0 || row >= kLayerSide) continue;
      const std::size_t i = (static_cast<std::size_t>(row) * kLayerSide + col) * 4 + 1;
      const double d = std::abs(int(with[i]) - int(without[i]));
      const double angle = std::atan2(std::abs(zeta), s) * 180.0 / std::numbers::pi;
      if (angle < 22.0) inside += d, ++n_in;
      if (angle > 35.0) outside += d, ++n_out;
    }
  }
  ASSERT_GT(n_in, 1000);
  ASSERT_GT(n_out, 1000);
  inside /= n_in, outside /= n_out;
  std::printf("mean |difference| inside the wedge %.2f LSB, outside %.2f LSB\n", inside, outside);
  EXPECT_GT(inside, 2.0);
  EXPECT_GT(inside, 5.0 * outside);
}

// A layer whose array does not match its grid, or a bad area, is refused with one line.
TEST(LocalLayerRender, BadGridsAreRefused) {
  auto ctx = ocean::render::testing::graphics_context();
  if (ctx == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto r = ocean::render::Renderer::make(ctx, {.width = 8, .height = 8});
  ASSERT_TRUE(r.ok()) << r.status().message();
  const std::vector<float> values(3 * 4 * 4, 0.0f);
  const auto refused = [&](const ocean::render::LocalLayerGrid& g) {
    const ocean::Status s = r.value()->set_local_layer(g);
    EXPECT_EQ(s.code(), ocean::ErrorCode::invalid_argument) << s.message();
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
  };
  refused({.origin_m = {0.0, 0.0}, .size_m = 10.0, .resolution = 5, .displacement = values});
  refused({.origin_m = {0.0, 0.0}, .size_m = -1.0, .resolution = 4, .displacement = values});
  refused({.origin_m = {NAN, 0.0}, .size_m = 10.0, .resolution = 4, .displacement = values});
  refused({.origin_m = {0.0, 0.0}, .size_m = 10.0, .resolution = 0, .displacement = values});
  EXPECT_TRUE(
      r.value()
          ->set_local_layer(
              {.origin_m = {0.0, 0.0}, .size_m = 10.0, .resolution = 4, .displacement = values})
          .ok());
}

}  // namespace
