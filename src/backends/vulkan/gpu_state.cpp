// Creation of the simulation's Vulkan objects and the recording of the frame command buffer:
// rows (evolution + FFT along x) → columns (FFT along z + sign) → finalize → mips → readback
// copies, each stage one dispatch over all cascades (mips: one per level), timestamps between.
#include "gpu_state.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

#include "spirv.hpp"

namespace ocean::vk::detail {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
constexpr VkBufferUsageFlags kTransferDst = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkBufferUsageFlags kTransferSrc = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

std::uint32_t groups(std::uint32_t n) { return (n + OCEAN_TILE - 1) / OCEAN_TILE; }

// A device-local storage buffer filled from host memory through a temporary staging buffer.
Status upload(const Context& ctx, const Commands& cmds, Buffer& dst, const void* data,
              std::size_t bytes) {
  Result<Buffer> dev = create_buffer(ctx, bytes, kStorage | kTransferDst, MemoryUse::device);
  if (!dev.ok()) return dev.status();
  dst = dev.value();
  Result<Buffer> staging = create_buffer(ctx, bytes, kTransferSrc, MemoryUse::upload);
  if (!staging.ok()) return staging.status();
  std::memcpy(staging.value().mapped, data, bytes);
  Status s = run_once(ctx, cmds, [&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, staging.value().buffer, dst.buffer, 1, &region);
  });
  destroy_buffer(ctx, staging.value());
  return s;
}

Status create_layouts(GpuState& gpu) {
  const VkDevice device = gpu.ctx->device;
  std::array<VkDescriptorSetLayoutBinding, OCEAN_BINDING_COUNT> bindings{};
  for (std::uint32_t b = 0; b < OCEAN_BINDING_COUNT; ++b) {
    bindings[b] = {.binding = b,
                   .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                   .descriptorCount = 1,
                   .stageFlags = VK_SHADER_STAGE_COMPUTE_BIT};
  }
  bindings[OCEAN_BINDING_DISP_IMAGE].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  bindings[OCEAN_BINDING_NORMAL_IMAGE].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
  bindings[OCEAN_BINDING_NORMAL_IMAGE].descriptorCount = OCEAN_MAX_MIPS;
  const VkDescriptorSetLayoutCreateInfo set_info{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
      .bindingCount = OCEAN_BINDING_COUNT,
      .pBindings = bindings.data()};
  if (Status s = check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &gpu.set_layout),
                       "vkCreateDescriptorSetLayout");
      !s.ok())
    return s;
  const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(shader::MipPush)};
  const VkPipelineLayoutCreateInfo layout_info{
      .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
      .setLayoutCount = 1,
      .pSetLayouts = &gpu.set_layout,
      .pushConstantRangeCount = 1,
      .pPushConstantRanges = &push};
  if (Status s = check(vkCreatePipelineLayout(device, &layout_info, nullptr, &gpu.pipeline_layout),
                       "vkCreatePipelineLayout");
      !s.ok())
    return s;
  const VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, OCEAN_BINDING_COUNT - 2},
      {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1 + OCEAN_MAX_MIPS}};
  const VkDescriptorPoolCreateInfo pool_info{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                             .maxSets = 1,
                                             .poolSizeCount = 2,
                                             .pPoolSizes = sizes};
  if (Status s = check(vkCreateDescriptorPool(device, &pool_info, nullptr, &gpu.pool),
                       "vkCreateDescriptorPool");
      !s.ok())
    return s;
  const VkDescriptorSetAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                          .descriptorPool = gpu.pool,
                                          .descriptorSetCount = 1,
                                          .pSetLayouts = &gpu.set_layout};
  return check(vkAllocateDescriptorSets(device, &alloc, &gpu.set), "vkAllocateDescriptorSets");
}

