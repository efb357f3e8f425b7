// The HDR environment map (docs/rendering.md R.17), on any Vulkan device with the validation
// layer on: a map whose sky is green within 45° of +x and blue elsewhere shows green looking
// along +x and blue looking along −x, with the map's radiance times sky_brightness; the water
// reflects it; the analytic sky returns with set_environment(nullptr); and load_environment
// refuses what is not an equirectangular RGB HDR image. Skips without a Vulkan device (fails
// with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/io.hpp"
#include "ocean/render.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"
#include "support/temp_dir.hpp"

namespace {

using ocean::render::Environment;
using ocean::render::load_environment;
using ocean::render::Renderer;
using ocean::render::View;
using ocean::render::testing::graphics_context;

constexpr std::array<float, 3> kGreen = {0.1f, 2.0f, 0.2f}, kBlue = {0.1f, 0.3f, 2.5f};

// Writes a W × W/2 map: sky green within 45° of +x, blue elsewhere; below the horizon grey.
ocean::Status write_map(const std::filesystem::path& path, int w, bool with_blue = true) {
  const int h = w / 2;
  std::array<std::vector<float>, 3> planes;
  for (auto& p : planes) p.resize(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double u = (x + 0.5) / w;  // azimuth / 2π
      const bool green = u < 0.125 || u > 0.875;
      for (std::size_t c = 0; c < 3; ++c)
        planes[c][static_cast<std::size_t>(y) * w + x] =
            y >= h / 2 ? 0.05f : (green ? kGreen[c] : kBlue[c]);
    }
  }
  std::vector<ocean::io::ExrChannel> channels = {{"R", planes[0].data()}, {"G", planes[1].data()}};
  if (with_blue) channels.push_back({"B", planes[2].data()});
  return ocean::io::write_exr(path, w, h, channels, ocean::io::ExrPixelType::half);
}

