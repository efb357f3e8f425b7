// The render scene (ocean/scene.hpp) on any Vulkan device (lavapipe on CPU-only machines), with
// the validation layer on and zero messages asserted: the CPU backend's uploaded frames and the
// Vulkan backend's zero-copy images give the same picture, warm-up and reconfiguration keep the
// two in step, and bad backends are refused. Skips where no Vulkan device exists (fails with
// OCEAN_REQUIRE_DEVICES=1).
#include "ocean/scene.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::Scene;
using ocean::render::SceneParams;
using ocean::render::testing::difference;
using ocean::render::testing::eye_level_view;
using ocean::render::testing::graphics_context;
using ocean::render::testing::PictureDifference;
using ocean::render::testing::small_config;

constexpr int kWidth = 128, kHeight = 72;

std::unique_ptr<Scene> make_scene(const std::string& backend,
                                  const ocean::SimulationConfig& config) {
  ocean::Result<std::unique_ptr<Scene>> scene = Scene::make({.config = config,
                                                             .backend = backend,
                                                             .width = kWidth,
                                                             .height = kHeight,
                                                             .validation = true});
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  return scene.ok() ? std::move(scene).value() : nullptr;
}

std::vector<std::uint8_t> draw(Scene& scene) {
  std::vector<std::uint8_t> srgb;
  const ocean::Status drawn = scene.renderer().draw(eye_level_view(kWidth, kHeight));
  EXPECT_TRUE(drawn.ok()) << drawn.message();
  EXPECT_TRUE(scene.renderer().read_srgb(srgb).ok());
  return srgb;
}

void expect_no_validation_messages(const Scene& scene) {
  EXPECT_EQ(scene.context()->validation_messages.load(), 0u)
      << scene.context()->last_validation_message;
}

#define REQUIRE_DEVICE() \
  if (graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device")

// The bounds of tests/render/render_test.cpp (VulkanBackendImagesGiveTheCpuPicture): the two
// backends' maps agree within the conformance bounds (ocean/conformance.hpp: RGBA8 within 1 LSB,
// displacement within a few 1e-6·Hs), so the pictures agree to within rounding: on average
// always, pixel by pixel (`per_pixel`) for the calm sea's first frame. Foam starts where the
// Jacobian crosses a threshold and accumulates over frames: where J sits at the threshold the
// backends' rounding can flip a crest pixel's foam, so after a warm-up, or on a rougher sea with
// more crests at the threshold, only the mean is bounded.
void expect_same_picture(const std::vector<std::uint8_t>& cpu, const std::vector<std::uint8_t>& gpu,
                         bool per_pixel) {
  ASSERT_EQ(cpu.size(), static_cast<std::size_t>(kWidth) * kHeight * 4);
  ASSERT_EQ(gpu.size(), cpu.size());
  const PictureDifference d = difference(cpu, gpu);
  EXPECT_LE(d.mean, 0.05);
  if (per_pixel) {  // up to ~10 LSB in distant glitter: render_test.cpp explains
    EXPECT_LE(d.max, 12);
  }
}

TEST(Scene, CpuUploadAndVulkanImagesGiveTheSamePicture) {
  REQUIRE_DEVICE();
  auto cpu = make_scene("cpu", small_config());
  auto gpu = make_scene("vulkan", small_config());
  ASSERT_NE(cpu, nullptr);
  ASSERT_NE(gpu, nullptr);
  ASSERT_TRUE(cpu->step(2.0).ok());
  ASSERT_TRUE(gpu->step(2.0).ok());
  const std::vector<std::uint8_t> a = draw(*cpu), b = draw(*gpu);
  expect_same_picture(a, b, true);
  // The picture shows a sea that moved: a later time differs.
  ASSERT_TRUE(cpu->step(3.0).ok());
  EXPECT_GT(difference(a, draw(*cpu)).mean, 0.5);
  expect_no_validation_messages(*cpu);
  expect_no_validation_messages(*gpu);
}

TEST(Scene, WarmUpAndReconfigureKeepTheBackendsInStep) {
  REQUIRE_DEVICE();
  auto cpu = make_scene("cpu", small_config());
  auto gpu = make_scene("vulkan", small_config());
  ASSERT_NE(cpu, nullptr);
  ASSERT_NE(gpu, nullptr);
  ASSERT_TRUE(cpu->warm_up(4.0, 1.0).ok());
  ASSERT_TRUE(gpu->warm_up(4.0, 1.0).ok());
  expect_same_picture(draw(*cpu), draw(*gpu), false);
  const double calm_hs_m = cpu->renderer().significant_wave_height_m();
  ocean::SimulationConfig rougher = small_config();
  rougher.sea.wind_sea.spectrum.wind_speed_mps = 18.0;
  ASSERT_TRUE(cpu->reconfigure(rougher).ok());
  ASSERT_TRUE(gpu->reconfigure(rougher).ok());
  EXPECT_GT(cpu->renderer().significant_wave_height_m(), 1.2 * calm_hs_m);  // Hs grows with U
  ASSERT_TRUE(cpu->step(2.0).ok());
  ASSERT_TRUE(gpu->step(2.0).ok());
  expect_same_picture(draw(*cpu), draw(*gpu), false);
  expect_no_validation_messages(*cpu);
  expect_no_validation_messages(*gpu);
}

TEST(Scene, UsesTheCallersContext) {
  std::shared_ptr<ocean::vk::Context> ctx = graphics_context();
  if (ctx == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  auto scene = Scene::make(ctx, {.config = small_config(), .width = kWidth, .height = kHeight});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene.value()->context().get(), ctx.get());
  ASSERT_TRUE(scene.value()->step(1.0).ok());
  EXPECT_EQ(draw(*scene.value()).size(), static_cast<std::size_t>(kWidth) * kHeight * 4);
  EXPECT_EQ(ctx->validation_messages.load(), 0u) << ctx->last_validation_message;
}

TEST(Scene, BadBackendIsRefusedWithAMessage) {
  auto scene = Scene::make({.config = small_config(), .backend = "opengl"});
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.status().code(), ocean::ErrorCode::invalid_argument);
  EXPECT_NE(scene.status().message().find("must be cpu, vulkan or cuda"), std::string::npos);
}

