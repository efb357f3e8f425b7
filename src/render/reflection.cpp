// Planar reflections of the scene's objects in the water (docs/rendering.md R.53): the objects
// drawn once more, mirrored in the mean sea level y = 0, into a half-resolution target before the
// HDR pass; the water reads it where its reflected ray would meet them and keeps the sky's
// reflection elsewhere (coverage in alpha), both weighed by the same Fresnel term (R.6).
//
// A planar mirror rather than screen-space reflection: the objects' undersides and everything
// outside the picture that a wave reflects into it are there, and nothing depends on what the
// camera happens to see. The waves only distort the lookup (the reflected ray is followed to the
// water point's distance and mirrored back into the target), so reflections of objects far above
// steep waves are approximate; the sky's reflection stays exact.
#include <algorithm>
#include <cstdint>

#include "object_pass.hpp"
#include "state.hpp"

namespace ocean::render {

Status size_reflection(Renderer::State& st) {
  ObjectPass& op = pass<ObjectPass>(st);
  vk::destroy_image(*st.ctx, op.reflection);
  vk::destroy_image(*st.ctx, op.reflection_depth);
  // Half the picture's resolution while there are objects to reflect; 1×1 of nothing otherwise.
  const bool objects = !op.meshes.empty();
  const std::uint32_t w = objects ? (st.hdr.width + 1) / 2 : 1;
  const std::uint32_t h = objects ? (st.hdr.height + 1) / 2 : 1;
  // With a mip chain down to 1 × 1 (R.53b), filled after the objects are drawn.
  std::uint32_t mips = 1;
  while ((std::max(w, h) >> mips) > 0) ++mips;
  Result<vk::Image2D> colour = vk::create_image_2d(
      *st.ctx, kHdrFormat, w, h,
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
          VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
      VK_IMAGE_ASPECT_COLOR_BIT, 1, mips);
  if (!colour.ok()) return colour.status();
  op.reflection = colour.value();
  Result<vk::Image2D> depth =
      vk::create_image_2d(*st.ctx, kDepthFormat, w, h, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                          VK_IMAGE_ASPECT_DEPTH_BIT);
  if (!depth.ok()) return depth.status();
  op.reflection_depth = depth.value();
  write_scene_images(st);
  return {};
}

void record_reflection(Renderer::State& st, VkCommandBuffer cmd, const View& view,
                       RenderStats& stats) {
  const ObjectPass& op = pass<ObjectPass>(st);
  const std::uint32_t w = op.reflection.width, h = op.reflection.height;
  vk::image_barrier(cmd, op.reflection.image, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                    0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  vk::image_barrier(
      cmd, op.reflection_depth.image, VK_IMAGE_LAYOUT_UNDEFINED,
      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, 0,
      VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
      VK_IMAGE_ASPECT_DEPTH_BIT);
  const VkRenderingAttachmentInfo colour{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                         .imageView = op.reflection.mips > 1
                                                          ? op.reflection.level0_view
                                                          : op.reflection.view,
                                         .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                         .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                         .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                         .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 0.0f}}}};
  const VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                        .imageView = op.reflection_depth.view,
                                        .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                        .clearValue = {.depthStencil = {1.0f, 0}}};
  const VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                  .renderArea = {{0, 0}, {w, h}},
                                  .layerCount = 1,
                                  .colorAttachmentCount = 1,
                                  .pColorAttachments = &colour,
                                  .pDepthAttachment = &depth};
  vkCmdBeginRendering(cmd, &rendering);
  // The main pass's flipped viewport at this size: texel rows are the picture's rows, halved.
  const VkViewport flipped{
      0.0f, static_cast<float>(h), static_cast<float>(w), -static_cast<float>(h), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {w, h}};
  vkCmdSetViewport(cmd, 0, 1, &flipped);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  if (!op.meshes.empty() && view.object_reflections)
    record_objects(st, cmd, view, stats, VK_NULL_HANDLE, true);
  vkCmdEndRendering(cmd);
  vk::generate_mips(cmd, op.reflection);  // every level ready for the fragment shaders
}

Status ObjectPass::resize(Renderer::State& st) { return size_reflection(st); }

void ObjectPass::scene_images(const Renderer::State&, SceneImages& images) const {
  images.add(OCEAN_RENDER_BINDING_REFLECTION, VK_SHADER_STAGE_FRAGMENT_BIT,
             {reflection_sampler, reflection.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
}

void ObjectPass::release_targets(Renderer::State& st) {
  vk::destroy_image(*st.ctx, reflection);
  vk::destroy_image(*st.ctx, reflection_depth);
}

}  // namespace ocean::render
