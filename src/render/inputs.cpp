// The simulation's images as the renderer samples them: its own displacement and normal/foam
// arrays, filled from a CPU Frame through a staging buffer (upload path), or a Vulkan backend's
// images on the same context, sampled where they are (zero-copy path). configure() also derives
// what the shaders need per cascade.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>

#include "state.hpp"

namespace ocean::render {

Status Renderer::configure(const SurfaceDescription& surface) {
  const auto cascade_count = surface.patch_sizes_m.size();
  if (cascade_count == 0 || cascade_count > static_cast<std::size_t>(kMaxCascades) ||
      surface.tiling_wavelengths_m.size() != cascade_count || surface.resolution < 16 ||
      !std::has_single_bit(static_cast<unsigned>(surface.resolution)))
    return invalid_argument(
        "renderer: the surface description has " + std::to_string(cascade_count) +
        " cascades (1 to " + std::to_string(kMaxCascades) +
        ", one tiling wavelength each) at N = " + std::to_string(surface.resolution) +
        " (a power of two, at least 16): describe a plan's surface");
  State& st = *state_;
  st.hs_m = surface.significant_wave_height_m;
  st.crest_bound_m = surface.crest_bound_m;
  st.horizontal_reach_m = surface.horizontal_reach_m;
  st.choppiness = surface.choppiness;
  st.foam_ramp = surface.foam_ramp;
  st.foam_weights = surface.foam_weights;
  st.foam_drift_mps = surface.foam_drift_mps;
  st.foam_decay_time_s = surface.foam_decay_time_s;
  st.peak_period_s = surface.peak_period_s;
  st.unresolved_slope_variance = surface.unresolved_slope_variance;
  st.map_base_normal_length = surface.map_base_normal_length;
  pass<FarFieldPass>(st).noise = surface.far_noise;
  pass<RipplePass>(st).waves = surface.short_waves;
  // Whitecaps as patches (R.11b) where the cascades' foam is the breaking probability.
  WhitecapPass& whitecaps = pass<WhitecapPass>(st);
  const auto whitecap_sines = whitecap_waves(surface);
  whitecaps.enabled = !surface.foam_weights.empty() && whitecap_sines.has_value();
  if (whitecaps.enabled) whitecaps.waves = *whitecap_sines;
  st.cascades = static_cast<int>(cascade_count);
  const int n = surface.resolution;
  for (int c = 0; c < st.cascades; ++c) {
    const double size = surface.patch_sizes_m[static_cast<std::size_t>(c)];
    st.patch_size_m[static_cast<std::size_t>(c)] = size;
    st.cascade_params[static_cast<std::size_t>(c)] = {
        .patch_size_m = static_cast<float>(size),
        .resolution = static_cast<float>(n),
        .wavelength_m =
            static_cast<float>(surface.tiling_wavelengths_m[static_cast<std::size_t>(c)]),
        .coarsest_mip = static_cast<float>(std::countr_zero(static_cast<unsigned>(n)))};
  }
  // Own images for the upload path.
  vkDeviceWaitIdle(st.ctx->device);
  st.destroy_shared();
  st.destroy_sim_images();
  const auto size = static_cast<std::uint32_t>(n);
  const auto layers = static_cast<std::uint32_t>(st.cascades);
  const std::uint32_t mips = static_cast<std::uint32_t>(std::countr_zero(size)) + 1;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  Result<vk::Image> disp =
      vk::create_image_array(*st.ctx, VK_FORMAT_R16G16B16A16_SFLOAT, size, layers, 1,
                             usage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);  // motion: kept (R.26)
  if (!disp.ok()) return disp.status();
  st.displacement = disp.value();
  Result<vk::Image> normal =
      vk::create_image_array(*st.ctx, VK_FORMAT_R8G8B8A8_UNORM, size, layers, mips, usage);
  if (!normal.ok()) return normal.status();
  st.normal_foam = normal.value();
  const std::size_t bytes = interop::inputs_layout(n, st.cascades).bytes();
  Result<vk::Buffer> staging =
      vk::create_buffer(*st.ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::upload);
  if (!staging.ok()) return staging.status();
  st.staging = staging.value();
  std::memset(st.staging.mapped, 0, bytes);
  // The images start in GENERAL with zeros (flat sea) until the first upload.
  st.upload_pending = true;
  st.borrowed = false;
  st.displacement_view = st.displacement.view;
  st.normal_view = st.normal_foam.view;
  st.sim_size = size, st.sim_layers = layers, st.sim_mips = mips;
  write_scene_images(st);
  return {};
}

Status Renderer::upload(const Frame& frame) {
  State& st = *state_;
  if (st.displacement.image == VK_NULL_HANDLE)
    return invalid_argument("renderer: upload() before configure()");
  if (frame.cascades.size() != st.sim_layers)
    return invalid_argument("renderer: the frame has " + std::to_string(frame.cascades.size()) +
                            " cascades, configured for " + std::to_string(st.sim_layers));
  const std::size_t texels = static_cast<std::size_t>(st.sim_size) * st.sim_size;
  const std::size_t chain = mip_chain_texels(static_cast<int>(st.sim_size));
  auto* out = static_cast<std::byte*>(st.staging.mapped);
  for (const CascadeFrame& c : frame.cascades) {
    if (c.displacement_half.size() != texels * 4 || c.packed_mips.size() != chain)
      return invalid_argument("renderer: the frame's arrays do not match the configuration");
  }
  for (const CascadeFrame& c : frame.cascades) {
    std::memcpy(out, c.displacement_half.data(), texels * 8);
    out += texels * 8;
  }
  for (const CascadeFrame& c : frame.cascades) {
    std::memcpy(out, c.packed_mips.data(), chain * 4);
    out += chain * 4;
  }
  if (Status s = pass<FarFieldPass>(st).stage(st, frame.far_noise, frame.time_s); !s.ok()) return s;
  if (st.borrowed) {
    st.borrowed = false;
    st.displacement_view = st.displacement.view;
    st.normal_view = st.normal_foam.view;
    write_scene_images(st);
  }
  st.upload_pending = true;
  return {};
}

void Renderer::use_simulation_images(const vk::SimulationImages& images) {
  State& st = *state_;
  st.borrowed = true;
  st.upload_pending = false;
  st.displacement_view = images.displacement_view;
  st.normal_view = images.normal_foam_view;
  write_scene_images(st);
}

void record_uploads(Renderer::State& st, VkCommandBuffer cmd) {
  record_uploads(st, cmd, st.staging.buffer);
}

void record_uploads(Renderer::State& st, VkCommandBuffer cmd, VkBuffer source) {
  // Staging → images (GENERAL); the first use transitions them from UNDEFINED.
  static_assert(sizeof(std::uint16_t) * 4 == 8);
  for (vk::Image* im : {&st.displacement, &st.normal_foam})
    vk::image_barrier(cmd, im->image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                      VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                      0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  const std::uint32_t n = st.sim_size;
  const interop::InputsLayout layout =
      interop::inputs_layout(static_cast<int>(n), static_cast<int>(st.sim_layers));
  // ≤ 8 cascades × 12 mip levels (N ≤ 2048): on the stack, no allocation per frame.
  std::array<VkBufferImageCopy, kMaxCascades * 12> regions{};
  std::uint32_t count = 0;
  for (std::uint32_t c = 0; c < st.sim_layers; ++c) {
    regions[count++] = {.bufferOffset = layout.displacement_offset(static_cast<int>(c)),
                        .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, c, 1},
                        .imageExtent = {n, n, 1}};
  }
  vkCmdCopyBufferToImage(cmd, source, st.displacement.image, VK_IMAGE_LAYOUT_GENERAL, count,
                         regions.data());
  count = 0;
  for (std::uint32_t c = 0; c < st.sim_layers; ++c) {
    for (std::uint32_t m = 0; m < st.sim_mips; ++m) {
      const std::uint32_t s = n >> m;
      regions[count++] = {.bufferOffset = layout.mips_offset(static_cast<int>(c)) +
                                          mip_offset(static_cast<int>(n), static_cast<int>(m)) * 4,
                          .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m, c, 1},
                          .imageExtent = {s, s, 1}};
    }
  }
  vkCmdCopyBufferToImage(cmd, source, st.normal_foam.image, VK_IMAGE_LAYOUT_GENERAL, count,
                         regions.data());
  vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
              VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
}

}  // namespace ocean::render
