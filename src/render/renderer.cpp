// The Vulkan ocean renderer (ocean/render.hpp): targets, pipelines, the LOD mesh's buffers, the
// per-frame uniforms and the recorded frame. Shaders: shaders/ocean.*, sky.*, tonemap.frag,
// wire.frag; equations R.n in docs/rendering.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <string>

#include "ocean/half.hpp"
#include "ocean/render.hpp"
#include "spirv.hpp"

namespace ocean::render {

namespace {

constexpr int kMaxCascades = 8;
constexpr std::uint8_t kSkirtLevel = 255;
constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kSrgbFormat = VK_FORMAT_R8G8B8A8_SRGB;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr int kMaxTargetSize = 16384;

// std140 mirror of FrameUniforms in shaders/render_common.glsl.
struct FrameUniforms {
  float view_proj[16];
  float camera_pos[4];
  float sun_dir[4];
  float sun_ground[4];
  float sky_ambient[4];
  float water_colour[4];
  float params[4];
  float grid[4];
  float lod[4];
  float sky[4];
  float cascades[kMaxCascades][4];
};

struct TonemapPush {
  float exposure;
};

// Inverse of a 4×4 column-major matrix by cofactors (double precision).
std::array<double, 16> inverse(const std::array<double, 16>& m) {
  std::array<double, 16> inv{};
  inv[0] = m[5] * m[10] * m[15] - m[5] * m[11] * m[14] - m[9] * m[6] * m[15] + m[9] * m[7] * m[14] +
           m[13] * m[6] * m[11] - m[13] * m[7] * m[10];
  inv[4] = -m[4] * m[10] * m[15] + m[4] * m[11] * m[14] + m[8] * m[6] * m[15] -
           m[8] * m[7] * m[14] - m[12] * m[6] * m[11] + m[12] * m[7] * m[10];
  inv[8] = m[4] * m[9] * m[15] - m[4] * m[11] * m[13] - m[8] * m[5] * m[15] + m[8] * m[7] * m[13] +
           m[12] * m[5] * m[11] - m[12] * m[7] * m[9];
  inv[12] = -m[4] * m[9] * m[14] + m[4] * m[10] * m[13] + m[8] * m[5] * m[14] -
            m[8] * m[6] * m[13] - m[12] * m[5] * m[10] + m[12] * m[6] * m[9];
  inv[1] = -m[1] * m[10] * m[15] + m[1] * m[11] * m[14] + m[9] * m[2] * m[15] -
           m[9] * m[3] * m[14] - m[13] * m[2] * m[11] + m[13] * m[3] * m[10];
  inv[5] = m[0] * m[10] * m[15] - m[0] * m[11] * m[14] - m[8] * m[2] * m[15] + m[8] * m[3] * m[14] +
           m[12] * m[2] * m[11] - m[12] * m[3] * m[10];
  inv[9] = -m[0] * m[9] * m[15] + m[0] * m[11] * m[13] + m[8] * m[1] * m[15] - m[8] * m[3] * m[13] -
           m[12] * m[1] * m[11] + m[12] * m[3] * m[9];
  inv[13] = m[0] * m[9] * m[14] - m[0] * m[10] * m[13] - m[8] * m[1] * m[14] + m[8] * m[2] * m[13] +
            m[12] * m[1] * m[10] - m[12] * m[2] * m[9];
  inv[2] = m[1] * m[6] * m[15] - m[1] * m[7] * m[14] - m[5] * m[2] * m[15] + m[5] * m[3] * m[14] +
           m[13] * m[2] * m[7] - m[13] * m[3] * m[6];
  inv[6] = -m[0] * m[6] * m[15] + m[0] * m[7] * m[14] + m[4] * m[2] * m[15] - m[4] * m[3] * m[14] -
           m[12] * m[2] * m[7] + m[12] * m[3] * m[6];
  inv[10] = m[0] * m[5] * m[15] - m[0] * m[7] * m[13] - m[4] * m[1] * m[15] + m[4] * m[3] * m[13] +
            m[12] * m[1] * m[7] - m[12] * m[3] * m[5];
  inv[14] = -m[0] * m[5] * m[14] + m[0] * m[6] * m[13] + m[4] * m[1] * m[14] - m[4] * m[2] * m[13] -
            m[12] * m[1] * m[6] + m[12] * m[2] * m[5];
  inv[3] = -m[1] * m[6] * m[11] + m[1] * m[7] * m[10] + m[5] * m[2] * m[11] - m[5] * m[3] * m[10] -
           m[9] * m[2] * m[7] + m[9] * m[3] * m[6];
  inv[7] = m[0] * m[6] * m[11] - m[0] * m[7] * m[10] - m[4] * m[2] * m[11] + m[4] * m[3] * m[10] +
           m[8] * m[2] * m[7] - m[8] * m[3] * m[6];
  inv[11] = -m[0] * m[5] * m[11] + m[0] * m[7] * m[9] + m[4] * m[1] * m[11] - m[4] * m[3] * m[9] -
            m[8] * m[1] * m[7] + m[8] * m[3] * m[5];
  inv[15] = m[0] * m[5] * m[10] - m[0] * m[6] * m[9] - m[4] * m[1] * m[10] + m[4] * m[2] * m[9] +
            m[8] * m[1] * m[6] - m[8] * m[2] * m[5];
  const double det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
  for (double& v : inv) v /= det;
  return inv;
}

}  // namespace

// ---- parameters ---------------------------------------------------------------------------------

Status validate(const ShadingParams& p) {
  const std::pair<std::string_view, std::array<double, 3>> checks[] = {
      {"sun_azimuth_deg", {p.sun_azimuth_deg, -360.0, 360.0}},
      {"sun_elevation_deg", {p.sun_elevation_deg, -89.9, 90.0}},
      {"sun_irradiance", {p.sun_irradiance, 1e-6, 1e6}},
      {"sky_brightness", {p.sky_brightness, 0.0, 1e3}},
      {"aerosol", {p.aerosol, 0.0, 100.0}},
      {"aerosol_g", {p.aerosol_g, 0.0, 0.99}},
      {"water_colour[0]", {p.water_colour[0], 0.0, 1.0}},
      {"water_colour[1]", {p.water_colour[1], 0.0, 1.0}},
      {"water_colour[2]", {p.water_colour[2], 0.0, 1.0}},
      {"crest_scatter", {p.crest_scatter, 0.0, 100.0}},
      {"foam_brightness", {p.foam_brightness, 0.0, 100.0}},
      {"roughness", {p.roughness, 1e-3, 1.0}},
      {"fog_density_per_m", {p.fog_density_per_m, 0.0, 1.0}},
      {"exposure", {p.exposure, 1e-6, 1e6}},
  };
  for (const auto& [name, c] : checks) {
    if (Status s = require_in_range(name, c[0], c[1], c[2]); !s.ok()) return s;
  }
  return {};
}

std::string_view to_string(DebugView view) {
  switch (view) {
    case DebugView::shaded: return "shaded";
    case DebugView::lod_colours: return "lod";
    case DebugView::wireframe: return "wireframe";
  }
  return "shaded";
}

Result<DebugView> parse_debug_view(std::string_view name) {
  for (DebugView v : {DebugView::shaded, DebugView::lod_colours, DebugView::wireframe}) {
    if (name == to_string(v)) return v;
  }
  return invalid_argument("view = " + std::string(name) +
                          " is not a view: must be shaded, lod or wireframe");
}

Status validate(const View& view) {
  if (Status s = lod::validate(view.camera); !s.ok()) return s;
  if (Status s = lod::validate(view.quality); !s.ok()) return s;
  if (Status s = require_in_range("ocean_size_m", view.ocean_size_m, lod::kMinOceanSize_m,
                                  lod::kMaxOceanSize_m);
      !s.ok())
    return s;
  if (!std::isfinite(view.skirt_half_extent_m))
    return invalid_argument("skirt_half_extent_m must be finite");
  if (view.skirt_half_extent_m > 0.0 && view.skirt_half_extent_m <= 0.5 * view.ocean_size_m)
    return invalid_argument("skirt_half_extent_m = " + std::to_string(view.skirt_half_extent_m) +
                            " must exceed half the ocean size");
  return validate(view.shading);
}

// ---- state --------------------------------------------------------------------------------------

struct Renderer::State {
  const vk::Context* ctx = nullptr;
  vk::Commands commands;
  // Targets.
  vk::Image2D hdr, depth, srgb;
  vk::Buffer readback;  // large enough for the HDR image (8 bytes per pixel)
  // Simulation inputs: own images (upload path) or borrowed ones (GPU path).
  vk::Image displacement, normal_foam;
  vk::Buffer staging;
  bool upload_pending = false;
  bool borrowed = false;
  VkImageView displacement_view = VK_NULL_HANDLE, normal_view = VK_NULL_HANDLE;
  std::uint32_t sim_size = 0, sim_layers = 0, sim_mips = 0;
  // Samplers, descriptors, pipelines.
  VkSampler displacement_sampler = VK_NULL_HANDLE, normal_sampler = VK_NULL_HANDLE,
            hdr_sampler = VK_NULL_HANDLE, lut_sampler = VK_NULL_HANDLE;
  // The sky-view table (R.1–R.4) and what it was computed for.
  vk::Image2D sky_lut;
  vk::Buffer lut_staging;
  bool lut_pending = false;
  std::optional<ShadingParams> lut_params;  // what the table holds; none before the first draw
  std::array<double, 3> sun_ground{}, sky_ambient{};
  VkDescriptorSetLayout scene_layout = VK_NULL_HANDLE, tonemap_layout = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkDescriptorSet scene_set = VK_NULL_HANDLE, tonemap_set = VK_NULL_HANDLE;
  VkPipelineLayout scene_pipeline_layout = VK_NULL_HANDLE, tonemap_pipeline_layout = VK_NULL_HANDLE;
  VkPipeline sky = VK_NULL_HANDLE, ocean = VK_NULL_HANDLE, wire = VK_NULL_HANDLE,
             tonemap = VK_NULL_HANDLE;
  std::vector<VkShaderModule> modules;
  vk::Buffer uniforms;
  // Geometry.
  int vertices = 0;                    // V of the patch mesh now built
  vk::Buffer patch_vertices, indices;  // static
  std::array<std::uint32_t, lod::kConfigurations> index_first{}, index_count{};
  std::uint32_t skirt_first = 0, skirt_count = 0;
  vk::Buffer instances, skirt_vertices;  // per frame, host-visible
  lod::LodSelection selection;
  lod::SkirtMesh skirt;
  double skirt_size = -1.0, skirt_extent = -1.0;
  vk::Timestamps timestamps;
  bool has_timestamps = false;
  // From configure().
  int cascades = 0;
  std::array<std::array<float, 4>, kMaxCascades> cascade_params{};
  double hs_m = 1.0;
  double choppiness = 1.0;

