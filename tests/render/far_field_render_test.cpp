// The far field as a picture (docs/rendering.md R.5, R.13, R.14) on any Vulkan device (lavapipe
// on CPU-only machines): from a high camera every distance band of a render keeps its mean
// luminance and at least half of the detail of the same view rendered 4×4 larger and averaged
// down in linear light (what a pixel should show), and looking straight down the picture does
// not repeat at the largest cascade's period more than at unrelated shifts. The figures are
// printed; `ocean render` draws the same views (docs/rendering.md). Skips where no Vulkan device
// exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "ocean/plan.hpp"
#include "ocean/scene.hpp"
#include "ocean/statistics.hpp"
#include "ocean/task_runner.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::Scene;
using ocean::render::View;

// The moderate preset (presets/moderate.json): the default sea with four cascades.
ocean::SimulationConfig moderate() {
  ocean::SimulationConfig c;
  c.cascade_patch_sizes_m = {1000.0, 233.0, 57.0, 13.0};
  return c;
}

// `ocean render`'s defaults (time 20 s after a 4 s warm-up, high quality, 4096 m square, clear
// sky) for a camera; linear RGB of the sRGB picture, row-major.
std::vector<double> render_linear(int width, int height, std::array<double, 3> eye,
                                  std::array<double, 3> target, double fov_deg,
                                  ocean::render::FarFieldRange far_field = {},
                                  double sun_elevation_deg = 20.0,
                                  ocean::FoamSource foam = ocean::FoamSource::breaking) {
  ocean::SimulationConfig config = moderate();
  config.foam.source = foam;
  auto scene = Scene::make({.config = config, .width = width, .height = height});
  if (!scene.ok()) return {};
  EXPECT_TRUE(scene.value()->warm_up(20.0, 4.0).ok());
  View view;
  view.camera = {.position_m = {eye[0], eye[1], eye[2]},
                 .target_m = {target[0], target[1], target[2]},
                 .fov_y_rad = fov_deg * std::numbers::pi / 180.0,
                 .aspect = static_cast<double>(width) / height,
                 .near_m = 0.2,
                 .far_m = 2e5};
  view.shading = ocean::render::sky_preset("clear").value();
  view.shading.sun_elevation_deg = sun_elevation_deg;
  view.far_field = far_field;
  const ocean::Status drawn = scene.value()->renderer().draw(view);
  EXPECT_TRUE(drawn.ok()) << drawn.message();
  std::vector<std::uint8_t> srgb;
  EXPECT_TRUE(scene.value()->renderer().read_srgb(srgb).ok());
  std::vector<double> rgb;
  rgb.reserve(srgb.size() / 4 * 3);
  for (std::size_t i = 0; i < srgb.size(); ++i) {
    if (i % 4 == 3) continue;
    const double c = srgb[i] / 255.0;  // the sRGB transfer function, inverted
    rgb.push_back(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
  }
  return rgb;
}

// Luminance (Rec. 709) of linear RGB, averaged over factor × factor blocks.
std::vector<double> luminance(const std::vector<double>& rgb, int width, int height, int factor) {
  const int w = width / factor, h = height / factor;
  std::vector<double> y(static_cast<std::size_t>(w) * h, 0.0);
  for (int row = 0; row < height; ++row)
    for (int col = 0; col < width; ++col) {
      const std::size_t i = (static_cast<std::size_t>(row) * width + col) * 3;
      y[static_cast<std::size_t>(row / factor) * w + col / factor] +=
          (0.2126 * rgb[i] + 0.7152 * rgb[i + 1] + 0.0722 * rgb[i + 2]) / (factor * factor);
    }
  return y;
}

double encode(double linear) {  // sRGB transfer function, 0..255
  const double c = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
  return 255.0 * c;
}

#define REQUIRE_DEVICE()                                     \
  if (ocean::render::testing::graphics_context() == nullptr) \
  OCEAN_SKIP_OR_FAIL(                                        \
      "no Vulkan "                                           \
      "device")

// From 400 m up, per band of distance to the sea: mean luminance (linear) and mean |horizontal
// difference| of the sRGB-encoded luminance (the detail), the render against the 4×4
// supersampled one averaged down in linear light. Bands end where the horizon fog (R.8) takes
// over a tenth of the colour.
TEST(FarFieldRender, EveryDistanceBandKeepsTheSupersampledBrightnessAndDetail) {
  REQUIRE_DEVICE();
  constexpr int kW = 192, kH = 108, kSuper = 4;
  const std::array<double, 3> eye = {0.0, 400.0, 0.0}, target = {800.0, 0.0, 300.0};
  constexpr double kFovDeg = 55.0;
  const std::vector<double> plain = render_linear(kW, kH, eye, target, kFovDeg);
  const std::vector<double> super = render_linear(kW * kSuper, kH * kSuper, eye, target, kFovDeg);
  ASSERT_FALSE(plain.empty());
  ASSERT_FALSE(super.empty());
  const std::vector<double> y_plain = luminance(plain, kW, kH, 1);
  const std::vector<double> y_super = luminance(super, kW * kSuper, kH * kSuper, kSuper);
  // Each pixel's distance to the undisplaced sea along its central ray (row 0 at the top).
  const double fx = target[0] - eye[0], fy = target[1] - eye[1], fz = target[2] - eye[2];
  const double fl = std::sqrt(fx * fx + fy * fy + fz * fz);
  const std::array<double, 3> f = {fx / fl, fy / fl, fz / fl};
  std::array<double, 3> r = {-f[2], 0.0, f[0]};  // f × up
  const double rl = std::hypot(r[0], r[2]);
  r = {r[0] / rl, 0.0, r[2] / rl};
  const std::array<double, 3> up = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2],
                                    r[0] * f[1] - r[1] * f[0]};
  const double tan_half = std::tan(0.5 * kFovDeg * std::numbers::pi / 180.0);
  constexpr std::array<double, 6> kBands = {500.0, 800.0, 1300.0, 2000.0, 3200.0, 5000.0};
  std::array<double, 5> lum_p{}, lum_s{}, det_p{}, det_s{};
  std::array<int, 5> count{};
  for (int row = 0; row < kH; ++row)
    for (int col = 0; col + 1 < kW; ++col) {
      const double sx = (2.0 * (col + 0.5) / kW - 1.0) * tan_half * kW / kH;
      const double sy = (1.0 - 2.0 * (row + 0.5) / kH) * tan_half;
      const std::array<double, 3> d = {f[0] + sx * r[0] + sy * up[0], f[1] + sx * r[1] + sy * up[1],
                                       f[2] + sx * r[2] + sy * up[2]};
      if (d[1] >= 0.0) continue;
      const double dist = eye[1] / -d[1] * std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (std::size_t b = 0; b + 1 < kBands.size(); ++b) {
        if (dist < kBands[b] || dist >= kBands[b + 1]) continue;
        const std::size_t i = static_cast<std::size_t>(row) * kW + col;
        lum_p[b] += y_plain[i];
        lum_s[b] += y_super[i];
        det_p[b] += std::abs(encode(y_plain[i + 1]) - encode(y_plain[i]));
        det_s[b] += std::abs(encode(y_super[i + 1]) - encode(y_super[i]));
        ++count[b];
      }
    }
  for (std::size_t b = 0; b + 1 < kBands.size(); ++b) {
    ASSERT_GT(count[b], 50) << "band " << kBands[b];
    const double luminance_ratio = lum_p[b] / lum_s[b], detail_ratio = det_p[b] / det_s[b];
    std::printf("band %5.0f-%5.0f m: %4d px, luminance ratio %.3f, detail %.2f vs %.2f (%.2f)\n",
                kBands[b], kBands[b + 1], count[b], luminance_ratio, det_p[b] / count[b],
                det_s[b] / count[b], detail_ratio);
    EXPECT_NEAR(luminance_ratio, 1.0, 0.05) << "band from " << kBands[b] << " m";
    EXPECT_GE(detail_ratio, 0.5) << "band from " << kBands[b] << " m";
  }
}

