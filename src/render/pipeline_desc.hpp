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

// The Vulkan objects of a full-screen pass (pipelines.cpp): a set layout of combined image
// samplers read by the fragment shader, a pool of its own for the pass's sets, a pipeline layout
// with fragment push constants, and the pipeline: the sky's full-screen triangle
// (shaders/sky.vert) and the pass's fragment shader into one colour target, no depth.
struct FullscreenObjects {
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
};
struct FullscreenDesc {
  std::span<const std::uint32_t> frag;      // the fragment shader's SPIR-V
  VkFormat colour = kHdrFormat;             // the target's format
  std::span<const std::uint32_t> samplers;  // the combined image samplers' binding numbers
  std::uint32_t push_bytes = 0;             // fragment push constants
};
// Makes the objects, and sets.size() sets of the layout into `sets`.
Status make_fullscreen(Renderer::State& st, const FullscreenDesc& d, FullscreenObjects& out,
                       std::span<VkDescriptorSet> sets);
// Destroys what make_fullscreen made (the sets go with the pool); null handles are skipped.
void destroy_fullscreen(VkDevice device, FullscreenObjects& objects);

// A full-screen pass: `pipeline` (the sky's full-screen triangle, one set, fragment push
// constants) drawn once into `target`, width × height, COLOR_ATTACHMENT_OPTIMAL, its old contents
// not kept (pipelines.cpp).
struct FullscreenDraw {
  VkImageView target = VK_NULL_HANDLE;
  std::uint32_t width = 0, height = 0;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkDescriptorSet set = VK_NULL_HANDLE;
  const void* push = nullptr;
  std::uint32_t push_bytes = 0;
};
void draw_fullscreen(VkCommandBuffer cmd, const FullscreenDraw& d);

}  // namespace ocean::render