// Whether OCEAN_REQUIRE_CUDA is set to a value other than "" and "0" (tools/gpu-check.sh).
bool scene_cuda_required() {
  const char* v = std::getenv("OCEAN_REQUIRE_CUDA");
  return v != nullptr && std::string_view(v) != "" && std::string_view(v) != "0";
}

// Without a CUDA device the cuda scene is refused with the backend's one line, before any Vulkan
// object is made; with one (tools/gpu-check.sh on an NVIDIA machine) its frames, shared with the
// renderer where the GPU is the Vulkan device (else read back and uploaded, as `interop()` says),
// give the CPU backend's picture within the bounds the Vulkan backend is held to above, through
// steps, a warm-up and a reconfiguration.
TEST(Scene, CudaFramesGiveTheCpuPicture) {
  const ocean::Status available = Scene::available("cuda");
  if (!available.ok()) {
    auto refused = Scene::make({.config = small_config(), .backend = "cuda"});
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.status().message(), available.message());
    EXPECT_EQ(available.message().find('\n'), std::string::npos);
    if (scene_cuda_required()) GTEST_FAIL() << "OCEAN_REQUIRE_CUDA is set: " << available.message();
    GTEST_SKIP() << "no CUDA device (" << available.message()
                 << "); tools/gpu-check.sh runs this on an NVIDIA machine";
  }
  REQUIRE_DEVICE();
  auto cpu = make_scene("cpu", small_config());
  auto gpu = make_scene("cuda", small_config());
  ASSERT_NE(cpu, nullptr);
  ASSERT_NE(gpu, nullptr);
  std::cout << "cuda scene: " << gpu->interop() << "\n";
  EXPECT_FALSE(gpu->interop().empty());
  if (const char* z = std::getenv("OCEAN_REQUIRE_CUDA_ZERO_COPY"); z != nullptr && *z == '1') {
    EXPECT_TRUE(gpu->zero_copy()) << gpu->interop();
  }
  for (const double t : {2.0, 2.5}) {
    ASSERT_TRUE(cpu->step(t).ok());
    ASSERT_TRUE(gpu->step(t).ok());
    expect_same_picture(draw(*cpu), draw(*gpu), t == 2.0);
  }
  ASSERT_TRUE(cpu->warm_up(4.0, 1.0).ok());
  ASSERT_TRUE(gpu->warm_up(4.0, 1.0).ok());
  expect_same_picture(draw(*cpu), draw(*gpu), false);
  ocean::SimulationConfig rougher = small_config();
  rougher.sea.wind_sea.spectrum.wind_speed_mps = 18.0;
  ASSERT_TRUE(cpu->reconfigure(rougher).ok());
  ASSERT_TRUE(gpu->reconfigure(rougher).ok());
  ASSERT_TRUE(cpu->step(2.0).ok());
  ASSERT_TRUE(gpu->step(2.0).ok());
  expect_same_picture(draw(*cpu), draw(*gpu), false);
  expect_no_validation_messages(*gpu);
}

}  // namespace
#undef REQUIRE_DEVICE
