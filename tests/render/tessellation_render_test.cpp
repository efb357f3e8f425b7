// The tessellated mesh on lavapipe (validation layer on, zero messages asserted;
// docs/rendering.md R.40–R.42): no background shows through the surface — a bright box far
// below the water changes no pixel, from eye heights where neighbouring quads differ most in
// level — while Algorithm 1's printed per-quad levels let it show through their T-junctions; the
// tessellated sea looks like the quadtree's; a device without tessellation shaders is refused
// with one line.
#include <gtest/gtest.h>

#include "ocean/backends.hpp"
#include "ocean/bodies.hpp"
#include "render/render_helpers.hpp"

namespace {

using namespace ocean::render;
namespace helpers = ocean::render::testing;

constexpr int kW = 160, kH = 100;

using helpers::Rig;

// A renderer on `ctx` with a sea uploaded and one mesh: a bright slab.
std::unique_ptr<Rig> make_rig(std::shared_ptr<ocean::vk::Context> ctx) {
  auto rig = helpers::make_rig(std::move(ctx), helpers::small_config(), kW, kH);
  if (rig == nullptr) return nullptr;
  // A flat 600 m square slab, bright orange, 40 m down: only a hole in the water shows it.
  const auto hull = ocean::bodies::box_hull({600.0, 2.0, 600.0}).value();
  const Mesh slab = flat_mesh(hull.vertices, hull.triangles, {.base_colour = {0.9, 0.3, 0.02}});
  EXPECT_TRUE(rig->renderer->set_meshes(std::span(&slab, 1)).ok());
  return rig;
}

std::vector<std::uint8_t> draw(Rig& rig, const View& view) {
  const ocean::Status drawn = rig.renderer->draw(view);
  EXPECT_TRUE(drawn.ok()) << drawn.message();
  std::vector<std::uint8_t> rgba;
  EXPECT_TRUE(rig.renderer->read_srgb(rgba).ok());
  return rgba;
}

// Looking down at 30° from `height_m` over the eye's projection, where the levels fall fastest:
// D_span = 4 m takes them from N = 16 to 1 within 64 m. A flat world, so nothing but the waves
// moves the surface.
View steep_levels_view(double height_m, bool shared_edges) {
  View v = helpers::eye_level_view(kW, kH);
  v.camera.position_m = {0.0, height_m, 0.0};
  v.camera.target_m = {1.7 * height_m, 0.0, 0.4 * height_m};
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.tessellation = {.mesh = MeshMode::tessellation,
                    .base_quads = 256,
                    .max_level = 16,
                    .span_m = 4.0,
                    .shared_edges = shared_edges};
  return v;
}

// Pixels of `b` that differ from `a`.
int changed_pixels(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  int changed = 0;
  for (std::size_t p = 0; p + 3 < a.size(); p += 4)
    changed += a[p] != b[p] || a[p + 1] != b[p + 1] || a[p + 2] != b[p + 2];
  return changed;
}

TEST(TessellationRender, NoBackgroundShowsThroughTheSurface) {
  auto ctx = helpers::graphics_context();
  if (ctx == nullptr) GTEST_SKIP() << "no Vulkan device";
  if (!ctx->tessellation) GTEST_SKIP() << "the device lacks tessellation shaders";
  auto rig = make_rig(ctx);
  int printed_holes = 0;
  for (double height : {6.0, 15.0, 30.0}) {
    for (bool shared : {true, false}) {
      View view = steep_levels_view(height, shared);
      const std::vector<std::uint8_t> water = draw(*rig, view);
      view.objects = {{.mesh = 0, .model = model_matrix({0.0, -40.0, 0.0}, {1, 0, 0, 0})}};
      const std::vector<std::uint8_t> with_slab = draw(*rig, view);
      if (shared) {
        EXPECT_EQ(changed_pixels(water, with_slab), 0) << "eye at " << height << " m";
      } else {
        printed_holes += changed_pixels(water, with_slab);
      }
    }
  }
  // The printed levels' cracks: the check above can see holes.
  EXPECT_GT(printed_holes, 0);
}

// The same sea through either mesh: the tessellated picture differs from the quadtree's only
// where the two meshes place vertices differently (a mean of a few levels of 255).
TEST(TessellationRender, LooksLikeTheQuadtreesSea) {
  auto ctx = helpers::graphics_context();
  if (ctx == nullptr) GTEST_SKIP() << "no Vulkan device";
  if (!ctx->tessellation) GTEST_SKIP() << "the device lacks tessellation shaders";
  auto rig = make_rig(ctx);
  View view = helpers::eye_level_view(kW, kH);
  const std::vector<std::uint8_t> quadtree = draw(*rig, view);
  RenderStats quadtree_stats = rig->renderer->stats();
  view.tessellation = {.mesh = MeshMode::tessellation, .base_quads = 64, .max_level = 32};
  const std::vector<std::uint8_t> tessellated = draw(*rig, view);
  EXPECT_GT(rig->renderer->stats().patches, 0u);
  EXPECT_LT(rig->renderer->stats().patches, 64u * 64u);  // culled
  EXPECT_GT(quadtree_stats.patches, 0u);
  EXPECT_LT(helpers::difference(quadtree, tessellated).mean, 4.0);
  EXPECT_GT(changed_pixels(quadtree, tessellated), 0);  // a different mesh was drawn
}

// A device without tessellation shaders (stated so when adopted): one line, nothing drawn; the
// quadtree still draws.
TEST(TessellationRender, RefusedWithoutTessellationShaders) {
  auto own = helpers::graphics_context();
  if (own == nullptr) GTEST_SKIP() << "no Vulkan device";
  auto adopted = ocean::vk::adopt_context({.instance = own->instance,
                                           .physical = own->physical,
                                           .device = own->device,
                                           .queue_family = own->queue_family,
                                           .queue = own->queue,
                                           .api_version = VK_API_VERSION_1_3,
                                           .graphics = true,
                                           .dynamic_rendering = true,
                                           .fill_mode_non_solid = own->wireframe,
                                           .tessellation_shader = false});
  ASSERT_TRUE(adopted.ok()) << adopted.status().message();
  std::shared_ptr<ocean::vk::Context> ctx = std::move(adopted.value());
  EXPECT_FALSE(ctx->tessellation);
  {
    auto rig = make_rig(ctx);
    View view = helpers::eye_level_view(kW, kH);
    EXPECT_TRUE(rig->renderer->draw(view).ok());
    view.tessellation.mesh = MeshMode::tessellation;
    const ocean::Status s = rig->renderer->draw(view);
    EXPECT_EQ(s.code(), ocean::ErrorCode::unsupported);
    EXPECT_NE(s.message().find("lacks tessellation shaders"), std::string::npos) << s.message();
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
  }
  EXPECT_EQ(own->validation_messages.load(), 0u) << own->last_validation_message;
}

}  // namespace
