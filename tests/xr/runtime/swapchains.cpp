// The test runtime's swapchains: images made on the application's Vulkan device (as a runtime
// with XR_KHR_vulkan_enable must), handed over in COLOR_ATTACHMENT_OPTIMAL, and read back at
// xrEndFrame to check that the application drew into them.
#include <png.h>

#include <algorithm>
#include <cstring>
#include <utility>

#include "runtime.hpp"

namespace ocean::test_xr {

namespace {

std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags wanted) {
  VkPhysicalDeviceMemoryProperties props;
  vkGetPhysicalDeviceMemoryProperties(runtime().binding.physicalDevice, &props);
  for (std::uint32_t i = 0; i < props.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  return UINT32_MAX;
}

// Records `record` into a one-shot command buffer, submits it on the application's queue and
// waits (the application waits for its own work before releasing an image).
template <typename Record>
bool submit_once(Record record) {
  Runtime& rt = runtime();
  const VkDevice device = rt.binding.device;
  const VkCommandBufferAllocateInfo alloc{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                          .commandPool = rt.pool,
                                          .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                          .commandBufferCount = 1};
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  if (vkAllocateCommandBuffers(device, &alloc, &cmd) != VK_SUCCESS) return false;
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  vkBeginCommandBuffer(cmd, &begin);
  record(cmd);
  vkEndCommandBuffer(cmd);
  const VkSubmitInfo submit{
      .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
  bool ok = vkQueueSubmit(rt.queue, 1, &submit, VK_NULL_HANDLE) == VK_SUCCESS &&
            vkQueueWaitIdle(rt.queue) == VK_SUCCESS;
  vkFreeCommandBuffers(device, rt.pool, 1, &cmd);
  return ok;
}

void barrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to) {
  const VkImageMemoryBarrier b{
      .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
      .srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT,
      .dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT,
      .oldLayout = from,
      .newLayout = to,
      .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
      .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
      .image = image,
      .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       0, 0, nullptr, 0, nullptr, 1, &b);
}

}  // namespace

bool open_device_queue() {
  Runtime& rt = runtime();
  vkGetDeviceQueue(rt.binding.device, rt.binding.queueFamilyIndex, rt.binding.queueIndex,
                   &rt.queue);
  const VkCommandPoolCreateInfo info{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                     .queueFamilyIndex = rt.binding.queueFamilyIndex};
  return vkCreateCommandPool(rt.binding.device, &info, nullptr, &rt.pool) == VK_SUCCESS;
}

void close_device_queue() {
  Runtime& rt = runtime();
  if (rt.pool != VK_NULL_HANDLE) vkDestroyCommandPool(rt.binding.device, rt.pool, nullptr);
  rt.pool = VK_NULL_HANDLE;
}

XrResult create_swapchain(const XrSwapchainCreateInfo& info, XrSwapchain* out) {
  Runtime& rt = runtime();
  const auto format = static_cast<VkFormat>(info.format);
  if (format != VK_FORMAT_R8G8B8A8_SRGB && format != VK_FORMAT_B8G8R8A8_SRGB)
    return XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED;
  if (info.arraySize != 1 || info.mipCount != 1 || info.faceCount != 1 || info.sampleCount != 1 ||
      info.width == 0 || info.height == 0 || info.width > 4096 || info.height > 4096)
    return XR_ERROR_VALIDATION_FAILURE;
  auto s = std::make_unique<Swapchain>();
  s->width = info.width;
  s->height = info.height;
  s->format = format;
  VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if (info.usageFlags & XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT)
    usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (info.usageFlags & XR_SWAPCHAIN_USAGE_SAMPLED_BIT) usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
  for (int i = 0; i < 3; ++i) {
    const VkImageCreateInfo ici{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                                .imageType = VK_IMAGE_TYPE_2D,
                                .format = format,
                                .extent = {info.width, info.height, 1},
                                .mipLevels = 1,
                                .arrayLayers = 1,
                                .samples = VK_SAMPLE_COUNT_1_BIT,
                                .tiling = VK_IMAGE_TILING_OPTIMAL,
                                .usage = usage,
                                .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
    VkImage image = VK_NULL_HANDLE;
    if (vkCreateImage(rt.binding.device, &ici, nullptr, &image) != VK_SUCCESS)
      return XR_ERROR_RUNTIME_FAILURE;
    s->images.push_back(image);
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(rt.binding.device, image, &req);
    const VkMemoryAllocateInfo mai{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = req.size,
        .memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)};
    VkDeviceMemory memory = VK_NULL_HANDLE;
    if (mai.memoryTypeIndex == UINT32_MAX ||
        vkAllocateMemory(rt.binding.device, &mai, nullptr, &memory) != VK_SUCCESS) {
      destroy_swapchain(*s);
      return XR_ERROR_RUNTIME_FAILURE;
    }
    s->memory.push_back(memory);
    vkBindImageMemory(rt.binding.device, image, memory, 0);
  }
  // Images are handed to the application in COLOR_ATTACHMENT_OPTIMAL (XR_KHR_vulkan_enable).
  if (!submit_once([&](VkCommandBuffer cmd) {
        for (VkImage image : s->images)
          barrier(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
      })) {
    destroy_swapchain(*s);
    return XR_ERROR_RUNTIME_FAILURE;
  }
  *out = reinterpret_cast<XrSwapchain>(s.get());
  rt.swapchains.push_back(std::move(s));
  return XR_SUCCESS;
}

void destroy_swapchain(Swapchain& s) {
  const VkDevice device = runtime().binding.device;
  for (VkImage image : s.images) vkDestroyImage(device, image, nullptr);
  for (VkDeviceMemory memory : s.memory) vkFreeMemory(device, memory, nullptr);
  s.images.clear();
  s.memory.clear();
}

bool read_back(Swapchain& s, std::uint32_t image, std::vector<std::uint8_t>& rgba) {
  Runtime& rt = runtime();
  const VkDevice device = rt.binding.device;
  const VkDeviceSize bytes = VkDeviceSize{s.width} * s.height * 4;
  const VkBufferCreateInfo bci{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                               .size = bytes,
                               .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT};
  VkBuffer buffer = VK_NULL_HANDLE;
  if (vkCreateBuffer(device, &bci, nullptr, &buffer) != VK_SUCCESS) return false;
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, buffer, &req);
  const VkMemoryAllocateInfo mai{
      .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
      .allocationSize = req.size,
      .memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                             VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)};
  VkDeviceMemory memory = VK_NULL_HANDLE;
  bool read = false;
  if (mai.memoryTypeIndex != UINT32_MAX &&
      vkAllocateMemory(device, &mai, nullptr, &memory) == VK_SUCCESS) {
    vkBindBufferMemory(device, buffer, memory, 0);
    const VkImage img = s.images[image];
    const bool ok = submit_once([&](VkCommandBuffer cmd) {
      barrier(cmd, img, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
      const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                     .imageExtent = {s.width, s.height, 1}};
      vkCmdCopyImageToBuffer(cmd, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
      barrier(cmd, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
              VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    });
    void* mapped = nullptr;
    if (ok && vkMapMemory(device, memory, 0, bytes, 0, &mapped) == VK_SUCCESS) {
      const auto* px = static_cast<const std::uint8_t*>(mapped);
      rgba.assign(px, px + bytes);
      if (s.format == VK_FORMAT_B8G8R8A8_SRGB)
        for (std::size_t i = 0; i < rgba.size(); i += 4) std::swap(rgba[i], rgba[i + 2]);
      read = true;
      vkUnmapMemory(device, memory);
    }
    vkFreeMemory(device, memory, nullptr);
  }
  vkDestroyBuffer(device, buffer, nullptr);
  return read;
}

bool write_png(const std::string& path, std::uint32_t width, std::uint32_t height,
               const std::vector<std::uint8_t>& rgba) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = width;
  image.height = height;
  image.format = PNG_FORMAT_RGBA;
  return png_image_write_to_file(&image, path.c_str(), 0, rgba.data(), 0, nullptr) != 0;
}

}  // namespace ocean::test_xr
