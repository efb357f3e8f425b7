// The damping's pass (damping.hpp, docs/rendering.md R.24): its image filled from a DampingGrid
// through a staging buffer. Until the first set_damping() it is 1×1 and the uniforms say "no
// damping", so the descriptor is always valid.
#include "damping.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "far_map.hpp"
#include "ocean/half.hpp"
#include "ocean/waves.hpp"
#include "state.hpp"
#include "world_grid.hpp"

namespace ocean::render {

namespace {

constexpr std::uint32_t kLayers = 3;
// g of the deep-water wavelength the swash is reckoned from (W.40): the default sea's.
constexpr double kSwashGravity_mps2 = 9.81;

Status allocate_damping(Renderer::State& st, std::uint32_t side) {
  DampingPass& damping = pass<DampingPass>(st);
  vkDeviceWaitIdle(st.ctx->device);
  vk::destroy_image(*st.ctx, damping.image);
  vk::destroy_buffer(*st.ctx, damping.staging);
  damping.side = 0;
  Result<vk::Image> image =
      vk::create_image_array(*st.ctx, VK_FORMAT_R16G16B16A16_SFLOAT, side, kLayers, 1,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  if (!image.ok()) return image.status();
  damping.image = image.value();
  const std::size_t bytes = static_cast<std::size_t>(side) * side * 8 * kLayers;
  Result<vk::Buffer> staging =
      vk::create_buffer(*st.ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::upload);
  if (!staging.ok()) return staging.status();
  damping.staging = staging.value();
  std::memset(damping.staging.mapped, 0, bytes);
  damping.side = side;
  damping.pending = true;
  return {};
}

}  // namespace

Status DampingPass::create(Renderer::State& st) {
  Result<VkSampler> linear = make_sampler(*st.ctx, true, false, false, 1.0f);
  if (!linear.ok()) return linear.status();
  sampler = linear.value();
  uniforms = {};
  return allocate_damping(st, 1);
}

void DampingPass::destroy(Renderer::State& st) {
  vk::destroy_image(*st.ctx, image);
  vk::destroy_buffer(*st.ctx, staging);
  if (sampler != VK_NULL_HANDLE) vkDestroySampler(st.ctx->device, sampler, nullptr);
}

void DampingPass::scene_images(const Renderer::State&, SceneImages& images) const {
  images.add(OCEAN_RENDER_BINDING_DAMPING, images.surface_stages,
             {sampler, image.view, VK_IMAGE_LAYOUT_GENERAL});
}

void DampingPass::fill_uniforms(const Renderer::State& st, const View&,
                                shader::FrameUniforms& u) const {
  const lod::LodSelection& sel = st.selection;
  u.damping = uniforms;
  u.damping.origin_m = {static_cast<float>(origin_m[0] - sel.grid_centre_x_m),
                        static_cast<float>(origin_m[1] - sel.grid_centre_z_m)};
  // Pure water's absorption at 650, 550 and 450 nm (Pope & Fry 1997: 0.340, 0.0565 and
  // 0.0092 per m) and a sandy bottom's albedo, a chosen value (R.24).
  u.damping.absorption_per_m = {0.340f, 0.0565f, 0.0092f};
  u.damping.bottom_albedo = {0.45f, 0.40f, 0.30f};
  // The swash on the land (R.67): its period is the sea's peak period, its phase taken here in
  // double precision so that it does not lose its fraction over a long run.
  const double period = st.peak_period_s;
  if (period > 0.0 && std::isfinite(period) && st.hs_m > 0.0) {
    const double cycles = pass<FarFieldPass>(st).time_s / period;
    u.damping.swash_phase = static_cast<float>(cycles - std::floor(cycles));
    u.damping.swash_wavelength_m =
        static_cast<float>(waves::deep_water_wavelength_m(period, kSwashGravity_mps2));
  }
}

void DampingPass::upload(Renderer::State&, VkCommandBuffer cmd) {
  if (!pending) return;
  record_world_grid_upload(cmd, staging.buffer, image.image, side, kLayers);
  pending = false;
}

Status Renderer::set_damping(const DampingGrid& grid) {
  State& st = *state_;
  DampingPass& damping = pass<DampingPass>(st);
  if (grid.band_weights.empty()) {
    damping.uniforms.resolution = 0.0f;
    return {};
  }
  if (Status s = check_world_grid("damping", grid.origin_m, grid.size_m, grid.resolution); !s.ok())
    return s;
  const auto side = static_cast<std::uint32_t>(grid.resolution);
  const std::size_t cells = static_cast<std::size_t>(side) * side;
  if (grid.band_weights.size() != kDampingBands * cells || grid.depth_m.size() != cells)
    return invalid_argument("damping: " + std::to_string(grid.band_weights.size()) +
                            " weights and " + std::to_string(grid.depth_m.size()) + " depths for " +
                            std::to_string(side) + "² cells (" + std::to_string(kDampingBands) +
                            " and 1 each expected)");
  if (!grid.breaking_fraction.empty() && grid.breaking_fraction.size() != cells)
    return invalid_argument("damping: " + std::to_string(grid.breaking_fraction.size()) +
                            " breaking fractions for " + std::to_string(side) +
                            "² cells (1 each or none expected)");
  if (side != damping.side) {
    if (Status s = allocate_damping(st, side); !s.ok()) {
      damping.uniforms.resolution = 0.0f;
      (void)allocate_damping(st, 1);
      write_scene_images(st);
      return s;
    }
    write_scene_images(st);
  }
  auto* out = static_cast<std::uint16_t*>(damping.staging.mapped);
  const auto clamped = [](float v, float hi) {
    return std::isfinite(v) ? std::clamp(v, 0.0f, hi) : hi;  // +inf: deep water, weight 1
  };
  for (std::size_t i = 0; i < cells; ++i) {
    for (std::size_t b = 0; b < kDampingBands; ++b) {
      const std::size_t layer = b / 4;
      out[(layer * cells + i) * 4 + b % 4] =
          float_to_half(clamped(grid.band_weights[kDampingBands * i + b], 1.0f));
    }
    std::uint16_t* depth = &out[(2 * cells + i) * 4];
    // Negative: land, its height above the sea level (R.64); ±inf and NaN: deep water.
    const float d = grid.depth_m[i];
    const auto deep = static_cast<float>(OCEAN_RENDER_DEEP_M);
    depth[0] = float_to_half(std::isfinite(d) ? std::clamp(d, -deep, deep) : deep);
    depth[1] = grid.breaking_fraction.empty()
                   ? 0
                   : float_to_half(clamped(grid.breaking_fraction[i], 1.0f));
    depth[2] = depth[3] = 0;
  }
  damping.origin_m = grid.origin_m;
  damping.uniforms.size_m = static_cast<float>(grid.size_m);
  damping.uniforms.resolution = static_cast<float>(side);
  damping.pending = true;
  return {};
}

}  // namespace ocean::render
