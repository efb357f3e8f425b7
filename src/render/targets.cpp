// The renderer's state (state.hpp): its lifetime, and the targets of a draw — the linear HDR
// image (RGBA16F), its depth (D32), the tone-mapped sRGB image (RGBA8) and the buffer that reads
// either back — with the check that they fit the device and the machine's memory.
#include <algorithm>
#include <string>

#include "object_pass.hpp"
#include "ocean/memory_budget.hpp"
#include "state.hpp"

namespace ocean::render {

Renderer::State::~State() {
  if (ctx == nullptr) return;
  VkDevice d = ctx->device;
  vkDeviceWaitIdle(d);
  destroy_targets();
  destroy_shared();
  destroy_sim_images();
  for_each_pass(*this, [&](auto& p) { p.destroy(*this); });
  for (VkPipeline p : {sky, ocean, wire})
    if (p != VK_NULL_HANDLE) vkDestroyPipeline(d, p, nullptr);
  for (VkShaderModule m : modules) vkDestroyShaderModule(d, m, nullptr);
  if (scene_pipeline_layout != VK_NULL_HANDLE)
    vkDestroyPipelineLayout(d, scene_pipeline_layout, nullptr);
  if (pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(d, pool, nullptr);
  if (scene_layout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(d, scene_layout, nullptr);
  for (VkSampler s : {displacement_sampler, normal_sampler, hdr_sampler})
    if (s != VK_NULL_HANDLE) vkDestroySampler(d, s, nullptr);
  for (vk::Buffer* b : {
           &uniforms,
           &patch_vertices,
           &indices,
           &instances,
           &skirt_vertices,
       })
    vk::destroy_buffer(*ctx, *b);
  vk::destroy_timestamps(*ctx, timestamps);
  vk::destroy_commands(*ctx, commands);
}

void Renderer::State::destroy_targets() {
  for_each_pass(*this, [&](auto& p) { p.release_targets(*this); });
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

Status check_target_size(const vk::Context& ctx, int width, int height) {
  const auto w = static_cast<std::uint64_t>(width), h = static_cast<std::uint64_t>(height);
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const std::string& device = ctx.info.name;
  const std::uint32_t max_side = ctx.properties.limits.maxImageDimension2D;
  if (w > max_side || h > max_side)
    return invalid_argument("image size " + size + " is larger than " + device +
                            " allows: at most " + std::to_string(max_side) +
                            " pixels a side (maxImageDimension2D)");
  // The largest device-local heap, and whether host-visible memory comes from it too (unified
  // memory: integrated GPUs, lavapipe), in which case the read-back buffer counts against it.
  const VkPhysicalDeviceMemoryProperties& memory = ctx.memory;
  std::uint32_t heap = memory.memoryHeapCount;
  for (std::uint32_t i = 0; i < memory.memoryHeapCount; ++i) {
    if ((memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) != 0 &&
        (heap == memory.memoryHeapCount ||
         memory.memoryHeaps[i].size > memory.memoryHeaps[heap].size))
      heap = i;
  }
  bool unified = false;
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    unified = unified ||
              (memory.memoryTypes[i].heapIndex == heap &&
               (memory.memoryTypes[i].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) != 0);
  }
  const std::uint64_t targets = w * h * kTargetBytesPerPixel;
  const std::uint64_t readback = w * h * kReadbackBytesPerPixel;
  if (heap < memory.memoryHeapCount) {
    const std::uint64_t on_heap = targets + (unified ? readback : 0);
    const VkDeviceSize heap_size = memory.memoryHeaps[heap].size;
    if (on_heap > heap_size)
      return invalid_argument("image size " + size + " needs " + format_bytes(on_heap) +
                              " of device memory for its targets" +
                              (unified ? " and read-back buffer" : "") + ", more than the " +
                              format_bytes(heap_size) + " of " + device + "'s device-local heap");
  }
  // The read-back buffer is host memory; on a CPU device the targets are as well.
  const bool cpu = ctx.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  return require_memory("image size " + size + " (the renderer's targets)",
                        readback + (cpu ? targets : 0));
}

Status create_targets(Renderer::State& st, int width, int height) {
  const auto w = static_cast<std::uint32_t>(width), h = static_cast<std::uint32_t>(height);
  Result<vk::Image2D> hdr =
      vk::create_image_2d(*st.ctx, kHdrFormat, w, h,
                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                              VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                              VK_IMAGE_USAGE_TRANSFER_DST_BIT);  // stereo: the eyes' layers
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
  Status sized;
  for_each_pass(st, [&](auto& p) {
    if (sized.ok()) sized = p.resize(st);
  });
  return sized;
}

}  // namespace ocean::render