constexpr double kStraightDownFovDeg = 55.0;
constexpr int kSide = 216;

// Straight down from `height_m` (kSide² pixels): the luminance detail, i.e. luminance less its
// mean over 15 × 15 pixels (≈ 220 m from 3 km), so the sun's glitter gradient across the
// picture does not correlate everything with everything.
std::vector<double> straight_down_detail(double height_m,
                                         ocean::render::FarFieldRange far_field = {},
                                         double sun_elevation_deg = 20.0,
                                         ocean::FoamSource foam = ocean::FoamSource::breaking) {
  const std::vector<double> rgb =
      render_linear(kSide, kSide, {0.0, height_m, 0.0}, {1.0, 0.0, 0.0}, kStraightDownFovDeg,
                    far_field, sun_elevation_deg, foam);
  if (rgb.empty()) return {};
  const std::vector<double> lum = luminance(rgb, kSide, kSide, 1);
  std::vector<double> y(lum.size(), 0.0);
  constexpr int kBox = 7;
  for (int row = 0; row < kSide; ++row)
    for (int col = 0; col < kSide; ++col) {
      double sum = 0.0;
      int n = 0;
      for (int a = std::max(row - kBox, 0); a <= std::min(row + kBox, kSide - 1); ++a)
        for (int b = std::max(col - kBox, 0); b <= std::min(col + kBox, kSide - 1); ++b)
          sum += lum[static_cast<std::size_t>(a) * kSide + b], ++n;
      const std::size_t i = static_cast<std::size_t>(row) * kSide + col;
      y[i] = lum[i] - sum / n;
    }
  return y;
}