  ~State();
  void destroy_targets();
  void destroy_sim_images();
};

Renderer::State::~State() {
  if (ctx == nullptr) return;
  VkDevice d = ctx->device;
  vkDeviceWaitIdle(d);
  destroy_targets();
  destroy_sim_images();
  for (VkPipeline p : {sky, ocean, wire, tonemap})
    if (p != VK_NULL_HANDLE) vkDestroyPipeline(d, p, nullptr);
  for (VkShaderModule m : modules) vkDestroyShaderModule(d, m, nullptr);
  for (VkPipelineLayout l : {scene_pipeline_layout, tonemap_pipeline_layout})
    if (l != VK_NULL_HANDLE) vkDestroyPipelineLayout(d, l, nullptr);
  if (pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(d, pool, nullptr);
  for (VkDescriptorSetLayout l : {scene_layout, tonemap_layout})
    if (l != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(d, l, nullptr);
  vk::destroy_image(*ctx, sky_lut);
  vk::destroy_buffer(*ctx, lut_staging);
  for (VkSampler s : {displacement_sampler, normal_sampler, hdr_sampler, lut_sampler})
    if (s != VK_NULL_HANDLE) vkDestroySampler(d, s, nullptr);
  for (vk::Buffer* b : {&uniforms, &patch_vertices, &indices, &instances, &skirt_vertices})
    vk::destroy_buffer(*ctx, *b);
  vk::destroy_timestamps(*ctx, timestamps);
  vk::destroy_commands(*ctx, commands);
}

void Renderer::State::destroy_targets() {
  vk::destroy_image(*ctx, hdr);
  vk::destroy_image(*ctx, depth);
  vk::destroy_image(*ctx, srgb);
  vk::destroy_buffer(*ctx, readback);
}

void Renderer::State::destroy_sim_images() {
  vk::destroy_image(*ctx, displacement);
  vk::destroy_image(*ctx, normal_foam);
  vk::destroy_buffer(*ctx, staging);
}

namespace {

Result<VkShaderModule> shader(Renderer::State& st, std::span<const std::uint32_t> words) {
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

struct PipelineDesc {
  VkShaderModule vert = VK_NULL_HANDLE, frag = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkFormat colour = kHdrFormat;
  bool depth = true;        // depth attachment present
  bool depth_test = true;   // test and write
  bool mesh_input = false;  // the patch vertex/instance layout
  bool lines = false;
};

Result<VkPipeline> make_pipeline(const vk::Context& ctx, const PipelineDesc& d) {
  const VkPipelineShaderStageCreateInfo stages[] = {
      {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
       .stage = VK_SHADER_STAGE_VERTEX_BIT,
       .module = d.vert,
       .pName = "main"},
      {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
       .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
       .module = d.frag,
       .pName = "main"}};
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
  const VkPipelineInputAssemblyStateCreateInfo assembly{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
      .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
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
      .colorAttachmentCount = 1,
      .pColorAttachmentFormats = &d.colour,
      .depthAttachmentFormat = d.depth ? kDepthFormat : VK_FORMAT_UNDEFINED};
  const VkGraphicsPipelineCreateInfo info{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                          .pNext = &rendering,
                                          .stageCount = 2,
                                          .pStages = stages,
                                          .pVertexInputState = &input,
                                          .pInputAssemblyState = &assembly,
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

Result<VkSampler> make_sampler(const vk::Context& ctx, bool linear, bool mips, bool repeat,
                               float anisotropy, bool repeat_v_too = true) {
  const VkSamplerAddressMode mode =
      repeat ? VK_SAMPLER_ADDRESS_MODE_REPEAT : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  const VkSamplerAddressMode mode_v = repeat_v_too ? mode : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  const VkFilter filter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  const VkSamplerCreateInfo info{
      .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
      .magFilter = filter,
      .minFilter = filter,
      .mipmapMode = mips ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST,
      .addressModeU = mode,
      .addressModeV = mode_v,
      .addressModeW = mode,
      .anisotropyEnable = anisotropy > 1.0f ? VK_TRUE : VK_FALSE,
      .maxAnisotropy = anisotropy,
      .minLod = 0.0f,
      .maxLod = mips ? VK_LOD_CLAMP_NONE : 0.0f};
  VkSampler s = VK_NULL_HANDLE;
  if (Status st = vk::check(vkCreateSampler(ctx.device, &info, nullptr, &s), "vkCreateSampler");
      !st.ok())
    return st;
  return s;
}

Status create_targets(Renderer::State& st, int width, int height) {
  const auto w = static_cast<std::uint32_t>(width), h = static_cast<std::uint32_t>(height);
  Result<vk::Image2D> hdr =
      vk::create_image_2d(*st.ctx, kHdrFormat, w, h,
                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                              VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  if (!hdr.ok()) return hdr.status();
  st.hdr = hdr.value();
  Result<vk::Image2D> depth =
      vk::create_image_2d(*st.ctx, kDepthFormat, w, h, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                          VK_IMAGE_ASPECT_DEPTH_BIT);
  if (!depth.ok()) return depth.status();
  st.depth = depth.value();
  Result<vk::Image2D> srgb =
      vk::create_image_2d(*st.ctx, kSrgbFormat, w, h,
                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  if (!srgb.ok()) return srgb.status();
  st.srgb = srgb.value();
  Result<vk::Buffer> rb =
      vk::create_buffer(*st.ctx, static_cast<VkDeviceSize>(w) * h * 8,
                        VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::readback);
  if (!rb.ok()) return rb.status();
  st.readback = rb.value();
  const VkDescriptorImageInfo image{st.hdr_sampler, st.hdr.view,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  const VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                   .dstSet = st.tonemap_set,
                                   .dstBinding = 0,
                                   .descriptorCount = 1,
                                   .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                   .pImageInfo = &image};
  vkUpdateDescriptorSets(st.ctx->device, 1, &write, 0, nullptr);
  return {};
}

void write_scene_images(Renderer::State& st) {
  const VkDescriptorBufferInfo ubo{st.uniforms.buffer, 0, sizeof(FrameUniforms)};
  const VkDescriptorImageInfo disp{st.displacement_sampler, st.displacement_view,
                                   VK_IMAGE_LAYOUT_GENERAL};
  const VkDescriptorImageInfo normal{st.normal_sampler, st.normal_view, VK_IMAGE_LAYOUT_GENERAL};
  const VkDescriptorImageInfo lut{st.lut_sampler, st.sky_lut.view, VK_IMAGE_LAYOUT_GENERAL};
  VkWriteDescriptorSet writes[4] = {{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                     .dstSet = st.scene_set,
                                     .dstBinding = 3,
                                     .descriptorCount = 1,
                                     .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                     .pImageInfo = &lut},
                                    {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                     .dstSet = st.scene_set,
                                     .dstBinding = 0,
                                     .descriptorCount = 1,
                                     .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                     .pBufferInfo = &ubo},
                                    {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                     .dstSet = st.scene_set,
                                     .dstBinding = 1,
                                     .descriptorCount = 1,
                                     .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                     .pImageInfo = &disp},
                                    {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                     .dstSet = st.scene_set,
                                     .dstBinding = 2,
                                     .descriptorCount = 1,
                                     .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                     .pImageInfo = &normal}};
  const std::uint32_t count = st.displacement_view != VK_NULL_HANDLE ? 4u : 2u;
  vkUpdateDescriptorSets(st.ctx->device, count, writes, 0, nullptr);
}

Status create_descriptors_and_pipelines(Renderer::State& st) {
  const vk::Context& ctx = *st.ctx;
  Result<VkSampler> s1 = make_sampler(ctx, true, false, true, 1.0f);
  if (!s1.ok()) return s1.status();
  st.displacement_sampler = s1.value();
  Result<VkSampler> s2 = make_sampler(ctx, true, true, true, ctx.max_anisotropy);
  if (!s2.ok()) return s2.status();
  st.normal_sampler = s2.value();
  Result<VkSampler> s3 = make_sampler(ctx, false, false, false, 1.0f);
  if (!s3.ok()) return s3.status();
  st.hdr_sampler = s3.value();
  Result<VkSampler> s4 = make_sampler(ctx, true, false, true, 1.0f, false);
  if (!s4.ok()) return s4.status();
  st.lut_sampler = s4.value();

  const VkShaderStageFlags both = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  const VkDescriptorSetLayoutBinding scene_bindings[] = {
      {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, both, nullptr},
      {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, both, nullptr},
      {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
  const VkDescriptorSetLayoutCreateInfo scene_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = 4,
      .pBindings = scene_bindings};
  if (Status s =
          vk::check(vkCreateDescriptorSetLayout(ctx.device, &scene_info, nullptr, &st.scene_layout),
                    "vkCreateDescriptorSetLayout");
      !s.ok())
    return s;
  const VkDescriptorSetLayoutBinding tonemap_binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                                     1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  const VkDescriptorSetLayoutCreateInfo tonemap_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = 1,
      .pBindings = &tonemap_binding};
  if (Status s = vk::check(
          vkCreateDescriptorSetLayout(ctx.device, &tonemap_info, nullptr, &st.tonemap_layout),
          "vkCreateDescriptorSetLayout");
      !s.ok())
    return s;
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                        {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4}};
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .maxSets = 2,
                                             .poolSizeCount = 2,
                                             .pPoolSizes = sizes};
  if (Status s = vk::check(vkCreateDescriptorPool(ctx.device, &pool_info, nullptr, &st.pool),
                           "vkCreateDescriptorPool");
      !s.ok())
    return s;
  const VkDescriptorSetLayout layouts[] = {st.scene_layout, st.tonemap_layout};
  VkDescriptorSet sets[2];
  const VkDescriptorSetAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                          .descriptorPool = st.pool,
                                          .descriptorSetCount = 2,
                                          .pSetLayouts = layouts};
  if (Status s =
          vk::check(vkAllocateDescriptorSets(ctx.device, &alloc, sets), "vkAllocateDescriptorSets");
      !s.ok())
    return s;
  st.scene_set = sets[0], st.tonemap_set = sets[1];

  const VkPushConstantRange scene_push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, 64};
  const VkPipelineLayoutCreateInfo scene_layout{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
      .setLayoutCount = 1,
      .pSetLayouts = &st.scene_layout,
      .pushConstantRangeCount = 1,
      .pPushConstantRanges = &scene_push};
  if (Status s = vk::check(
          vkCreatePipelineLayout(ctx.device, &scene_layout, nullptr, &st.scene_pipeline_layout),
          "vkCreatePipelineLayout");
      !s.ok())
    return s;
  const VkPushConstantRange tonemap_push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(TonemapPush)};
  const VkPipelineLayoutCreateInfo tonemap_layout{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
      .setLayoutCount = 1,
      .pSetLayouts = &st.tonemap_layout,
      .pushConstantRangeCount = 1,
      .pPushConstantRanges = &tonemap_push};
  if (Status s = vk::check(
          vkCreatePipelineLayout(ctx.device, &tonemap_layout, nullptr, &st.tonemap_pipeline_layout),
          "vkCreatePipelineLayout");
      !s.ok())
    return s;

  Result<VkShaderModule> sky_vert = shader(st, spirv::sky_vert());
  Result<VkShaderModule> sky_frag = shader(st, spirv::sky_frag());
  Result<VkShaderModule> ocean_vert = shader(st, spirv::ocean_vert());
  Result<VkShaderModule> ocean_frag = shader(st, spirv::ocean_frag());
  Result<VkShaderModule> wire_frag = shader(st, spirv::wire_frag());
  Result<VkShaderModule> tonemap_frag = shader(st, spirv::tonemap_frag());
  for (const auto* m : {&sky_vert, &sky_frag, &ocean_vert, &ocean_frag, &wire_frag, &tonemap_frag})
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
  Result<VkPipeline> tonemap = make_pipeline(ctx, {.vert = sky_vert.value(),
                                                   .frag = tonemap_frag.value(),
                                                   .layout = st.tonemap_pipeline_layout,
                                                   .colour = kSrgbFormat,
                                                   .depth = false,
                                                   .depth_test = false});
  if (!tonemap.ok()) return tonemap.status();
  st.tonemap = tonemap.value();
  return {};
}

// The patch mesh of V quads per side: vertices and the 16 index lists, plus the skirt's
// indices (4 rotated copies of its 4 triangles over 24 per-frame vertices).
Status build_patch_buffers(Renderer::State& st, int vertices) {
  Result<lod::PatchMeshes> meshes = lod::build_patch_meshes(vertices);
  if (!meshes.ok()) return meshes.status();
  Result<lod::SkirtMesh> skirt = lod::build_skirt(lod::kMinOceanSize_m);
  if (!skirt.ok()) return skirt.status();
  std::vector<std::uint16_t> all;
  for (int c = 0; c < lod::kConfigurations; ++c) {
    st.index_first[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(all.size());
    const auto& list = meshes.value().indices[static_cast<std::size_t>(c)];
    st.index_count[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(list.size());
    all.insert(all.end(), list.begin(), list.end());
  }
  st.skirt_first = static_cast<std::uint32_t>(all.size());
  for (std::uint16_t r = 0; r < 4; ++r) {
    for (std::uint16_t i : skirt.value().triangles)
      all.push_back(static_cast<std::uint16_t>(r * 6 + i));
  }
  st.skirt_count = static_cast<std::uint32_t>(all.size()) - st.skirt_first;
  vk::destroy_buffer(*st.ctx, st.patch_vertices);
  vk::destroy_buffer(*st.ctx, st.indices);
  const auto& pos = meshes.value().positions_xz;
  Result<vk::Buffer> vb = vk::create_static_buffer(
      *st.ctx, st.commands, std::as_bytes(std::span(pos)), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  if (!vb.ok()) return vb.status();
  st.patch_vertices = vb.value();
  Result<vk::Buffer> ib = vk::create_static_buffer(
      *st.ctx, st.commands, std::as_bytes(std::span(all)), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  if (!ib.ok()) return ib.status();
  st.indices = ib.value();
  st.vertices = vertices;
  return {};
}

}  // namespace

// ---- Renderer -----------------------------------------------------------------------------------

Result<std::unique_ptr<Renderer>> Renderer::make(std::shared_ptr<vk::Context> context,
                                                 const RendererParams& params) {
  if (context == nullptr) return invalid_argument("renderer: no Vulkan context");
  if (!context->graphics)
    return unsupported("renderer: the Vulkan context was created without a graphics queue");
  std::unique_ptr<Renderer> r(new Renderer());
  r->context_ = std::move(context);
  r->state_ = std::make_unique<State>();
  State& st = *r->state_;
  st.ctx = r->context_.get();
  Result<vk::Commands> commands = vk::create_commands(*st.ctx);
  if (!commands.ok()) return commands.status();
  st.commands = commands.value();
  if (Status s = create_descriptors_and_pipelines(st); !s.ok()) return s;
  Result<vk::Buffer> ubo = vk::create_buffer(
      *st.ctx, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::upload);
  if (!ubo.ok()) return ubo.status();
  st.uniforms = ubo.value();
  Result<vk::Image2D> lut =
      vk::create_image_2d(*st.ctx, VK_FORMAT_R32G32B32A32_SFLOAT, Sky::kLutWidth, Sky::kLutHeight,
                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  if (!lut.ok()) return lut.status();
  st.sky_lut = lut.value();
  Result<vk::Buffer> lut_staging =
      vk::create_buffer(*st.ctx, Sky::kLutWidth * Sky::kLutHeight * 4 * sizeof(float),
                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::upload);
  if (!lut_staging.ok()) return lut_staging.status();
  st.lut_staging = lut_staging.value();
  write_scene_images(st);
  // Instances: the most any selection can hold (W² at S = 8192) and the skirt's one.
  if (Status s = lod::reserve_selection(st.selection, lod::kMaxOceanSize_m); !s.ok()) return s;
  const int w = 1 << lod::max_level(lod::kMaxOceanSize_m);
  Result<vk::Buffer> inst =
      vk::create_buffer(*st.ctx, static_cast<VkDeviceSize>(w * w + 1) * sizeof(lod::PatchInstance),
                        VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vk::MemoryUse::upload);
  if (!inst.ok()) return inst.status();
  st.instances = inst.value();
  Result<vk::Buffer> skirt = vk::create_buffer(
      *st.ctx, 24 * 2 * sizeof(float), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vk::MemoryUse::upload);
  if (!skirt.ok()) return skirt.status();
  st.skirt_vertices = skirt.value();
  if (st.ctx->timestamps) {
    Result<vk::Timestamps> ts = vk::create_timestamps(*st.ctx, 2);
    if (ts.ok()) st.timestamps = ts.value(), st.has_timestamps = true;
  }
  if (Status s = r->resize(params.width, params.height); !s.ok()) return s;
  return r;
}

Renderer::~Renderer() = default;

Status Renderer::resize(int width, int height) {
  if (width < 1 || height < 1 || width > kMaxTargetSize || height > kMaxTargetSize)
    return invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) +
                            " must be between 1x1 and " + std::to_string(kMaxTargetSize) + "x" +
                            std::to_string(kMaxTargetSize));
  vkDeviceWaitIdle(state_->ctx->device);
  state_->destroy_targets();
  return create_targets(*state_, width, height);
}

int Renderer::width() const { return static_cast<int>(state_->hdr.width); }
int Renderer::height() const { return static_cast<int>(state_->hdr.height); }
VkImage Renderer::srgb_image() const { return state_->srgb.image; }
double Renderer::significant_wave_height_m() const { return state_->hs_m; }

Status Renderer::configure(const SimulationConfig& config) {
  if (Status s = ocean::validate(config); !s.ok()) return s;
  State& st = *state_;
  Result<SeaState> sea = SeaState::make(config.sea);
  if (!sea.ok()) return sea.status();
  st.hs_m = 4.0 * std::sqrt(std::max(sea.value().variance_m2(), 0.0));
  st.choppiness = config.choppiness;
  double peak_wavelength = 1e9;
  for (const WaveSystem& w : sea.value().systems()) {
    const double k = sea.value().dispersion().wavenumber(w.spectrum().peak_omega());
    if (k > 0.0) peak_wavelength = std::min(peak_wavelength, 2.0 * std::numbers::pi / k);
  }
  const std::vector<std::array<double, 2>> bands = cascade_bands(config);
  st.cascades = static_cast<int>(config.cascade_patch_sizes_m.size());
  const int n = config.resolution;
  for (int c = 0; c < st.cascades; ++c) {
    const double size = config.cascade_patch_sizes_m[static_cast<std::size_t>(c)];
    const double k_min = bands[static_cast<std::size_t>(c)][0];
    double wavelength = k_min > 0.0 ? 2.0 * std::numbers::pi / k_min : size;
    wavelength = std::min(wavelength, std::max(peak_wavelength, 4.0 * size / n));
    st.cascade_params[static_cast<std::size_t>(c)] = {
        static_cast<float>(size), static_cast<float>(n), static_cast<float>(wavelength),
        static_cast<float>(std::countr_zero(static_cast<unsigned>(n)))};
  }
  // Own images for the upload path.
  vkDeviceWaitIdle(st.ctx->device);
  st.destroy_sim_images();
  const auto size = static_cast<std::uint32_t>(n);
  const auto layers = static_cast<std::uint32_t>(st.cascades);
  const std::uint32_t mips = static_cast<std::uint32_t>(std::countr_zero(size)) + 1;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  Result<vk::Image> disp =
      vk::create_image_array(*st.ctx, VK_FORMAT_R16G16B16A16_SFLOAT, size, layers, 1, usage);
  if (!disp.ok()) return disp.status();
  st.displacement = disp.value();
  Result<vk::Image> normal =
      vk::create_image_array(*st.ctx, VK_FORMAT_R8G8B8A8_UNORM, size, layers, mips, usage);
  if (!normal.ok()) return normal.status();
  st.normal_foam = normal.value();
  const std::size_t bytes =
      layers * (static_cast<std::size_t>(size) * size * 8 + mip_chain_texels(n) * 4);
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

namespace {

void record_uploads(Renderer::State& st, VkCommandBuffer cmd) {
  // Staging → images (GENERAL); the first use transitions them from UNDEFINED.
  static_assert(sizeof(std::uint16_t) * 4 == 8);
  for (vk::Image* im : {&st.displacement, &st.normal_foam})
    vk::image_barrier(cmd, im->image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                      VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                      0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  const std::uint32_t n = st.sim_size;
  const VkDeviceSize texels = static_cast<VkDeviceSize>(n) * n;
  VkDeviceSize offset = 0;
  // ≤ 8 cascades × 12 mip levels (N ≤ 2048): on the stack, no allocation per frame.
  std::array<VkBufferImageCopy, kMaxCascades * 12> regions{};
  std::uint32_t count = 0;
  for (std::uint32_t c = 0; c < st.sim_layers; ++c) {
    regions[count++] = {.bufferOffset = offset,
                        .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, c, 1},
                        .imageExtent = {n, n, 1}};
    offset += texels * 8;
  }
  vkCmdCopyBufferToImage(cmd, st.staging.buffer, st.displacement.image, VK_IMAGE_LAYOUT_GENERAL,
                         count, regions.data());
  count = 0;
  for (std::uint32_t c = 0; c < st.sim_layers; ++c) {
    for (std::uint32_t m = 0; m < st.sim_mips; ++m) {
      const std::uint32_t s = n >> m;
      regions[count++] = {
          .bufferOffset = offset + mip_offset(static_cast<int>(n), static_cast<int>(m)) * 4,
          .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, m, c, 1},
          .imageExtent = {s, s, 1}};
    }
    offset += mip_chain_texels(static_cast<int>(n)) * 4;
  }
  vkCmdCopyBufferToImage(cmd, st.staging.buffer, st.normal_foam.image, VK_IMAGE_LAYOUT_GENERAL,
                         count, regions.data());
  vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
              VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
}

bool same_sky(const ShadingParams& a, const ShadingParams& b) {
  return a.sun_azimuth_deg == b.sun_azimuth_deg && a.sun_elevation_deg == b.sun_elevation_deg &&
         a.sun_irradiance == b.sun_irradiance && a.sky_brightness == b.sky_brightness &&
         a.aerosol == b.aerosol && a.aerosol_g == b.aerosol_g;
}

// Recomputes the sky-view table and the irradiances when the sky's parameters change.
void update_sky(Renderer::State& st, const ShadingParams& shading) {
  if (st.lut_params && same_sky(*st.lut_params, shading)) return;
  const Sky sky(shading);
  sky.fill_lut({static_cast<float*>(st.lut_staging.mapped),
                static_cast<std::size_t>(Sky::kLutWidth * Sky::kLutHeight * 4)});
  st.sun_ground = sky.sun_irradiance_ground();
  st.sky_ambient = sky.sky_irradiance_horizontal();
  st.lut_params = shading;
  st.lut_pending = true;
}

void fill_uniforms(const Renderer::State& st, const View& view, const lod::Mat4& vp,
                   const lod::LodSelection& sel, FrameUniforms& u) {
  for (int i = 0; i < 16; ++i)
    u.view_proj[i] = static_cast<float>(vp.m[static_cast<std::size_t>(i)]);
  const lod::Vec3 eye = view.camera.position_m;
  u.camera_pos[0] = static_cast<float>(eye.x), u.camera_pos[1] = static_cast<float>(eye.y);
  u.camera_pos[2] = static_cast<float>(eye.z);
  u.camera_pos[3] = static_cast<float>(view.camera.fov_y_rad);
  const ShadingParams& sh = view.shading;
  const std::array<double, 3> sun = sun_direction(sh.sun_azimuth_deg, sh.sun_elevation_deg);
  for (int i = 0; i < 3; ++i) u.sun_dir[i] = static_cast<float>(sun[static_cast<std::size_t>(i)]);
  u.sun_dir[3] = 0.0f;
  for (int i = 0; i < 3; ++i) {
    u.sun_ground[i] = static_cast<float>(st.sun_ground[static_cast<std::size_t>(i)]);
    u.sky_ambient[i] = static_cast<float>(st.sky_ambient[static_cast<std::size_t>(i)]);
  }
  for (int i = 0; i < 3; ++i)
    u.water_colour[i] = static_cast<float>(sh.water_colour[static_cast<std::size_t>(i)]);
  u.water_colour[3] = static_cast<float>(sh.crest_scatter);
  u.params[0] = static_cast<float>(sh.foam_brightness);
  u.params[1] = static_cast<float>(sh.roughness);
  u.params[2] = static_cast<float>(sh.fog_density_per_m);
  u.grid[0] = static_cast<float>(sel.grid_centre_x_m);
  u.grid[1] = static_cast<float>(sel.grid_centre_z_m);
  u.grid[2] = static_cast<float>(view.ocean_size_m);
  u.grid[3] = static_cast<float>(0.1 * view.ocean_size_m);  // border fade width (R.10)
  u.lod[0] = static_cast<float>(view.quality.lod_scale);
  u.lod[1] = static_cast<float>(view.quality.vertices);
  u.lod[2] = view.debug == DebugView::lod_colours ? 1.0f : 0.0f;
  u.lod[3] = static_cast<float>(st.displacement_view != VK_NULL_HANDLE ? st.cascades : 0);
  u.sky[0] = static_cast<float>(st.hs_m);
  for (int c = 0; c < kMaxCascades; ++c)
    for (int i = 0; i < 4; ++i)
      u.cascades[c][i] =
          st.cascade_params[static_cast<std::size_t>(c)][static_cast<std::size_t>(i)];
}

}  // namespace

Status Renderer::record(VkCommandBuffer cmd, const View& view) {
  if (Status s = validate(view); !s.ok()) return s;
  State& st = *state_;
  if (view.debug == DebugView::wireframe && st.wire == VK_NULL_HANDLE)
    return unsupported("wireframe view: the Vulkan device lacks fillModeNonSolid");
  if (Status s = prepare(view); !s.ok()) return s;  // a one-off submission of its own
  // LOD selection (seed 000 §5) with culling boxes that include the waves' reach.
  const auto t0 = std::chrono::steady_clock::now();
  lod::LodParams lp;
  lp.ocean_size_m = view.ocean_size_m;
  lp.quality = view.quality;
  lp.camera_position_m = view.camera.position_m;
  const lod::Mat4 vp = lod::view_projection(view.camera);  // culling and drawing share it
  lp.frustum = lod::frustum_from_view_projection(vp);
  lp.max_vertical_displacement_m = 1.2 * st.hs_m + 0.5;
  lp.max_horizontal_displacement_m = st.choppiness * st.hs_m;
  if (Status s = lod::select_patches(lp, st.selection); !s.ok()) return s;
  const lod::LodSelection& sel = st.selection;
  stats_.cpu_select_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  auto* inst = static_cast<lod::PatchInstance*>(st.instances.mapped);
  std::memcpy(inst, sel.instances.data(), sel.instances.size() * sizeof(lod::PatchInstance));
  const auto skirt_instance = static_cast<std::uint32_t>(sel.instances.size());
  inst[skirt_instance] = {
      .centre_x_m = 0.0f, .centre_z_m = 0.0f, .size_m = 1.0f, .level = kSkirtLevel};
  // Skirt vertices in world space around this frame's grid centre.
  if (st.skirt_size != view.ocean_size_m || st.skirt_extent != view.skirt_half_extent_m) {
    Result<lod::SkirtMesh> skirt = lod::build_skirt(view.ocean_size_m, view.skirt_half_extent_m);
    if (!skirt.ok()) return skirt.status();
    st.skirt = std::move(skirt).value();
    st.skirt_size = view.ocean_size_m, st.skirt_extent = view.skirt_half_extent_m;
  }
  auto* sv = static_cast<float*>(st.skirt_vertices.mapped);
  for (int r = 0; r < 4; ++r) {
    const auto [c, s] = st.skirt.rotations[static_cast<std::size_t>(r)];
    for (int i = 0; i < 6; ++i) {
      const float x = st.skirt.positions_xz[static_cast<std::size_t>(2 * i)];
      const float z = st.skirt.positions_xz[static_cast<std::size_t>(2 * i + 1)];
      sv[(r * 6 + i) * 2] = static_cast<float>(sel.grid_centre_x_m) + c * x + s * z;
      sv[(r * 6 + i) * 2 + 1] = static_cast<float>(sel.grid_centre_z_m) - s * x + c * z;
    }
  }
  update_sky(st, view.shading);
  FrameUniforms u{};
  fill_uniforms(st, view, vp, sel, u);
  std::memcpy(st.uniforms.mapped, &u, sizeof(u));
  const std::array<double, 16> inv = inverse(vp.m);
  float inv_vp[16];
  for (int i = 0; i < 16; ++i) inv_vp[i] = static_cast<float>(inv[static_cast<std::size_t>(i)]);

  if (st.has_timestamps) {
    vkCmdResetQueryPool(cmd, st.timestamps.pool, 0, 2);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, st.timestamps.pool, 0);
  }
  if (st.lut_pending) {
    vk::image_barrier(cmd, st.sky_lut.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {Sky::kLutWidth, Sky::kLutHeight, 1}};
    vkCmdCopyBufferToImage(cmd, st.lut_staging.buffer, st.sky_lut.image, VK_IMAGE_LAYOUT_GENERAL, 1,
                           &region);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
    st.lut_pending = false;
  }
  if (st.upload_pending) {
    record_uploads(st, cmd);
    st.upload_pending = false;
  } else if (st.borrowed) {  // the backend's compute writes → our sampling
    vk::barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  }
  // Host writes of this frame's uniforms and instances.
  vk::barrier(cmd, VK_PIPELINE_STAGE_HOST_BIT,
              VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);

  const std::uint32_t w = st.hdr.width, h = st.hdr.height;
  vk::image_barrier(
      cmd, st.hdr.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  vk::image_barrier(
      cmd, st.depth.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
      VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, 0,
      VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
      VK_IMAGE_ASPECT_DEPTH_BIT);
  const VkRenderingAttachmentInfo colour{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                         .imageView = st.hdr.view,
                                         .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                         .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                         .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                         .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 1.0f}}}};
  const VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                        .imageView = st.depth.view,
                                        .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                        .clearValue = {.depthStencil = {1.0f, 0}}};
  const VkRenderingInfo scene{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                              .renderArea = {{0, 0}, {w, h}},
                              .layerCount = 1,
                              .colorAttachmentCount = 1,
                              .pColorAttachments = &colour,
                              .pDepthAttachment = &depth};
  vkCmdBeginRendering(cmd, &scene);
  // Clip y is up (lod::perspective); a negative-height viewport puts +y at the top.
  const VkViewport flipped{
      0.0f, static_cast<float>(h), static_cast<float>(w), -static_cast<float>(h), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {w, h}};
  vkCmdSetViewport(cmd, 0, 1, &flipped);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, st.scene_pipeline_layout, 0, 1,
                          &st.scene_set, 0, nullptr);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, st.sky);
  vkCmdPushConstants(cmd, st.scene_pipeline_layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, 64, inv_vp);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  stats_ = {.cpu_select_ms = stats_.cpu_select_ms};
  stats_.draw_calls = 1;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                    view.debug == DebugView::wireframe ? st.wire : st.ocean);
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &st.patch_vertices.buffer, &zero);
  vkCmdBindVertexBuffers(cmd, 1, 1, &st.instances.buffer, &zero);
  vkCmdBindIndexBuffer(cmd, st.indices.buffer, 0, VK_INDEX_TYPE_UINT16);
  for (const lod::Batch& b : sel.batches) {  // ≤ 16 instanced draws (seed 000 eq. 70)
    vkCmdDrawIndexed(cmd, st.index_count[b.config], b.count, st.index_first[b.config], 0, b.first);
    ++stats_.draw_calls;
    stats_.patches += b.count;
    stats_.triangles += static_cast<std::uint64_t>(st.index_count[b.config] / 3) * b.count;
  }
  vkCmdBindVertexBuffers(cmd, 0, 1, &st.skirt_vertices.buffer, &zero);
  vkCmdDrawIndexed(cmd, st.skirt_count, 1, st.skirt_first, 0, skirt_instance);
  ++stats_.draw_calls;
  stats_.triangles += st.skirt_count / 3;
  stats_.patches_per_level = sel.patches_per_level;
  vkCmdEndRendering(cmd);

  // Tone map HDR → sRGB.
  vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_SHADER_READ_BIT);
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
  vkCmdSetViewport(cmd, 0, 1, &straight);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, st.tonemap);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, st.tonemap_pipeline_layout, 0, 1,
                          &st.tonemap_set, 0, nullptr);
  const TonemapPush push{static_cast<float>(view.shading.exposure)};
  vkCmdPushConstants(cmd, st.tonemap_pipeline_layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push),
                     &push);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  ++stats_.draw_calls;
  vkCmdEndRendering(cmd);
  vk::image_barrier(cmd, st.srgb.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_READ_BIT);
  if (st.has_timestamps)
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, st.timestamps.pool, 1);
  return {};
}

