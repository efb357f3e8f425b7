// The far field's noise map on the device (docs/rendering.md R.13a): its parameters (rewritten
// each frame), its output and read-back buffers, its own descriptor set and pipeline, and a
// command buffer that computes the map alone (what `ocean bench --overlap` times). The frame's
// command buffer (gpu_state.cpp) records the same dispatch beside the cascades' first stage.
#pragma once

#include <cstdint>

#include "ocean/vk.hpp"

namespace ocean::vk::detail {

struct FarNoisePass {
  const Context* ctx = nullptr;
  std::uint32_t resolution = 0;  ///< N; 0: no map, nothing created
  Buffer params;                 ///< noise::FarNoiseMapParams, mapped
  Buffer map, host;              ///< float3 per texel: written by the kernel, read back
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  ComputePipeline pipeline;
  Commands alone;  ///< the map alone, pre-recorded

  FarNoisePass() = default;
  FarNoisePass(const FarNoisePass&) = delete;
  FarNoisePass& operator=(const FarNoisePass&) = delete;
  ~FarNoisePass();
};

/// Creates every object of an N×N map and records `alone`; N = 0 creates nothing.
Status create_far_noise_pass(FarNoisePass& pass, const Context& ctx, std::uint32_t resolution);
/// Records the map's dispatch (binds its own pipeline and set: rebind others afterwards).
void record_far_noise(const FarNoisePass& pass, VkCommandBuffer cmd);
/// Records the copy of the map into its read-back buffer (after a compute → transfer barrier).
void record_far_noise_copy(const FarNoisePass& pass, VkCommandBuffer cmd);

}  // namespace ocean::vk::detail