// Straight down from height_m m: the luminance detail's correlation with itself shifted by
// cascade 0's 1000 m period is at most 0.35 and no higher than at shifts unrelated to any
// cascade's period.
void expect_no_repetition(double height_m) {
  const std::vector<double> y = straight_down_detail(height_m);
  ASSERT_FALSE(y.empty());
  constexpr double kFovDeg = kStraightDownFovDeg;
  const double metres_per_pixel =
      2.0 * height_m * std::tan(0.5 * kFovDeg * std::numbers::pi / 180.0) / kSide;
  const auto correlation = [&](int shift) {  // along image rows, Pearson
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    int n = 0;
    for (int row = 0; row < kSide; ++row)
      for (int col = 0; col + shift < kSide; ++col) {
        const double a = y[static_cast<std::size_t>(row) * kSide + col];
        const double b = y[static_cast<std::size_t>(row) * kSide + col + shift];
        sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b, ++n;
      }
    const double cov = sab / n - sa / n * sb / n;
    return cov / std::sqrt((saa / n - sa * sa / n / n) * (sbb / n - sb * sb / n / n));
  };
  const int period = static_cast<int>(std::lround(1000.0 / metres_per_pixel));
  const double at_period = correlation(period);
  double unrelated = 0.0;
  for (double fraction : {0.37, 0.61, 0.83, 1.29}) {
    const double c = correlation(static_cast<int>(std::lround(fraction * period)));
    std::printf("shift %.2f periods: correlation %.3f\n", fraction, c);
    unrelated = std::max(unrelated, c);
  }
  std::printf("from %.0f m, shift 1 period (%d px): correlation %.3f\n", height_m, period,
              at_period);
  EXPECT_LE(at_period, 0.35) << "from " << height_m << " m";
  EXPECT_LE(at_period, unrelated) << "from " << height_m << " m";
}

// From 3 km a pixel is ≈ 14.5 m and the period 69 pixels; from 10 km, 48 m and 21 pixels.
TEST(FarFieldRender, StraightDownViewsDoNotRepeatAtTheLargestPeriod) {
  REQUIRE_DEVICE();
  expect_no_repetition(3000.0);
  expect_no_repetition(10000.0);
}

// Whitecaps are the long waves' breaking crests, and the far field replaces cascade 0's heights
// and slopes, not its foam (R.13): from 3 km, where every pixel lies beyond D_min, with a low sun
// whose glitter lies outside the picture, the brightest 0.1 % of the detail (the whitecaps)
// reaches at least 40 % of what it reaches with the far field pushed beyond the picture (the
// rest of the difference: cascade 0's slopes, which the noise replaces, shade the reference).
// Measured 0.51; 0.17 when the far field also faded cascade 0's foam.
TEST(FarFieldRender, WhitecapsSurviveBeyondTheNearField) {
  REQUIRE_DEVICE();
  const auto brightest = [](std::vector<double> y) {
    std::sort(y.begin(), y.end());
    return y[y.size() - 1 - y.size() / 1000];
  };
  constexpr double kLowSun = 5.0;  // the sun's glitter lies outside the picture
  // The ramp's foam is cascade 0's folds, so it shows what the far field does to cascade 0's foam.
  constexpr ocean::FoamSource kRamp = ocean::FoamSource::ramp;
  const std::vector<double> far = straight_down_detail(3000.0, {}, kLowSun, kRamp);
  const std::vector<double> near =
      straight_down_detail(3000.0, {.near_m = 1e5, .far_m = 2e5}, kLowSun, kRamp);
  ASSERT_FALSE(far.empty());
  ASSERT_FALSE(near.empty());
  const double ratio = brightest(far) / brightest(near);
  std::printf("whitecap detail (99.9th percentile) far field / none: %.3g / %.3g = %.2f\n",
              brightest(far), brightest(near), ratio);
  EXPECT_GE(ratio, 0.4);
}

