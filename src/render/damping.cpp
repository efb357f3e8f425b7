// The damping of the bands as the renderer samples it (docs/rendering.md R.24): an RGBA16F 2-D
// array of three layers (the weights of cascades 0–3 and 4–7, the depth), filled from a
// DampingGrid through a staging buffer. Until the first set_damping() it is 1×1 and the uniforms
// say "no damping", so the descriptor is always valid.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "ocean/half.hpp"
#include "state.hpp"
#include "world_grid.hpp"

namespace ocean::render {

namespace {

constexpr std::uint32_t kLayers = 3;

Status allocate_damping(Renderer::State& st, std::uint32_t side) {
  vkDeviceWaitIdle(st.ctx->device);
  vk::destroy_image(*st.ctx, st.damping_image);
  vk::destroy_buffer(*st.ctx, st.damping_staging);
  st.damping_side = 0;
  Result<vk::Image> image =
      vk::create_image_array(*st.ctx, VK_FORMAT_R16G16B16A16_SFLOAT, side, kLayers, 1,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  if (!image.ok()) return image.status();
  st.damping_image = image.value();
  const std::size_t bytes = static_cast<std::size_t>(side) * side * 8 * kLayers;
  Result<vk::Buffer> staging =
      vk::create_buffer(*st.ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::upload);
  if (!staging.ok()) return staging.status();
  st.damping_staging = staging.value();
  std::memset(st.damping_staging.mapped, 0, bytes);
  st.damping_side = side;
  st.damping_pending = true;
  return {};
}

}  // namespace

Status create_damping(Renderer::State& st) {
  st.damping = {};
  return allocate_damping(st, 1);
}

Status Renderer::set_damping(const DampingGrid& grid) {
  State& st = *state_;
  if (grid.band_weights.empty()) {
    st.damping.resolution = 0.0f;
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
  if (side != st.damping_side) {
    if (Status s = allocate_damping(st, side); !s.ok()) {
      st.damping.resolution = 0.0f;
      (void)allocate_damping(st, 1);
      write_scene_images(st);
      return s;
    }
    write_scene_images(st);
  }
  auto* out = static_cast<std::uint16_t*>(st.damping_staging.mapped);
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
    depth[0] = float_to_half(clamped(grid.depth_m[i], static_cast<float>(OCEAN_RENDER_DEEP_M)));
    depth[1] = depth[2] = depth[3] = 0;
  }
  st.damping_origin_m = grid.origin_m;
  st.damping.size_m = static_cast<float>(grid.size_m);
  st.damping.resolution = static_cast<float>(side);
  st.damping_pending = true;
  return {};
}

void Renderer::set_calm(bool calm) { state_->local.calm = calm ? 1.0f : 0.0f; }

void record_damping_upload(Renderer::State& st, VkCommandBuffer cmd) {
  record_world_grid_upload(cmd, st.damping_staging.buffer, st.damping_image.image, st.damping_side,
                           kLayers);
  st.damping_pending = false;
}

}  // namespace ocean::render
