// The sea from below (lavapipe, validation layer on; docs/rendering.md R.50–R.51, R.54). Under calm
// water looking straight up, the sky shows inside Snell's window by the Fresnel transmittance,
// which ends at the critical angle arcsin(1/1.333) = 48.6° from the vertical, and total internal
// reflection fills the rest; a target's contrast fades by the beam attenuation e^{−c·r}. With the
// camera straddling a wavy surface, every pixel whose near-plane point the CPU height query puts
// under the surface shows the water (no gap to the sky along the waterline) and every one above it
// shows the air's side (no bar of water).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
  return helpers::make_rig(helpers::graphics_context(), helpers::small_config(), width, height);
}

// Looking straight up from 3 m under calm water at a uniform grey sky, through water that neither
// absorbs nor scatters and has no light of its own: a pixel at θ from the zenith shows n²·T(θ)·L,
// T the water-to-air Fresnel transmittance (R.50), box-filtered over the pixel. The window's
// half-level radius, read off the picture along eight directions and converted to an angle by
// the projection, lies where T falls to half its zenith value (Fresnel's, 0.39° inside the
// critical angle); the picture turns dark one pixel beyond the critical angle at most; and the
// edge is a ramp of many pixels, each a level of its own.
TEST(Underwater, SnellsWindowFollowsFresnelToTheCriticalAngle) {
  constexpr int kSide = 161;
  auto rig = make_rig(kSide, kSide);
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  rig->renderer->set_calm(true);  // no layer either: the surface is the plane y = 0
  constexpr float kSky = 0.3f;
  const Environment grey{.width = 4, .height = 2, .rgb = std::vector<float>(24, kSky)};
  ASSERT_TRUE(rig->renderer->set_environment(&grey).ok());
  View v = helpers::eye_level_view(kSide, kSide);
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.camera.position_m = {0.0, -3.0, 0.0};
  v.camera.target_m = {0.0, 10.0, 1e-3};  // straight up
  v.camera.fov_y_rad = 120.0 * kDeg;
  v.shading.water_colour = {0.0, 0.0, 0.0};
  v.shading.foam_brightness = 0.0;
  v.seabed.absorption_per_m = {0.0, 0.0, 0.0};
  v.underwater.scattering_per_m = 0.0;
  ASSERT_TRUE(rig->renderer->draw(v).ok());
  std::vector<float> hdr;
  ASSERT_TRUE(rig->renderer->read_hdr(hdr).ok());
  std::vector<std::uint8_t> srgb;
  ASSERT_TRUE(rig->renderer->read_srgb(srgb).ok());
  const auto px = [&](int x, int y) { return static_cast<std::size_t>(y * kSide + x); };
  const auto green = [&](int x, int y) { return static_cast<double>(hdr[4 * px(x, y) + 1]); };

  const double n = ocean::render::kWaterIor, critical = std::asin(1.0 / n);
  EXPECT_NEAR(critical / kDeg, 48.6, 0.05);  // the angle the docs state
  // The transmittance against its published values: ((n−1)/(n+1))² reflected at normal
  // incidence, none at Brewster's angle for p (the unpolarised mean of r_s² alone), all beyond
  // the critical angle.
  EXPECT_NEAR(water_to_air_transmittance(1.0), 1.0 - std::pow((n - 1) / (n + 1), 2), 1e-12);
  const double brewster = std::atan(1.0 / n);
  const double ct = std::cos(std::asin(n * std::sin(brewster)));
  const double r_s = (n * std::cos(brewster) - ct) / (n * std::cos(brewster) + ct);
  EXPECT_NEAR(water_to_air_transmittance(std::cos(brewster)), 1.0 - 0.5 * r_s * r_s, 1e-12);
  EXPECT_EQ(water_to_air_transmittance(std::cos(critical + 1e-9)), 0.0);
  // Where Fresnel's transmittance is half its zenith value: bisection on the falling branch.
  const double t0 = water_to_air_transmittance(1.0);
  double lo = 0.0, hi = critical;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (water_to_air_transmittance(std::cos(mid)) > 0.5 * t0 ? lo : hi) = mid;
  }
  const double half_fresnel = lo;

  // Inside: the zenith pixel n²·T(0)·L (R.50's n² law); outside: the corners, dark.
  const int c = kSide / 2;  // the optical axis passes through this pixel's centre
  const double inside = green(c, c), outside = green(0, 0);
  EXPECT_NEAR(inside, n * n * t0 * kSky, 0.01 * inside);
  EXPECT_LT(outside, 1e-4 * inside);
  const double focal_px = 0.5 * kSide / std::tan(0.5 * v.camera.fov_y_rad);
  // One pixel's angle along a radius at θ from the axis: dθ = cos²θ/f.
  const double pixel = std::pow(std::cos(critical), 2) / focal_px;
  const int dirs[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
  double worst_half = 0.0, mean_half = 0.0, widest = 0.0, narrowest = 1e9;
  for (const auto& d : dirs) {
    const double step = std::hypot(d[0], d[1]);
    std::vector<double> profile;  // brightness over inside, outwards from the centre
    for (int k = 0; k <= c; ++k)
      profile.push_back((green(c + k * d[0], c + k * d[1]) - outside) / (inside - outside));
    const auto angle = [&](double k) { return std::atan(k * step / focal_px); };
    // The half-level crossing, linear between the two pixels on either side.
    std::size_t k = 1;
    while (k < profile.size() && profile[k] > 0.5) ++k;
    ASSERT_LT(k, profile.size()) << "no edge found";
    const double at =
        static_cast<double>(k - 1) + (profile[k - 1] - 0.5) / (profile[k - 1] - profile[k]);
    const double half = angle(at);
    // The sampling's error: half a pixel (along a diagonal the pixels lie √2 apart).
    EXPECT_NEAR(half, half_fresnel, 0.5 * step * pixel) << "direction " << d[0] << "," << d[1];
    EXPECT_NEAR(half, critical, (critical - half_fresnel) + 0.5 * step * pixel);
    worst_half = std::max(worst_half, std::abs(half - half_fresnel));
    mean_half += half / 8.0;
    // The window ends at the critical angle: the first dark pixel's footprint lies beyond it, the
    // one before reaches inside it.
    std::size_t dark = 1;
    while (dark < profile.size() && profile[dark] > 1e-4) ++dark;
    ASSERT_LT(dark, profile.size());
    EXPECT_GE(angle(static_cast<double>(dark) + 0.5), critical) << d[0] << "," << d[1];
    EXPECT_LE(angle(static_cast<double>(dark) - 1.5), critical) << d[0] << "," << d[1];
    // A soft edge: the pixels between 90 % and 10 % of the inside level, at least two, and in the
    // 8-bit picture each darker than the one before (no posterised steps, no flat run).
    int ramp = 0, levels = 0;
    int last = 256;
    for (std::size_t j = 0; j < profile.size(); ++j) {
      if (profile[j] > 0.9 || profile[j] < 0.1) continue;
      ++ramp;
      const int level =
          srgb[4 * px(c + static_cast<int>(j) * d[0], c + static_cast<int>(j) * d[1]) + 1];
      levels += level < last ? 1 : 0;
      last = level;
    }
    EXPECT_GE(ramp, 2) << "direction " << d[0] << "," << d[1];
    EXPECT_EQ(levels, ramp) << "direction " << d[0] << "," << d[1];
    widest = std::max(widest, ramp * step);
    narrowest = std::min(narrowest, ramp * step);
  }
  std::printf(
      "Snell's window: half level at %.3f deg (Fresnel %.3f, worst %.3f deg off, pixel "
      "%.3f deg), critical angle %.3f deg, 90-10 %% ramp %.1f-%.1f px\n",
      mean_half / kDeg, half_fresnel / kDeg, worst_half / kDeg, pixel / kDeg, critical / kDeg,
      narrowest, widest);
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
  v.underwater.scattering_per_m = 0.0;  // no sunlight scattered white in the water (R.66)
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
// light looking down from 2 m, as R.51 writes them with the stated absorption and scattering, and
// the sunlight the path scatters back (R.66).
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
    // The sunlight the 3 m of water scatters back up to the eye (R.66).
    const double shafts =
        sun[c] * mu_s * (1.0 - fresnel) *
        sun_single_scattering(sun_direction(v.shading.sun_azimuth_deg, v.shading.sun_elevation_deg),
                              {0.0, -1.0, 0.0}, 2.0, 3.0, a, b);
    const double expected = bed * t + water * (1.0 - t) + shafts;
    EXPECT_NEAR(hdr[centre + c], expected, 0.01 * expected) << "channel " << c;
  }
}