// A square view straight down from `height_m` under the clear sky.
View straight_down(double height_m) {
  View view;
  view.camera = {.position_m = {0.0, height_m, 0.0},
                 .target_m = {1.0, 0.0, 0.0},
                 .fov_y_rad = kStraightDownFovDeg * std::numbers::pi / 180.0,
                 .aspect = 1.0,
                 .near_m = 0.2,
                 .far_m = 2e5};
  view.shading = ocean::render::sky_preset("clear").value();
  return view;
}

// Straight down from each of `heights_m`, the fraction of the picture that the renderer draws as
// foam: the normals debug view writes each pixel's foam cover (R.11, after the mip filtering, the
// far field and the distance fades) to the HDR image's alpha. Empty without a picture.
std::vector<double> drawn_foam_fractions(ocean::FoamSource foam,
                                         const std::vector<double>& heights_m) {
  ocean::SimulationConfig config = moderate();
  config.foam.source = foam;
  constexpr int kFoamSide = 128;
  auto scene = Scene::make({.config = config, .width = kFoamSide, .height = kFoamSide});
  if (!scene.ok()) return {};
  EXPECT_TRUE(scene.value()->warm_up(20.0, 4.0).ok());
  std::vector<double> fractions;
  for (const double height_m : heights_m) {
    View view = straight_down(height_m);
    view.debug = ocean::render::DebugView::normals;
    EXPECT_TRUE(scene.value()->renderer().draw(view).ok());
    std::vector<float> rgba;
    EXPECT_TRUE(scene.value()->renderer().read_hdr(rgba).ok());
    if (rgba.size() != 4u * kFoamSide * kFoamSide) return {};
    double sum = 0.0;
    for (std::size_t i = 3; i < rgba.size(); i += 4) sum += rgba[i];
    fractions.push_back(sum / (kFoamSide * kFoamSide));
  }
  return fractions;
}

// Monahan & O'Muircheartaigh (1980): W = 3.84·10⁻⁶·U¹⁰^3.41, about 1 % at the moderate preset's
// 10 m/s. The breaking source's foam (M.7.4) is that fraction of the field, and the picture keeps
// it from any height: straight down from 400 m, 3 km and 10 km the drawn foam cover lies within
// the factor the field's own cover keeps from the law (2.2, the Whitecaps tests), where the
// ramp's foam of folds alone, averaged down the mips, draws a tenth of it or less from 10 km.
TEST(FarFieldRender, DrawnWhitecapCoverFollowsMonahansLaw) {
  REQUIRE_DEVICE();
  const double law = ocean::monahan_whitecap_coverage(10.0);
  const std::vector<double> heights_m = {400.0, 3000.0, 10000.0};
  const std::vector<double> breaking = drawn_foam_fractions(ocean::FoamSource::breaking, heights_m);
  const std::vector<double> ramp = drawn_foam_fractions(ocean::FoamSource::ramp, {10000.0});
  ASSERT_EQ(breaking.size(), heights_m.size());
  ASSERT_EQ(ramp.size(), 1u);
  for (std::size_t i = 0; i < heights_m.size(); ++i) {
    std::printf("from %5.0f m: drawn foam %.3f %%, Monahan %.3f %%, ratio %.2f\n", heights_m[i],
                100.0 * breaking[i], 100.0 * law, breaking[i] / law);
    EXPECT_GE(breaking[i], law / 2.2) << "from " << heights_m[i] << " m";
    EXPECT_LE(breaking[i], law * 2.2) << "from " << heights_m[i] << " m";
  }
  std::printf("the ramp from 10 km: %.3f %%\n", 100.0 * ramp[0]);
  EXPECT_LT(ramp[0], law / 10.0);
}

