// The local layer as the renderer samples it (docs/rendering.md R.19): a 2-D RGBA16F image of
// (Dx, h, Dz, 0), filled from a LocalLayerGrid through a staging buffer. Until the first
// set_local_layer() it is 1×1 of zeros and the uniforms say "no layer", so the descriptor is
// always valid.
#include <cstring>
#include <string>

#include "ocean/half.hpp"
#include "state.hpp"
#include "world_grid.hpp"

namespace ocean::render {

namespace {

// The image and its staging buffer for a side × side layer; the old ones are destroyed first.
Status allocate_local(Renderer::State& st, std::uint32_t side) {
  vkDeviceWaitIdle(st.ctx->device);
  vk::destroy_image(*st.ctx, st.local_image);
  vk::destroy_buffer(*st.ctx, st.local_staging);
  st.local_side = 0;
  Result<vk::Image2D> image =
      vk::create_image_2d(*st.ctx, VK_FORMAT_R16G16B16A16_SFLOAT, side, side,
                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  if (!image.ok()) return image.status();
  st.local_image = image.value();
  Result<vk::Buffer> staging =
      vk::create_buffer(*st.ctx, static_cast<VkDeviceSize>(side) * side * 8,
                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::upload);
  if (!staging.ok()) return staging.status();
  st.local_staging = staging.value();
  std::memset(st.local_staging.mapped, 0, static_cast<std::size_t>(side) * side * 8);
  st.local_side = side;
  st.local_pending = true;
  return {};
}

}  // namespace

Status create_local_layer(Renderer::State& st) {
  st.local = {};
  return allocate_local(st, 1);
}

Status Renderer::set_local_layer(const LocalLayerGrid& grid) {
  State& st = *state_;
  if (grid.displacement.empty()) {  // no layer: the uniforms switch it off; the image may stay
    st.local.resolution = 0.0f;
    return {};
  }
  if (Status s = check_world_grid("local layer", grid.origin_m, grid.size_m, grid.resolution);
      !s.ok())
    return s;
  const auto side = static_cast<std::uint32_t>(grid.resolution);
  const std::size_t cells = static_cast<std::size_t>(side) * side;
  if (grid.displacement.size() != 3 * cells)
    return invalid_argument("local layer: " + std::to_string(grid.displacement.size()) +
                            " values for " + std::to_string(side) + "² cells (3 each expected)");
  if (side != st.local_side) {
    if (Status s = allocate_local(st, side); !s.ok()) {
      st.local.resolution = 0.0f;
      (void)allocate_local(st, 1);  // keep a valid, empty image behind the descriptor
      write_scene_images(st);
      return s;
    }
    write_scene_images(st);
  }
  auto* out = static_cast<std::uint16_t*>(st.local_staging.mapped);
  for (std::size_t i = 0; i < cells; ++i) {
    for (std::size_t c = 0; c < 3; ++c)
      out[4 * i + c] = float_to_half(grid.displacement[3 * i + c]);
    out[4 * i + 3] = 0;
  }
  st.local_origin_m = grid.origin_m;
  st.local.size_m = static_cast<float>(grid.size_m);
  st.local.resolution = static_cast<float>(side);
  st.local_pending = true;
  return {};
}

void record_local_upload(Renderer::State& st, VkCommandBuffer cmd) {
  record_world_grid_upload(cmd, st.local_staging.buffer, st.local_image.image, st.local_side, 1);
  st.local_pending = false;
}

}  // namespace ocean::render
