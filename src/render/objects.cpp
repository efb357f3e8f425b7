// The object pass (object_pass.hpp): meshes uploaded once by Renderer::set_meshes into
// device-local buffers, drawn per instance with the model matrix and material as push constants,
// in the HDR pass after the water and depth-tested with it (docs/rendering.md R.20–R.21).
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "object_pass.hpp"
#include "pipeline_desc.hpp"
#include "shaders/object_shared.h"
#include "spirv.hpp"
#include "state.hpp"

namespace ocean::render {

Result<VkPipeline> make_object_pipeline(Renderer::State& st, std::span<const std::uint32_t> vert,
                                        std::span<const std::uint32_t> frag,
                                        std::uint32_t view_mask) {
  Result<VkShaderModule> v = shader_module(st, vert);
  if (!v.ok()) return v.status();
  Result<VkShaderModule> f = shader_module(st, frag);
  if (!f.ok()) return f.status();
  const VkVertexInputBindingDescription binding{0, OCEAN_OBJECT_VERTEX_FLOATS * sizeof(float),
                                                VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attributes[] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 3 * sizeof(float)}};
  const VkPipelineVertexInputStateCreateInfo input{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
      .vertexBindingDescriptionCount = 1,
      .pVertexBindingDescriptions = &binding,
      .vertexAttributeDescriptionCount = 2,
      .pVertexAttributeDescriptions = attributes};
  return make_pipeline(*st.ctx, {.vert = v.value(),
                                 .frag = f.value(),
                                 .layout = pass<ObjectPass>(st).layout,
                                 .vertex_input = &input,
                                 .view_mask = view_mask});
}

Status ObjectPass::create(Renderer::State& st) {
  const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                 sizeof(shader::ObjectPush)};
  const VkPipelineLayoutCreateInfo info{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                        .setLayoutCount = 1,
                                        .pSetLayouts = &st.scene_layout,
                                        .pushConstantRangeCount = 1,
                                        .pPushConstantRanges = &push};
  if (Status s = vk::check(vkCreatePipelineLayout(st.ctx->device, &info, nullptr, &layout),
                           "vkCreatePipelineLayout");
      !s.ok())
    return s;
  Result<VkSampler> sampler = make_sampler(*st.ctx, true, true, false, 1.0f);
  if (!sampler.ok()) return sampler.status();
  reflection_sampler = sampler.value();
  Result<VkPipeline> mono = make_object_pipeline(st, spirv::object_vert(), spirv::object_frag(), 0);
  if (!mono.ok()) return mono.status();
  pipeline = mono.value();
  return {};
}

Status Renderer::set_meshes(std::span<const Mesh> meshes) {
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (Status s = validate(meshes[i]); !s.ok())
      return invalid_argument("meshes[" + std::to_string(i) + "]: " + s.message());
  State& st = *state_;
  vkDeviceWaitIdle(st.ctx->device);  // the old buffers may be in use by the last frame
  destroy_objects(st, false);
  std::vector<float> vertices;
  for (const Mesh& m : meshes) {
    vertices.resize(m.positions.size() * OCEAN_OBJECT_VERTEX_FLOATS);
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      std::memcpy(&vertices[v * OCEAN_OBJECT_VERTEX_FLOATS], m.positions[v].data(), 12);
      std::memcpy(&vertices[v * OCEAN_OBJECT_VERTEX_FLOATS + 3], m.normals[v].data(), 12);
    }
    ObjectPass::MeshBuffers b;
    Result<vk::Buffer> vb =
        vk::create_static_buffer(*st.ctx, st.commands, std::as_bytes(std::span(vertices)),
                                 VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    if (!vb.ok()) return vb.status();
    b.vertices = vb.value();
    Result<vk::Buffer> ib =
        vk::create_static_buffer(*st.ctx, st.commands, std::as_bytes(std::span(m.indices)),
                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    if (!ib.ok()) {
      vk::destroy_buffer(*st.ctx, b.vertices);
      return ib.status();
    }
    b.indices = ib.value();
    b.index_count = static_cast<std::uint32_t>(m.indices.size());
    b.material = m.material;
    pass<ObjectPass>(st).meshes.push_back(b);
  }
  return size_reflection(st);  // the objects' reflections (R.53)
}

Status validate_objects(const Renderer::State& st, const View& view) {
  const std::size_t meshes = pass<ObjectPass>(st).meshes.size();
  for (std::size_t i = 0; i < view.objects.size(); ++i)
    if (view.objects[i].mesh >= meshes)
      return invalid_argument("objects[" + std::to_string(i) +
                              "].mesh = " + std::to_string(view.objects[i].mesh) +
                              " is not one of the " + std::to_string(meshes) + " meshes set");
  return {};
}

void record_objects(Renderer::State& st, VkCommandBuffer cmd, const View& view, RenderStats& stats,
                    VkPipeline pipeline, bool mirrored) {
  if (view.objects.empty()) return;
  const ObjectPass& op = pass<ObjectPass>(st);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                    pipeline != VK_NULL_HANDLE ? pipeline : op.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, op.layout, 0, 1, &st.scene_set, 0,
                          nullptr);
  const VkDeviceSize zero = 0;
  for (const ObjectInstance& o : view.objects) {
    const ObjectPass::MeshBuffers& m = op.meshes[o.mesh];
    shader::ObjectPush push{};
    // Positions the GPU sees are relative to the frame's origin O (R.16): the translation moves
    // by −O in double before it becomes float.
    std::array<double, 16> model = o.model;
    model[12] -= st.selection.grid_centre_x_m;
    model[14] -= st.selection.grid_centre_z_m;
    for (std::size_t i = 0; i < 16; ++i) push.model.m[i] = static_cast<float>(model[i]);
    push.base_metallic = {static_cast<float>(m.material.base_colour[0]),
                          static_cast<float>(m.material.base_colour[1]),
                          static_cast<float>(m.material.base_colour[2]),
                          static_cast<float>(m.material.metallic)};
    push.roughness_pad = {static_cast<float>(m.material.roughness), mirrored ? 1.0f : 0.0f, 0.0f,
                          0.0f};
    vkCmdPushConstants(cmd, op.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(push), &push);
    vkCmdBindVertexBuffers(cmd, 0, 1, &m.vertices.buffer, &zero);
    vkCmdBindIndexBuffer(cmd, m.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, m.index_count, 1, 0, 0, 0);
    ++stats.draw_calls;
    stats.triangles += m.index_count / 3;
  }
}

void destroy_objects(Renderer::State& st, bool all) {
  ObjectPass& op = pass<ObjectPass>(st);
  for (ObjectPass::MeshBuffers& m : op.meshes) {
    vk::destroy_buffer(*st.ctx, m.vertices);
    vk::destroy_buffer(*st.ctx, m.indices);
  }
  op.meshes.clear();
  if (!all) return;
  if (op.pipeline != VK_NULL_HANDLE) vkDestroyPipeline(st.ctx->device, op.pipeline, nullptr);
  if (op.layout != VK_NULL_HANDLE) vkDestroyPipelineLayout(st.ctx->device, op.layout, nullptr);
  if (op.reflection_sampler != VK_NULL_HANDLE)
    vkDestroySampler(st.ctx->device, op.reflection_sampler, nullptr);
  op.pipeline = VK_NULL_HANDLE;
  op.layout = VK_NULL_HANDLE;
  op.reflection_sampler = VK_NULL_HANDLE;
}

void ObjectPass::destroy(Renderer::State& st) { destroy_objects(st, true); }

}  // namespace ocean::render
