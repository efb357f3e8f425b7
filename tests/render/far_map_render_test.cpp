// The far field drawn from the per-frame noise map (docs/rendering.md R.13b) on any Vulkan device
// (lavapipe on CPU-only machines), the validation layer on and zero messages asserted: per band
// of distance the map's picture keeps the mean luminance and the detail of the supersampled
// picture of the analytic noise (R.13b-4's bound, the one R.5's filtering is held to), and so
// stays within 10.5 % of the analytic picture; time moves the far field and leaves the near sea
// exactly as it was; the CPU upload and the Vulkan backend's buffer give the same picture; and
// moving the window by its snap step (what a camera crossing a snap line does) keeps the
// picture. Skips where no Vulkan device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include "ocean/far_field.hpp"
#include "ocean/scene.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::Scene;
using ocean::render::View;
using ocean::render::testing::difference;
using ocean::render::testing::graphics_context;

constexpr int kMapW = 192, kMapH = 108;
constexpr double kMapFovDeg = 55.0;
constexpr std::array<double, 3> kMapEye = {0.0, 400.0, 0.0}, kMapTarget = {800.0, 0.0, 300.0};
constexpr int kMapTexels = 512;  // the window's side in texels: 12.1 m for D_max = 2500 m

// The moderate preset's sea (presets/moderate.json) at N = `resolution` (256 in the preset; 128
// where the picture is compared with itself only): the far field is fitted to cascade 0 of the
// 1000 m patch; the map of kMapTexels around the camera when `map` is set.
ocean::SimulationConfig far_map_config(bool map, int resolution) {
  ocean::SimulationConfig c;
  c.resolution = resolution;
  c.cascade_patch_sizes_m = {1000.0, 233.0, 57.0, 13.0};
  c.outputs = ocean::FrameOutputs::textures();
  if (map)
    c.far_noise = ocean::render::far_noise_window({}, kMapTexels, kMapEye[0], kMapEye[2]).value();
  return c;
}

View far_map_view(int width, int height, const std::array<double, 3>& eye = kMapEye) {
  View v;
  v.camera = {.position_m = {eye[0], eye[1], eye[2]},
              .target_m = {kMapTarget[0], kMapTarget[1], kMapTarget[2]},
              .fov_y_rad = kMapFovDeg * std::numbers::pi / 180.0,
              .aspect = static_cast<double>(width) / height,
              .near_m = 0.2,
              .far_m = 2e5};
  v.shading = ocean::render::sky_preset("clear").value();
  return v;
}

std::unique_ptr<Scene> far_map_scene(bool map, const std::string& backend, int w, int h,
                                     int resolution = 128) {
  auto scene = Scene::make({.config = far_map_config(map, resolution),
                            .backend = backend,
                            .width = w,
                            .height = h,
                            .validation = true});
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  return scene.ok() ? std::move(scene).value() : nullptr;
}

std::vector<std::uint8_t> far_map_draw(Scene& scene, const View& view) {
  std::vector<std::uint8_t> srgb;
  const ocean::Status drawn = scene.renderer().draw(view);
  EXPECT_TRUE(drawn.ok()) << drawn.message();
  EXPECT_TRUE(scene.renderer().read_srgb(srgb).ok());
  EXPECT_EQ(scene.context()->validation_messages.load(), 0u)
      << scene.context()->last_validation_message;
  return srgb;
}

// Linear luminance (Rec. 709) of an sRGB picture, averaged over factor × factor blocks.
std::vector<double> far_map_luminance(const std::vector<std::uint8_t>& srgb, int width, int height,
                                      int factor) {
  const auto linear = [](std::uint8_t v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const int w = width / factor;
  std::vector<double> y(static_cast<std::size_t>(w) * (height / factor), 0.0);
  for (int row = 0; row < height; ++row)
    for (int col = 0; col < width; ++col) {
      const std::uint8_t* p = &srgb[(static_cast<std::size_t>(row) * width + col) * 4];
      y[static_cast<std::size_t>(row / factor) * w + col / factor] +=
          (0.2126 * linear(p[0]) + 0.7152 * linear(p[1]) + 0.0722 * linear(p[2])) /
          (factor * factor);
    }
  return y;
}

double far_map_encode(double linear) {  // the sRGB transfer function, 0..255
  return 255.0 * (linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055);
}

// The distance from `eye` to the undisplaced sea along pixel (col, row)'s central ray of the
// kMapW × kMapH view towards `target`; infinite above the horizon.
double far_map_distance(int col, int row, const std::array<double, 3>& eye = kMapEye,
                        const std::array<double, 3>& target = kMapTarget) {
  const double fx = target[0] - eye[0], fy = target[1] - eye[1], fz = target[2] - eye[2];
  const double fl = std::sqrt(fx * fx + fy * fy + fz * fz);
  const std::array<double, 3> f = {fx / fl, fy / fl, fz / fl};
  const double rl = std::hypot(f[2], f[0]);
  const std::array<double, 3> r = {-f[2] / rl, 0.0, f[0] / rl};  // f × up
  const std::array<double, 3> up = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2],
                                    r[0] * f[1] - r[1] * f[0]};
  const double tan_half = std::tan(0.5 * kMapFovDeg * std::numbers::pi / 180.0);
  const double sx = (2.0 * (col + 0.5) / kMapW - 1.0) * tan_half * kMapW / kMapH;
  const double sy = (1.0 - 2.0 * (row + 0.5) / kMapH) * tan_half;
  const std::array<double, 3> d = {f[0] + sx * r[0] + sy * up[0], f[1] + sx * r[1] + sy * up[1],
                                   f[2] + sx * r[2] + sy * up[2]};
  if (d[1] >= 0.0) return INFINITY;
  return eye[1] / -d[1] * std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