// Contrast through the water's fog (R.51, R.54): a white square facing a camera 5 m down is seen
// at distances d on the view axis against the endless water behind it. Its apparent contrast
// C(d) = (L_t − L_b)/L_b is its inherent contrast times e^{−c·d}, c = a + b per channel, whatever
// the square's own light (Duntley's contrast transmittance), so the ratio between distances
// gives c back; with the default water, 4.8/c at 550 nm (the green channel) is 20–40 m.
TEST(Underwater, ContrastFadesByTheBeamAttenuation) {
  constexpr int kSide = 33;
  auto rig = make_rig(kSide, kSide);
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  rig->renderer->set_calm(true);
  const std::array<std::array<double, 3>, 4> corners{
      {{0.0, -2.0, -2.0}, {0.0, 2.0, -2.0}, {0.0, 2.0, 2.0}, {0.0, -2.0, 2.0}}};
  const std::array<std::array<std::uint32_t, 3>, 4> both_sides{
      {{0, 1, 2}, {0, 2, 3}, {0, 2, 1}, {0, 3, 2}}};
  const Mesh square = flat_mesh(corners, both_sides, {.base_colour = {1.0, 1.0, 1.0}});
  ASSERT_TRUE(rig->renderer->set_meshes(std::span(&square, 1)).ok());
  View v = helpers::eye_level_view(kSide, kSide);
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.camera.position_m = {0.0, -5.0, 0.0};
  v.camera.target_m = {10.0, -5.0, 0.0};  // along +x, level
  v.camera.fov_y_rad = 20.0 * kDeg;
  const std::size_t centre = static_cast<std::size_t>(4 * ((kSide / 2) * kSide + kSide / 2));
  const auto centre_rgb = [&]() {
    std::vector<float> hdr;
    EXPECT_TRUE(rig->renderer->draw(v).ok());
    EXPECT_TRUE(rig->renderer->read_hdr(hdr).ok());
    return std::array<double, 3>{hdr[centre], hdr[centre + 1], hdr[centre + 2]};
  };
  const std::array<double, 3> background = centre_rgb();
  const std::array<double, 3> distances{3.0, 8.0, 14.0};
  std::array<std::array<double, 3>, 3> contrast{};
  for (std::size_t i = 0; i < distances.size(); ++i) {
    v.objects = {{.mesh = 0, .model = model_matrix({distances[i], -5.0, 0.0}, {1, 0, 0, 0})}};
    const std::array<double, 3> target = centre_rgb();
    for (std::size_t ch = 0; ch < 3; ++ch)
      contrast[i][ch] = (target[ch] - background[ch]) / background[ch];
  }
  std::array<double, 3> c_measured{};
  for (std::size_t ch = 0; ch < 3; ++ch) {
    const double c = ocean::render::beam_attenuation_per_m(v.seabed.absorption_per_m[ch],
                                                           v.underwater.scattering_per_m);
    for (std::size_t i = 1; i < distances.size(); ++i) {
      const double expected = std::exp(-c * (distances[i] - distances[0]));
      EXPECT_NEAR(contrast[i][ch] / contrast[0][ch], expected, 0.03 * expected)
          << "channel " << ch << ", " << distances[i] << " m";
    }
    c_measured[ch] = std::log(contrast[0][ch] / contrast[2][ch]) / (distances[2] - distances[0]);
    EXPECT_NEAR(c_measured[ch], c, 0.03 * c) << "channel " << ch;
  }
  const double visibility =
      ocean::render::visibility_m(v.seabed.absorption_per_m[1], v.underwater.scattering_per_m);
  EXPECT_NEAR(visibility, 4.8 / (v.seabed.absorption_per_m[1] + v.underwater.scattering_per_m),
              1e-12);
  EXPECT_GE(visibility, 20.0);
  EXPECT_LE(visibility, 40.0);
  const double measured = 4.8 / c_measured[1];
  EXPECT_GE(measured, 20.0);
  EXPECT_LE(measured, 40.0);
  std::printf(
      "beam attenuation measured %.4f %.4f %.4f /m (a + b: %.4f %.4f %.4f); visibility "
      "4.8/c at 550 nm %.1f m (measured %.1f m)\n",
      c_measured[0], c_measured[1], c_measured[2],
      v.seabed.absorption_per_m[0] + v.underwater.scattering_per_m,
      v.seabed.absorption_per_m[1] + v.underwater.scattering_per_m,
      v.seabed.absorption_per_m[2] + v.underwater.scattering_per_m, visibility, measured);
}

