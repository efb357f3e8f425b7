// Motion vectors (Renderer::set_motion_vectors, read_motion; docs/rendering.md R.26): after the
// HDR pass the patches and the skirt are drawn again into an RG16F target with ocean.vert's
// OCEAN_MOTION variant, which places each vertex's label also where it was a frame ago — the
// previous frame's displacement array (kept as a copy) under the previous camera — and
// motion.frag writes the difference of the two NDC positions; the sky's pixels move with the
// camera's rotation (motion_sky.frag). The read-back scales NDC to pixels.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>

#include "frame_steps.hpp"
#include "ocean/half.hpp"
#include "pipeline_desc.hpp"
#include "shaders/motion_shared.h"
#include "spirv.hpp"
#include "state.hpp"

namespace ocean::render {

namespace {

constexpr VkFormat kMotionFormat = VK_FORMAT_R16G16_SFLOAT;

// The sky's and the surface's motion pipelines from their shaders (one view, or the eyes of
// `view_mask` at once), on the pass's layout, into `sky` and `ocean`.
Status make_motion_pipelines(Renderer::State& st, std::span<const std::uint32_t> sky_vert_spv,
                             std::span<const std::uint32_t> sky_frag_spv,
                             std::span<const std::uint32_t> ocean_vert_spv, std::uint32_t view_mask,
                             VkPipeline& sky, VkPipeline& ocean) {
  const MotionPass& mp = pass<MotionPass>(st);
  Result<VkShaderModule> sky_vert = shader_module(st, sky_vert_spv);
  Result<VkShaderModule> sky_frag = shader_module(st, sky_frag_spv);
  Result<VkShaderModule> ocean_vert = shader_module(st, ocean_vert_spv);
  Result<VkShaderModule> ocean_frag = shader_module(st, spirv::motion_frag());
  for (const auto* m : {&sky_vert, &sky_frag, &ocean_vert, &ocean_frag})
    if (!m->ok()) return m->status();
  Result<VkPipeline> p = make_pipeline(*st.ctx, {.vert = sky_vert.value(),
                                                 .frag = sky_frag.value(),
                                                 .layout = mp.layout,
                                                 .colour = kMotionFormat,
                                                 .depth_test = false,
                                                 .view_mask = view_mask});
  if (!p.ok()) return p.status();
  sky = p.value();
  p = make_pipeline(*st.ctx, {.vert = ocean_vert.value(),
                              .frag = ocean_frag.value(),
                              .layout = mp.layout,
                              .colour = kMotionFormat,
                              .mesh_input = true,
                              .view_mask = view_mask});
  if (!p.ok()) return p.status();
  ocean = p.value();
  return {};
}

Status create_motion_objects(Renderer::State& st) {
  MotionPass& mp = pass<MotionPass>(st);
  if (mp.ocean != VK_NULL_HANDLE) return {};
  const VkDevice d = st.ctx->device;
  const VkDescriptorSetLayoutBinding binding{OCEAN_MOTION_BINDING_PREVIOUS,
                                             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                             VK_SHADER_STAGE_VERTEX_BIT, nullptr};
  const VkDescriptorSetLayoutCreateInfo set_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = 1,
      .pBindings = &binding};
  Status s = vk::check(vkCreateDescriptorSetLayout(d, &set_info, nullptr, &mp.set_layout),
                       "vkCreateDescriptorSetLayout");
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .maxSets = 1,
                                             .poolSizeCount = 1,
                                             .pPoolSizes = &size};
  if (s.ok())
    s = vk::check(vkCreateDescriptorPool(d, &pool_info, nullptr, &mp.pool),
                  "vkCreateDescriptorPool");
  const VkDescriptorSetAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                          .descriptorPool = mp.pool,
                                          .descriptorSetCount = 1,
                                          .pSetLayouts = &mp.set_layout};
  if (s.ok())
    s = vk::check(vkAllocateDescriptorSets(d, &alloc, &mp.set), "vkAllocateDescriptorSets");
  const VkDescriptorSetLayout sets[] = {st.scene_layout, mp.set_layout};
  const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                 sizeof(shader::MotionPush)};
  const VkPipelineLayoutCreateInfo layout{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                          .setLayoutCount = 2,
                                          .pSetLayouts = sets,
                                          .pushConstantRangeCount = 1,
                                          .pPushConstantRanges = &push};
  if (s.ok())
    s = vk::check(vkCreatePipelineLayout(d, &layout, nullptr, &mp.layout),
                  "vkCreatePipelineLayout");
  if (!s.ok()) return s;
  return make_motion_pipelines(st, spirv::sky_vert(), spirv::motion_sky_frag(),
                               spirv::ocean_vert_motion(), 0, mp.sky, mp.ocean);
}

