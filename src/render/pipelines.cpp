// The renderer's pipelines (dynamic rendering, no render pass objects): the sky and the tone map
// as fullscreen triangles, the ocean patches and skirt with the patch vertex/instance layout, and
// the same mesh as lines for the wireframe view. Push-constant layouts: shaders/render_shared.h.
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

}  // namespace ocean::render
