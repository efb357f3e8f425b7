// The sea on a sphere in the renderer (docs/rendering.md R.30–R.38), on any Vulkan device
// (lavapipe on CPU-only machines) with the validation layer on:
// - a planet of 5 km seen from 10 km up fills the disc of angular radius asin(R/d) and the sky
//   shows through no crack inside it (the stitched cube-sphere is closed on the GPU too);
// - the same calm sea seen from 2 m above Earth's surface at several latitudes and longitudes,
//   the poles included, gives the same picture (positions relative to the camera, R.38);
// - bad views are refused.
// Skips where no Vulkan device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/render.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::View;
using ocean::render::testing::graphics_context;
using Rig = ocean::render::testing::ValidatedRig;
constexpr double kSpherePi = std::numbers::pi;

// A renderer of w × h pixels with the CPU backend's frame of a light sea uploaded.
std::unique_ptr<Rig> make_rig(int w, int h) {
  auto rig = std::make_unique<Rig>();
  rig->ctx = graphics_context();
  if (rig->ctx == nullptr) return nullptr;
  auto r = ocean::render::Renderer::make(rig->ctx, {.width = w, .height = h});
  if (!r.ok()) return nullptr;
  rig->renderer = std::move(r).value();
  ocean::SimulationConfig c = ocean::render::testing::small_config();
  c.sea.wind_sea.spectrum.wind_speed_mps = 6.0;
  auto sim = ocean::Simulator::make(c, std::move(ocean::make_backend("cpu")).value());
  if (!sim.ok() || !rig->renderer->configure(ocean::SimulationPlan::make(c).value().surface()).ok())
    return nullptr;
  sim.value()->step(3.0);
  if (!rig->renderer->upload(sim.value()->frame()).ok()) return nullptr;
  return rig;
}

#define REQUIRE_RIG(rig)                                                       \
  if ((rig) == nullptr) {                                                      \
    if (graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device"); \
    FAIL() << "could not build the renderer";                                  \
  }

bool lit(const std::vector<float>& rgba, int w, int x, int y) {
  const float* p = &rgba[static_cast<std::size_t>(4 * (y * w + x))];
  return p[0] + p[1] + p[2] > 1e-4f;
}

TEST(SphereRender, ASmallPlanetFillsItsDiscWithoutCracks) {
  constexpr int kW = 160, kH = 160;
  auto rig = make_rig(kW, kH);
  REQUIRE_RIG(rig);
  const double radius = 5000.0, altitude = 10000.0, d = radius + altitude;
  const double fov = 50.0 * kSpherePi / 180.0;
  for (const auto& [lat, lon] :
       {std::pair{0.0, 0.0}, std::pair{35.26, 45.0}, std::pair{90.0, 0.0}}) {
    View v;
    v.planet_radius_m = radius;
    v.sphere = {.enabled = true, .latitude_deg = lat, .longitude_deg = lon};
    v.camera = {.position_m = {0.0, altitude, 0.0},
                .target_m = {0.0, -radius, 1e-3},
                .fov_y_rad = fov,
                .aspect = 1.0,
                .near_m = 10.0,
                .far_m = 1e5};
    v.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::low);
    v.shading.sky_brightness = 0.0;  // black: the disc's edge and any crack are unambiguous
    v.shading.fog_density_per_m = 0.0;
    v.debug = ocean::render::DebugView::lod_colours;  // a tint that is never black
    ASSERT_TRUE(rig->renderer->draw(v).ok());
    std::vector<float> hdr;
    ASSERT_TRUE(rig->renderer->read_hdr(hdr).ok());
    // The limb of a sphere seen from distance d: angular radius asin(R/d); in pixels from the
    // centre, tan of it over tan(fov/2) times half the side.
    const double expected = std::tan(std::asin(radius / d)) / std::tan(fov / 2) * kW / 2;
    int first = kW, last = -1;
    for (int x = 0; x < kW; ++x)
      if (lit(hdr, kW, x, kH / 2)) first = std::min(first, x), last = std::max(last, x);
    EXPECT_NEAR((last - first + 1) / 2.0, expected, 1.5) << lat << "," << lon;
    int holes = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const double r = std::hypot(x + 0.5 - kW / 2.0, y + 0.5 - kH / 2.0);
        if (r < expected - 2.0 && !lit(hdr, kW, x, y)) ++holes;
      }
    EXPECT_EQ(holes, 0) << lat << "," << lon;
  }
}

