// Motion vectors (docs/rendering.md R.26) on any Vulkan device (lavapipe on CPU-only machines),
// validation layer on, against motion computed here from the cameras and the waves:
// - a calm flat sea and a camera that moves and turns between two frames: each pixel's motion is
//   where the ray through it meets the sea (or, for the sky, its direction) projected by the
//   previous camera (within 0.02 px; measured 0.003 px);
// - a single Gerstner wave written into cascade 0 by hand at t and t + Δt, the camera moving as
//   well: the motion of surface points (labels) between their two displaced positions, each
//   seen by its frame's camera (within 0.1 px; measured 0.07 px at most of 2–3 px);
// - read_motion before any motion frame refused.
// Skips where no Vulkan device exists (fails with OCEAN_REQUIRE_DEVICES=1).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/half.hpp"
#include "ocean/render.hpp"
#include "render/render_helpers.hpp"
#include "support/require_devices.hpp"

namespace {

using ocean::render::Renderer;
using ocean::render::View;
using ocean::render::testing::graphics_context;

constexpr int kW = 96, kH = 64;
constexpr double kPi = std::numbers::pi;
using Mat = std::array<double, 16>;

// p' = M·(x, y, z, w) for a column-major M.
std::array<double, 4> apply(const Mat& m, std::array<double, 4> p) {
  std::array<double, 4> r{};
  for (std::size_t row = 0; row < 4; ++row)
    for (std::size_t k = 0; k < 4; ++k) r[row] += m[k * 4 + row] * p[k];
  return r;
}

// The pixel (x right, y down, continuous) a clip position lands on.
std::array<double, 2> to_pixel(const std::array<double, 4>& clip) {
  return {(clip[0] / clip[3] + 1.0) * 0.5 * kW, (1.0 - clip[1] / clip[3]) * 0.5 * kH};
}

// The world direction through NDC (nx, ny) of a camera (lod::look_at's basis: side = f × up).
std::array<double, 3> ray(const ocean::lod::Camera& c, double nx, double ny) {
  const ocean::lod::Vec3 p = c.position_m, t = c.target_m;
  std::array<double, 3> f{t.x - p.x, t.y - p.y, t.z - p.z};
  const double fl = std::hypot(f[0], f[1], f[2]);
  for (double& v : f) v /= fl;
  std::array<double, 3> s{-f[2], 0.0, f[0]};  // f × (0, 1, 0)
  const double sl = std::hypot(s[0], s[2]);
  s[0] /= sl, s[2] /= sl;
  const std::array<double, 3> u{s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2],
                                s[0] * f[1] - s[1] * f[0]};
  const double ty = std::tan(0.5 * c.fov_y_rad), tx = ty * c.aspect;
  return {nx * tx * s[0] + ny * ty * u[0] + f[0], nx * tx * s[1] + ny * ty * u[1] + f[1],
          nx * tx * s[2] + ny * ty * u[2] + f[2]};
}

using Rig = ocean::render::testing::ValidatedRig;

std::unique_ptr<Rig> make_rig(const ocean::SimulationConfig& config) {
  auto rig = std::make_unique<Rig>();
  rig->ctx = graphics_context();
  if (rig->ctx == nullptr) return nullptr;
  auto r = Renderer::make(rig->ctx, {.width = kW, .height = kH});
  if (!r.ok() || !r.value()->configure(ocean::SimulationPlan::make(config).value().surface()).ok())
    return nullptr;
  rig->renderer = std::move(r).value();
  return rig;
}

#define REQUIRE_RIG(rig)                                                       \
  if ((rig) == nullptr) {                                                      \
    if (graphics_context() == nullptr) OCEAN_SKIP_OR_FAIL("no Vulkan device"); \
    FAIL() << "could not build the renderer";                                  \
  }

View flat_view() {
  View v = ocean::render::testing::eye_level_view(kW, kH);
  v.planet_radius_m = std::numeric_limits<double>::infinity();
  v.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::high);
  return v;
}