void write_descriptors(GpuState& gpu) {
  std::array<VkDescriptorBufferInfo, OCEAN_BINDING_COUNT> buffers{};
  const auto whole = [](const Buffer& b) { return VkDescriptorBufferInfo{b.buffer, 0, b.size}; };
  buffers[OCEAN_BINDING_PARAMS] = whole(gpu.params);
  buffers[OCEAN_BINDING_SPECTRUM] = whole(gpu.spectrum);
  buffers[OCEAN_BINDING_PHASE_RATE] = whole(gpu.phase_rate);
  buffers[OCEAN_BINDING_TWIDDLE] = whole(gpu.twiddle);
  buffers[OCEAN_BINDING_PLANES] = whole(gpu.plane_data);
  buffers[OCEAN_BINDING_DISPLACEMENT] = whole(gpu.device[displacement]);
  buffers[OCEAN_BINDING_DISP_HALF] = whole(gpu.device[displacement_half]);
  buffers[OCEAN_BINDING_NORMAL] = whole(gpu.device[normal]);
  buffers[OCEAN_BINDING_JACOBIAN] = whole(gpu.device[jacobian]);
  buffers[OCEAN_BINDING_FOAM] = whole(gpu.device[foam]);
  buffers[OCEAN_BINDING_MIP_WORK] = whole(gpu.mip_work);
  buffers[OCEAN_BINDING_PACKED] = whole(gpu.device[packed]);
  std::array<VkDescriptorImageInfo, 1 + OCEAN_MAX_MIPS> images{};
  images[0] = {VK_NULL_HANDLE, gpu.displacement_image.view, VK_IMAGE_LAYOUT_GENERAL};
  for (std::uint32_t m = 0; m < OCEAN_MAX_MIPS; ++m) {
    // Levels beyond the chain are never written; they alias level 0 to keep the array valid.
    const VkImageView view = gpu.normal_image.mip_views[m < gpu.normal_image.mips ? m : 0u];
    images[1 + m] = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
  }
  std::vector<VkWriteDescriptorSet> writes;
  for (std::uint32_t b = 0; b < OCEAN_BINDING_COUNT; ++b) {
    VkWriteDescriptorSet w{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                           .dstSet = gpu.set,
                           .dstBinding = b,
                           .descriptorCount = 1,
                           .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           .pBufferInfo = &buffers[b]};
    if (b == OCEAN_BINDING_DISP_IMAGE || b == OCEAN_BINDING_NORMAL_IMAGE) {
      w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
      w.pBufferInfo = nullptr;
      w.pImageInfo = b == OCEAN_BINDING_DISP_IMAGE ? &images[0] : &images[1];
      w.descriptorCount = b == OCEAN_BINDING_DISP_IMAGE ? 1u : OCEAN_MAX_MIPS;
    }
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(gpu.ctx->device, static_cast<std::uint32_t>(writes.size()), writes.data(),
                         0, nullptr);
}

void stamp(const GpuState& gpu, VkCommandBuffer cmd, Stamp s) {
  if (gpu.stamps.pool != VK_NULL_HANDLE)
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, gpu.stamps.pool, s);
}

void record_frame(const GpuState& gpu, VkCommandBuffer cmd) {
  const std::uint32_t n = gpu.resolution;
  if (gpu.stamps.pool != VK_NULL_HANDLE) vkCmdResetQueryPool(cmd, gpu.stamps.pool, 0, kStamps);
  stamp(gpu, cmd, start);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gpu.pipeline_layout, 0, 1, &gpu.set,
                          0, nullptr);
  // The previous frame's copies read the outputs this frame overwrites.
  barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
          VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  if (gpu.far_noise.resolution > 0) {
    // The far field's noise map shares nothing with the cascades: its dispatch goes beside the
    // evolution and row FFT with no barrier between them, so the device may run both at once
    // (the concurrent kernels of [VR-GIS FFT+Perlin]). The barrier after the rows, their dependency
    // for the columns, also waits for it (a pipeline barrier's first scope is every earlier command
    // of the queue); the copies at the end read it.
    record_far_noise(gpu.far_noise, cmd);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gpu.pipeline_layout, 0, 1,
                            &gpu.set, 0, nullptr);
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gpu.rows.pipeline);
  vkCmdDispatch(cmd, n, gpu.planes, gpu.cascades);
  barrier(cmd);
  stamp(gpu, cmd, rows);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gpu.columns.pipeline);
  vkCmdDispatch(cmd, n, gpu.planes, gpu.cascades);
  barrier(cmd);
  stamp(gpu, cmd, columns);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gpu.finalize.pipeline);
  vkCmdDispatch(cmd, groups(n), groups(n), gpu.cascades);
  barrier(cmd);
  stamp(gpu, cmd, finalized);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gpu.mips.pipeline);
  for (std::uint32_t level = 1; level <= gpu.log2n; ++level) {
    const shader::MipPush push{.level = level, .size = n >> level};
    vkCmdPushConstants(cmd, gpu.pipeline_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push),
                       &push);
    vkCmdDispatch(cmd, groups(push.size), groups(push.size), gpu.cascades);
    barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
            VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT);
  }
  stamp(gpu, cmd, mipped);
  for (int o = 0; o < kOutputs; ++o) {
    if (!gpu.read_back[static_cast<std::size_t>(o)]) continue;
    const VkBufferCopy region{0, 0, gpu.device[static_cast<std::size_t>(o)].size};
    vkCmdCopyBuffer(cmd, gpu.device[static_cast<std::size_t>(o)].buffer,
                    gpu.host[static_cast<std::size_t>(o)].buffer, 1, &region);
  }
  if (gpu.far_noise.resolution > 0) record_far_noise_copy(gpu.far_noise, cmd);
  const VkMemoryBarrier to_host{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                                .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &to_host, 0, nullptr, 0, nullptr);
  stamp(gpu, cmd, copied);
}