Status Renderer::prepare(const View& view) {
  State& st = *state_;
  if (view.quality.vertices == st.vertices) return {};
  if (Status s = lod::validate(view.quality); !s.ok()) return s;
  return build_patch_buffers(st, view.quality.vertices);
}

Result<double> Renderer::read_gpu_ms() {
  State& st = *state_;
  if (!st.has_timestamps) return 0.0;
  double ms[2];
  if (Status s = vk::read_timestamps_ms(*st.ctx, st.timestamps, ms); !s.ok()) return s;
  stats_.gpu_ms = ms[1];
  return ms[1];
}

Status Renderer::draw(const View& view) {
  State& st = *state_;
  // Mesh changes upload through the renderer's own command buffer: before recording into it.
  if (Status s = prepare(view); !s.ok()) return s;
  Status recorded;
  const Status run = vk::run_once(*st.ctx, st.commands,
                                  [&](VkCommandBuffer cmd) { recorded = record(cmd, view); });
  if (!recorded.ok()) return recorded;
  if (!run.ok()) return run;
  return read_gpu_ms().status();
}

Status Renderer::read_srgb(std::vector<std::uint8_t>& rgba) {
  State& st = *state_;
  const std::uint32_t w = st.srgb.width, h = st.srgb.height;
  const Status s = vk::run_once(*st.ctx, st.commands, [&](VkCommandBuffer cmd) {
    const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {w, h, 1}};
    vkCmdCopyImageToBuffer(cmd, st.srgb.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           st.readback.buffer, 1, &region);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
  });
  if (!s.ok()) return s;
  rgba.resize(static_cast<std::size_t>(w) * h * 4);
  std::memcpy(rgba.data(), st.readback.mapped, rgba.size());
  return {};
}

Status Renderer::read_hdr(std::vector<float>& rgba) {
  State& st = *state_;
  const std::uint32_t w = st.hdr.width, h = st.hdr.height;
  const Status s = vk::run_once(*st.ctx, st.commands, [&](VkCommandBuffer cmd) {
    vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                      0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {w, h, 1}};
    vkCmdCopyImageToBuffer(cmd, st.hdr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           st.readback.buffer, 1, &region);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
    vk::image_barrier(cmd, st.hdr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0);
  });
  if (!s.ok()) return s;
  const std::size_t n = static_cast<std::size_t>(w) * h * 4;
  rgba.resize(n);
  const auto* half = static_cast<const std::uint16_t*>(st.readback.mapped);
  for (std::size_t i = 0; i < n; ++i) rgba[i] = half_to_float(half[i]);
  return {};
}

}  // namespace ocean::render
