// Buffers and images with memory-type selection, compute pipelines from SPIR-V, command
// submission, barriers and timestamp queries.
#include <algorithm>
#include <cassert>
#include <cstring>
#include <string>

#include "ocean/memory_budget.hpp"
#include "ocean/vk.hpp"

namespace ocean::vk {
namespace {

// The first memory type allowed by `bits` that has all of `required`, preferring `preferred`.
int find_memory_type(const Context& ctx, std::uint32_t bits, VkMemoryPropertyFlags required,
                     VkMemoryPropertyFlags preferred) {
  int fallback = -1;
  for (std::uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i) {
    const VkMemoryPropertyFlags flags = ctx.memory.memoryTypes[i].propertyFlags;
    if ((bits & (1u << i)) == 0 || (flags & required) != required) continue;
    if ((flags & preferred) == preferred) return static_cast<int>(i);
    if (fallback < 0) fallback = static_cast<int>(i);
  }
  return fallback;
}

Result<VkDeviceMemory> allocate(const Context& ctx, const VkMemoryRequirements& req,
                                VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
  if (ctx.max_allocation_bytes != 0 && req.size > ctx.max_allocation_bytes)
    return invalid_argument("one allocation of " + format_bytes(req.size) + " is more than " +
                            ctx.info.name + " allows (maxMemoryAllocationSize " +
                            format_bytes(ctx.max_allocation_bytes) + ")");
  const int type = find_memory_type(ctx, req.memoryTypeBits, required, preferred);
  if (type < 0)
    return unsupported("Vulkan device '" + ctx.info.name + "' has no suitable memory type");
  const VkMemoryAllocateInfo info{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                  .allocationSize = req.size,
                                  .memoryTypeIndex = static_cast<std::uint32_t>(type)};
  VkDeviceMemory memory = VK_NULL_HANDLE;
  if (Status s = check(vkAllocateMemory(ctx.device, &info, nullptr, &memory),
                       ("vkAllocateMemory (" + std::to_string(req.size >> 20) + " MiB)").c_str());
      !s.ok())
    return s;
  return memory;
}

// A device-local 2D image (array) of `layers` layers and `mips` levels with its memory bound.
Status create_device_image(const Context& ctx, VkFormat format, std::uint32_t width,
                           std::uint32_t height, std::uint32_t layers, std::uint32_t mips,
                           VkImageUsageFlags usage, VkImage& image, VkDeviceMemory& memory) {
  const VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                               .imageType = VK_IMAGE_TYPE_2D,
                               .format = format,
                               .extent = {width, height, 1},
                               .mipLevels = mips,
                               .arrayLayers = layers,
                               .samples = VK_SAMPLE_COUNT_1_BIT,
                               .tiling = VK_IMAGE_TILING_OPTIMAL,
                               .usage = usage,
                               .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                               .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
  if (Status s = check(vkCreateImage(ctx.device, &info, nullptr, &image), "vkCreateImage"); !s.ok())
    return s;
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(ctx.device, image, &req);
  Result<VkDeviceMemory> m = allocate(ctx, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
  if (!m.ok()) {
    vkDestroyImage(ctx.device, image, nullptr);
    image = VK_NULL_HANDLE;
    return m.status();
  }
  memory = m.value();
  return check(vkBindImageMemory(ctx.device, image, memory, 0), "vkBindImageMemory");
}

}  // namespace

Result<Buffer> create_buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                             MemoryUse use) {
  assert(size > 0);
  Buffer b;
  b.size = size;
  const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                .size = size,
                                .usage = usage,
                                .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
  if (Status s = check(vkCreateBuffer(ctx.device, &info, nullptr, &b.buffer), "vkCreateBuffer");
      !s.ok())
    return s;
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(ctx.device, b.buffer, &req);
  const VkMemoryPropertyFlags host =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  VkMemoryPropertyFlags required = 0, preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  if (use == MemoryUse::upload) required = host;
  if (use == MemoryUse::readback) required = host, preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
  Result<VkDeviceMemory> memory = allocate(ctx, req, required, preferred);
  if (!memory.ok()) {
    vkDestroyBuffer(ctx.device, b.buffer, nullptr);
    return memory.status();
  }
  b.memory = memory.value();
  Status s = check(vkBindBufferMemory(ctx.device, b.buffer, b.memory, 0), "vkBindBufferMemory");
  if (s.ok() && use != MemoryUse::device)
    s = check(vkMapMemory(ctx.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  if (!s.ok()) {
    destroy_buffer(ctx, b);
    return s;
  }
  return b;
}

void destroy_buffer(const Context& ctx, Buffer& b) {
  if (b.buffer != VK_NULL_HANDLE) vkDestroyBuffer(ctx.device, b.buffer, nullptr);
  if (b.memory != VK_NULL_HANDLE) vkFreeMemory(ctx.device, b.memory, nullptr);
  b = {};
}

Result<Image> create_image_array(const Context& ctx, VkFormat format, std::uint32_t size,
                                 std::uint32_t layers, std::uint32_t mips,
                                 VkImageUsageFlags usage) {
  Image im;
  im.format = format, im.size = size, im.layers = layers, im.mips = mips;
  Status s = create_device_image(ctx, format, size, size, layers, mips, usage, im.image, im.memory);
  const auto make_view = [&](std::uint32_t base, std::uint32_t count, VkImageView& view) {
    const VkImageViewCreateInfo v{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = im.image,
        .viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY,
        .format = format,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, base, count, 0, layers}};
    return check(vkCreateImageView(ctx.device, &v, nullptr, &view), "vkCreateImageView");
  };
  if (s.ok()) s = make_view(0, mips, im.view);
  im.mip_views.assign(mips, VK_NULL_HANDLE);
  for (std::uint32_t m = 0; m < mips && s.ok(); ++m) s = make_view(m, 1, im.mip_views[m]);
  if (!s.ok()) {
    destroy_image(ctx, im);
    return s;
  }
  return im;
}

void destroy_image(const Context& ctx, Image& im) {
  for (VkImageView v : im.mip_views)
    if (v != VK_NULL_HANDLE) vkDestroyImageView(ctx.device, v, nullptr);
  if (im.view != VK_NULL_HANDLE) vkDestroyImageView(ctx.device, im.view, nullptr);
  if (im.image != VK_NULL_HANDLE) vkDestroyImage(ctx.device, im.image, nullptr);
  if (im.memory != VK_NULL_HANDLE) vkFreeMemory(ctx.device, im.memory, nullptr);
  im = {};
}

Result<Image2D> create_image_2d(const Context& ctx, VkFormat format, std::uint32_t width,
                                std::uint32_t height, VkImageUsageFlags usage,
                                VkImageAspectFlags aspect, std::uint32_t layers,
                                std::uint32_t mips) {
  Image2D im;
  im.format = format, im.width = width, im.height = height, im.layers = layers, im.mips = mips;
  Status s =
      create_device_image(ctx, format, width, height, layers, mips, usage, im.image, im.memory);
  const auto make_view = [&](std::uint32_t levels, VkImageView& view) {
    const VkImageViewCreateInfo v{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = im.image,
        .viewType = layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D,
        .format = format,
        .subresourceRange = {aspect, 0, levels, 0, layers}};
    return check(vkCreateImageView(ctx.device, &v, nullptr, &view), "vkCreateImageView");
  };
  if (s.ok()) s = make_view(mips, im.view);
  if (s.ok() && mips > 1) s = make_view(1, im.level0_view);
  if (!s.ok()) {
    destroy_image(ctx, im);
    return s;
  }
  return im;
}

void destroy_image(const Context& ctx, Image2D& im) {
  if (im.view != VK_NULL_HANDLE) vkDestroyImageView(ctx.device, im.view, nullptr);
  if (im.level0_view != VK_NULL_HANDLE) vkDestroyImageView(ctx.device, im.level0_view, nullptr);
  if (im.image != VK_NULL_HANDLE) vkDestroyImage(ctx.device, im.image, nullptr);
  if (im.memory != VK_NULL_HANDLE) vkFreeMemory(ctx.device, im.memory, nullptr);
  im = {};
}

Result<Buffer> create_static_buffer(const Context& ctx, const Commands& commands,
                                    std::span<const std::byte> bytes, VkBufferUsageFlags usage) {
  Result<Buffer> staging =
      create_buffer(ctx, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::upload);
  if (!staging.ok()) return staging.status();
  Buffer up = staging.value();
  std::memcpy(up.mapped, bytes.data(), bytes.size());
  Result<Buffer> buffer =
      create_buffer(ctx, bytes.size(), usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::device);
  if (!buffer.ok()) {
    destroy_buffer(ctx, up);
    return buffer.status();
  }
  Buffer out = buffer.value();
  const Status s = run_once(ctx, commands, [&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, bytes.size()};
    vkCmdCopyBuffer(cmd, up.buffer, out.buffer, 1, &region);
    barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT);
  });
  destroy_buffer(ctx, up);
  if (!s.ok()) {
    destroy_buffer(ctx, out);
    return s;
  }
  return out;
}