// The horizon seen from altitude (R.8, R.15): between the horizontal and the dipped horizon, √(2h/R)
// below it, the sky pass shows the sky's horizon, and the sea just below takes the same colour, so
// the picture runs on without a step. Looking 3.125° down, away from the sun, from 400 m, 3 km and
// 10 km under the clear and the overcast sky (the storm's), 160 × 90 HDR pixels of 0.125° each,
// the mean luminance of the rows from 4 above the horizontal to 12 below the dipped horizon
// changes between two rows by no more than three times the larger change on either side plus
// 0.2 % (a step stands out of its neighbours; a gradient does not), and the band between the
// horizontal and the dipped horizon is not one colour (R.8d).
TEST(FarFieldRender, TheHorizonHasNoStepFromAltitude) {
  REQUIRE_DEVICE();
  constexpr int kW = 160, kH = 90;
  constexpr double kFovDeg = 11.25;  // 0.125° a row
  constexpr double kPitchDeg = 3.125, kRad = std::numbers::pi / 180.0;
  const double kRun = std::hypot(100000.0, 30000.0);
  // The row (from the top) where a direction `elevation_deg` above the horizontal projects.
  const auto row_of = [&](double elevation_deg) {
    return 0.5 * kH * (1.0 - std::tan((elevation_deg + kPitchDeg) * kRad) /
                                 std::tan(0.5 * kFovDeg * kRad));
  };
  auto scene = Scene::make({.config = moderate(), .width = kW, .height = kH});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_TRUE(scene.value()->warm_up(20.0, 4.0).ok());
  for (const char* sky : {"clear", "overcast"}) {
    for (const double h : {400.0, 3000.0, 10000.0}) {
      View view;
      view.camera = {.position_m = {0.0, h, 0.0},
                     // 3.125° down, azimuth 197°: the sun behind
                     .target_m = {-100000.0, h - kRun * std::tan(kPitchDeg * kRad), -30000.0},
                     .fov_y_rad = kFovDeg * std::numbers::pi / 180.0,
                     .aspect = static_cast<double>(kW) / kH,
                     .near_m = 0.2,
                     .far_m = 2e5};
      view.shading = ocean::render::sky_preset(sky).value();
      ASSERT_TRUE(scene.value()->renderer().draw(view).ok());
      std::vector<float> hdr;
      ASSERT_TRUE(scene.value()->renderer().read_hdr(hdr).ok());
      ASSERT_EQ(hdr.size(), 4u * kW * kH);
      std::vector<double> row_y(kH, 0.0);
      for (int r = 0; r < kH; ++r)
        for (int c = 0; c < kW; ++c) {
          const std::size_t i = (static_cast<std::size_t>(r) * kW + c) * 4;
          row_y[static_cast<std::size_t>(r)] +=
              (0.2126 * hdr[i] + 0.7152 * hdr[i + 1] + 0.0722 * hdr[i + 2]) / kW;
        }
      const int horizontal = static_cast<int>(std::floor(row_of(0.0)));
      const double dip_deg = std::sqrt(2.0 * h / view.planet_radius_m) / kRad;
      const int dipped = static_cast<int>(std::ceil(row_of(-dip_deg)));
      ASSERT_GE(horizontal - 16, 0);
      ASSERT_LT(dipped + 24, kH);
      // Relative change from row r to r + 1.
      const auto step = [&](int r) {
        const double a = row_y[static_cast<std::size_t>(r)];
        return std::abs(row_y[static_cast<std::size_t>(r + 1)] - a) / std::max(a, 1e-6);
      };
      // A step is a change between two rows well beyond the changes on either side of it.
      double worst = 0.0;  // the largest step over its neighbours' largest, less the allowance
      for (int r = horizontal - 4; r <= dipped + 12; ++r)
        worst = std::max(worst, step(r) - 3.0 * std::max(step(r - 1), step(r + 1)));
      // The band between the horizontal and the dipped horizon is not one colour: its rows span
      // more than 0.2 % of its mean, and no 4 rows in a row hold one value (within 0.02 %).
      double lo = 1e30, hi = 0.0, mean = 0.0;
      int flat_run = 0, longest_flat = 0;
      for (int r = horizontal + 1; r < dipped; ++r) {
        const double y = row_y[static_cast<std::size_t>(r)];
        lo = std::min(lo, y), hi = std::max(hi, y), mean += y / (dipped - horizontal - 1);
        flat_run = step(r) < 2e-4 ? flat_run + 1 : 0;
        longest_flat = std::max(longest_flat, flat_run);
      }
      std::printf("%-8s from %5.0f m: band of %d rows spans %.2f %% of its mean, longest flat run %d "
                  "rows; largest step beyond 3x its neighbours' %.4f\n",
                  sky, h, dipped - horizontal - 1, 100.0 * (hi - lo) / mean, longest_flat, worst);
      EXPECT_LE(worst, 0.002) << sky << " from " << h << " m";
      if (dipped - horizontal - 1 >= 4) {
        EXPECT_GT((hi - lo) / mean, 0.002) << sky << " from " << h << " m";
        EXPECT_LT(longest_flat, 3) << sky << " from " << h << " m";
      }
      if (worst > 0.002)
        for (int r = horizontal - 6; r < dipped + 14; ++r)
          std::printf("  row %d%s: %.5f\n", r, r == horizontal ? " (horizontal)" : r == dipped ? " (dipped)" : "",
                      row_y[static_cast<std::size_t>(r)]);
    }
  }
}

