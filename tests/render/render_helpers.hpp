// What the renderer's and the scene's tests share: a validated graphics context, a rig that
// checks the validation layer stayed silent (and one with a simulated frame uploaded), a small
// sea, an eye-level view and the difference of two sRGB pictures.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/render.hpp"

namespace ocean::render::testing {

/// A context with a graphics queue and the Khronos validation layer; nullptr without a device.
inline std::shared_ptr<vk::Context> graphics_context() {
  auto ctx = vk::create_context({.validation = true, .graphics = true});
  if (!ctx.ok()) return nullptr;
  return std::shared_ptr<vk::Context>(std::move(ctx).value());
}

/// A context, a simulator and a renderer; when it goes, the validation layer must have stayed
/// silent.
struct ValidatedRig {
  std::shared_ptr<vk::Context> ctx;
  std::unique_ptr<Simulator> sim;
  std::unique_ptr<Renderer> renderer;
  ValidatedRig() = default;
  ValidatedRig(const ValidatedRig&) = delete;
  ValidatedRig& operator=(const ValidatedRig&) = delete;
  ~ValidatedRig() {
    if (ctx != nullptr) {
      EXPECT_EQ(ctx->validation_messages.load(), 0u) << ctx->last_validation_message;
    }
  }
};
using Rig = ValidatedRig;

/// A renderer of w × h pixels on `ctx` with the CPU backend's frame of `config` at t = 3 s
/// uploaded; nullptr when `ctx` is or anything fails.
inline std::unique_ptr<Rig> make_rig(std::shared_ptr<vk::Context> ctx,
                                     const SimulationConfig& config, int w, int h) {
  if (ctx == nullptr) return nullptr;
  auto rig = std::make_unique<Rig>();
  rig->ctx = std::move(ctx);
  auto backend = make_backend("cpu");
  if (!backend.ok()) return nullptr;
  auto sim = Simulator::make(config, std::move(backend).value());
  if (!sim.ok()) return nullptr;
  rig->sim = std::move(sim).value();
  auto r = Renderer::make(rig->ctx, {.width = w, .height = h});
  if (!r.ok()) return nullptr;
  rig->renderer = std::move(r).value();
  if (!rig->renderer->configure(ocean::SimulationPlan::make(config).value().surface()).ok())
    return nullptr;
  rig->sim->step(3.0);
  if (!rig->renderer->upload(rig->sim->frame()).ok()) return nullptr;
  return rig;
}

/// Two cascades of a 12 m/s wind sea at N = 64.
inline SimulationConfig small_config() {
  SimulationConfig c;
  c.resolution = 64;
  c.cascade_patch_sizes_m = {200.0, 47.0};
  c.sea.wind_sea.spectrum.wind_speed_mps = 12.0;
  c.sea.wind_sea.spectrum.fetch_m = 100e3;
  return c;
}

/// A camera 5 m up looking level, away from the sun (azimuth 35°), low LOD quality.
inline View eye_level_view(int width, int height) {
  View v;
  v.camera = {.position_m = {0.0, 5.0, 0.0},
              .target_m = {-100.0, 5.0, -70.0},
              .fov_y_rad = 50.0 * std::numbers::pi / 180.0,
              .aspect = static_cast<double>(width) / height,
              .near_m = 0.2,
              .far_m = 2e5};
  v.quality = lod::quality_preset(lod::QualityPreset::low);
  v.ocean_size_m = 2048.0;
  return v;
}

/// A square picture straight down from `height_m` over the origin (50° field of view, +x up the
/// picture) in the normals debug view: the shading normal as colour, the foam in alpha.
inline View top_down_debug_view(double height_m) {
  View view;
  view.camera = {.position_m = {0.0, height_m, 0.0},
                 .target_m = {1e-3 * height_m, 0.0, 0.0},
                 .fov_y_rad = 50.0 * std::numbers::pi / 180.0,
                 .aspect = 1.0,
                 .near_m = 0.5,
                 .far_m = 1e5};
  view.shading = render::sky_preset("clear").value();
  view.debug = render::DebugView::normals;
  return view;
}

/// An 8-bit sRGB code (0..255) in linear light (IEC 61966-2-1).
inline double srgb8_to_linear(double code) {
  const double c = code / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

/// Mean and largest absolute difference of two RGBA8 pictures of equal size, in LSB.
struct PictureDifference {
  double mean = 0.0;
  int max = 0;
};
inline PictureDifference difference(const std::vector<std::uint8_t>& a,
                                    const std::vector<std::uint8_t>& b) {
  PictureDifference d;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    const int e = std::abs(int(a[i]) - int(b[i]));
    d.max = std::max(d.max, e);
    sum += e;
  }
  d.mean = a.empty() ? 0.0 : sum / static_cast<double>(a.size());
  return d;
}

}  // namespace ocean::render::testing
