// Objects reflected in the water (lavapipe, validation layer on; docs/rendering.md R.53): over a
// flat sea, a box's reflection changes exactly the pixels whose ray, mirrored at the water, meets
// the box — found on the CPU by intersecting each pixel's reflected ray with the box — and no
// pixel elsewhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/bodies.hpp"
#include "ocean/render.hpp"
#include "ocean/scene.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using namespace ocean::render;
namespace helpers = ocean::render::testing;
constexpr int kReflW = 128, kReflH = 96;
constexpr double kHalf = 2.0;                             // the box's half side, m
constexpr std::array<double, 3> kCentre{25.0, 4.0, 0.0};  // 2 to 6 m above the sea

// Whether the ray o + t·d (t > 0) meets the box (slabs).
bool hits_box(const std::array<double, 3>& o, const std::array<double, 3>& d) {
  double near = 0.0, far = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double lo = (kCentre[i] - kHalf - o[i]) / d[i], hi = (kCentre[i] + kHalf - o[i]) / d[i];
    near = std::max(near, std::min(lo, hi));
    far = std::min(far, std::max(lo, hi));
  }
  return near < far;
}

TEST(Reflection, ABoxAppearsWhereTheMirrorPutsIt) {
  auto ctx = helpers::graphics_context();
  if (ctx == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const ocean::SimulationConfig config = helpers::small_config();
  auto sim = ocean::make_simulator(config).value();
  sim->step(1.0);
  auto renderer = Renderer::make(ctx, {.width = kReflW, .height = kReflH}).value();
  ASSERT_TRUE(renderer->configure(ocean::SimulationPlan::make(config).value().surface()).ok());
  ASSERT_TRUE(renderer->upload(sim->frame()).ok());
  renderer->set_calm(true);  // no layer either: the sea is the mirror y = 0
  const auto hull = ocean::bodies::box_hull({2 * kHalf, 2 * kHalf, 2 * kHalf}).value();
  const Mesh box = flat_mesh(hull.vertices, hull.triangles, {.base_colour = {0.9, 0.2, 0.02}});
  ASSERT_TRUE(renderer->set_meshes(std::span(&box, 1)).ok());
  View v = helpers::eye_level_view(kReflW, kReflH);
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.camera.position_m = {0.0, 3.0, 0.0};
  v.camera.target_m = {25.0, -1.0, 0.0};
  const auto picture = [&](bool with_box) {
    v.objects.clear();
    if (with_box) v.objects.push_back({.mesh = 0, .model = model_matrix(kCentre, {1, 0, 0, 0})});
    EXPECT_TRUE(renderer->draw(v).ok());
    std::vector<float> hdr;
    EXPECT_TRUE(renderer->read_hdr(hdr).ok());
    return hdr;
  };
  const std::vector<float> empty = picture(false), with_box = picture(true);
  EXPECT_EQ(ctx->validation_messages.load(), 0u) << ctx->last_validation_message;
  // Per pixel: 1 where the reflected ray meets the box, 2 where the ray meets it directly.
  // Each pixel's ray from the camera's basis (lod::view_projection: look-at with +y up, the
  // vertical field of view, row 0 on top).
  const auto& e = v.camera.position_m;
  const std::array<double, 3> o{e.x, e.y, e.z};
  std::array<double, 3> f{v.camera.target_m.x - e.x, v.camera.target_m.y - e.y,
                          v.camera.target_m.z - e.z};
  const auto normalise = [](std::array<double, 3> a) {
    const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    return std::array<double, 3>{a[0] / n, a[1] / n, a[2] / n};
  };
  f = normalise(f);
  const std::array<double, 3> right = normalise({-f[2], 0.0, f[0]});  // f × (0, 1, 0)
  const std::array<double, 3> up{right[1] * f[2] - right[2] * f[1],
                                 right[2] * f[0] - right[0] * f[2],
                                 right[0] * f[1] - right[1] * f[0]};
  const double ty = std::tan(0.5 * v.camera.fov_y_rad), tx = ty * v.camera.aspect;
  std::vector<int> kind(kReflW * kReflH, 0);
  for (int py = 0; py < kReflH; ++py)
    for (int px = 0; px < kReflW; ++px) {
      const double sx = ((px + 0.5) / kReflW * 2.0 - 1.0) * tx,
                   sy = (1.0 - (py + 0.5) / kReflH * 2.0) * ty;
      std::array<double, 3> d{};
      for (std::size_t i = 0; i < 3; ++i) d[i] = f[i] + sx * right[i] + sy * up[i];
      int& k = kind[static_cast<std::size_t>(py * kReflW + px)];
      if (hits_box(o, d)) {
        k = 2;
      } else if (d[1] < 0.0) {  // to the water, then mirrored
        const double t = -o[1] / d[1];
        k = hits_box({o[0] + t * d[0], 0.0, o[2] + t * d[2]}, {d[0], -d[1], d[2]}) ? 1 : 0;
      }
    }
  // Pixels 2 or more from another kind: the half-resolution target blurs edges by a pixel.
  const auto surely = [&](int px, int py, int want) {
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const int x = std::clamp(px + dx, 0, kReflW - 1), y = std::clamp(py + dy, 0, kReflH - 1);
        if (kind[static_cast<std::size_t>(y * kReflW + x)] != want) return false;
      }
    return true;
  };
  int reflected = 0, changed_inside = 0, elsewhere = 0, changed_elsewhere = 0;
  for (int py = 0; py < kReflH; ++py)
    for (int px = 0; px < kReflW; ++px) {
      const std::size_t i = static_cast<std::size_t>(4 * (py * kReflW + px));
      double change = 0.0, level = 0.0;
      for (std::size_t c = 0; c < 3; ++c) {
        change += std::abs(with_box[i + c] - empty[i + c]);
        level += empty[i + c];
      }
      if (surely(px, py, 1)) {
        ++reflected;
        changed_inside += change > 0.05 * level ? 1 : 0;
      } else if (surely(px, py, 0)) {
        ++elsewhere;
        changed_elsewhere += change > 1e-4 * level ? 1 : 0;
      }
    }
  EXPECT_GT(reflected, 50);
  EXPECT_EQ(changed_inside, reflected) << "pixels of the mirror image showing no box";
  EXPECT_GT(elsewhere, kReflW * kReflH / 2);
  EXPECT_EQ(changed_elsewhere, 0) << "pixels away from the box and its image that changed";
}

}  // namespace