// The view-projection of `camera` with its eye at the origin: what a direction sees.
std::array<double, 16> rotation_view_projection(lod::Camera camera) {
  camera.target_m = {camera.target_m.x - camera.position_m.x,
                     camera.target_m.y - camera.position_m.y,
                     camera.target_m.z - camera.position_m.z};
  camera.position_m = {};
  return lod::view_projection(camera).m;
}

std::array<double, 16> multiply(const std::array<double, 16>& a, const std::array<double, 16>& b) {
  std::array<double, 16> c{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k)
        c[static_cast<std::size_t>(col * 4 + row)] +=
            a[static_cast<std::size_t>(k * 4 + row)] * b[static_cast<std::size_t>(col * 4 + k)];
  return c;
}

}  // namespace

Status Renderer::set_motion_vectors(bool on) {
  State& st = *state_;
  if (on) {
    if (Status s = create_motion_objects(st); !s.ok()) return s;
  }
  pass<MotionPass>(st).enabled = on;
  pass<MotionPass>(st).previous_valid = false;
  return {};
}

Status prepare_motion(Renderer::State& st) {
  MotionPass& mp = pass<MotionPass>(st);
  if (!mp.enabled) return {};
  if (st.borrowed)
    return unsupported(
        "motion vectors: the renderer keeps the previous frame of uploaded cascades only, not of "
        "a backend's images (use upload())");
  if (mp.target.image == VK_NULL_HANDLE || mp.target.width != st.hdr.width ||
      mp.target.height != st.hdr.height) {
    vk::destroy_image(*st.ctx, mp.target);
    Result<vk::Image2D> target =
        vk::create_image_2d(*st.ctx, kMotionFormat, st.hdr.width, st.hdr.height,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                VK_IMAGE_USAGE_SAMPLED_BIT |       // read by a later pass
                                VK_IMAGE_USAGE_TRANSFER_DST_BIT);  // a stereo frame's eyes
    if (!target.ok()) return target.status();
    mp.target = target.value();
  }
  // A copy of the displacement array as it is now (1×1 before configure()).
  const std::uint32_t size = std::max(st.sim_size, 1u), layers = std::max(st.sim_layers, 1u);
  if (mp.previous.image == VK_NULL_HANDLE || mp.previous.size != size ||
      mp.previous.layers != layers) {
    vkDeviceWaitIdle(st.ctx->device);  // the set may be in use by the last frame
    vk::destroy_image(*st.ctx, mp.previous);
    Result<vk::Image> previous =
        vk::create_image_array(*st.ctx, VK_FORMAT_R16G16B16A16_SFLOAT, size, layers, 1,
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
    if (!previous.ok()) return previous.status();
    mp.previous = previous.value();
    mp.previous_valid = false;
    const VkDescriptorImageInfo image{st.displacement_sampler, mp.previous.view,
                                      VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                     .dstSet = mp.set,
                                     .dstBinding = OCEAN_MOTION_BINDING_PREVIOUS,
                                     .descriptorCount = 1,
                                     .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                     .pImageInfo = &image};
    vkUpdateDescriptorSets(st.ctx->device, 1, &write, 0, nullptr);
  }
  return {};
}

namespace {

// displacement → previous, both GENERAL, after the vertex shaders' reads.
void keep_displacement(Renderer::State& st, VkCommandBuffer cmd, bool first) {
  MotionPass& mp = pass<MotionPass>(st);
  if (first)
    vk::image_barrier(cmd, mp.previous.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                      VK_PIPELINE_STAGE_VERTEX_SHADER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_ACCESS_TRANSFER_WRITE_BIT);
  vk::barrier(cmd, VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
              VK_PIPELINE_STAGE_TRANSFER_BIT);
  if (st.displacement.image != VK_NULL_HANDLE) {
    const VkImageCopy region{
        .srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, mp.previous.layers},
        .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, mp.previous.layers},
        .extent = {mp.previous.size, mp.previous.size, 1}};
    vkCmdCopyImage(cmd, st.displacement.image, VK_IMAGE_LAYOUT_GENERAL, mp.previous.image,
                   VK_IMAGE_LAYOUT_GENERAL, 1, &region);
  }
  vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
              VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT);
}

}  // namespace

