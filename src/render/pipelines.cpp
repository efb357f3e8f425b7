// The renderer's pipelines (dynamic rendering, no render pass objects): the sky and the tone map
// as fullscreen triangles, the ocean patches and skirt with the patch vertex/instance layout, and
// the same mesh as lines for the wireframe view. Push-constant layouts: shaders/render_shared.h.
#include <vector>

#include "object_pass.hpp"
#include "pipeline_desc.hpp"
#include "spirv.hpp"
#include "state.hpp"

namespace ocean::render {

Result<VkShaderModule> shader_module(Renderer::State& st, std::span<const std::uint32_t> words) {
  VkShaderModule m = VK_NULL_HANDLE;
  const VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                      .codeSize = words.size_bytes(),
                                      .pCode = words.data()};
  if (Status s = vk::check(vkCreateShaderModule(st.ctx->device, &info, nullptr, &m),
                           "vkCreateShaderModule");
      !s.ok())
    return s;
  st.modules.push_back(m);
  return m;
}

Result<VkPipeline> make_pipeline(const vk::Context& ctx, const PipelineDesc& d) {
  const VkPipelineShaderStageCreateInfo stages[] = {
      {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
       .stage = VK_SHADER_STAGE_VERTEX_BIT,
       .module = d.vert,
       .pName = "main"},
      {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
       .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
       .module = d.frag,
       .pName = "main"},
      {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
       .stage = VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
       .module = d.tesc,
       .pName = "main"},
      {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
       .stage = VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT,
       .module = d.tese,
       .pName = "main"}};
  const bool tessellated = d.tesc != VK_NULL_HANDLE;
  const VkPipelineTessellationStateCreateInfo tessellation{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO, .patchControlPoints = 1};
  const VkVertexInputBindingDescription bindings[] = {
      {0, 2 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX},
      {1, sizeof(lod::PatchInstance), VK_VERTEX_INPUT_RATE_INSTANCE}};
  const VkVertexInputAttributeDescription attributes[] = {
      {0, 0, VK_FORMAT_R32G32_SFLOAT, 0},
      {1, 1, VK_FORMAT_R32G32B32_SFLOAT, 0},
      {2, 1, VK_FORMAT_R8G8B8A8_UINT, offsetof(lod::PatchInstance, grid_x)}};
  const VkPipelineVertexInputStateCreateInfo input{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
      .vertexBindingDescriptionCount = d.mesh_input ? 2u : 0u,
      .pVertexBindingDescriptions = bindings,
      .vertexAttributeDescriptionCount = d.mesh_input ? 3u : 0u,
      .pVertexAttributeDescriptions = attributes};
  const VkPipelineVertexInputStateCreateInfo* vertex_input =
      d.vertex_input != nullptr ? d.vertex_input : &input;
  const VkPipelineInputAssemblyStateCreateInfo assembly{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
      .topology =
          tessellated ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
  const VkPipelineViewportStateCreateInfo viewport{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
      .viewportCount = 1,
      .scissorCount = 1};
  const VkPipelineRasterizationStateCreateInfo raster{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
      .polygonMode = d.lines ? VK_POLYGON_MODE_LINE : VK_POLYGON_MODE_FILL,
      .cullMode = VK_CULL_MODE_NONE,
      .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
      .lineWidth = 1.0f};
  const VkPipelineMultisampleStateCreateInfo multisample{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
      .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
  const VkPipelineDepthStencilStateCreateInfo depth{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
      .depthTestEnable = d.depth_test ? VK_TRUE : VK_FALSE,
      .depthWriteEnable = d.depth_test ? VK_TRUE : VK_FALSE,
      .depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL};
  const VkPipelineColorBlendAttachmentState blend_attachment{
      .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                        VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT};
  const VkPipelineColorBlendStateCreateInfo blend{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
      .attachmentCount = 1,
      .pAttachments = &blend_attachment};
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  const VkPipelineDynamicStateCreateInfo dynamic{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
      .dynamicStateCount = 2,
      .pDynamicStates = dynamic_states};
  const VkPipelineRenderingCreateInfo rendering{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
      .viewMask = d.view_mask,
      .colorAttachmentCount = 1,
      .pColorAttachmentFormats = &d.colour,
      .depthAttachmentFormat = d.depth ? kDepthFormat : VK_FORMAT_UNDEFINED};
  const VkGraphicsPipelineCreateInfo info{
      .sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
      .pNext = &rendering,
      .stageCount = tessellated ? 4u : 2u,
      .pStages = stages,
      .pVertexInputState = vertex_input,
      .pInputAssemblyState = &assembly,
      .pTessellationState = tessellated ? &tessellation : nullptr,
      .pViewportState = &viewport,
      .pRasterizationState = &raster,
      .pMultisampleState = &multisample,
      .pDepthStencilState = d.depth ? &depth : nullptr,
      .pColorBlendState = &blend,
      .pDynamicState = &dynamic,
      .layout = d.layout};
  VkPipeline p = VK_NULL_HANDLE;
  if (Status s =
          vk::check(vkCreateGraphicsPipelines(ctx.device, VK_NULL_HANDLE, 1, &info, nullptr, &p),
                    "vkCreateGraphicsPipelines");
      !s.ok())
    return s;
  return p;
}

Status create_pipelines(Renderer::State& st) {
  const vk::Context& ctx = *st.ctx;
  // The fragment stage's range, and the tessellation stages' after it where the device has them.
  const VkPushConstantRange scene_push[] = {
      {VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(shader::SkyPush)}, tessellation_push_range()};
  const VkPipelineLayoutCreateInfo scene_layout{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
      .setLayoutCount = 1,
      .pSetLayouts = &st.scene_layout,
      .pushConstantRangeCount = ctx.tessellation ? 2u : 1u,
      .pPushConstantRanges = scene_push};
  if (Status s = vk::check(
          vkCreatePipelineLayout(ctx.device, &scene_layout, nullptr, &st.scene_pipeline_layout),
          "vkCreatePipelineLayout");
      !s.ok())
    return s;

  Result<VkShaderModule> sky_vert = shader_module(st, spirv::sky_vert());
  Result<VkShaderModule> sky_frag = shader_module(st, spirv::sky_frag());
  Result<VkShaderModule> ocean_vert = shader_module(st, spirv::ocean_vert());
  Result<VkShaderModule> ocean_frag = shader_module(st, spirv::ocean_frag());
  Result<VkShaderModule> wire_frag = shader_module(st, spirv::wire_frag());
  for (const auto* m : {&sky_vert, &sky_frag, &ocean_vert, &ocean_frag, &wire_frag})
    if (!m->ok()) return m->status();

  Result<VkPipeline> sky = make_pipeline(ctx, {.vert = sky_vert.value(),
                                               .frag = sky_frag.value(),
                                               .layout = st.scene_pipeline_layout,
                                               .depth_test = false});
  if (!sky.ok()) return sky.status();
  st.sky = sky.value();
  Result<VkPipeline> ocean = make_pipeline(ctx, {.vert = ocean_vert.value(),
                                                 .frag = ocean_frag.value(),
                                                 .layout = st.scene_pipeline_layout,
                                                 .mesh_input = true});
  if (!ocean.ok()) return ocean.status();
  st.ocean = ocean.value();
  if (ctx.wireframe) {
    Result<VkPipeline> wire = make_pipeline(ctx, {.vert = ocean_vert.value(),
                                                  .frag = wire_frag.value(),
                                                  .layout = st.scene_pipeline_layout,
                                                  .mesh_input = true,
                                                  .lines = true});
    if (!wire.ok()) return wire.status();
    st.wire = wire.value();
  }
  return {};
}

Status make_fullscreen(Renderer::State& st, const FullscreenDesc& d, FullscreenObjects& out,
                       std::span<VkDescriptorSet> sets) {
  const VkDevice device = st.ctx->device;
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const std::uint32_t b : d.samplers)
    bindings.push_back(
        {b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
  const VkDescriptorSetLayoutCreateInfo set_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = static_cast<std::uint32_t>(bindings.size()),
      .pBindings = bindings.data()};
  if (Status s = vk::check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &out.set_layout),
                           "vkCreateDescriptorSetLayout");
      !s.ok())
    return s;
  const auto set_count = static_cast<std::uint32_t>(sets.size());
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                  set_count * static_cast<std::uint32_t>(bindings.size())};
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .maxSets = set_count,
                                             .poolSizeCount = 1,
                                             .pPoolSizes = &size};
  if (Status s = vk::check(vkCreateDescriptorPool(device, &pool_info, nullptr, &out.pool),
                           "vkCreateDescriptorPool");
      !s.ok())
    return s;
  const std::vector<VkDescriptorSetLayout> layouts(sets.size(), out.set_layout);
  const VkDescriptorSetAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                          .descriptorPool = out.pool,
                                          .descriptorSetCount = set_count,
                                          .pSetLayouts = layouts.data()};
  if (Status s = vk::check(vkAllocateDescriptorSets(device, &alloc, sets.data()),
                           "vkAllocateDescriptorSets");
      !s.ok())
    return s;
  const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, d.push_bytes};
  const VkPipelineLayoutCreateInfo layout_info{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
      .setLayoutCount = 1,
      .pSetLayouts = &out.set_layout,
      .pushConstantRangeCount = d.push_bytes > 0 ? 1u : 0u,
      .pPushConstantRanges = &push};
  if (Status s = vk::check(vkCreatePipelineLayout(device, &layout_info, nullptr, &out.layout),
                           "vkCreatePipelineLayout");
      !s.ok())
    return s;
  Result<VkShaderModule> vert = shader_module(st, spirv::sky_vert());  // the fullscreen triangle
  if (!vert.ok()) return vert.status();
  Result<VkShaderModule> frag = shader_module(st, d.frag);
  if (!frag.ok()) return frag.status();
  Result<VkPipeline> made = make_pipeline(*st.ctx, {.vert = vert.value(),
                                                    .frag = frag.value(),
                                                    .layout = out.layout,
                                                    .colour = d.colour,
                                                    .depth = false,
                                                    .depth_test = false});
  if (!made.ok()) return made.status();
  out.pipeline = made.value();
  return {};
}