TEST(SphereRender, TheSameCalmSeaAtAnyLatitudeAndLongitudeGivesTheSamePicture) {
  constexpr int kW = 96, kH = 64;
  auto rig = make_rig(kW, kH);
  REQUIRE_RIG(rig);
  rig->renderer->set_calm(true);  // no cascades: the sphere's own shape alone
  std::vector<std::vector<std::uint8_t>> pictures;
  for (const auto& [lat, lon] :
       {std::pair{0.0, 0.0}, std::pair{37.3, 121.7}, std::pair{-63.1, -170.2},
        std::pair{89.999, 10.0}, std::pair{90.0, 0.0}}) {
    View v;
    v.sphere = {.enabled = true, .latitude_deg = lat, .longitude_deg = lon};
    v.camera = {.position_m = {0.0, 2.0, 0.0},
                .target_m = {-100.0, -1.0, -70.0},
                .fov_y_rad = 50.0 * kSpherePi / 180.0,
                .aspect = double(kW) / kH,
                .near_m = 0.2,
                .far_m = 2e5};
    v.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::low);
    // shaded: the levels (the LOD tint) depend on where the faces' grids fall
    ASSERT_TRUE(rig->renderer->draw(v).ok());
    pictures.emplace_back();
    ASSERT_TRUE(rig->renderer->read_srgb(pictures.back()).ok());
  }
  for (std::size_t i = 1; i < pictures.size(); ++i) {
    const auto diff = ocean::render::testing::difference(pictures[0], pictures[i]);
    std::printf("place %zu: mean %.3f, max %d LSB\n", i, diff.mean, diff.max);
    EXPECT_LT(diff.mean, 0.25) << "place " << i;
    EXPECT_LE(diff.max, 12) << "place " << i;
  }
}

// The first row (from the top) of the middle column whose linear radiance is not the black sky.
int sphere_first_sea_row(const std::vector<float>& rgba, int w, int h) {
  for (int y = 0; y < h; ++y)
    if (lit(rgba, w, w / 2, y)) return y;
  return h;
}

TEST(SphereRender, TheHorizonSitsAtTheDipOfAnEyeAboveTheSphere) {
  // As planet_render_test's flat sea bent by R.15, now on the sphere itself: a level camera at
  // height h sees the sea begin arccos(R/(R + h)) below level, within two rows.
  constexpr int kW = 24, kH = 240;
  auto rig = make_rig(kW, kH);
  REQUIRE_RIG(rig);
  rig->renderer->set_calm(true);
  struct Case {
    double radius_m, h_m, fov_deg;
  };
  for (const Case& k :
       {Case{6.371e6, 20.0, 2.4}, Case{6.371e6, 400.0, 2.4}, Case{5000.0, 20.0, 24.0}}) {
    const double fov = k.fov_deg * kSpherePi / 180.0;
    View v;
    v.planet_radius_m = k.radius_m;
    v.sphere = {.enabled = true, .latitude_deg = 10.0, .longitude_deg = 20.0};
    v.camera = {.position_m = {0.0, k.h_m, 0.0},
                .target_m = {1000.0, k.h_m, 0.0},
                .fov_y_rad = fov,
                .aspect = double(kW) / kH,
                .near_m = 0.5,
                .far_m = 2e5};
    v.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::low);
    v.shading.sky_brightness = 0.0;
    v.shading.fog_density_per_m = 0.0;
    v.debug = ocean::render::DebugView::lod_colours;
    ASSERT_TRUE(rig->renderer->draw(v).ok());
    std::vector<float> hdr;
    ASSERT_TRUE(rig->renderer->read_hdr(hdr).ok());
    const double dip = std::acos(k.radius_m / (k.radius_m + k.h_m));
    const int expected =
        static_cast<int>(std::floor((kH * (1.0 + std::tan(dip) / std::tan(fov / 2)) - 1.0) / 2.0)) +
        1;
    EXPECT_NEAR(sphere_first_sea_row(hdr, kW, kH), expected, 2)
        << "R " << k.radius_m << ", h " << k.h_m;
  }
}