// Reflections of an object stay coherent on the waves (R.53b): a dark box 18 m ahead of a camera
// 2.5 m above the moderate sea, drawn at 160 × 90 and as the 16-sample reference (4 × 4 larger,
// averaged in linear light), at 20 s and 1/30 s later. On the water within 50 m in front of the
// box, in its columns, the reflection's share of the picture, D = Y(with box) − Y(without), is
// compared with the reference's pixel by pixel, and its change over the 1/30 s with the
// reference's: a reflection broken into speckle shimmers more from frame to frame than the
// 16-sample average of the same view.
namespace coherent {

constexpr int kPicW = 160, kPicH = 90;
constexpr std::array<double, 3> kBoxCentre{18.0, 1.2, 3.0};
constexpr std::array<double, 3> kBoxSize{6.0, 2.4, 2.4};
constexpr std::array<double, 3> kEye{0.0, 2.5, 0.0};
constexpr std::array<double, 3> kTarget{30.0, 0.0, 5.0};

using ocean::render::testing::srgb8_to_linear;

// Luminance of the moderate sea at `time_s` without and with the box, drawn `factor` times
// larger and resolved.
std::array<std::vector<double>, 2> pictures(int factor, double time_s) {
  ocean::SimulationConfig config;
  config.cascade_patch_sizes_m = {1000.0, 233.0, 57.0, 13.0};  // presets/moderate.json
  auto scene = ocean::render::Scene::make(
      {.config = config, .width = kPicW * factor, .height = kPicH * factor, .validation = true});
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  if (!scene.ok()) return {};
  Renderer& renderer = scene.value()->renderer();
  const auto hull = ocean::bodies::box_hull({kBoxSize[0], kBoxSize[1], kBoxSize[2]}).value();
  const Mesh box = flat_mesh(hull.vertices, hull.triangles, {.base_colour = {0.05, 0.05, 0.06}});
  EXPECT_TRUE(renderer.set_meshes(std::span(&box, 1)).ok());
  EXPECT_TRUE(scene.value()->warm_up(time_s, 4.0).ok());
  View v;
  v.camera = {.position_m = {kEye[0], kEye[1], kEye[2]},
              .target_m = {kTarget[0], kTarget[1], kTarget[2]},
              .fov_y_rad = 40.0 * std::numbers::pi / 180.0,
              .aspect = static_cast<double>(kPicW) / kPicH,
              .near_m = 0.2,
              .far_m = 2e5};
  v.shading = sky_preset("clear").value();
  std::array<std::vector<double>, 2> out;
  for (int with_box = 0; with_box < 2; ++with_box) {
    v.objects.clear();
    if (with_box == 1)
      v.objects.push_back({.mesh = 0, .model = model_matrix(kBoxCentre, {1, 0, 0, 0})});
    EXPECT_TRUE(renderer.draw(v).ok());
    std::vector<std::uint8_t> srgb;
    EXPECT_TRUE(renderer.read_srgb(srgb).ok());
    auto resolved =
        resolve_supersampled(std::span<const std::uint8_t>(srgb), kPicW * factor, kPicH * factor, factor);
    EXPECT_TRUE(resolved.ok());
    if (!resolved.ok()) return {};
    auto& y = out[static_cast<std::size_t>(with_box)];
    y.resize(static_cast<std::size_t>(kPicW) * kPicH);
    for (std::size_t i = 0; i < y.size(); ++i) {
      const std::uint8_t* p = &resolved.value()[4 * i];
      y[i] = 0.2126 * srgb8_to_linear(p[0]) + 0.7152 * srgb8_to_linear(p[1]) +
             0.0722 * srgb8_to_linear(p[2]);
    }
  }
  const ocean::vk::Context& ctx = *scene.value()->context();
  EXPECT_EQ(ctx.validation_messages.load(), 0u) << ctx.last_validation_message;
  return out;
}

}  // namespace coherent