void destroy_fullscreen(VkDevice device, FullscreenObjects& objects) {
  if (objects.pipeline != VK_NULL_HANDLE) vkDestroyPipeline(device, objects.pipeline, nullptr);
  if (objects.layout != VK_NULL_HANDLE) vkDestroyPipelineLayout(device, objects.layout, nullptr);
  if (objects.pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(device, objects.pool, nullptr);
  if (objects.set_layout != VK_NULL_HANDLE)
    vkDestroyDescriptorSetLayout(device, objects.set_layout, nullptr);
  objects = {};
}

void draw_fullscreen(VkCommandBuffer cmd, const FullscreenDraw& d) {
  const VkRenderingAttachmentInfo out{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                      .imageView = d.target,
                                      .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                      .loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                      .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
  const VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                  .renderArea = {{0, 0}, {d.width, d.height}},
                                  .layerCount = 1,
                                  .colorAttachmentCount = 1,
                                  .pColorAttachments = &out};
  vkCmdBeginRendering(cmd, &rendering);
  const VkViewport straight{0.0f, 0.0f, static_cast<float>(d.width), static_cast<float>(d.height),
                            0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {d.width, d.height}};
  vkCmdSetViewport(cmd, 0, 1, &straight);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.layout, 0, 1, &d.set, 0, nullptr);
  vkCmdPushConstants(cmd, d.layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, d.push_bytes, d.push);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdEndRendering(cmd);
}

}  // namespace ocean::render
