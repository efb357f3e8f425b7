// The damping in the picture (docs/rendering.md R.24): a grid that damps every cascade but the
// first and holds shallow water over one half of a straight-down view calms and tints that half
// and leaves the other half's pixels as they were. Skips where no Vulkan device exists (fails
// with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "ocean/scene.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::Scene;
using ocean::render::View;

struct Half {
  double detail = 0.0;  // mean |horizontal difference| of the green channel, LSB
  double red = 0.0;     // mean red, LSB
};

// The left (x < 0) or right half of the picture, away from the seam.
Half measure(const std::vector<std::uint8_t>& rgba, int side, bool left) {
  Half h;
  int n = 0;
  for (int row = 0; row < side; ++row) {
    for (int col = left ? 4 : side / 2 + 4; col < (left ? side / 2 - 4 : side - 4); ++col) {
      const std::size_t i = (static_cast<std::size_t>(row) * side + col) * 4;
      h.detail += std::abs(int(rgba[i + 5]) - int(rgba[i + 1]));
      h.red += rgba[i];
      ++n;
    }
  }
  h.detail /= n, h.red /= n;
  return h;
}

TEST(DampingRender, AMaskedShallowHalfIsCalmAndTintedAndTheOtherHalfUnchanged) {
  if (ocean::render::testing::graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  constexpr int kDampSide = 192;
  auto scene = Scene::make(
      {.config = ocean::render::testing::small_config(), .width = kDampSide, .height = kDampSide});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_TRUE(scene.value()->warm_up(10.0, 2.0).ok());
  ocean::render::Renderer& r = scene.value()->renderer();
  View view;  // straight down from 60 m: +x to the right of the picture, the seam at x = 0
  view.camera = {.position_m = {0.0, 60.0, 0.0},
                 .target_m = {0.0, 0.0, 0.01},
                 .fov_y_rad = 50.0 * std::numbers::pi / 180.0,
                 .aspect = 1.0,
                 .near_m = 0.5,
                 .far_m = 1e5};
  view.shading = ocean::render::sky_preset("clear").value();
  view.shading.sun_elevation_deg = 50.0;
  std::vector<std::uint8_t> plain, damped;
  ASSERT_TRUE(r.draw(view).ok());
  ASSERT_TRUE(r.read_srgb(plain).ok());
  // Over x in [−400, 0): cascade 1 weighs 0 (the mask's 0) and the water is 3 m deep.
  constexpr int kN = 8;
  std::vector<float> weights(ocean::render::kDampingBands * kN * kN, 1.0f);
  std::vector<float> depth(kN * kN, 3.0f);
  for (std::size_t cell = 0; cell < kN * kN; ++cell)
    weights[cell * ocean::render::kDampingBands + 1] = 0.0f;
  ASSERT_TRUE(r.set_damping({.origin_m = {-400.0, -200.0},
                             .size_m = 400.0,
                             .resolution = kN,
                             .band_weights = weights,
                             .depth_m = depth})
                  .ok());
  ASSERT_TRUE(r.draw(view).ok());
  ASSERT_TRUE(r.read_srgb(damped).ok());
  // Which side of the picture is x < 0 depends on the camera's up vector: find it from the
  // difference, then check both halves.
  const Half plain_l = measure(plain, kDampSide, true), plain_r = measure(plain, kDampSide, false);
  const Half damped_l = measure(damped, kDampSide, true), damped_r = measure(damped, kDampSide, false);
  const bool left_is_damped =
      std::abs(damped_l.red - plain_l.red) > std::abs(damped_r.red - plain_r.red);
  const Half& before = left_is_damped ? plain_l : plain_r;
  const Half& after = left_is_damped ? damped_l : damped_r;
  const Half& other_before = left_is_damped ? plain_r : plain_l;
  const Half& other_after = left_is_damped ? damped_r : damped_l;
  std::printf(
      "damped half: detail %.2f -> %.2f LSB, red %.1f -> %.1f; other half: detail %.2f -> "
      "%.2f, red %.1f -> %.1f\n",
      before.detail, after.detail, before.red, after.red, other_before.detail, other_after.detail,
      other_before.red, other_after.red);
  EXPECT_LT(after.detail, 0.7 * before.detail);  // the short cascade's ripples are gone
  EXPECT_GT(after.red, before.red + 5.0);        // the sand shows through 3 m of water
  EXPECT_NEAR(other_after.detail, other_before.detail, 0.05);
  EXPECT_NEAR(other_after.red, other_before.red, 0.05);
}

TEST(DampingRender, BadGridsAreRefused) {
  auto ctx = ocean::render::testing::graphics_context();
  if (ctx == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto r = ocean::render::Renderer::make(ctx, {.width = 8, .height = 8});
  ASSERT_TRUE(r.ok()) << r.status().message();
  const std::vector<float> weights(ocean::render::kDampingBands * 16, 1.0f), depth(16, 1.0f);
  const auto refused = [&](const ocean::render::DampingGrid& g) {
    const ocean::Status s = r.value()->set_damping(g);
    EXPECT_EQ(s.code(), ocean::ErrorCode::invalid_argument) << s.message();
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
  };
  refused({.size_m = 10.0, .resolution = 5, .band_weights = weights, .depth_m = depth});
  refused({.size_m = 0.0, .resolution = 4, .band_weights = weights, .depth_m = depth});
  refused({.size_m = 10.0, .resolution = 4, .band_weights = weights, .depth_m = {}});
  EXPECT_TRUE(r.value()
                  ->set_damping(
                      {.size_m = 10.0, .resolution = 4, .band_weights = weights, .depth_m = depth})
                  .ok());
}

}  // namespace
