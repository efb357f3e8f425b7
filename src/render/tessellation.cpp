// The tessellated mesh (docs/rendering.md R.40–R.42; VR-GIS FFT+Perlin, §II, Algorithm 1): a base
// grid of quads over the ocean square, culled on the CPU against the frustum (the culling boxes
// widened by the waves' reach, as the quadtree's), drawn as patches of one control point each
// — the quad's cell — and subdivided by the tessellation stages (ocean_tess.vert, ocean.tesc,
// ocean.tese) by the levels of shaders/tessellation.h. The skirt beyond the square is the
// quadtree mode's, drawn after it with the ocean pipeline.
#include "tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "pipeline_desc.hpp"
#include "spirv.hpp"
#include "state.hpp"

namespace ocean::render {

VkPushConstantRange tessellation_push_range() {
  return {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT | VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT,
          OCEAN_TESS_PUSH_OFFSET, sizeof(shader::TessellationPush)};
}

Status TessellationPass::create(Renderer::State& st) {
  const vk::Context& ctx = *st.ctx;
  if (!ctx.tessellation) return {};
  Result<VkShaderModule> vert = shader_module(st, spirv::ocean_tess_vert());
  Result<VkShaderModule> tesc = shader_module(st, spirv::ocean_tesc());
  Result<VkShaderModule> tese = shader_module(st, spirv::ocean_tese());
  Result<VkShaderModule> frag = shader_module(st, spirv::ocean_frag());
  Result<VkShaderModule> wire = shader_module(st, spirv::wire_frag());
  for (const auto* m : {&vert, &tesc, &tese, &frag, &wire})
    if (!m->ok()) return m->status();
  // One uint per control point: the cell i | j << 16.
  const VkVertexInputBindingDescription binding{0, sizeof(std::uint32_t),
                                                VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attribute{0, 0, VK_FORMAT_R32_UINT, 0};
  const VkPipelineVertexInputStateCreateInfo input{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
      .vertexBindingDescriptionCount = 1,
      .pVertexBindingDescriptions = &binding,
      .vertexAttributeDescriptionCount = 1,
      .pVertexAttributeDescriptions = &attribute};
  PipelineDesc desc{.vert = vert.value(),
                    .frag = frag.value(),
                    .layout = st.scene_pipeline_layout,
                    .vertex_input = &input,
                    .tesc = tesc.value(),
                    .tese = tese.value()};
  Result<VkPipeline> made = make_pipeline(ctx, desc);
  if (!made.ok()) return made.status();
  filled = made.value();
  if (ctx.wireframe) {
    desc.frag = wire.value();
    desc.lines = true;
    Result<VkPipeline> made_lines = make_pipeline(ctx, desc);
    if (!made_lines.ok()) return made_lines.status();
    lines = made_lines.value();
  }
  Result<vk::Buffer> list = vk::create_buffer(
      ctx, static_cast<VkDeviceSize>(OCEAN_TESS_MAX_QUADS) * OCEAN_TESS_MAX_QUADS * 4,
      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, vk::MemoryUse::upload);
  if (!list.ok()) return list.status();
  cells = list.value();
  return {};
}

void TessellationPass::destroy(Renderer::State& st) {
  for (VkPipeline p : {filled, lines})
    if (p != VK_NULL_HANDLE) vkDestroyPipeline(st.ctx->device, p, nullptr);
  vk::destroy_buffer(*st.ctx, cells);
}

Status check_tessellation(const vk::Context& ctx, const TessellationParams& params) {
  if (params.mesh != MeshMode::tessellation) return {};
  if (!ctx.tessellation)
    return unsupported("tessellation mesh: the Vulkan device '" + ctx.info.name +
                       "' lacks tessellation shaders; use the quadtree mesh");
  const auto limit = ctx.properties.limits.maxTessellationGenerationLevel;
  if (params.max_level > limit)
    return unsupported("tessellation.max_level = " + std::to_string(params.max_level) +
                       " exceeds the Vulkan device's maxTessellationGenerationLevel " +
                       std::to_string(limit));
  return {};
}

void TessellationPass::record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame) {
  const View& view = frame.view;
  RenderStats& stats = frame.stats;
  const TessellationParams& tp = view.tessellation;
  const lod::LodSelection& sel = st.selection;
  // Everything relative to the frame's origin, the grid centre (R.16): the grid is centred on it.
  const double size = view.ocean_size_m, cell = size / tp.base_quads;
  const TessellationGrid grid{
      .corner_m = {static_cast<float>(-0.5 * size), static_cast<float>(-0.5 * size)},
      .cell_m = static_cast<float>(cell),
      .quads = tp.base_quads,
      .eye_m = {static_cast<float>(view.camera.position_m.x - sel.grid_centre_x_m),
                static_cast<float>(view.camera.position_m.z - sel.grid_centre_z_m)}};
  const shader::TessellationPush push = tessellation_push(tp, grid);
  // The visible quads: each quad's box, widened by the waves' reach and the curvature's drop.
  const lod::Frustum frustum =
      lod::frustum_from_view_projection(lod::view_projection(relative_camera(view.camera, sel)));
  const double reach = st.horizontal_reach_m;
  const lod::Vec3 half{0.5 * cell + reach, st.crest_bound_m + curvature_drop_bound_m(view),
                       0.5 * cell + reach};
  auto* out = static_cast<std::uint32_t*>(cells.mapped);
  std::uint32_t count = 0;
  for (int j = 0; j < tp.base_quads; ++j)
    for (int i = 0; i < tp.base_quads; ++i) {
      const lod::Vec3 centre{-0.5 * size + (i + 0.5) * cell, 0.0, -0.5 * size + (j + 0.5) * cell};
      if (lod::box_visible(frustum, centre, half))
        out[count++] = static_cast<std::uint32_t>(i) | static_cast<std::uint32_t>(j) << 16;
    }
  const bool wire = view.debug == DebugView::wireframe;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, wire ? lines : filled);
  vkCmdPushConstants(cmd, st.scene_pipeline_layout, tessellation_push_range().stageFlags,
                     OCEAN_TESS_PUSH_OFFSET, sizeof(push), &push);
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &cells.buffer, &zero);
  // Draws of at most 2¹⁶ vertices the tessellator may generate, (N + 1)² a patch: lavapipe drops
  // larger tessellated draws whole (measured: 1026 patches at N = 16 vanished, 256 did not).
  const double per_patch = (tp.max_level + 1.0) * (tp.max_level + 1.0);
  const auto chunk = static_cast<std::uint32_t>(std::max(1.0, std::floor(65536.0 / per_patch)));
  for (std::uint32_t first = 0; first < count; first += chunk) {
    vkCmdDraw(cmd, std::min(chunk, count - first), 1, first, 0);
    ++stats.draw_calls;
  }
  stats.patches = count;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, wire ? st.wire : st.ocean);
}

}  // namespace ocean::render