// A sea of short waves for the caustics: cascades of 47 and 11 m (texels 0.73 and 0.17 m) of a
// 7 m/s wind sea, Hs about 0.8 m.
std::unique_ptr<Rig> make_short_wave_rig(int width, int height) {
  ocean::SimulationConfig c = helpers::small_config();
  c.cascade_patch_sizes_m = {47.0, 11.0};
  c.sea.wind_sea.spectrum.wind_speed_mps = 7.0;
  c.sea.wind_sea.spectrum.fetch_m = 20e3;
  return helpers::make_rig(helpers::graphics_context(), c, width, height);
}

// The unit view direction of pixel (x, y) (row 0 at the top) of a camera without roll.
std::array<double, 3> pixel_ray(const View& v, int width, int height, int x, int y) {
  const auto& p = v.camera.position_m;
  const auto& t = v.camera.target_m;
  std::array<double, 3> f{t.x - p.x, t.y - p.y, t.z - p.z};
  const auto normalise = [](std::array<double, 3> a) {
    const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    return std::array<double, 3>{a[0] / l, a[1] / l, a[2] / l};
  };
  f = normalise(f);
  const std::array<double, 3> r = normalise({-f[2], 0.0, f[0]});  // f × up
  const std::array<double, 3> up{r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2],
                                 r[0] * f[1] - r[1] * f[0]};
  const double half = std::tan(0.5 * v.camera.fov_y_rad);
  const double sx = (2.0 * (x + 0.5) / width - 1.0) * half * width / height;
  const double sy = (1.0 - 2.0 * (y + 0.5) / height) * half;
  return normalise({f[0] + sx * r[0] + sy * up[0], f[1] + sx * r[1] + sy * up[1],
                    f[2] + sx * r[2] + sy * up[2]});
}