TEST(MotionVectors, CameraMotionOverCalmWater) {
  auto rig = make_rig(ocean::render::testing::small_config());
  REQUIRE_RIG(rig);
  Renderer& r = *rig->renderer;
  std::vector<float> motion;
  EXPECT_EQ(r.read_motion(motion).code(), ocean::ErrorCode::invalid_argument);
  r.set_calm(true);  // the sea at y = 0 exactly
  ASSERT_TRUE(r.set_motion_vectors(true).ok());
  View a = flat_view();
  a.camera.target_m = {-100.0, -4.0, -70.0};  // the horizon in the upper part
  View b = a;                                 // moved 0.3 m sideways, 0.1 m up, and turned a little
  b.camera.position_m = {0.3, 5.1, -0.2};
  b.camera.target_m = {-97.0, -4.0, -72.0};
  ASSERT_TRUE(r.draw(a).ok());
  ASSERT_TRUE(r.draw(b).ok());
  ASSERT_TRUE(r.read_motion(motion).ok());
  ASSERT_EQ(motion.size(), static_cast<std::size_t>(kW * kH * 2));
  const Mat vp_a = ocean::lod::view_projection(a.camera).m;
  double worst = 0.0, largest = 0.0;
  int sea = 0, sky = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const double nx = (x + 0.5) / kW * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / kH * 2.0;
      const std::array<double, 3> d = ray(b.camera, nx, ny);
      const std::array<double, 3> o{b.camera.position_m.x, b.camera.position_m.y,
                                    b.camera.position_m.z};
      std::array<double, 4> world{};
      if (d[1] < -1e-9) {  // meets the sea
        const double t = -o[1] / d[1];
        world = {o[0] + t * d[0], 0.0, o[2] + t * d[2], 1.0};
        // Far away the sea's pixel is a fraction of a metre's resolution: the nearer pixels.
        if (t * std::sqrt(d[0] * d[0] + d[2] * d[2]) > 300.0) continue;
        ++sea;
      } else {
        world = {d[0], d[1], d[2], 0.0};  // a direction: the sky
        ++sky;
      }
      const auto prev = to_pixel(apply(vp_a, world));
      const double ex = x + 0.5 - prev[0], ey = y + 0.5 - prev[1];
      const std::size_t i = static_cast<std::size_t>(2 * (y * kW + x));
      worst = std::max(worst, std::hypot(motion[i] - ex, motion[i + 1] - ey));
      largest = std::max(largest, std::hypot(ex, ey));
    }
  }
  std::printf("camera motion: %d sea and %d sky pixels, largest %.3f px, worst error %.4f px\n",
              sea, sky, largest, worst);
  EXPECT_GT(sea, kW * kH / 4);
  EXPECT_GT(sky, kW * 4);
  EXPECT_GT(largest, 1.0);
  EXPECT_LT(worst, 0.02);
}

// One Gerstner wave (Gerstner 1802; Tessendorf 2001, eq. 7 with one component) of amplitude A
// and wavevector k periodic on the patch: displacement (−k̂x·A·sin θ, A·cos θ, −k̂z·A·sin θ),
// θ = k·x − ωt, deep-water ω = √(g|k|).
struct Gerstner {
  double kx, kz, a;
  [[nodiscard]] std::array<double, 3> at(double x, double z, double t) const {
    const double k = std::hypot(kx, kz), w = std::sqrt(9.81 * k);
    const double th = kx * x + kz * z - w * t;
    return {-kx / k * a * std::sin(th), a * std::cos(th), -kz / k * a * std::sin(th)};
  }
};