void record_motion(Renderer::State& st, VkCommandBuffer cmd, const lod::Camera& camera,
                   std::uint32_t skirt_instance) {
  MotionPass& mp = pass<MotionPass>(st);
  // The first frame has no previous one: itself (no motion).
  if (!mp.previous_valid) keep_displacement(st, cmd, true), mp.camera = camera;
  shader::MotionPush push{};
  push.previous_view_proj =
      to_mat4(lod::view_projection(relative_camera(mp.camera, st.selection)).m);
  push.sky_reprojection = to_mat4(
      multiply(rotation_view_projection(mp.camera), inverse(rotation_view_projection(camera))));
  begin_scene(st, cmd, mp.target, st.depth, 0);
  const VkDescriptorSet sets[] = {st.scene_set, mp.set};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mp.layout, 0, 2, sets, 0, nullptr);
  vkCmdPushConstants(cmd, mp.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(push), &push);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mp.sky);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mp.ocean);
  record_patches(st, cmd, skirt_instance, nullptr);
  vkCmdEndRendering(cmd);
  vk::image_barrier(cmd, mp.target.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_READ_BIT);
  keep_displacement(st, cmd, false);
  mp.camera = camera;
  mp.previous_stereo = false;
  mp.previous_valid = true;
}

void fill_stereo_motion(const Renderer::State& st, const std::array<lod::Camera, 2>& eyes,
                        shader::FrameUniforms& u) {
  const MotionPass& mp = pass<MotionPass>(st);
  if (!mp.enabled) return;
  const bool moved = mp.previous_valid && mp.previous_stereo;
  for (std::size_t e = 0; e < 2; ++e) {
    const lod::Camera& before = moved ? mp.eye_cameras[e] : eyes[e];
    u.eyes[e].previous_view_proj =
        to_mat4(lod::view_projection(relative_camera(before, st.selection)).m);
    u.eyes[e].sky_reprojection = to_mat4(
        multiply(rotation_view_projection(before), inverse(rotation_view_projection(eyes[e]))));
  }
}