constexpr std::array<double, 5> kMapBands = {1000.0, 1500.0, 2500.0, 4000.0, 8000.0};

// Where two pictures from `eye` differ: per pixel and channel, |a − b| nearer than near_m (the
// largest, and how many samples), and between far_lo_m and far_hi_m its sum beside the sum of
// a's horizontal detail there (and how many samples).
struct BandChange {
  int near_max = 0, near_count = 0, far_count = 0;
  double far_difference = 0.0, far_detail = 0.0;
};
BandChange far_map_change(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                          const std::array<double, 3>& eye, double near_m, double far_lo_m,
                          double far_hi_m) {
  BandChange c;
  for (int row = 0; row < kMapH; ++row)
    for (int col = 0; col + 1 < kMapW; ++col) {
      const double dist = far_map_distance(col, row, eye);
      const std::size_t p = (static_cast<std::size_t>(row) * kMapW + col) * 4;
      for (std::size_t k = 0; k < 3; ++k) {
        const int e = std::abs(int(a[p + k]) - int(b[p + k]));
        if (dist < near_m) c.near_max = std::max(c.near_max, e), ++c.near_count;
        if (dist > far_lo_m && dist < far_hi_m) {
          c.far_difference += e;
          c.far_detail += std::abs(int(a[p + 4 + k]) - int(a[p + k]));
          ++c.far_count;
        }
      }
    }
  return c;
}

// Per band: mean linear luminance and mean |horizontal difference| of the sRGB-encoded
// luminance (the detail).
struct BandFigures {
  std::array<double, 4> luminance{}, detail{};
  std::array<int, 4> count{};
};
BandFigures far_map_bands(const std::vector<double>& y) {
  BandFigures b;
  for (int row = 0; row < kMapH; ++row)
    for (int col = 0; col + 1 < kMapW; ++col) {
      const double dist = far_map_distance(col, row);
      for (std::size_t i = 0; i + 1 < kMapBands.size(); ++i) {
        if (dist < kMapBands[i] || dist >= kMapBands[i + 1]) continue;
        const std::size_t p = static_cast<std::size_t>(row) * kMapW + col;
        b.luminance[i] += y[p];
        b.detail[i] += std::abs(far_map_encode(y[p + 1]) - far_map_encode(y[p]));
        ++b.count[i];
      }
    }
  return b;
}