TEST(MotionVectors, SingleGerstnerWaveAndAMovingCamera) {
  ocean::SimulationConfig config = ocean::render::testing::small_config();
  config.resolution = 64;
  config.cascade_patch_sizes_m = {64.0};
  config.outputs = ocean::FrameOutputs::textures();
  auto rig = make_rig(config);
  REQUIRE_RIG(rig);
  Renderer& r = *rig->renderer;
  const double l = 64.0;
  const Gerstner wave{2.0 * kPi * 2.0 / l, 2.0 * kPi * 1.0 / l, 1.0};
  ocean::Frame frame;
  ocean::allocate_frame(config, frame);
  ocean::CascadeFrame& c0 = frame.cascades[0];
  // Texel (col, row) holds the displacement of x = col·L/N, z = row·L/N (planet.glsl's uv).
  const auto write_wave = [&](double t) {
    const int n = config.resolution;
    for (int row = 0; row < n; ++row)
      for (int col = 0; col < n; ++col) {
        const auto d = wave.at(col * l / n, row * l / n, t);
        for (std::size_t k = 0; k < 3; ++k)
          c0.displacement_half[static_cast<std::size_t>(4 * (row * n + col)) + k] =
              ocean::float_to_half(static_cast<float>(d[k]));
      }
    return r.upload(frame);
  };
  View v = flat_view();
  v.camera = {.position_m = {3.0, 14.0, 2.0},
              .target_m = {23.0, 0.0, 12.0},
              .fov_y_rad = 50.0 * kPi / 180.0,
              .aspect = static_cast<double>(kW) / kH,
              .near_m = 0.2,
              .far_m = 2e4};
  ASSERT_TRUE(r.set_motion_vectors(true).ok());
  const double t0 = 1.0, t1 = 1.4;
  ASSERT_TRUE(write_wave(t0).ok());
  ASSERT_TRUE(r.draw(v).ok());
  View v1 = v;  // the camera moves too: 0.2 m sideways, 5 cm up, and turns a little
  v1.camera.position_m = {3.2, 14.05, 1.9};
  v1.camera.target_m = {23.5, 0.0, 12.0};
  ASSERT_TRUE(write_wave(t1).ok());
  ASSERT_TRUE(r.draw(v1).ok());
  std::vector<float> motion;
  ASSERT_TRUE(r.read_motion(motion).ok());
  // Surface points (labels) on a 0.25 m lattice: where they are now and were at t0, on screen.
  const Mat vp0 = ocean::lod::view_projection(v.camera).m;
  const Mat vp = ocean::lod::view_projection(v1.camera).m;
  double worst = 0.0, largest = 0.0, sum = 0.0;
  int n = 0;
  for (double z = -10.0; z <= 40.0; z += 0.25) {
    for (double x = -10.0; x <= 50.0; x += 0.25) {
      const auto d1 = wave.at(x, z, t1), d0 = wave.at(x, z, t0);
      const auto p1 = to_pixel(apply(vp, {x + d1[0], d1[1], z + d1[2], 1.0}));
      const auto p0 = to_pixel(apply(vp0, {x + d0[0], d0[1], z + d0[2], 1.0}));
      // Only points well inside the picture, at a pixel's centre to within 0.1 px.
      if (p1[0] < 2 || p1[1] < 2 || p1[0] > kW - 2 || p1[1] > kH - 2) continue;
      if (std::abs(p1[0] - std::floor(p1[0]) - 0.5) > 0.1 ||
          std::abs(p1[1] - std::floor(p1[1]) - 0.5) > 0.1)
        continue;
      const auto i =
          static_cast<std::size_t>(2 * (static_cast<int>(p1[1]) * kW + static_cast<int>(p1[0])));
      const double e = std::hypot(motion[i] - (p1[0] - p0[0]), motion[i + 1] - (p1[1] - p0[1]));
      worst = std::max(worst, e);
      largest = std::max(largest, std::hypot(p1[0] - p0[0], p1[1] - p0[1]));
      sum += e;
      ++n;
    }
  }
  std::printf("wave motion: %d points, largest %.3f px, mean error %.4f px, worst %.4f px\n", n,
              largest, sum / std::max(n, 1), worst);
  EXPECT_GT(n, 100);
  EXPECT_GT(largest, 1.0);
  EXPECT_LT(worst, 0.1);
}

}  // namespace
#undef REQUIRE_RIG