Status record_stereo_motion(Renderer::State& st, VkCommandBuffer cmd,
                            const std::array<lod::Camera, 2>& eyes, const lod::Camera& head,
                            const vk::Image2D& depth, std::uint32_t skirt_instance) {
  MotionPass& mp = pass<MotionPass>(st);
  constexpr std::uint32_t kBothEyes = 0b11;
  if (mp.ocean_mv == VK_NULL_HANDLE) {
    Status made =
        make_motion_pipelines(st, spirv::sky_vert_mv(), spirv::motion_sky_frag_mv(),
                              spirv::ocean_vert_motion_mv(), kBothEyes, mp.sky_mv, mp.ocean_mv);
    if (!made.ok()) return made;
  }
  if (mp.stereo_target.image == VK_NULL_HANDLE || mp.stereo_target.width != depth.width ||
      mp.stereo_target.height != depth.height) {
    vk::destroy_image(*st.ctx, mp.stereo_target);
    Result<vk::Image2D> target =
        vk::create_image_2d(*st.ctx, kMotionFormat, depth.width, depth.height,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT, 2);
    if (!target.ok()) return target.status();
    mp.stereo_target = target.value();
  }
  if (!mp.previous_valid) keep_displacement(st, cmd, true);
  const shader::MotionPush push{};  // the eyes' matrices are in the uniforms (fill_stereo_motion)
  begin_scene(st, cmd, mp.stereo_target, depth, kBothEyes);
  const VkDescriptorSet sets[] = {st.scene_set, mp.set};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mp.layout, 0, 2, sets, 0, nullptr);
  vkCmdPushConstants(cmd, mp.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof(push), &push);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mp.sky_mv);
  vkCmdDraw(cmd, 6, 1, 0, 0);  // the multiview sky's quad (sky.vert)
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mp.ocean_mv);
  record_patches(st, cmd, skirt_instance, nullptr);
  vkCmdEndRendering(cmd);
  // The eyes' layers side by side into the motion target, left where read_motion() copies from.
  vk::image_barrier(cmd, mp.stereo_target.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_READ_BIT);
  vk::image_barrier(cmd, mp.target.image, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  VkImageCopy regions[2];
  for (std::uint32_t e = 0; e < 2; ++e)
    regions[e] = {.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, e, 1},
                  .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                  .dstOffset = {static_cast<std::int32_t>(e * mp.stereo_target.width), 0, 0},
                  .extent = {mp.stereo_target.width, mp.stereo_target.height, 1}};
  vkCmdCopyImage(cmd, mp.stereo_target.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, mp.target.image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 2, regions);
  vk::image_barrier(cmd, mp.target.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_READ_BIT);
  keep_displacement(st, cmd, false);
  mp.camera = head;
  mp.eye_cameras = eyes;
  mp.previous_stereo = true;
  mp.previous_valid = true;
  return {};
}

void destroy_motion(Renderer::State& st, bool all) {
  MotionPass& mp = pass<MotionPass>(st);
  vk::destroy_image(*st.ctx, mp.target);
  vk::destroy_image(*st.ctx, mp.stereo_target);
  if (!all) return;
  vk::destroy_image(*st.ctx, mp.previous);
  const VkDevice d = st.ctx->device;
  for (VkPipeline p : {mp.sky, mp.ocean, mp.sky_mv, mp.ocean_mv})
    if (p != VK_NULL_HANDLE) vkDestroyPipeline(d, p, nullptr);
  if (mp.layout != VK_NULL_HANDLE) vkDestroyPipelineLayout(d, mp.layout, nullptr);
  if (mp.pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(d, mp.pool, nullptr);
  if (mp.set_layout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(d, mp.set_layout, nullptr);
  mp = {};
}

void MotionPass::destroy(Renderer::State& st) { destroy_motion(st, true); }
void MotionPass::release_targets(Renderer::State& st) { destroy_motion(st, false); }

void MotionPass::record(Renderer::State& st, VkCommandBuffer cmd, const FrameContext& frame) {
  if (enabled) record_motion(st, cmd, frame.view.camera, frame.skirt_instance);
}

Status Renderer::read_motion(std::vector<float>& xy) {
  State& st = *state_;
  const MotionPass& mp = pass<MotionPass>(st);
  const vk::Image2D& target = mp.target;
  if (!mp.enabled || !mp.previous_valid || target.image == VK_NULL_HANDLE)
    return invalid_argument("read_motion: no frame drawn with motion vectors on");
  const std::uint32_t w = target.width, h = target.height;
  const Status s = vk::run_once(*st.ctx, st.commands, [&](VkCommandBuffer cmd) {
    const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                   .imageExtent = {w, h, 1}};
    vkCmdCopyImageToBuffer(cmd, target.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           st.readback.buffer, 1, &region);
    vk::barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
  });
  if (!s.ok()) return s;
  // NDC (y up) → pixels (rows down): x·w/2, −y·h/2.
  const std::size_t n = static_cast<std::size_t>(w) * h * 2;
  xy.resize(n);
  const auto* half = static_cast<const std::uint16_t*>(st.readback.mapped);
  for (std::size_t i = 0; i < n; i += 2) {
    xy[i] = half_to_float(half[i]) * 0.5f * static_cast<float>(w);
    xy[i + 1] = -half_to_float(half[i + 1]) * 0.5f * static_cast<float>(h);
  }
  return {};
}

}  // namespace ocean::render