TEST(Reflection, AnObjectsReflectionOnWavesIsAsCoherentAsTheReference) {
  using namespace coherent;
  if (helpers::graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device");
  const auto plain = pictures(1, 20.0), ref = pictures(4, 20.0);
  const auto plain_next = pictures(1, 20.0 + 1.0 / 30.0), ref_next = pictures(4, 20.0 + 1.0 / 30.0);
  ASSERT_FALSE(plain[0].empty());
  ASSERT_FALSE(ref[0].empty());
  // Each pixel's ray (look-at with +y up, row 0 on top), as in the test above.
  const auto normalise = [](std::array<double, 3> a) {
    const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    return std::array<double, 3>{a[0] / n, a[1] / n, a[2] / n};
  };
  const std::array<double, 3> f =
      normalise({kTarget[0] - kEye[0], kTarget[1] - kEye[1], kTarget[2] - kEye[2]});
  const std::array<double, 3> right = normalise({-f[2], 0.0, f[0]});
  const std::array<double, 3> up{right[1] * f[2] - right[2] * f[1],
                                 right[2] * f[0] - right[0] * f[2],
                                 right[0] * f[1] - right[1] * f[0]};
  const double ty = std::tan(20.0 * std::numbers::pi / 180.0), tx = ty * kPicW / kPicH;
  const auto D = [](const std::array<std::vector<double>, 2>& p, int x, int y) {
    const std::size_t i = static_cast<std::size_t>(std::clamp(y, 0, kPicH - 1) * kPicW +
                                                   std::clamp(x, 0, kPicW - 1));
    return p[1][i] - p[0][i];
  };
  // The rays of the picture, and which of them meet the box itself.
  const auto ray = [&](int px, int py) {
    const double sx = ((px + 0.5) / kPicW * 2.0 - 1.0) * tx,
                 sy = (1.0 - (py + 0.5) / kPicH * 2.0) * ty;
    std::array<double, 3> d{};
    for (std::size_t i = 0; i < 3; ++i) d[i] = f[i] + sx * right[i] + sy * up[i];
    return d;
  };
  const auto meets_box = [&](int px, int py) {
    const std::array<double, 3> d = ray(px, py);
    double near = 0.0, far = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < 3; ++i) {
      const double lo = (kBoxCentre[i] - 0.5 * kBoxSize[i] - kEye[i]) / d[i],
                   hi = (kBoxCentre[i] + 0.5 * kBoxSize[i] - kEye[i]) / d[i];
      near = std::max(near, std::min(lo, hi));
      far = std::min(far, std::max(lo, hi));
    }
    return near < far;
  };
  // Every pixel of water within 50 m more than 2 pixels from the box itself (the waves move it
  // up and down by a little): its reflection, and the water round it where none should show,
  // In the columns of the box and 4 on either side, where a reflection of it may show.
  int first = kPicW, last = -1;
  for (int py = 0; py < kPicH; ++py)
    for (int px = 0; px < kPicW; ++px)
      if (meets_box(px, py)) first = std::min(first, px), last = std::max(last, px);
  ASSERT_LE(first, last);
  // In front of the box, its reflection: how far the picture's is from the reference's, and how
  // much each changes in 1/30 s.
  double err = 0.0, size = 0.0, flicker_plain = 0.0, flicker_ref = 0.0;
  int front = 0;
  for (int py = 2; py < kPicH - 2; ++py)
    for (int px = std::max(first - 4, 2); px <= std::min(last + 4, kPicW - 3); ++px) {
      const std::array<double, 3> d = ray(px, py);
      if (d[1] >= 0.0) continue;
      const double t = -kEye[1] / d[1];
      if (t * std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) > 50.0) continue;
      if (kEye[0] + t * d[0] > kBoxCentre[0] - 0.5 * kBoxSize[0]) continue;
      bool near_box = false;
      for (int dy = -2; dy <= 2 && !near_box; ++dy)
        for (int dx = -2; dx <= 2 && !near_box; ++dx) near_box = meets_box(px + dx, py + dy);
      if (near_box) continue;
      ++front;
      err += std::abs(D(plain, px, py) - D(ref, px, py));
      size += std::abs(D(ref, px, py));
      flicker_plain += std::abs(D(plain_next, px, py) - D(plain, px, py));
      flicker_ref += std::abs(D(ref_next, px, py) - D(ref, px, py));
    }
  std::printf("[ reflection ] %d pixels in front of the box: |D − D_ref| / |D_ref| = %.3f; "
              "change in 1/30 s %.4f (reference %.4f, ratio %.2f)\n",
              front, err / size, flicker_plain / front, flicker_ref / front,
              flicker_plain / flicker_ref);
  EXPECT_GT(front, 200);
  EXPECT_LT(err / size, 0.5) << "the reflection differs from the reference's by half its size";
  EXPECT_LT(flicker_plain, flicker_ref) << "speckle: the reflection shimmers more than the reference";
}
