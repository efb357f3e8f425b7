// The far field's noise map as the renderer samples it (src/render, private; docs/rendering.md
// R.13b): an RGBA16F image with its mip chain, (h, ∂h/∂x, ∂h/∂z, (∂h/∂x)² + (∂h/∂z)²) of the
// octaves whose cells span at least four texels, filled on the device from a float3 buffer — the
// renderer's own (upload path) or a Vulkan backend's (no copy) — by shaders/far_map.comp, the
// coarser levels by blits. 1×1 while there is no map.
#pragma once

#include <array>

#include "ocean/vk.hpp"
#include "shaders/render_shared.h"

namespace ocean::render {

struct FarMapPass {
  vk::Image image;                  // the map and its mips (GENERAL once recorded)
  vk::Buffer source;                // host-visible float3 map of the upload path
  VkBuffer bound = VK_NULL_HANDLE;  // the buffer the descriptor set reads
  VkSampler sampler = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  vk::ComputePipeline pipeline;
  bool pending = false;    // the image is rebuilt at the next record()
  std::uint32_t side = 0;  // N of `image` (1 while empty)
  // The map's window and the time the far field shows (R.13b): world metres, seconds.
  std::array<double, 2> origin_m{};
  double size_m = 0.0;
  int resolution = 0;  // 0: no map, the analytic noise everywhere
  double time_s = 0.0;
};

}  // namespace ocean::render
