// The recorded frame (Renderer::record): LOD selection with culling boxes that include the
// waves' reach, pending uploads, the HDR pass (sky, patches by stitching configuration, skirt),
// the tone-map pass into the sRGB image, and the GPU timestamps around it all. The steps
// (frame_steps.hpp) serve the stereo frame of stereo.cpp as well.
#include <chrono>
#include <cstring>
#include <span>
#include <string>

#include "frame_steps.hpp"

namespace ocean::render {

Status check_view(const Renderer::State& st, const View& view) {
  if (Status s = validate(view); !s.ok()) return s;
  if (Status s = validate_objects(st, view); !s.ok()) return s;
  if (view.debug == DebugView::wireframe && !st.ctx->wireframe)
    return unsupported("wireframe view: the Vulkan device lacks fillModeNonSolid");
  Status checked;
  for_each_pass(st, [&](const auto& p) {
    if (checked.ok()) checked = p.check(st, view);
  });
  return checked;
}

void fill_frame_uniforms(const Renderer::State& st, const View& view, const lod::Mat4& vp,
                         shader::FrameUniforms& u) {
  fill_uniforms(st, view, vp, u);
  fill_origin_uniforms(st, view, u);
  for_each_pass(st, [&](const auto& p) { p.fill_uniforms(st, view, u); });
}

Result<std::uint32_t> select_frame(Renderer::State& st, const View& view, lod::Vec3 lod_position,
                                   const lod::Frustum& frustum, RenderStats& stats) {
  // LOD selection (Aebi, VR Ocean, §5) with culling boxes that include the waves' reach.
  const auto t0 = std::chrono::steady_clock::now();
  lod::LodParams lp;
  lp.ocean_size_m = view.ocean_size_m;
  lp.quality = view.quality;
  lp.camera_position_m = lod_position;
  lp.frustum = frustum;
  lp.max_vertical_displacement_m = st.crest_bound_m + curvature_drop_bound_m(view);
  lp.max_horizontal_displacement_m = st.horizontal_reach_m;
  if (Status s = lod::select_patches(lp, st.selection); !s.ok()) return s;
  const lod::LodSelection& sel = st.selection;
  stats = {
      .cpu_select_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()};
  // The GPU draws relative to the grid centre (R.16): the instances and the skirt.
  auto* inst = static_cast<lod::PatchInstance*>(st.instances.mapped);
  write_relative_instances(sel, view.ocean_size_m, inst);
  const auto skirt_instance = static_cast<std::uint32_t>(sel.instances.size());
  inst[skirt_instance] = {
      .centre_x_m = 0.0f, .centre_z_m = 0.0f, .size_m = 1.0f, .level = kSkirtLevel};
  if (Status s = write_skirt_vertices(st, view, skirt_extent_m(view, st.hs_m)); !s.ok()) return s;
  pass<SkyPass>(st).update(view.shading);
  return skirt_instance;
}

void begin_frame(Renderer::State& st, VkCommandBuffer cmd) {
  if (st.has_timestamps) {
    vkCmdResetQueryPool(cmd, st.timestamps.pool, 0, 2);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, st.timestamps.pool, 0);
  }
  for_each_pass(st, [&](auto& p) { p.upload(st, cmd); });
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
}

void begin_scene(Renderer::State& st, VkCommandBuffer cmd, const vk::Image2D& colour_target,
                 const vk::Image2D& depth_target, std::uint32_t view_mask) {
  const std::uint32_t w = colour_target.width, h = colour_target.height;
  vk::image_barrier(
      cmd, colour_target.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
      VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
      VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  vk::image_barrier(
      cmd, depth_target.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
      VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, 0,
      VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
      VK_IMAGE_ASPECT_DEPTH_BIT);
  const VkRenderingAttachmentInfo colour{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                         .imageView = colour_target.view,
                                         .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                         .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                         .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                         .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 1.0f}}}};
  const VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                        .imageView = depth_target.view,
                                        .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                        .clearValue = {.depthStencil = {1.0f, 0}}};
  const VkRenderingInfo scene{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                              .renderArea = {{0, 0}, {w, h}},
                              .layerCount = view_mask == 0 ? 1u : 0u,
                              .viewMask = view_mask,
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
}

void record_scene(Renderer::State& st, VkCommandBuffer cmd, const View& view,
                  const ScenePipelines& pipelines, const shader::SkyPush& sky_push,
                  std::uint32_t skirt_instance, RenderStats& stats) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.sky);
  vkCmdPushConstants(cmd, st.scene_pipeline_layout, VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(sky_push), &sky_push);
  vkCmdDraw(cmd, pipelines.sky_vertices, 1, 0, 0);
  ++stats.draw_calls;
  const FrameContext frame{.view = view, .stats = stats, .skirt_instance = skirt_instance};
  if (view.sphere.enabled) {  // the sea on a sphere (R.30–R.38) instead of the flat patches
    pass<SpherePass>(st).record(st, cmd, frame);
  } else {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.ocean);
    pass<SeabedPass>(st).record(st, cmd, frame);
    const bool tessellated = view.tessellation.mesh == MeshMode::tessellation;
    if (tessellated) pass<TessellationPass>(st).record(st, cmd, frame);  // R.40–R.42
    record_patches(st, cmd, skirt_instance, &stats, !tessellated);
    stats.patches_per_level = st.selection.patches_per_level;
  }
  record_objects(st, cmd, view, stats, pipelines.objects);
}