// Caustics on the bed seen from below (R.65): looking straight down from 2 m under the short
// waves onto a bed 12 m down, through water that neither absorbs nor scatters, has no light of
// its own and so shows the bed's light unchanged. Per pixel the waves' picture over the calm
// one's is f·C + (1 − f), C the caustic irradiance and f the sun's share of the bed's light
// (R.23): the mean of C over the 20 m × 20 m of bed in view is the sun's irradiance (energy is
// conserved: the exact mean over a period is 1, here a sample of some 400 caustic cells), and
// the waves do focus it (bright lines, dark cells).
TEST(Underwater, CausticsOnTheBedConserveTheSunsLight) {
  constexpr int kSide = 96;
  auto rig = make_short_wave_rig(kSide, kSide);
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  View v = helpers::eye_level_view(kSide, kSide);
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.camera.position_m = {0.0, -2.0, 0.0};
  v.camera.target_m = {1e-3, -10.0, 0.0};  // straight down
  v.camera.fov_y_rad = 90.0 * kDeg;
  v.shading.sun_elevation_deg = 70.0;
  v.shading.water_colour = {0.0, 0.0, 0.0};
  v.seabed = {.enabled = true,
              .depth_m = 12.0,
              .albedo = {0.5, 0.5, 0.5},
              .absorption_per_m = {0.0, 0.0, 0.0}};
  v.underwater.scattering_per_m = 0.0;
  const auto picture = [&]() {
    std::vector<float> hdr;
    EXPECT_TRUE(rig->renderer->draw(v).ok());
    EXPECT_TRUE(rig->renderer->read_hdr(hdr).ok());
    return hdr;
  };
  const std::vector<float> waves = picture();
  rig->renderer->set_calm(true);
  const std::vector<float> calm = picture();
  const Sky sky(v.shading);
  const double mu_s = std::sin(v.shading.sun_elevation_deg * kDeg);
  const double sun_h =
      sky.sun_irradiance_ground()[1] * mu_s * (1.0 - (0.02 + 0.98 * std::pow(1.0 - mu_s, 5.0)));
  const double f = sun_h / (sun_h + sky.sky_irradiance_horizontal()[1]);
  double sum = 0.0, sum_sq = 0.0, lo = 1e9, hi = 0.0, calm_lo = 1e9, calm_hi = 0.0;
  const int n = kSide * kSide;
  for (int i = 0; i < n; ++i) {
    const double c0 = calm[4 * static_cast<std::size_t>(i) + 1];
    const double C = (waves[4 * static_cast<std::size_t>(i) + 1] / c0 - (1.0 - f)) / f;
    sum += C;
    sum_sq += C * C;
    lo = std::min(lo, C);
    hi = std::max(hi, C);
    calm_lo = std::min(calm_lo, c0);
    calm_hi = std::max(calm_hi, c0);
  }
  const double mean = sum / n, sd = std::sqrt(std::max(sum_sq / n - mean * mean, 0.0));
  std::printf(
      "caustics on a 12 m bed: mean E/E0 %.4f, sd %.3f, min %.3f, max %.3f (sun's share "
      "%.2f); calm bed uniform within %.2e\n",
      mean, sd, lo, hi, f, calm_hi / calm_lo - 1.0);
  EXPECT_LT(calm_hi / calm_lo - 1.0, 1e-3);  // a Lambertian bed seen through clear water
  EXPECT_NEAR(mean, 1.0, 0.05);
  EXPECT_GT(sd, 0.1);
  EXPECT_GT(hi, 1.3);
  EXPECT_LT(lo, 0.8);
}

