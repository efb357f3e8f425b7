// The sea from below (lavapipe, validation layer on; docs/rendering.md R.50–R.51). Under calm
// water looking straight up, the sky shows inside Snell's window, whose edge lies at the
// critical angle arcsin(1/1.333) = 48.6° from the vertical, and total internal reflection fills
// the rest. With the camera straddling a wavy surface, every pixel whose near-plane point the
// CPU height query puts under the surface shows the water (no gap to the sky along the
// waterline) and every one above it shows the air's side (no bar of water).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "ocean/backends.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using namespace ocean::render;
namespace helpers = ocean::render::testing;
constexpr double kDeg = std::numbers::pi / 180.0;

using Rig = helpers::ValidatedRig;

std::unique_ptr<Rig> make_rig(int width, int height) {
  auto rig = std::make_unique<Rig>();
  rig->ctx = helpers::graphics_context();
  if (rig->ctx == nullptr) return nullptr;
  const ocean::SimulationConfig c = helpers::small_config();
  rig->sim = ocean::make_simulator(c).value();
  rig->sim->step(3.0);
  rig->renderer = Renderer::make(rig->ctx, {.width = width, .height = height}).value();
  EXPECT_TRUE(rig->renderer->configure(ocean::SimulationPlan::make(c).value().surface()).ok());
  EXPECT_TRUE(rig->renderer->upload(rig->sim->frame()).ok());
  return rig;
}

TEST(Underwater, SnellsWindowEndsAtTheCriticalAngle) {
  constexpr int kSide = 161;
  auto rig = make_rig(kSide, kSide);
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  rig->renderer->set_calm(true);  // no layer either: the surface is the plane y = 0
  View v = helpers::eye_level_view(kSide, kSide);
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.camera.position_m = {0.0, -2.0, 0.0};
  v.camera.target_m = {0.0, 10.0, 1e-3};  // straight up
  v.camera.fov_y_rad = 120.0 * kDeg;
  ASSERT_TRUE(rig->renderer->draw(v).ok());
  std::vector<float> hdr;
  ASSERT_TRUE(rig->renderer->read_hdr(hdr).ok());
  const auto green = [&](int x, int y) {
    return hdr[static_cast<std::size_t>(4 * (y * kSide + x) + 1)];
  };
  // Beyond the window the water mirrors itself: the picture's corners hold that level.
  const double reflected = green(0, 0);
  ASSERT_GT(reflected, 0.0);
  const double focal_px = 0.5 * kSide / std::tan(0.5 * v.camera.fov_y_rad);
  const double critical = std::asin(1.0 / 1.333);
  EXPECT_NEAR(critical / kDeg, 48.6, 0.05);  // the angle the docs state
  // Along the four half-axes from the centre: the last window pixel lies inside the critical
  // angle and the first reflecting one outside it (the pixel centres' angles from the zenith).
  const int c = kSide / 2;
  const int dirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const auto& d : dirs) {
    int k = 0;
    while (k < c && green(c + k * d[0], c + k * d[1]) > 2.0 * reflected) ++k;
    ASSERT_GT(k, 0);
    ASSERT_LT(k, c) << "no edge found";
    const double inside = std::atan((k - 1) / focal_px), outside = std::atan(k / focal_px);
    EXPECT_LT(inside, critical) << "direction " << d[0] << "," << d[1];
    EXPECT_GT(outside, critical) << "direction " << d[0] << "," << d[1];
  }
}