Result<ComputePipeline> create_compute_pipeline(const Context& ctx,
                                                std::span<const std::uint32_t> spirv,
                                                VkPipelineLayout layout,
                                                std::span<const std::uint32_t> specialization) {
  ComputePipeline p;
  const VkShaderModuleCreateInfo module{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                        .codeSize = spirv.size_bytes(),
                                        .pCode = spirv.data()};
  if (Status s = check(vkCreateShaderModule(ctx.device, &module, nullptr, &p.module),
                       "vkCreateShaderModule");
      !s.ok())
    return s;
  std::vector<VkSpecializationMapEntry> entries(specialization.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    entries[i] = {static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(4 * i), 4};
  }
  const VkSpecializationInfo spec{.mapEntryCount = static_cast<std::uint32_t>(entries.size()),
                                  .pMapEntries = entries.data(),
                                  .dataSize = specialization.size_bytes(),
                                  .pData = specialization.data()};
  const VkComputePipelineCreateInfo info{
      .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
      .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                .module = p.module,
                .pName = "main",
                .pSpecializationInfo = entries.empty() ? nullptr : &spec},
      .layout = layout};
  if (Status s = check(
          vkCreateComputePipelines(ctx.device, VK_NULL_HANDLE, 1, &info, nullptr, &p.pipeline),
          "vkCreateComputePipelines");
      !s.ok()) {
    destroy_pipeline(ctx, p);
    return s;
  }
  return p;
}