Status transition_images(GpuState& gpu, const Commands& cmds) {
  return run_once(*gpu.ctx, cmds, [&](VkCommandBuffer cmd) {
    VkImageMemoryBarrier b[2];
    const Image* images[2] = {&gpu.displacement_image, &gpu.normal_image};
    for (int i = 0; i < 2; ++i) {
      b[i] = {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
              .srcAccessMask = 0,
              .dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
              .oldLayout = VK_IMAGE_LAYOUT_UNDEFINED,
              .newLayout = VK_IMAGE_LAYOUT_GENERAL,
              .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
              .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
              .image = images[i]->image,
              .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, images[i]->mips, 0,
                                   images[i]->layers}};
    }
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0, nullptr, 2, b);
  });
}

}  // namespace

GpuState::~GpuState() {
  if (ctx == nullptr) return;
  vkDeviceWaitIdle(ctx->device);
  destroy_timestamps(*ctx, stamps);
  destroy_commands(*ctx, frame);
  for (ComputePipeline* p : {&rows, &columns, &finalize, &mips}) destroy_pipeline(*ctx, *p);
  if (pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(ctx->device, pool, nullptr);
  if (pipeline_layout != VK_NULL_HANDLE)
    vkDestroyPipelineLayout(ctx->device, pipeline_layout, nullptr);
  if (set_layout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(ctx->device, set_layout, nullptr);
  destroy_image(*ctx, displacement_image);
  destroy_image(*ctx, normal_image);
  for (Buffer* b : {&params, &spectrum, &phase_rate, &twiddle, &plane_data, &mip_work})
    destroy_buffer(*ctx, *b);
  for (int o = 0; o < kOutputs; ++o) {
    destroy_buffer(*ctx, device[static_cast<std::size_t>(o)]);
    destroy_buffer(*ctx, host[static_cast<std::size_t>(o)]);
  }
}

Status create_gpu_state(GpuState& gpu, const Context& ctx, std::uint32_t resolution,
                        std::uint32_t cascades, std::uint32_t planes, const Uploads& data,
                        const shader::SimParams& params,
                        const std::array<bool, kOutputs>& read_back,
                        std::uint32_t far_noise_resolution) {
  gpu.ctx = &ctx;
  gpu.read_back = read_back;
  gpu.resolution = resolution;
  gpu.log2n = static_cast<std::uint32_t>(std::countr_zero(resolution));
  gpu.cascades = cascades;
  gpu.planes = planes;
  const std::size_t texels = std::size_t{resolution} * resolution;
  const std::size_t chain = (4 * texels - 1) / 3;  // mip_chain_texels

  Result<Commands> cmds = create_commands(ctx);
  if (!cmds.ok()) return cmds.status();
  gpu.frame = cmds.value();

  Result<Buffer> p = create_buffer(ctx, sizeof(shader::SimParams), kStorage, MemoryUse::upload);
  if (!p.ok()) return p.status();
  gpu.params = p.value();
  std::memcpy(gpu.params.mapped, &params, sizeof(params));
  if (Status s =
          upload(ctx, gpu.frame, gpu.spectrum, data.spectrum.data(), data.spectrum.size_bytes());
      !s.ok())
    return s;
  if (Status s = upload(ctx, gpu.frame, gpu.phase_rate, data.phase_rate.data(),
                        data.phase_rate.size_bytes());
      !s.ok())
    return s;
  if (Status s =
          upload(ctx, gpu.frame, gpu.twiddle, data.twiddle.data(), data.twiddle.size_bytes());
      !s.ok())
    return s;
  const auto device_buffer = [&](Buffer& b, std::size_t bytes, VkBufferUsageFlags extra) {
    Result<Buffer> r = create_buffer(ctx, bytes, kStorage | extra, MemoryUse::device);
    if (r.ok()) b = r.value();
    return r.status();
  };
  if (Status s = device_buffer(gpu.plane_data, cascades * planes * texels * 8, 0); !s.ok())
    return s;
  if (Status s = device_buffer(gpu.mip_work, cascades * chain * 16, 0); !s.ok()) return s;
  gpu.bytes_per_cascade = {3 * texels * 4, 4 * texels * 2, 3 * texels * 4,
                           texels * 4,     texels * 4,     chain * 4};
  for (int o = 0; o < kOutputs; ++o) {
    const auto i = static_cast<std::size_t>(o);
    const std::size_t bytes = cascades * gpu.bytes_per_cascade[i];
    if (Status s = device_buffer(gpu.device[i], bytes, kTransferSrc | kTransferDst); !s.ok())
      return s;
    if (!read_back[i]) continue;
    Result<Buffer> r = create_buffer(ctx, bytes, kTransferDst, MemoryUse::readback);
    if (!r.ok()) return r.status();
    gpu.host[i] = r.value();
  }
  // Foam starts at zero (the first frame resets it anyway; this keeps reads defined).
  if (Status s = run_once(ctx, gpu.frame,
                          [&](VkCommandBuffer cmd) {
                            vkCmdFillBuffer(cmd, gpu.device[foam].buffer, 0, VK_WHOLE_SIZE, 0);
                          });
      !s.ok())
    return s;

  const VkImageUsageFlags usage =
      VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  Result<Image> di =
      create_image_array(ctx, VK_FORMAT_R16G16B16A16_SFLOAT, resolution, cascades, 1, usage);
  if (!di.ok()) return di.status();
  gpu.displacement_image = std::move(di).value();
  Result<Image> ni =
      create_image_array(ctx, VK_FORMAT_R8G8B8A8_UNORM, resolution, cascades, gpu.log2n + 1, usage);
  if (!ni.ok()) return ni.status();
  gpu.normal_image = std::move(ni).value();
  if (Status s = transition_images(gpu, gpu.frame); !s.ok()) return s;

  if (Status s = create_layouts(gpu); !s.ok()) return s;
  write_descriptors(gpu);
  const std::uint32_t spec[] = {resolution, gpu.log2n, std::max(1u, resolution / 4)};
  const std::pair<ComputePipeline*, std::span<const std::uint32_t>> kernels[] = {
      {&gpu.rows, spirv::fft_rows()},
      {&gpu.columns, spirv::fft_columns()},
      {&gpu.finalize, spirv::finalize()},
      {&gpu.mips, spirv::mips()}};
  for (const auto& [pipeline, code] : kernels) {
    Result<ComputePipeline> r = create_compute_pipeline(ctx, code, gpu.pipeline_layout, spec);
    if (!r.ok()) return r.status();
    *pipeline = r.value();
  }
  if (Status s = create_far_noise_pass(gpu.far_noise, ctx, far_noise_resolution); !s.ok()) return s;
  if (ctx.timestamps) {
    Result<Timestamps> t = create_timestamps(ctx, kStamps);
    if (!t.ok()) return t.status();
    gpu.stamps = t.value();
  }

  VkCommandBuffer cmd = gpu.frame.buffer;
  if (Status s = check(vkResetCommandBuffer(cmd, 0), "vkResetCommandBuffer"); !s.ok()) return s;
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  if (Status s = check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer"); !s.ok())
    return s;
  record_frame(gpu, cmd);
  return check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
}

}  // namespace ocean::vk::detail
