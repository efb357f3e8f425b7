// The planet's curvature and large worlds in the renderer (docs/rendering.md R.15, R.16), on any
// Vulkan device (lavapipe on CPU-only machines) with the validation layer on:
// - the horizon's row against the geometric dip arccos(R/(R + h)) of an eye at h = 2, 20, 400 m
//   (a narrow field of view, one row = 0.01°), and against where a flat world puts it;
// - the same sea seen from the origin and from 10⁶ m and 10⁷ m away (whole multiples of every
//   cascade's period) giving the same picture.
// Skips where no Vulkan device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/render.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::Renderer;
using ocean::render::View;
using ocean::render::testing::graphics_context;

constexpr double kPi = std::numbers::pi;

using ocean::render::testing::Rig;

// The CPU backend's frame at t = 3 s uploaded to a renderer of w × h pixels.
std::unique_ptr<Rig> make_rig(const ocean::SimulationConfig& config, int w, int h) {
  return ocean::render::testing::make_rig(graphics_context(), config, w, h);
}

#define REQUIRE_RIG(rig)                                                       \
  if ((rig) == nullptr) {                                                      \
    if (graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device"); \
    FAIL() << "could not build the renderer";                                  \
  }

// A light sea whose cascades both divide 10⁶ m.
ocean::SimulationConfig calm_config() {
  ocean::SimulationConfig c = ocean::render::testing::small_config();
  c.cascade_patch_sizes_m = {200.0, 50.0};
  c.sea.wind_sea.spectrum.wind_speed_mps = 5.0;
  return c;
}

// The first row (from the top) of each column whose linear radiance is not the black sky's,
// the smallest over the columns: the sea's topmost row.
int first_sea_row(const std::vector<float>& rgba, int w, int h) {
  int top = h;
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y) {
      const float* p = &rgba[static_cast<std::size_t>(4 * (y * w + x))];
      if (p[0] + p[1] + p[2] > 1e-3f) {
        top = std::min(top, y);
        break;
      }
    }
  }
  return top;
}

TEST(PlanetRender, TheHorizonSitsAtTheDipOfAnEyeAboveASphere) {
  constexpr int kW = 24, kH = 240;
  const double fov = 2.4 * kPi / 180.0;  // 0.01° a row
  auto rig = make_rig(calm_config(), kW, kH);
  REQUIRE_RIG(rig);
  for (const double h : {2.0, 20.0, 400.0}) {
    View v;
    v.camera = {
        .position_m = {0.0, h, 0.0},
        .target_m = {1000.0, h, 0.0},  // level, along +x: the sun (azimuth 35°) is out of view
        .fov_y_rad = fov,
        .aspect = double(kW) / kH,
        .near_m = 0.5,
        .far_m = 2e5};
    v.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::low);
    v.ocean_size_m = 2048.0;
    v.shading.sky_brightness = 0.0;  // a black sky, so the sea's first row is unambiguous
    v.shading.fog_density_per_m = 0.0;
    v.debug = ocean::render::DebugView::lod_colours;  // a tint that is never black
    // Where a pixel row's centre looks: tan(angle below level) = ((2i + 1)/H − 1)·tan(fov/2).
    // The sea begins at the first row below the dip.
    const auto expected_row = [&](double dip) {
      return static_cast<int>(
                 std::floor((kH * (1.0 + std::tan(dip) / std::tan(fov / 2)) - 1.0) / 2.0)) +
             1;
    };
    const double R = ocean::render::kEarthRadius_m;
    const double dip = std::acos(R / (R + h));  // the geometric dip, ≈ √(2h/R)
    ASSERT_TRUE(rig->renderer->draw(v).ok());
    std::vector<float> curved;
    ASSERT_TRUE(rig->renderer->read_hdr(curved).ok());
    const int row = first_sea_row(curved, kW, kH);
    EXPECT_NEAR(row, expected_row(dip), 2) << "h = " << h << " m, dip " << dip * 180 / kPi << "°";
    // A flat world (the skirt out to 10·S) puts the sea's edge at its end, nearly level: the
    // test tells the two apart.
    v.planet_radius_m = std::numeric_limits<double>::infinity();
    ASSERT_TRUE(rig->renderer->draw(v).ok());
    std::vector<float> flat;
    ASSERT_TRUE(rig->renderer->read_hdr(flat).ok());
    const double flat_dip = std::atan(h / (10.0 * v.ocean_size_m));
    EXPECT_NEAR(first_sea_row(flat, kW, kH), expected_row(flat_dip), 2) << "h = " << h;
    EXPECT_GT(std::abs(row - first_sea_row(flat, kW, kH)), 2) << "h = " << h;
  }
}

TEST(PlanetRender, TheSameSeaFarFromTheOriginGivesTheSamePicture) {
  constexpr int kW = 96, kH = 64;
  auto rig = make_rig(calm_config(), kW, kH);
  REQUIRE_RIG(rig);
  std::vector<std::vector<std::uint8_t>> pictures;
  for (const double offset : {0.0, 1e6, 1e7}) {  // whole multiples of 200 m and 50 m
    View v;
    // Looking down at 50°: everything in view lies within 100 m, inside the far field's D_min,
    // where the picture is the periodic simulation alone.
    v.camera = {.position_m = {offset + 3.0, 30.0, -7.0},
                .target_m = {offset + 28.0, 0.0, 14.0},
                .fov_y_rad = 40.0 * kPi / 180.0,
                .aspect = double(kW) / kH,
                .near_m = 0.5,
                .far_m = 2e5};
    v.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::low);
    v.ocean_size_m = 2048.0;
    // The whitecaps' patches (R.11b) do not repeat with the cascades: whole periods away they are
    // another realisation, which this test of the periodic sea's precision leaves out.
    v.shading.whitecap_patches = false;
    ASSERT_TRUE(rig->renderer->draw(v).ok());
    pictures.emplace_back();
    ASSERT_TRUE(rig->renderer->read_srgb(pictures.back()).ok());
  }
  for (std::size_t i = 1; i < pictures.size(); ++i) {
    const auto d = ocean::render::testing::difference(pictures[0], pictures[i]);
    // Floats relative to the grid centre differ only in their last bits (the origin's phase in
    // each cascade's period, R.16): a fraction of an 8-bit step on average, and no pixel moved by
    // a tenth of the range (a glint far out on the calm sea's Beckmann tail, exp(−tan²θ/α²),
    // moves most: 17 steps; 12 with GGX's polynomial tail).
    EXPECT_LT(d.mean, 0.25) << "offset " << (i == 1 ? "1e6" : "1e7") << " m";
    EXPECT_LE(d.max, 25) << "offset " << (i == 1 ? "1e6" : "1e7") << " m";
  }
}

}  // namespace
#undef REQUIRE_RIG