// Aerial perspective (R.8b) in the picture against the CPU's Sky::aerial_perspective: straight
// down from 3 km and 10 km, the centre pixels drawn with the air are those drawn without it times
// the path's transmittance plus its in-scattered light (HDR, half floats: 1 %).
TEST(FarFieldRender, AerialPerspectiveIsTheSkysAirAlongThePath) {
  REQUIRE_DEVICE();
  constexpr int kAirSide = 64;
  auto scene = Scene::make({.config = moderate(), .width = kAirSide, .height = kAirSide});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_TRUE(scene.value()->warm_up(20.0, 4.0).ok());
  for (const double height_m : {3000.0, 10000.0}) {
    View view = straight_down(height_m);
    std::vector<float> with_air, without;
    ASSERT_TRUE(scene.value()->renderer().draw(view).ok());
    ASSERT_TRUE(scene.value()->renderer().read_hdr(with_air).ok());
    view.shading.aerial_perspective = false;
    ASSERT_TRUE(scene.value()->renderer().draw(view).ok());
    ASSERT_TRUE(scene.value()->renderer().read_hdr(without).ok());
    // The centre 2 × 2 pixels look within 0.5° of straight down at the mean sea level (the waves'
    // metre of height changes the path by 3·10⁻⁴ of it).
    const auto air = ocean::render::Sky(view.shading)
                         .aerial_perspective(height_m, 0.0, height_m, {0.0, -1.0, 0.0});
    for (int row = kAirSide / 2 - 1; row <= kAirSide / 2; ++row)
      for (int col = kAirSide / 2 - 1; col <= kAirSide / 2; ++col)
        for (std::size_t c = 0; c < 3; ++c) {
          const std::size_t i = (static_cast<std::size_t>(row) * kAirSide + col) * 4 + c;
          const double expected = without[i] * air.transmittance[c] + air.inscattered[c];
          EXPECT_NEAR(with_air[i], expected, 0.01 * expected)
              << "from " << height_m << " m, pixel " << col << "," << row << " channel " << c;
        }
    const std::size_t centre =
        (static_cast<std::size_t>(kAirSide / 2) * kAirSide + kAirSide / 2) * 4;
    std::printf(
        "from %5.0f m straight down: transmittance %.3f %.3f %.3f, air light %.4f %.4f %.4f "
        "over the water's %.4f %.4f %.4f\n",
        height_m, air.transmittance[0], air.transmittance[1], air.transmittance[2],
        air.inscattered[0], air.inscattered[1], air.inscattered[2], without[centre],
        without[centre + 1], without[centre + 2]);
  }
}