// From orbit (R.8c) the sky is the planet's air marched along each ray, so where a ray meets no
// air, space, the picture is black; and straight down the sea lies under its whole column: the
// transmittance, measured as the change of the centre pixel with the water's colour over the
// same change without the air, is exp(−(β_R·H_R + β_M·H_M)) per channel within 1 % (the
// log-mean steps integrate a vertical ray exactly; the air's top at 80 km leaves e^(−10) of the
// Rayleigh column; half-float pixels).
TEST(SphereRender, FromOrbitSpaceIsBlackAndTheSeaLiesUnderItsColumnOfAir) {
  constexpr int kSide = 64;
  auto rig = make_rig(kSide, kSide);
  REQUIRE_RIG(rig);
  rig->renderer->set_calm(true);  // a level mirror: the centre pixel sees the water alone
  View v;
  v.sphere = {.enabled = true, .latitude_deg = 10.0, .longitude_deg = 20.0};
  v.camera = {.position_m = {0.0, 15e6, 0.0},
              .target_m = {1.0, 0.0, 0.0},
              .fov_y_rad = 60.0 * kSpherePi / 180.0,
              .aspect = 1.0,
              .near_m = 1000.0,
              .far_m = 1e8};
  v.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::low);
  const auto centre = [&](const std::array<double, 3>& water, bool air) {
    v.shading.water_colour = water;
    v.shading.aerial_perspective = air;
    std::vector<float> hdr;
    EXPECT_TRUE(rig->renderer->draw(v).ok());
    EXPECT_TRUE(rig->renderer->read_hdr(hdr).ok());
    std::array<double, 3> mean{};
    for (int y = kSide / 2 - 1; y <= kSide / 2; ++y)
      for (int x = kSide / 2 - 1; x <= kSide / 2; ++x)
        for (std::size_t c = 0; c < 3; ++c)
          mean[c] += 0.25 * hdr[static_cast<std::size_t>(4 * (y * kSide + x)) + c];
    // The planet's disc spans asin(R/(R + h)) = 17.3° of the 30° half field: each corner's
    // 6 × 6 pixels look past the air.
    if (air) {
      for (const int cy : {0, kSide - 6})
        for (const int cx : {0, kSide - 6})
          for (int y = cy; y < cy + 6; ++y)
            for (int x = cx; x < cx + 6; ++x)
              for (std::size_t c = 0; c < 3; ++c) {
                EXPECT_EQ(hdr[static_cast<std::size_t>(4 * (y * kSide + x)) + c], 0.0f)
                    << "pixel " << x << "," << y;
              }
    }
    return mean;
  };
  const std::array<double, 3> dark = {0.004, 0.016, 0.028}, light = {0.3, 0.3, 0.3};
  const auto with_dark = centre(dark, true), with_light = centre(light, true);
  const auto bare_dark = centre(dark, false), bare_light = centre(light, false);
  const ocean::render::Sky::Air air = ocean::render::Sky(v.shading).air();
  for (std::size_t c = 0; c < 3; ++c) {
    const double measured = (with_light[c] - with_dark[c]) / (bare_light[c] - bare_dark[c]);
    const double column = std::exp(-(air.rayleigh_per_m[c] * air.rayleigh_height_m *
                                          (1.0 - std::exp(-80e3 / air.rayleigh_height_m)) +
                                      air.mie_per_m * air.mie_height_m));
    std::printf("channel %zu: transmittance %.4f, column %.4f; air light %.4f over water %.4f\n", c,
                measured, column, with_dark[c] - bare_dark[c] * measured, bare_dark[c]);
    EXPECT_NEAR(measured, column, 0.01 * column) << "channel " << c;
  }
}

TEST(SphereRender, BadViewsAreRefused) {
  auto rig = make_rig(16, 16);
  REQUIRE_RIG(rig);
  View v;
  v.sphere.enabled = true;
  v.planet_radius_m = 5000.0;
  v.camera = {.position_m = {0.0, -10.0, 0.0}, .target_m = {0.0, -20.0, 1.0}};
  EXPECT_FALSE(rig->renderer->draw(v).ok());  // inside the planet
  v.camera.position_m.y = 10.0;
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(rig->renderer->draw(v).ok());
  v.planet_radius_m = std::nan("");
  EXPECT_FALSE(rig->renderer->draw(v).ok());
  v.planet_radius_m = 5000.0;
  v.sphere.latitude_deg = 91.0;
  EXPECT_FALSE(rig->renderer->draw(v).ok());
  v.sphere.latitude_deg = 0.0;
  EXPECT_TRUE(rig->renderer->draw(v).ok());
}

}  // namespace
#undef REQUIRE_RIG
