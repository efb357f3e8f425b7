// What a graphics pipeline of the renderer is made from (src/render, private): shaders, layout,
// attachments, depth, and the vertex input — the patch layout, none (fullscreen passes) or one
// of the caller's (the object pass). pipelines.cpp builds them all. It needs nothing of the
// state's definition (state.hpp): a pass's own header may build its pipelines with it.
#pragma once

#include <span>

#include "formats.hpp"
#include "ocean/render.hpp"

namespace ocean::render {

struct PipelineDesc {
  VkShaderModule vert = VK_NULL_HANDLE, frag = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkFormat colour = kHdrFormat;
  bool depth = true;        // depth attachment present
  bool depth_test = true;   // test and write
  bool mesh_input = false;  // the patch vertex/instance layout
  bool lines = false;
  // Another vertex input (overrides mesh_input); must outlive make_pipeline.
  const VkPipelineVertexInputStateCreateInfo* vertex_input = nullptr;
  std::uint32_t view_mask = 0;  // multiview: the views drawn at once (stereo: 0b11)
  // Tessellation stages (both or neither): patches of one control point (tessellation.cpp).
  VkShaderModule tesc = VK_NULL_HANDLE, tese = VK_NULL_HANDLE;
};

// A shader module owned by the state (destroyed with it).
Result<VkShaderModule> shader_module(Renderer::State& st, std::span<const std::uint32_t> words);
Result<VkPipeline> make_pipeline(const vk::Context& ctx, const PipelineDesc& d);
/// A sampler: linear or nearest, with or without linear mips, repeating or clamped (v clamped
/// unless repeat_v_too), anisotropic above 1 (descriptors.cpp).
Result<VkSampler> make_sampler(const vk::Context& ctx, bool linear, bool mips, bool repeat,
                               float anisotropy, bool repeat_v_too = true);

}  // namespace ocean::render