#define REQUIRE_DEVICE() \
  if (graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device")

// R.13b-4: where the map draws the far field, each band keeps the mean luminance of the analytic
// noise's supersampled picture within 5 % and at least half of its detail (the bounds R.5's
// filtering is held to, tests/render/far_field_render_test.cpp); the map's picture and the
// analytic one are then within 1.05/0.95 − 1 = 10.5 % of each other.
TEST(FarMapRender, EveryBandKeepsTheSupersampledAnalyticPicture) {
  REQUIRE_DEVICE();
  constexpr int kSuper = 4;
  auto scene = far_map_scene(true, "cpu", kMapW, kMapH, 256);
  auto super = far_map_scene(false, "cpu", kMapW * kSuper, kMapH * kSuper, 256);
  ASSERT_TRUE(scene && super);
  for (Scene* s : {scene.get(), super.get()}) ASSERT_TRUE(s->step(20.0).ok());
  const BandFigures m = far_map_bands(
      far_map_luminance(far_map_draw(*scene, far_map_view(kMapW, kMapH)), kMapW, kMapH, 1));
  ocean::Frame no_map = scene->simulator().frame();  // the same frame, the analytic noise only
  no_map.far_noise = {};
  ASSERT_TRUE(scene->renderer().upload(no_map).ok());
  const BandFigures a = far_map_bands(
      far_map_luminance(far_map_draw(*scene, far_map_view(kMapW, kMapH)), kMapW, kMapH, 1));
  const BandFigures s = far_map_bands(
      far_map_luminance(far_map_draw(*super, far_map_view(kMapW * kSuper, kMapH * kSuper)),
                        kMapW * kSuper, kMapH * kSuper, kSuper));
  for (std::size_t b = 0; b + 1 < kMapBands.size(); ++b) {
    ASSERT_GT(m.count[b], 100) << "band " << kMapBands[b];
    const double lum_ms = m.luminance[b] / s.luminance[b], lum_ma = m.luminance[b] / a.luminance[b];
    const double det_ms = m.detail[b] / s.detail[b], det_as = a.detail[b] / s.detail[b];
    std::printf(
        "band %5.0f-%5.0f m: %4d px, luminance map/super %.3f, map/analytic %.3f, detail "
        "map/super %.2f, analytic/super %.2f\n",
        kMapBands[b], kMapBands[b + 1], m.count[b], lum_ms, lum_ma, det_ms, det_as);
    EXPECT_NEAR(lum_ms, 1.0, 0.05) << "band from " << kMapBands[b] << " m";
    EXPECT_NEAR(lum_ma, 1.0, 0.105) << "band from " << kMapBands[b] << " m";
    EXPECT_GE(det_ms, 0.5) << "band from " << kMapBands[b] << " m";
  }
}

// Time moves the far field (R.13a, R.13b): the same simulated cascades drawn with the map of a
// later time give exactly the same pixels where the sea is nearer than 0.9·D_min (the noise has
// weight 0 there), and beyond D_max, where the noise alone draws cascade 0's band, pixels that
// differ by more than a quarter of the band's detail: the map's mips carry the local slope
// variance of the moving octaves, which the glitter shows. (The analytic noise moves too, its
// lattice placed as the map's: tests/render/far_field_test.cpp; its resolved slopes there are
// too small to show in 8 bits.) From 100 m with the far field from 250 to 500 m.
TEST(FarMapRender, TimeMovesTheFarFieldAndNothingNearTheCamera) {
  REQUIRE_DEVICE();
  constexpr std::array<double, 3> kLow = {0.0, 100.0, 0.0};
  View view = far_map_view(kMapW, kMapH, kLow);
  view.far_field = {.near_m = 250.0, .far_m = 500.0};
  // The whitecaps' patches (R.11b) move with the frame's time, which the frame below takes from
  // the later one along with its far field: drawn without them, the near sea is the cascades'.
  view.shading.whitecap_patches = false;
  auto scene = far_map_scene(true, "cpu", kMapW, kMapH);
  ASSERT_NE(scene, nullptr);
  ASSERT_TRUE(scene->step(30.0).ok());
  const ocean::Frame later = scene->simulator().frame();
  ASSERT_TRUE(scene->step(20.0).ok());
  const std::vector<std::uint8_t> now = far_map_draw(*scene, view);
  ocean::Frame moved = scene->simulator().frame();  // the cascades of t = 20 s ...
  moved.far_noise = later.far_noise;                // ... the far field of t = 30 s
  moved.time_s = later.time_s;
  ASSERT_TRUE(scene->renderer().upload(moved).ok());
  const std::vector<std::uint8_t> then = far_map_draw(*scene, view);
  const auto [near_max, near_count, far_count, far_difference, far_detail] =
      far_map_change(now, then, kLow, 0.9 * view.far_field.near_m, view.far_field.far_m, 1000.0);
  ASSERT_GT(near_count, 300);
  ASSERT_GT(far_count, 300);
  std::printf(
      "near the camera max |difference| %d LSB; beyond D_max mean %.2f LSB, detail "
      "%.2f LSB\n",
      near_max, far_difference / far_count, far_detail / far_count);
  EXPECT_EQ(near_max, 0);
  EXPECT_GT(far_difference, 0.25 * far_detail);
}

// The renderer reads the map (R.13b): a map of zeros (a flat far field, no slope variance) in
// place of the frame's changes the picture where the map draws the far field — from 400 m, the
// 2000–2500 m band, where a pixel spans more than two texels — by more than a quarter of the
// band's detail, and leaves every pixel nearer than 0.9·D_min as it was.
TEST(FarMapRender, TheMapIsWhatIsDrawnWhereItResolvesTheNoise) {
  REQUIRE_DEVICE();
  auto scene = far_map_scene(true, "cpu", kMapW, kMapH);
  ASSERT_NE(scene, nullptr);
  const View view = far_map_view(kMapW, kMapH);
  ASSERT_TRUE(scene->step(20.0).ok());
  const std::vector<std::uint8_t> drawn = far_map_draw(*scene, view);
  ocean::Frame flat = scene->simulator().frame();
  std::fill(flat.far_noise.height_slope.begin(), flat.far_noise.height_slope.end(), 0.0f);
  ASSERT_TRUE(scene->renderer().upload(flat).ok());
  const std::vector<std::uint8_t> zeros = far_map_draw(*scene, view);
  const auto [near_max, near_count, far_count, far_difference, far_detail] =
      far_map_change(drawn, zeros, kMapEye, 900.0, 2000.0, 2500.0);
  ASSERT_GT(near_count, 300);
  ASSERT_GT(far_count, 300);
  std::printf(
      "a map of zeros: near the camera max |difference| %d LSB; 2000-2500 m mean %.2f "
      "LSB, detail %.2f LSB\n",
      near_max, far_difference / far_count, far_detail / far_count);
  EXPECT_EQ(near_max, 0);
  EXPECT_GT(far_difference, 0.25 * far_detail);
}

// The conversion subtracts the octaves the map does not hold with the arithmetic that made the
// map (R.13b): with 128 texels (167 m, no octave's cell spans four) the image holds rounding
// residues only and every octave is drawn per pixel, so the picture is the one without a map —
// were the subtraction misplaced, the map would add the field a second time where it draws.
TEST(FarMapRender, AMapThatHoldsNoOctaveDrawsTheAnalyticPicture) {
  REQUIRE_DEVICE();
  auto scene = far_map_scene(false, "cpu", kMapW, kMapH);
  ASSERT_NE(scene, nullptr);
  const View view = far_map_view(kMapW, kMapH);
  ASSERT_TRUE(scene->step(20.0).ok());
  const std::vector<std::uint8_t> analytic = far_map_draw(*scene, view);
  ocean::SimulationConfig coarse = far_map_config(true, 128);
  coarse.far_noise = ocean::render::far_noise_window({}, 128, kMapEye[0], kMapEye[2]).value();
  ASSERT_TRUE(scene->reconfigure(coarse).ok());
  ASSERT_TRUE(scene->step(20.0).ok());
  ASSERT_EQ(scene->simulator().frame().far_noise.resolution, 128);
  const auto d = difference(analytic, far_map_draw(*scene, view));
  std::printf("a map holding no octave against none: mean %.4f LSB, max %d LSB\n", d.mean, d.max);
  EXPECT_LE(d.max, 1);
}

// The two paths of R.13b: Frame::far_noise uploaded (CPU backend) and the Vulkan backend's buffer
// read where it lies give the same picture within the bound of tests/render/scene_test.cpp (the
// backends' maps agree within ocean/conformance.hpp's kFarNoiseDeviceBounds, their cascades
// within theirs).
TEST(FarMapRender, CpuUploadAndVulkanBufferGiveTheSamePicture) {
  REQUIRE_DEVICE();
  auto cpu = far_map_scene(true, "cpu", kMapW, kMapH);
  auto gpu = far_map_scene(true, "vulkan", kMapW, kMapH);
  ASSERT_TRUE(cpu && gpu);
  const View view = far_map_view(kMapW, kMapH);
  for (Scene* s : {cpu.get(), gpu.get()}) {
    s->follow(view);
    ASSERT_TRUE(s->step(20.0).ok());
  }
  const auto d = difference(far_map_draw(*cpu, view), far_map_draw(*gpu, view));
  std::printf("cpu upload against vulkan buffer: mean %.4f LSB, max %d LSB\n", d.mean, d.max);
  EXPECT_LE(d.mean, 0.05);
  EXPECT_LE(d.max, 12);
}

// The window follows the camera in steps of 32 texels (R.13b-2): the same view drawn with the
// window one snap step along x and z keeps the picture within the bound of the upload and
// zero-copy paths above (the map's texels and its first five mip levels lie on the same world
// points; only coarser mips, float rounding and the outer fade move).
TEST(FarMapRender, MovingTheWindowByASnapStepKeepsThePicture) {
  REQUIRE_DEVICE();
  auto scene = far_map_scene(true, "cpu", kMapW, kMapH);
  ASSERT_NE(scene, nullptr);
  const View view = far_map_view(kMapW, kMapH);
  scene->follow(view);
  ASSERT_TRUE(scene->step(20.0).ok());
  const std::vector<std::uint8_t> a = far_map_draw(*scene, view);
  const ocean::FarNoiseConfig& window = scene->simulator().config().far_noise;
  const double snap = ocean::render::kFarNoiseSnapTexels * window.size_m / window.resolution;
  scene->simulator().set_far_noise_origin({window.origin_m[0] - snap, window.origin_m[1] + snap});
  ASSERT_TRUE(scene->step(20.0).ok());
  const auto d = difference(a, far_map_draw(*scene, view));
  std::printf("window moved by one snap step (%.0f m): mean %.4f LSB, max %d LSB\n", snap, d.mean,
              d.max);
  EXPECT_LE(d.mean, 0.05);
  EXPECT_LE(d.max, 12);
}

}  // namespace
#undef REQUIRE_DEVICE
