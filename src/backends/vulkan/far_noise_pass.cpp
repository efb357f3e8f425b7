// The far field's noise map on the device (far_noise_pass.hpp, docs/rendering.md R.13a).
#include "far_noise_pass.hpp"

#include <array>

#include "shaders/ocean_shared.h"
#include "sim/far_noise.h"
#include "spirv.hpp"

namespace ocean::vk::detail {

namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

Status create_layouts(FarNoisePass& pass) {
  const VkDevice device = pass.ctx->device;
  std::array<VkDescriptorSetLayoutBinding, 2> bindings{};
  for (std::uint32_t b = 0; b < 2; ++b) {
    bindings[b] = {.binding = b,
                   .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                   .descriptorCount = 1,
                   .stageFlags = VK_SHADER_STAGE_COMPUTE_BIT};
  }
  const VkDescriptorSetLayoutCreateInfo set_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = 2,
      .pBindings = bindings.data()};
  if (Status s = check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &pass.set_layout),
                       "vkCreateDescriptorSetLayout");
      !s.ok())
    return s;
  const VkPipelineLayoutCreateInfo layout_info{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
      .setLayoutCount = 1,
      .pSetLayouts = &pass.set_layout};
  if (Status s = check(vkCreatePipelineLayout(device, &layout_info, nullptr, &pass.pipeline_layout),
                       "vkCreatePipelineLayout");
      !s.ok())
    return s;
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .maxSets = 1,
                                             .poolSizeCount = 1,
                                             .pPoolSizes = &size};
  if (Status s = check(vkCreateDescriptorPool(device, &pool_info, nullptr, &pass.pool),
                       "vkCreateDescriptorPool");
      !s.ok())
    return s;
  const VkDescriptorSetAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                          .descriptorPool = pass.pool,
                                          .descriptorSetCount = 1,
                                          .pSetLayouts = &pass.set_layout};
  if (Status s =
          check(vkAllocateDescriptorSets(device, &alloc, &pass.set), "vkAllocateDescriptorSets");
      !s.ok())
    return s;
  const VkDescriptorBufferInfo buffers[2] = {{pass.params.buffer, 0, pass.params.size},
                                             {pass.map.buffer, 0, pass.map.size}};
  std::array<VkWriteDescriptorSet, 2> writes{};
  for (std::uint32_t b = 0; b < 2; ++b) {
    writes[b] = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                 .dstSet = pass.set,
                 .dstBinding = b,
                 .descriptorCount = 1,
                 .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                 .pBufferInfo = &buffers[b]};
  }
  vkUpdateDescriptorSets(device, 2, writes.data(), 0, nullptr);
  return {};
}

}  // namespace

FarNoisePass::~FarNoisePass() {
  if (ctx == nullptr) return;
  destroy_commands(*ctx, alone);
  destroy_pipeline(*ctx, pipeline);
  if (pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(ctx->device, pool, nullptr);
  if (pipeline_layout != VK_NULL_HANDLE)
    vkDestroyPipelineLayout(ctx->device, pipeline_layout, nullptr);
  if (set_layout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(ctx->device, set_layout, nullptr);
  for (Buffer* b : {&params, &map, &host}) destroy_buffer(*ctx, *b);
}

void record_far_noise(const FarNoisePass& pass, VkCommandBuffer cmd) {
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipeline_layout, 0, 1,
                          &pass.set, 0, nullptr);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.pipeline.pipeline);
  const std::uint32_t groups = (pass.resolution + OCEAN_TILE - 1) / OCEAN_TILE;
  vkCmdDispatch(cmd, groups, groups, 1);
}

void record_far_noise_copy(const FarNoisePass& pass, VkCommandBuffer cmd) {
  const VkBufferCopy region{0, 0, pass.map.size};
  vkCmdCopyBuffer(cmd, pass.map.buffer, pass.host.buffer, 1, &region);
}

Status create_far_noise_pass(FarNoisePass& pass, const Context& ctx, std::uint32_t resolution) {
  if (resolution == 0) return {};
  pass.ctx = &ctx;
  pass.resolution = resolution;
  const VkDeviceSize bytes = VkDeviceSize{3} * resolution * resolution * sizeof(float);
  Result<Buffer> params =
      create_buffer(ctx, sizeof(noise::FarNoiseMapParams), kStorage, MemoryUse::upload);
  if (!params.ok()) return params.status();
  pass.params = params.value();
  Result<Buffer> map =
      create_buffer(ctx, bytes, kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::device);
  if (!map.ok()) return map.status();
  pass.map = map.value();
  Result<Buffer> host =
      create_buffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::readback);
  if (!host.ok()) return host.status();
  pass.host = host.value();
  if (Status s = create_layouts(pass); !s.ok()) return s;
  Result<ComputePipeline> pipeline =
      create_compute_pipeline(ctx, spirv::far_noise(), pass.pipeline_layout);
  if (!pipeline.ok()) return pipeline.status();
  pass.pipeline = pipeline.value();
  Result<Commands> alone = create_commands(ctx);
  if (!alone.ok()) return alone.status();
  pass.alone = alone.value();

  // The map alone: the previous read-back done, the dispatch, the copy, visible to the host.
  VkCommandBuffer cmd = pass.alone.buffer;
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  if (Status s = check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer"); !s.ok())
    return s;
  barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
          VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  record_far_noise(pass, cmd);
  barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  record_far_noise_copy(pass, cmd);
  const VkMemoryBarrier to_host{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                                .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &to_host, 0, nullptr, 0, nullptr);
  return check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
}

}  // namespace ocean::vk::detail