TEST(Environment, TheSkyAndItsReflectionComeFromTheMap) {
  auto ctx = graphics_context();
  if (ctx == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  ocean_test::TempDir dir("ocean_environment");
  std::filesystem::create_directories(dir.path);
  ASSERT_TRUE(write_map(dir.path / "sky.exr", 64).ok());
  ocean::Result<Environment> env = load_environment(dir.path / "sky.exr");
  ASSERT_TRUE(env.ok()) << env.status().message();
  constexpr int kW = 48, kH = 32;
  auto made = Renderer::make(ctx, {.width = kW, .height = kH});
  ASSERT_TRUE(made.ok()) << made.status().message();
  Renderer& r = *made.value();
  const ocean::SimulationConfig config = ocean::render::testing::small_config();
  auto sim = ocean::make_simulator(config);
  ASSERT_TRUE(sim.ok()) << sim.status().message();
  sim.value()->step(2.0);
  ASSERT_TRUE(r.configure(ocean::SimulationPlan::make(config).value().surface()).ok());
  ASSERT_TRUE(r.upload(sim.value()->frame()).ok());
  ASSERT_TRUE(r.set_environment(&env.value()).ok());
  // Mean linear radiance of the top and bottom quarter of the picture looking along `dir`.
  const auto look = [&](double dx, double brightness) {
    View v = ocean::render::testing::eye_level_view(kW, kH);
    v.camera.target_m = {dx * 100.0, 5.0, 0.0};
    v.shading.sky_brightness = brightness;
    v.shading.fog_density_per_m = 0.0;
    EXPECT_TRUE(r.draw(v).ok());
    std::vector<float> hdr;
    EXPECT_TRUE(r.read_hdr(hdr).ok());
    std::array<std::array<double, 3>, 2> mean{};
    for (int y = 0; y < kH / 4; ++y)
      for (int x = 0; x < kW; ++x)
        for (std::size_t c = 0; c < 3; ++c) {
          mean[0][c] += hdr[static_cast<std::size_t>(4 * (y * kW + x)) + c] / (kW * kH / 4);
          mean[1][c] +=
              hdr[static_cast<std::size_t>(4 * ((kH - 1 - y) * kW + x)) + c] / (kW * kH / 4);
        }
    return mean;
  };
  const auto east = look(1.0, 1.0), west = look(-1.0, 1.0), dim = look(1.0, 0.5);
  for (std::size_t c = 0; c < 3; ++c) {
    // The sky is the map's radiance (half floats: 3 significant digits) times sky_brightness.
    EXPECT_NEAR(east[0][c], kGreen[c], 2e-3 * kGreen[c] + 1e-3) << "channel " << c;
    EXPECT_NEAR(west[0][c], kBlue[c], 2e-3 * kBlue[c] + 1e-3) << "channel " << c;
    EXPECT_NEAR(dim[0][c], 0.5 * kGreen[c], 2e-3 * kGreen[c] + 1e-3) << "channel " << c;
  }
  // Water reflects the sky in front of it: greener looking east, bluer looking west.
  EXPECT_GT(east[1][1] / east[1][2], 1.5 * west[1][1] / west[1][2]);
  // Back to the analytic sky: no longer the map's green (G/B = 20) but a sky bluer than red.
  ASSERT_TRUE(r.set_environment(nullptr).ok());
  const auto analytic = look(1.0, 1.0);
  EXPECT_LT(analytic[0][1] / analytic[0][2], 1.5);
  EXPECT_GT(analytic[0][2], analytic[0][0]);
  EXPECT_EQ(ctx->validation_messages.load(), 0u) << ctx->last_validation_message;
}

TEST(Environment, WhatIsNotAnEquirectangularHdrImageIsRefused) {
  ocean_test::TempDir dir("ocean_environment_bad");
  std::filesystem::create_directories(dir.path);
  const auto message = [](const ocean::Result<Environment>& e) {
    return e.ok() ? std::string("accepted") : e.status().message();
  };
  // Unreadable, and not OpenEXR at all (an 8-bit PNG is not HDR).
  ocean::Result<Environment> missing = load_environment(dir.path / "none.exr");
  EXPECT_EQ(missing.status().code(), ocean::ErrorCode::io_error) << message(missing);
  const std::vector<std::uint8_t> grey(8 * 4 * 3, 128);
  ASSERT_TRUE(ocean::io::write_png8(dir.path / "sky.png", 8, 4, 3, grey.data()).ok());
  ocean::Result<Environment> png = load_environment(dir.path / "sky.png");
  EXPECT_NE(message(png).find("not an OpenEXR file"), std::string::npos) << message(png);
  // No B channel; not 2:1.
  ASSERT_TRUE(write_map(dir.path / "rg.exr", 16, false).ok());
  EXPECT_NE(message(load_environment(dir.path / "rg.exr")).find("no channel B"), std::string::npos);
  const std::vector<float> one(6 * 6, 1.0f);
  const std::vector<ocean::io::ExrChannel> square = {
      {"R", one.data()}, {"G", one.data()}, {"B", one.data()}};
  ASSERT_TRUE(
      ocean::io::write_exr(dir.path / "square.exr", 6, 6, square, ocean::io::ExrPixelType::float32)
          .ok());
  EXPECT_NE(message(load_environment(dir.path / "square.exr")).find("twice as wide"),
            std::string::npos);
  // Negative radiance.
  std::vector<float> negative(8 * 4, 1.0f);
  negative[5] = -2.0f;
  const std::vector<ocean::io::ExrChannel> neg = {
      {"R", negative.data()}, {"G", one.data()}, {"B", one.data()}};
  ASSERT_TRUE(
      ocean::io::write_exr(dir.path / "neg.exr", 8, 4, neg, ocean::io::ExrPixelType::float32).ok());
  EXPECT_NE(message(load_environment(dir.path / "neg.exr")).find("negative or non-finite"),
            std::string::npos);
}

}  // namespace