TEST(Underwater, TheWaterlineShowsNoGapAndNoBar) {
  constexpr int kUnderW = 96, kUnderH = 64;
  auto rig = make_rig(kUnderW, kUnderH);
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  // A green sky over water that scatters blue alone: a pixel with green looks through the air
  // (the sky, or the surface from above reflecting it), one without through the water. No foam
  // (foam seen from below is lit white).
  const Environment green_sky{
      .width = 4, .height = 2, .rgb = {0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f,
                                       0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f,
                                       1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.0f}};
  ASSERT_TRUE(rig->renderer->set_environment(&green_sky).ok());
  View v = helpers::eye_level_view(kUnderW, kUnderH);
  v.shading.water_colour = {0.0, 0.0, 0.03};
  v.shading.foam_brightness = 0.0;
  // A flat world: on a curved one the skirt meets the patches at T-junctions whose hairline
  // cracks let single pixels of the horizon row through from below (docs/rendering.md R.50).
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  // The near plane 1 m away spans ±0.27 m in height; Snell's window (41° up and more) stays out
  // of the picture.
  v.camera.near_m = 1.0;
  v.camera.fov_y_rad = 30.0 * kDeg;
  const std::array<double, 2> eye_xz{3.0, -2.0};
  ocean::HeightSample here;
  rig->sim->heights_at(std::span(&eye_xz, 1), std::span(&here, 1));
  // The drawn mesh interpolates the surface between its vertices, so the waterline is where the
  // near plane meets the mesh, within decimetres of the exact height at this coarse quality:
  // eyes from 0.3 m below to 0.3 m above the surface, 0.1 m apart, straddle it at least once.
  int straddling = 0;
  for (int step = -3; step <= 3; ++step) {
    const double eye_y = here.height_m + 0.1 * step;
    v.camera.position_m = {eye_xz[0], eye_y, eye_xz[1]};
    v.camera.target_m = {eye_xz[0] - 100.0, eye_y, eye_xz[1] - 70.0};
    ASSERT_TRUE(rig->renderer->draw(v).ok());
    std::vector<float> hdr;
    ASSERT_TRUE(rig->renderer->read_hdr(hdr).ok());
    const auto sees_air = [&](int px, int py) {
      return hdr[static_cast<std::size_t>(4 * (py * kUnderW + px) + 1)] > 1e-4f;
    };
    // Per column, from the bottom up: pixels that look through the water, then pixels that
    // look through the air — at most one change, none back: no sky below the waterline (a gap),
    // no water above it (a bar).
    int wrong = 0, crossed = 0;
    for (int px = 0; px < kUnderW; ++px) {
      int changes = 0;
      for (int py = kUnderH - 1; py > 0; --py) changes += sees_air(px, py) != sees_air(px, py - 1);
      if (changes > 1 || (changes == 1 && (sees_air(px, kUnderH - 1) || !sees_air(px, 0)))) ++wrong;
      crossed += changes == 1 ? 1 : 0;
    }
    EXPECT_EQ(wrong, 0) << "columns with a gap or a bar, eye " << 0.1 * step << " m off";
    straddling += crossed == kUnderW ? 1 : 0;
  }
  EXPECT_GE(straddling, 1) << "no eye height put the waterline across the whole picture";
}

// Looking straight down from 2 m under calm water onto a 5 m bed (R.51, R.52): the bed's light
// (R.23's irradiance at 5 m on its albedo, Lambertian) through 3 m of water, plus the water's own
// light looking down from 2 m, as R.51 writes them with the stated absorption and scattering.
TEST(Underwater, TheBedBelowShowsThroughTheWatersFog) {
  constexpr int kSide = 33;
  auto rig = make_rig(kSide, kSide);
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  rig->renderer->set_calm(true);
  View v = helpers::eye_level_view(kSide, kSide);
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.camera.position_m = {0.0, -2.0, 0.0};
  v.camera.target_m = {1e-3, -10.0, 0.0};  // straight down
  v.seabed = {.enabled = true, .depth_m = 5.0, .albedo = {0.5, 0.5, 0.5}};
  ASSERT_TRUE(rig->renderer->draw(v).ok());
  std::vector<float> hdr;
  ASSERT_TRUE(rig->renderer->read_hdr(hdr).ok());
  const Sky sky(v.shading);
  const std::array<double, 3> sun = sky.sun_irradiance_ground(),
                              sky_e = sky.sky_irradiance_horizontal();
  const double mu_s = std::sin(v.shading.sun_elevation_deg * kDeg);
  const double fresnel = 0.02 + 0.98 * std::pow(1.0 - mu_s, 5.0);
  const double mu_w = std::sqrt(1.0 - (1.0 - mu_s * mu_s) / (1.333 * 1.333));
  const std::size_t centre = static_cast<std::size_t>(4 * ((kSide / 2) * kSide + kSide / 2));
  for (std::size_t c = 0; c < 3; ++c) {
    const double a = v.seabed.absorption_per_m[c], b = v.underwater.scattering_per_m;
    const double on_bed =
        sun[c] * mu_s * (1.0 - fresnel) * std::exp(-a * 5.0 / mu_w) + sky_e[c] * std::exp(-a * 5.0);
    const double bed = 0.5 * on_bed / std::numbers::pi;
    const double water = v.shading.water_colour[c] * (sun[c] * mu_s * (1.0 - fresnel) + sky_e[c]) /
                         std::numbers::pi * std::exp(-a * 2.0);  // looking down: 3^0
    const double t = std::exp(-(a + b) * 3.0);
    const double expected = bed * t + water * (1.0 - t);
    EXPECT_NEAR(hdr[centre + c], expected, 0.01 * expected) << "channel " << c;
  }
}

TEST(Underwater, RefusesABadScattering) {
  for (const double b : {-0.1, 11.0, std::numeric_limits<double>::quiet_NaN()}) {
    View v;
    v.underwater.scattering_per_m = b;
    const ocean::Status s = validate(v);
    EXPECT_EQ(s.code(), ocean::ErrorCode::invalid_argument) << b;
    EXPECT_NE(s.message().find("scattering_per_m"), std::string::npos) << s.message();
  }
  EXPECT_TRUE(validate(View{}).ok());
}

}  // namespace
