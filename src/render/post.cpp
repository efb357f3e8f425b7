// The tone map (post.hpp): the HDR image through shaders/tonemap.frag into the sRGB target, one
// fullscreen triangle with the exposure pushed (shaders/render_shared.h's TonemapPush).
#include "post.hpp"

#include "pipeline_desc.hpp"
#include "spirv.hpp"
#include "state.hpp"

namespace ocean::render {

Status PostPass::create(Renderer::State& st) {
  const vk::Context& ctx = *st.ctx;
  const VkDescriptorSetLayoutBinding binding{OCEAN_RENDER_BINDING_HDR,
                                             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                             VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  const VkDescriptorSetLayoutCreateInfo set_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = 1,
      .pBindings = &binding};
  if (Status s = vk::check(vkCreateDescriptorSetLayout(ctx.device, &set_info, nullptr, &set_layout),
                           "vkCreateDescriptorSetLayout");
      !s.ok())
    return s;
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .maxSets = 1,
                                             .poolSizeCount = 1,
                                             .pPoolSizes = &size};
  if (Status s = vk::check(vkCreateDescriptorPool(ctx.device, &pool_info, nullptr, &pool),
                           "vkCreateDescriptorPool");
      !s.ok())
    return s;
  const VkDescriptorSetAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                          .descriptorPool = pool,
                                          .descriptorSetCount = 1,
                                          .pSetLayouts = &set_layout};
  if (Status s =
          vk::check(vkAllocateDescriptorSets(ctx.device, &alloc, &set), "vkAllocateDescriptorSets");
      !s.ok())
    return s;
  const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(shader::TonemapPush)};
  const VkPipelineLayoutCreateInfo layout_info{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
      .setLayoutCount = 1,
      .pSetLayouts = &set_layout,
      .pushConstantRangeCount = 1,
      .pPushConstantRanges = &push};
  if (Status s = vk::check(vkCreatePipelineLayout(ctx.device, &layout_info, nullptr, &layout),
                           "vkCreatePipelineLayout");
      !s.ok())
    return s;
  Result<VkShaderModule> vert = shader_module(st, spirv::sky_vert());  // the fullscreen triangle
  if (!vert.ok()) return vert.status();
  Result<VkShaderModule> frag = shader_module(st, spirv::tonemap_frag());
  if (!frag.ok()) return frag.status();
  Result<VkPipeline> made = make_pipeline(ctx, {.vert = vert.value(),
                                                .frag = frag.value(),
                                                .layout = layout,
                                                .colour = kSrgbFormat,
                                                .depth = false,
                                                .depth_test = false});
  if (!made.ok()) return made.status();
  pipeline = made.value();
  return {};
}

void PostPass::destroy(Renderer::State& st) {
  const VkDevice d = st.ctx->device;
  if (pipeline != VK_NULL_HANDLE) vkDestroyPipeline(d, pipeline, nullptr);
  if (layout != VK_NULL_HANDLE) vkDestroyPipelineLayout(d, layout, nullptr);
  if (pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(d, pool, nullptr);
  if (set_layout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(d, set_layout, nullptr);
}

Status PostPass::resize(Renderer::State& st) {
  write_rendered_image(st, set, OCEAN_RENDER_BINDING_HDR, st.hdr.view);
  return {};
}

void PostPass::record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame) {
  const std::uint32_t w = st.hdr.width, h = st.hdr.height;
  vk::image_barrier(cmd, st.srgb.image, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  const VkRenderingAttachmentInfo out{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                      .imageView = st.srgb.view,
                                      .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                      .loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                      .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
  const VkRenderingInfo tonemap{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                .renderArea = {{0, 0}, {w, h}},
                                .layerCount = 1,
                                .colorAttachmentCount = 1,
                                .pColorAttachments = &out};
  vkCmdBeginRendering(cmd, &tonemap);
  const VkViewport straight{0.0f, 0.0f, static_cast<float>(w), static_cast<float>(h), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {w, h}};
  vkCmdSetViewport(cmd, 0, 1, &straight);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
  const shader::TonemapPush push{static_cast<float>(frame.view.shading.exposure)};
  vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push), &push);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  ++frame.stats.draw_calls;
  vkCmdEndRendering(cmd);
  vk::image_barrier(cmd, st.srgb.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_READ_BIT);
}

}  // namespace ocean::render