// Sun glitter as Cox & Munk (1954) read it: seen straight down from 3 km the glitter is the sun's
// reflection by a distribution of facets, L = E·F·p(s)/(4·μ_v·cos⁴β) (s the facet slope that
// mirrors the sun into the pixel, β its tilt, μ_v the view's cosine). With the sky, the water's
// body, foam, fog and air taken out the picture is the glitter alone; p recovered from each pixel,
// averaged over the pixels in bins of slope 0.02 (each pixel's lobe sits on its own mean normal,
// the waves a 27 m pixel still resolves, as Cox & Munk's photographs averaged facets) and fitted as
// a Gaussian over its core (p̄ above e^(−2) of its peak), ln p̄ = a − |s − s̄|²/m, gives the mean
// square slope m. −1 without a picture.
double glitter_mean_square_slope(bool calm) {
  constexpr int kGlitterSide = 128;
  constexpr double kGlitterHeight = 3000.0, kFov = 60.0 * std::numbers::pi / 180.0;
  ocean::SimulationConfig config = moderate();
  config.foam.source = ocean::FoamSource::ramp;  // no foam over the glitter
  auto scene = Scene::make({.config = config, .width = kGlitterSide, .height = kGlitterSide});
  if (!scene.ok()) return -1.0;
  EXPECT_TRUE(scene.value()->warm_up(20.0, 4.0).ok());
  scene.value()->renderer().set_calm(calm);
  View view;
  // Straight down with the picture's up along +x: right is +z.
  view.camera = {.position_m = {0.0, kGlitterHeight, 0.0},
                 .target_m = {0.0, 0.0, 0.0},
                 .fov_y_rad = kFov,
                 .aspect = 1.0,
                 .near_m = 1.0,
                 .far_m = 2e5,
                 .up = {1.0, 0.0, 0.0}};
  view.shading = ocean::render::sky_preset("clear").value();
  view.shading.sun_elevation_deg = 80.0;
  view.shading.sun_azimuth_deg = 0.0;
  view.shading.sky_brightness = 0.0;
  view.shading.water_colour = {0.0, 0.0, 0.0};
  view.shading.crest_scatter = 0.0;
  view.shading.fog_density_per_m = 0.0;
  view.shading.aerial_perspective = false;
  EXPECT_TRUE(scene.value()->renderer().draw(view).ok());
  std::vector<float> hdr;
  EXPECT_TRUE(scene.value()->renderer().read_hdr(hdr).ok());
  if (hdr.size() != 4u * kGlitterSide * kGlitterSide) return -1.0;
  const std::array<double, 3> sun =
      ocean::render::sun_direction(view.shading.sun_azimuth_deg, view.shading.sun_elevation_deg);
  const double e_sun = ocean::render::Sky(view.shading).sun_irradiance_ground()[1];
  struct Sample {
    double sx, sz, ln_p;
  };
  std::vector<Sample> samples;
  double peak = -1e300;
  const double t = std::tan(kFov / 2.0);
  for (int row = 0; row < kGlitterSide; ++row)
    for (int col = 0; col < kGlitterSide; ++col) {
      const double nx = 2.0 * (col + 0.5) / kGlitterSide - 1.0;
      const double ny = 1.0 - 2.0 * (row + 0.5) / kGlitterSide;
      std::array<double, 3> v = {ny * t, -1.0, nx * t};  // eye to the sea: up +x, right +z
      const double vl = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      for (double& c : v) c /= vl;
      std::array<double, 3> h = {sun[0] - v[0], sun[1] - v[1], sun[2] - v[2]};
      const double hl = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
      for (double& c : h) c /= hl;
      const double cos_beta = h[1], mu_v = -v[1];
      const double cos_vh = -(v[0] * h[0] + v[1] * h[1] + v[2] * h[2]);
      const double fresnel = 0.02 + 0.98 * std::pow(1.0 - cos_vh, 5.0);  // Schlick, F0 = 0.02
      const double radiance = hdr[static_cast<std::size_t>(4 * (row * kGlitterSide + col)) + 1];
      if (!(radiance > 0.0)) continue;
      const double p = 4.0 * mu_v * std::pow(cos_beta, 4.0) * radiance / (e_sun * fresnel);
      samples.push_back({-h[0] / h[1], -h[2] / h[1], std::log(p)});
      peak = std::max(peak, std::log(p));
    }
  // Each pixel's lobe is centred on its own mean normal (the waves that a 27 m pixel still
  // resolves): p is averaged over the pixels in bins of slope 0.02 wide, as Cox & Munk's
  // photographs averaged facets, before its logarithm is fitted.
  constexpr double kBin = 0.02;
  constexpr int kBins = 60;  // slopes in [−0.6, 0.6)
  std::vector<double> sum(kBins * kBins, 0.0);
  std::vector<int> count(kBins * kBins, 0);
  for (const Sample& s : samples) {
    const int bx = static_cast<int>(std::floor(s.sx / kBin)) + kBins / 2;
    const int bz = static_cast<int>(std::floor(s.sz / kBin)) + kBins / 2;
    if (bx < 0 || bz < 0 || bx >= kBins || bz >= kBins) continue;
    sum[static_cast<std::size_t>(bz * kBins + bx)] += std::exp(s.ln_p - peak);
    ++count[static_cast<std::size_t>(bz * kBins + bx)];
  }
  double top = 0.0;
  for (std::size_t i = 0; i < sum.size(); ++i)
    if (count[i] >= 3) top = std::max(top, sum[i] / count[i]);
  // Least squares of ln p̄ = a + b·(sx² + sz²) + cx·sx + cz·sz over the core's bins.
  double m[4][5] = {};
  std::size_t used = 0;
  for (int bz = 0; bz < kBins; ++bz)
    for (int bx = 0; bx < kBins; ++bx) {
      const std::size_t i = static_cast<std::size_t>(bz * kBins + bx);
      if (count[i] < 3 || sum[i] / count[i] < top * std::exp(-2.0)) continue;
      const double sx = (bx - kBins / 2 + 0.5) * kBin, sz = (bz - kBins / 2 + 0.5) * kBin;
      const double ln_p = std::log(sum[i] / count[i]);
      const double row[4] = {1.0, sx * sx + sz * sz, sx, sz};
      for (int r = 0; r < 4; ++r) {
        for (int j = 0; j < 4; ++j) m[r][j] += row[r] * row[j];
        m[r][4] += row[r] * ln_p;
      }
      ++used;
    }
  for (int i = 0; i < 4; ++i)  // Gauss–Jordan
    for (int k = 0; k < 4; ++k) {
      if (k == i) continue;
      const double f = m[k][i] / m[i][i];
      for (int j = 0; j < 5; ++j) m[k][j] -= f * m[i][j];
    }
  EXPECT_GT(used, 100u);
  return -m[1][1] / m[1][4];
}