void record_patches(Renderer::State& st, VkCommandBuffer cmd, std::uint32_t skirt_instance,
                    RenderStats* stats, bool quadtree) {
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &st.patch_vertices.buffer, &zero);
  vkCmdBindVertexBuffers(cmd, 1, 1, &st.instances.buffer, &zero);
  vkCmdBindIndexBuffer(cmd, st.indices.buffer, 0, VK_INDEX_TYPE_UINT16);
  const std::span<const lod::Batch> batches =
      quadtree ? std::span<const lod::Batch>(st.selection.batches) : std::span<const lod::Batch>();
  for (const lod::Batch& b : batches) {  // ≤ 16 instanced draws (Aebi, eq. 70)
    vkCmdDrawIndexed(cmd, st.index_count[b.config], b.count, st.index_first[b.config], 0, b.first);
    if (stats == nullptr) continue;
    ++stats->draw_calls;
    stats->patches += b.count;
    stats->triangles += static_cast<std::uint64_t>(st.index_count[b.config] / 3) * b.count;
  }
  vkCmdBindVertexBuffers(cmd, 0, 1, &st.skirt_vertices.buffer, &zero);
  vkCmdDrawIndexed(cmd, st.skirt_count, 1, st.skirt_first, 0, skirt_instance);
  if (stats == nullptr) return;
  ++stats->draw_calls;
  stats->triangles += st.skirt_count / 3;
}

void finish_frame(Renderer::State& st, VkCommandBuffer cmd, const View& view,
                  VkImageLayout hdr_layout, VkPipelineStageFlags src_stage,
                  VkAccessFlags src_access, RenderStats& stats) {
  vk::image_barrier(cmd, st.hdr.image, hdr_layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    src_stage, src_access, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_SHADER_READ_BIT);
  pass<PostPass>(st).record(st, cmd, {.view = view, .stats = stats});
  if (st.has_timestamps)
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, st.timestamps.pool, 1);
}

Status Renderer::record(VkCommandBuffer cmd, const View& view) {
  State& st = *state_;
  if (Status s = check_view(st, view); !s.ok()) return s;
  if (Status s = prepare(view); !s.ok()) return s;  // a one-off submission of its own
  if (Status s = check_tessellation(*st.ctx, view.tessellation); !s.ok()) return s;
  const bool tessellated = view.tessellation.mesh == MeshMode::tessellation;
  if ((view.sphere.enabled || tessellated) && pass<MotionPass>(st).enabled)
    return unsupported(std::string("motion vectors: not drawn for ") +
                       (tessellated ? "the tessellated mesh" : "the sea on a sphere"));
  if (view.sphere.enabled && tessellated)
    return unsupported("the tessellated mesh: not drawn for the sea on a sphere");
  if (Status s = prepare_motion(st); !s.ok()) return s;
  Result<std::uint32_t> skirt_instance =
      select_frame(st, view, view.camera.position_m,
                   lod::frustum_from_view_projection(lod::view_projection(view.camera)), stats_);
  if (!skirt_instance.ok()) return skirt_instance.status();
  // The GPU draws relative to the grid centre (R.16).
  lod::Mat4 vp = lod::view_projection(relative_camera(view.camera, st.selection));
  shader::FrameUniforms u{};
  fill_frame_uniforms(st, view, vp, u);
  if (view.sphere.enabled)  // the sea on a sphere (R.30–R.38): its selection, uniforms and vp
    if (Status s = prepare_sphere(st, view, vp, u); !s.ok()) return s;
  std::memcpy(st.uniforms.mapped, &u, sizeof(u));
  const std::array<double, 16> inv = inverse(vp.m);
  shader::SkyPush sky_push{};
  for (int i = 0; i < 16; ++i)
    sky_push.inverse_view_proj.m[i] = static_cast<float>(inv[static_cast<std::size_t>(i)]);

  begin_frame(st, cmd);
  record_reflection(st, cmd, view, stats_);  // the objects mirrored in the sea (R.53)
  begin_scene(st, cmd, st.hdr, st.depth, 0);
  record_scene(st, cmd, view,
               {.sky = st.sky, .ocean = view.debug == DebugView::wireframe ? st.wire : st.ocean},
               sky_push, skirt_instance.value(), stats_);
  vkCmdEndRendering(cmd);
  const FrameContext frame{view, stats_, skirt_instance.value()};
  pass<MotionPass>(st).record(st, cmd, frame);
  Status after;
  for_each_pass(st, [&](auto& p) {
    if (after.ok()) after = p.after_scene(st, cmd, frame);
  });
  if (!after.ok()) return after;
  finish_frame(st, cmd, view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
               stats_);
  return {};
}

}  // namespace ocean::render