// Light shafts under a flat surface (R.66): from 5 and 10 m deep, looking up towards the sun
// under a black sky into water with no light of its own, each pixel shows only the sunlight its
// path scatters once towards the eye, E_h·sun_single_scattering: b·p(θ)/μ_w·e^{−a·z/μ_w}·
// (1 − e^{−κ·r})/κ per channel, r the path to the surface (or endless, below the horizon), with
// the phase function's forward peak towards the refracted sun in the picture. Under waves the
// shafts vary from pixel to pixel about the same mean.
TEST(Underwater, LightShaftsFollowTheSingleScatteringIntegral) {
  constexpr int kShaftW = 64, kShaftH = 48;
  auto rig = make_short_wave_rig(kShaftW, kShaftH);
  if (rig == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const Environment black{.width = 4, .height = 2, .rgb = std::vector<float>(24, 0.0f)};
  ASSERT_TRUE(rig->renderer->set_environment(&black).ok());
  View v = helpers::eye_level_view(kShaftW, kShaftH);
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.shading.sun_elevation_deg = 60.0;
  v.shading.sun_azimuth_deg = 0.0;  // the sun over +x: its light runs towards −x
  v.shading.water_colour = {0.0, 0.0, 0.0};
  v.shading.foam_brightness = 0.0;
  v.underwater.scattering_per_m = 0.3;  // coastal water
  v.camera.fov_y_rad = 80.0 * kDeg;
  const auto look_from = [&](double depth) {
    // Towards +x, 30° up: the refracted sun's source, 68° up, lies near the top row.
    v.camera.position_m = {0.0, -depth, 0.0};
    v.camera.target_m = {10.0, -depth + 10.0 * std::tan(30.0 * kDeg), 0.0};
    std::vector<float> hdr;
    EXPECT_TRUE(rig->renderer->draw(v).ok());
    EXPECT_TRUE(rig->renderer->read_hdr(hdr).ok());
    return hdr;
  };
  rig->renderer->set_calm(true);
  const Sky sky(v.shading);
  const auto sun = sun_direction(v.shading.sun_azimuth_deg, v.shading.sun_elevation_deg);
  const double mu_s = sun[1], fresnel = 0.02 + 0.98 * std::pow(1.0 - mu_s, 5.0);
  double worst = 0.0, brightest = 0.0, dimmest = 1e9;
  std::vector<float> shallow;
  for (const double depth : {5.0, 10.0}) {
    const std::vector<float> hdr = look_from(depth);
    if (depth == 5.0) shallow = hdr;
    for (int y = 0; y < kShaftH; ++y)
      for (int x = 0; x < kShaftW; ++x) {
        const auto ray = pixel_ray(v, kShaftW, kShaftH, x, y);
        const double r = ray[1] > 0.0 ? depth / ray[1] : std::numeric_limits<double>::infinity();
        const std::size_t i = 4 * static_cast<std::size_t>(y * kShaftW + x);
        for (std::size_t c = 0; c < 3; ++c) {
          const double expected =
              sky.sun_irradiance_ground()[c] * mu_s * (1.0 - fresnel) *
              sun_single_scattering(sun, ray, depth, r, v.seabed.absorption_per_m[c],
                                    v.underwater.scattering_per_m);
          worst = std::max(worst, std::abs(hdr[i + c] - expected) / expected);
          if (c == 1) {
            brightest = std::max(brightest, expected);
            dimmest = std::min(dimmest, expected);
          }
        }
      }
  }
  std::printf(
      "shafts under a flat surface: largest error against the closed form %.2e (the "
      "picture spans %.0fx in brightness)\n",
      worst, brightest / dimmest);
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(brightest / dimmest, 10.0);  // the phase function's peak is in the picture

  rig->renderer->set_calm(false);
  const std::vector<float> waves = look_from(5.0);
  double sum = 0.0, sum_sq = 0.0;
  const int n = kShaftW * kShaftH;
  for (int i = 0; i < n; ++i) {
    const std::size_t g = 4 * static_cast<std::size_t>(i) + 1;
    const double r = waves[g] / shallow[g];
    sum += r;
    sum_sq += r * r;
  }
  const double mean = sum / n, sd = std::sqrt(std::max(sum_sq / n - mean * mean, 0.0));
  std::printf("shafts under waves over a flat surface's: mean %.4f, sd %.4f\n", mean, sd);
  EXPECT_NEAR(mean, 1.0, 0.1);
  EXPECT_GT(sd, 0.02);
}

TEST(Underwater, RefusesBadOptics) {
  for (const double a : {-0.1, std::numeric_limits<double>::quiet_NaN()}) {
    View v;
    v.seabed.absorption_per_m[1] = a;
    const ocean::Status s = validate(v);
    EXPECT_EQ(s.code(), ocean::ErrorCode::invalid_argument) << a;
    EXPECT_NE(s.message().find("absorption_per_m"), std::string::npos) << s.message();
    EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
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