// A calm sea (no cascades) is one facet distribution of mean square slope α₀², the waves shorter
// than the finest cascade (R.5): its glitter is Beckmann's Gaussian of that mss (R.7), within 5 %
// (bins of 0.02 over a core 0.3 wide; measured 1.005). Beckmann's slopes are Cox & Munk's
// Gaussian; the GGX lobe, narrower at its core and heavier in its tails, fits 0.89 of it the same
// way (its tails make its variance infinite). The whole moderate sea's glitter carries the sea's
// own mean square slope (its maps' and the short waves', SurfaceStats) within 5 %, the mips'
// smoothness read as the variance the averaging removed (R.5), and so Cox & Munk's clean-surface
// 0.003 + 5.12·10⁻³·U within the 20 % the sea's slopes keep from it (M.9).
TEST(FarFieldRender, SunGlitterIsAGaussianOfTheSlopeVariance) {
  REQUIRE_DEVICE();
  const ocean::SimulationPlan plan = ocean::SimulationPlan::make(moderate()).value();
  const double alpha0_sq = plan.surface().unresolved_slope_variance.value_or(0.0);
  // The sea's slopes as its maps' normals carry them (SurfaceStats: the cascades' finite-difference
  // slopes and the short waves', what Cox & Munk's glitter measures), at the picture's time.
  const std::unique_ptr<ocean::TaskRunner> runner = ocean::make_tbb_runner();
  const ocean::SurfaceStats stats =
      ocean::compute_surface_stats(moderate(), 1, 24.0, *runner).value();
  ASSERT_TRUE(stats.unresolved_slope_variance && stats.cox_munk_mss);
  const double total =
      stats.resolved_slope_variance.upwind + stats.resolved_slope_variance.crosswind +
      stats.unresolved_slope_variance->upwind + stats.unresolved_slope_variance->crosswind;
  const double calm = glitter_mean_square_slope(true);
  const double sea = glitter_mean_square_slope(false);
  const double cox_munk = *stats.cox_munk_mss;
  std::printf(
      "glitter from 3 km: calm %.4f against alpha0^2 %.4f (ratio %.3f); the sea %.4f, "
      "its slopes %.4f (ratio %.3f), Cox & Munk %.4f (ratio %.2f)\n",
      calm, alpha0_sq, calm / alpha0_sq, sea, total, sea / total, cox_munk, sea / cox_munk);
  ASSERT_GT(alpha0_sq, 0.0);
  EXPECT_NEAR(calm, alpha0_sq, 0.05 * alpha0_sq);
  EXPECT_NEAR(sea, total, 0.05 * total);
  EXPECT_NEAR(sea, cox_munk, 0.2 * cox_munk);
}

}  // namespace
#undef REQUIRE_DEVICE
