// Objects reflected in the water (lavapipe, validation layer on; docs/rendering.md R.53): over a
// flat sea, a box's reflection changes exactly the pixels whose ray, mirrored at the water, meets
// the box — found on the CPU by intersecting each pixel's reflected ray with the box — and no
// pixel elsewhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ocean/backends.hpp"
#include "ocean/bodies.hpp"
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
