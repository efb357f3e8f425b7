// Objects drawn with the water (lavapipe, validation layer on, zero messages asserted): a box
// above the sea covers the pixels its projection puts it on and no others; the same box deep
// under the surface is hidden by the water (depth-tested with it); bad meshes, indices and
// transforms are invalid_argument.
#include <gtest/gtest.h>

#include <limits>

#include "ocean/backends.hpp"
#include "ocean/bodies.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using namespace ocean::render;
namespace helpers = ocean::render::testing;

using helpers::Rig;

constexpr int kW = 96, kH = 64;

std::unique_ptr<Rig> make_rig() {
  auto rig = helpers::make_rig(helpers::graphics_context(), helpers::small_config(), kW, kH);
  if (rig == nullptr) return nullptr;
  const auto hull = ocean::bodies::box_hull({4.0, 4.0, 4.0}).value();
  const Mesh box = flat_mesh(hull.vertices, hull.triangles, {.base_colour = {0.9, 0.2, 0.02}});
  EXPECT_TRUE(rig->renderer->set_meshes(std::span(&box, 1)).ok());
  return rig;
}

// The pixel (column, row from the top) where the view puts a world point.
std::array<int, 2> pixel_of(const View& view, const std::array<double, 3>& p) {
  const ocean::lod::Mat4 vp = ocean::lod::view_projection(view.camera);
  double clip[4];
  for (int r = 0; r < 4; ++r)
    clip[r] = vp.m[static_cast<std::size_t>(r)] * p[0] +
              vp.m[static_cast<std::size_t>(4 + r)] * p[1] +
              vp.m[static_cast<std::size_t>(8 + r)] * p[2] + vp.m[static_cast<std::size_t>(12 + r)];
  const double x = clip[0] / clip[3], y = clip[1] / clip[3];
  return {static_cast<int>((x * 0.5 + 0.5) * kW), static_cast<int>((0.5 - y * 0.5) * kH)};
}

std::vector<std::uint8_t> draw(Rig& rig, const View& view) {
  EXPECT_TRUE(rig.renderer->draw(view).ok());
  std::vector<std::uint8_t> rgba;
  EXPECT_TRUE(rig.renderer->read_srgb(rgba).ok());
  return rgba;
}

TEST(Objects, ABoxAboveTheSeaCoversItsProjectionAndIsHiddenBelowIt) {
  auto rig = make_rig();
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  View view = helpers::eye_level_view(kW, kH);
  const std::array<double, 3> centre{-40.0, 6.0, -28.0};  // on the view axis, 49 m away
  const std::vector<std::uint8_t> empty = draw(*rig, view);
  view.objects = {{.mesh = 0, .model = model_matrix(centre, {1, 0, 0, 0})}};
  const std::vector<std::uint8_t> with_box = draw(*rig, view);
  const auto [cx, cy] = pixel_of(view, centre);
  ASSERT_TRUE(cx > 5 && cx < kW - 5 && cy > 5 && cy < kH - 5);
  const auto at = [](const std::vector<std::uint8_t>& px, int x, int y, int c) {
    return int(px[static_cast<std::size_t>((y * kW + x) * 4 + c)]);
  };
  // The box's centre pixel is the box's orange (red well above blue), the horizon's was not.
  EXPECT_GT(at(with_box, cx, cy, 0), at(with_box, cx, cy, 2) + 20);
  EXPECT_LT(at(empty, cx, cy, 0), at(empty, cx, cy, 2) + 10);
  // Pixels outside the box's projected bounding square (its half-diagonal 3.5 m at 49 m, under
  // 9 pixels here) and the columns beneath it, where the water reflects it (R.53), are untouched.
  int changed_far = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      if (std::abs(x - cx) > 9 || y < cy - 9)
        for (int c = 0; c < 3; ++c) changed_far += at(with_box, x, y, c) != at(empty, x, y, c);
  EXPECT_EQ(changed_far, 0);
  // 20 m down the water covers it: the picture is the empty sea's.
  view.objects[0].model = model_matrix({centre[0], -20.0, centre[2]}, {1, 0, 0, 0});
  const std::vector<std::uint8_t> sunk = draw(*rig, view);
  EXPECT_EQ(helpers::difference(sunk, empty).max, 0);
}

// Far from the world's origin (R.16: the GPU sees positions relative to the frame's origin) a
// box stays where its model matrix puts it: the same view and box moved by 10⁶ m in x show the
// box's orange at its projected centre.
TEST(Objects, ABoxFarFromTheOriginStaysWhereItIs) {
  auto rig = make_rig();
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  View view = helpers::eye_level_view(kW, kH);
  constexpr double kOffset = 1e6;
  view.camera.position_m.x += kOffset;
  view.camera.target_m.x += kOffset;
  const std::array<double, 3> centre{kOffset - 40.0, 6.0, -28.0};
  view.objects = {{.mesh = 0, .model = model_matrix(centre, {1, 0, 0, 0})}};
  const std::vector<std::uint8_t> px = draw(*rig, view);
  const auto [cx, cy] = pixel_of(view, centre);
  ASSERT_TRUE(cx > 5 && cx < kW - 5 && cy > 5 && cy < kH - 5);
  const auto at = [&](int c) { return int(px[static_cast<std::size_t>((cy * kW + cx) * 4 + c)]); };
  EXPECT_GT(at(0), at(2) + 20);
}

TEST(Objects, RefusesBadMeshesIndicesAndTransforms) {
  auto rig = make_rig();
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  View view = helpers::eye_level_view(kW, kH);
  view.objects = {{.mesh = 3}};
  EXPECT_EQ(rig->renderer->draw(view).code(), ocean::ErrorCode::invalid_argument);
  view.objects = {{.mesh = 0}};
  view.objects[0].model[13] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(rig->renderer->draw(view).code(), ocean::ErrorCode::invalid_argument);
  Mesh broken;
  broken.positions = {{0, 0, 0}};
  broken.normals = {{0, 1, 0}};
  broken.indices = {0, 0, 7};
  EXPECT_EQ(rig->renderer->set_meshes(std::span(&broken, 1)).code(),
            ocean::ErrorCode::invalid_argument);
}

}  // namespace