void destroy_pipeline(const Context& ctx, ComputePipeline& p) {
  if (p.pipeline != VK_NULL_HANDLE) vkDestroyPipeline(ctx.device, p.pipeline, nullptr);
  if (p.module != VK_NULL_HANDLE) vkDestroyShaderModule(ctx.device, p.module, nullptr);
  p = {};
}

Result<Commands> create_commands(const Context& ctx) {
  Commands c;
  const VkCommandPoolCreateInfo pool{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                     .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                     .queueFamilyIndex = ctx.queue_family};
  Status s = check(vkCreateCommandPool(ctx.device, &pool, nullptr, &c.pool), "vkCreateCommandPool");
  if (s.ok()) {
    const VkCommandBufferAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                            .commandPool = c.pool,
                                            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                            .commandBufferCount = 1};
    s = check(vkAllocateCommandBuffers(ctx.device, &alloc, &c.buffer), "vkAllocateCommandBuffers");
  }
  if (s.ok()) {
    const VkFenceCreateInfo fence{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    s = check(vkCreateFence(ctx.device, &fence, nullptr, &c.fence), "vkCreateFence");
  }
  if (!s.ok()) {
    destroy_commands(ctx, c);
    return s;
  }
  return c;
}

void destroy_commands(const Context& ctx, Commands& c) {
  if (c.fence != VK_NULL_HANDLE) vkDestroyFence(ctx.device, c.fence, nullptr);
  if (c.pool != VK_NULL_HANDLE) vkDestroyCommandPool(ctx.device, c.pool, nullptr);
  c = {};
}

Status submit(const Context& ctx, const Commands& c) {
  const VkSubmitInfo info{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                          .commandBufferCount = 1,
                          .pCommandBuffers = &c.buffer};
  return check(vkQueueSubmit(ctx.queue, 1, &info, c.fence), "vkQueueSubmit");
}

Status wait(const Context& ctx, const Commands& c, std::uint64_t timeout_ns) {
  if (Status s =
          check(vkWaitForFences(ctx.device, 1, &c.fence, VK_TRUE, timeout_ns), "vkWaitForFences");
      !s.ok())
    return s;
  return check(vkResetFences(ctx.device, 1, &c.fence), "vkResetFences");
}

namespace {
// The accesses a set of stages can perform (only those the stages support, as validation requires).
VkAccessFlags accesses(VkPipelineStageFlags stages, bool writes_only) {
  VkAccessFlags a = 0;
  if ((stages & VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT) != 0)
    a |= writes_only ? VK_ACCESS_SHADER_WRITE_BIT
                     : VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  if ((stages & VK_PIPELINE_STAGE_TRANSFER_BIT) != 0)
    a |= writes_only ? VK_ACCESS_TRANSFER_WRITE_BIT
                     : VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  if ((stages & VK_PIPELINE_STAGE_HOST_BIT) != 0)
    a |=
        writes_only ? VK_ACCESS_HOST_WRITE_BIT : VK_ACCESS_HOST_READ_BIT | VK_ACCESS_HOST_WRITE_BIT;
  if (!writes_only) {  // graphics stages are only ever read by the barriers of this project
    if ((stages & VK_PIPELINE_STAGE_VERTEX_INPUT_BIT) != 0)
      a |= VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDEX_READ_BIT;
    if ((stages & (VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT)) !=
        0)
      a |= VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_UNIFORM_READ_BIT;
    if ((stages & VK_PIPELINE_STAGE_ALL_COMMANDS_BIT) != 0)
      a |= VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  }
  return a;
}
}  // namespace

void barrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkPipelineStageFlags dst) {
  const VkMemoryBarrier b{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                          .srcAccessMask = accesses(src, true),
                          .dstAccessMask = accesses(dst, false)};
  vkCmdPipelineBarrier(cmd, src, dst, 0, 1, &b, 0, nullptr, 0, nullptr);
}

namespace {

// A layout transition of `range` of `image` with explicit stages and accesses.
void range_barrier(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range,
                   VkImageLayout from, VkImageLayout to, VkPipelineStageFlags src_stage,
                   VkAccessFlags src_access, VkPipelineStageFlags dst_stage,
                   VkAccessFlags dst_access) {
  const VkImageMemoryBarrier b{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                               .srcAccessMask = src_access,
                               .dstAccessMask = dst_access,
                               .oldLayout = from,
                               .newLayout = to,
                               .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                               .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                               .image = image,
                               .subresourceRange = range};
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

}  // namespace

void image_barrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                   VkPipelineStageFlags src_stage, VkAccessFlags src_access,
                   VkPipelineStageFlags dst_stage, VkAccessFlags dst_access,
                   VkImageAspectFlags aspect) {
  range_barrier(cmd, image, {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS},
                from, to, src_stage, src_access, dst_stage, dst_access);
}

void generate_mips(VkCommandBuffer cmd, const Image2D& im) {
  const auto barrier = [&](std::uint32_t level, std::uint32_t count, VkImageLayout from,
                           VkImageLayout to, VkPipelineStageFlags src_stage,
                           VkAccessFlags src_access, VkPipelineStageFlags dst_stage,
                           VkAccessFlags dst_access) {
    range_barrier(cmd, im.image, {VK_IMAGE_ASPECT_COLOR_BIT, level, count, 0, im.layers}, from, to,
                  src_stage, src_access, dst_stage, dst_access);
  };
  // Level 0 (rendered) and the rest (undefined) to the blits' layouts.
  barrier(0, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
          VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  if (im.mips > 1)
    barrier(1, im.mips - 1, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
            VK_ACCESS_TRANSFER_WRITE_BIT);
  for (std::uint32_t level = 1; level < im.mips; ++level) {
    const auto w = [&](std::uint32_t l) {
      return static_cast<std::int32_t>(std::max(im.width >> l, 1u));
    };
    const auto h = [&](std::uint32_t l) {
      return static_cast<std::int32_t>(std::max(im.height >> l, 1u));
    };
    const VkImageBlit blit{
        .srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, im.layers},
        .srcOffsets = {{0, 0, 0}, {w(level - 1), h(level - 1), 1}},
        .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, im.layers},
        .dstOffsets = {{0, 0, 0}, {w(level), h(level), 1}}};
    vkCmdBlitImage(cmd, im.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, im.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
    barrier(level, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  }
  barrier(0, im.mips, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
          VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT,
          VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
}

Result<Timestamps> create_timestamps(const Context& ctx, std::uint32_t count) {
  if (!ctx.timestamps)
    return unsupported("Vulkan device '" + ctx.info.name + "' has no compute timestamps");
  Timestamps t;
  t.count = count;
  const VkQueryPoolCreateInfo info{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                   .queryType = VK_QUERY_TYPE_TIMESTAMP,
                                   .queryCount = count};
  if (Status s = check(vkCreateQueryPool(ctx.device, &info, nullptr, &t.pool), "vkCreateQueryPool");
      !s.ok())
    return s;
  return t;
}

void destroy_timestamps(const Context& ctx, Timestamps& t) {
  if (t.pool != VK_NULL_HANDLE) vkDestroyQueryPool(ctx.device, t.pool, nullptr);
  t = {};
}

Status read_timestamps_ms(const Context& ctx, const Timestamps& t, std::span<double> out_ms) {
  assert(out_ms.size() <= t.count);
  std::uint64_t ticks[64];
  assert(out_ms.size() <= 64);
  const auto n = static_cast<std::uint32_t>(out_ms.size());
  if (Status s = check(vkGetQueryPoolResults(ctx.device, t.pool, 0, n, sizeof(ticks), ticks,
                                             sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT),
                       "vkGetQueryPoolResults");
      !s.ok())
    return s;
  for (std::uint32_t i = 0; i < n; ++i) {
    out_ms[i] = static_cast<double>(ticks[i] - ticks[0]) * ctx.timestamp_period_ns * 1e-6;
  }
  return {};
}

}  // namespace ocean::vk
