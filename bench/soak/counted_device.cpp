// The soak program's own instance and device, counted and adopted (counted_device.hpp).
#include "counted_device.hpp"

#include <cassert>
#include <string>
#include <vector>

namespace ocean::soak {

namespace {

struct Candidate {
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  std::uint32_t family = 0;
  VkPhysicalDeviceFeatures optional{};  // fillModeNonSolid, samplerAnisotropy where present
};

// What the renderer needs of `d`: Vulkan 1.3, dynamic rendering, a graphics+compute family.
Candidate examine(VkPhysicalDevice d) {
  Candidate c;
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(d, &properties);
  VkPhysicalDeviceVulkan13Features features13{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                     .pNext = &features13};
  vkGetPhysicalDeviceFeatures2(d, &features);
  if (properties.apiVersion < VK_API_VERSION_1_3 || features13.dynamicRendering != VK_TRUE)
    return c;
  std::uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(d, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(d, &n, families.data());
  constexpr VkQueueFlags kNeed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (std::uint32_t f = 0; f < n; ++f) {
    if ((families[f].queueFlags & kNeed) != kNeed) continue;
    c = {.physical = d, .family = f};
    c.optional.fillModeNonSolid = features.features.fillModeNonSolid;
    c.optional.samplerAnisotropy = features.features.samplerAnisotropy;
    break;
  }
  return c;
}

}  // namespace

Result<std::unique_ptr<CountedDevice>> CountedDevice::make() {
  auto d = std::unique_ptr<CountedDevice>(new CountedDevice());
  const VkAllocationCallbacks* callbacks = d->allocator_.callbacks();
  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "soak",
                              .apiVersion = VK_API_VERSION_1_3};
  const VkInstanceCreateInfo instance_info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                           .pApplicationInfo = &app};
  if (VkResult r = vkCreateInstance(&instance_info, callbacks, &d->instance_); r != VK_SUCCESS) {
    d->instance_ = VK_NULL_HANDLE;
    return vk::check(r, "vkCreateInstance");
  }
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(d->instance_, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(d->instance_, &count, devices.data());
  // The first that qualifies: the loader lists discrete GPUs first, then integrated, virtual and
  // CPU devices (Vulkan loader 1.3.204 and later), the order vk::create_context prefers.
  Candidate best;
  for (VkPhysicalDevice p : devices) {
    best = examine(p);
    if (best.physical != VK_NULL_HANDLE) break;
  }
  if (best.physical == VK_NULL_HANDLE)
    return unsupported(
        "no Vulkan 1.3 device with dynamic rendering and a graphics queue: install "
        "mesa-vulkan-drivers or a GPU driver");

  VkPhysicalDeviceVulkan13Features features13{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, .dynamicRendering = VK_TRUE};
  const VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                           .pNext = &features13,
                                           .features = best.optional};
  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queue_info{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                           .queueFamilyIndex = best.family,
                                           .queueCount = 1,
                                           .pQueuePriorities = &priority};
  const VkDeviceCreateInfo device_info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                       .pNext = &features,
                                       .queueCreateInfoCount = 1,
                                       .pQueueCreateInfos = &queue_info};
  if (VkResult r = vkCreateDevice(best.physical, &device_info, callbacks, &d->device_);
      r != VK_SUCCESS) {
    d->device_ = VK_NULL_HANDLE;
    return vk::check(r, "vkCreateDevice");
  }
  VkQueue queue = VK_NULL_HANDLE;
  vkGetDeviceQueue(d->device_, best.family, 0, &queue);
  Result<std::unique_ptr<vk::Context>> adopted = vk::adopt_context({
      .instance = d->instance_,
      .physical = best.physical,
      .device = d->device_,
      .queue_family = best.family,
      .queue = queue,
      .api_version = VK_API_VERSION_1_3,
      .graphics = true,
      .dynamic_rendering = true,
      .fill_mode_non_solid = best.optional.fillModeNonSolid == VK_TRUE,
      .sampler_anisotropy = best.optional.samplerAnisotropy == VK_TRUE,
  });
  if (!adopted.ok()) return adopted.status();
  d->context_ = std::move(adopted).value();
  return d;
}

CountedDevice::~CountedDevice() {
  // Every library object made on the context holds a reference to it: this one must be the last.
  assert(context_ == nullptr || context_.use_count() == 1);
  context_.reset();
  const VkAllocationCallbacks* callbacks = allocator_.callbacks();
  if (device_ != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device_);
    vkDestroyDevice(device_, callbacks);
  }
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, callbacks);
}

Result<ProbeResult> CountedDevice::probe() {
  constexpr VkDeviceSize kBytes = 4096;
  const DriverMemory before = live();
  Result<vk::Buffer> buffer =
      vk::create_buffer(*context_, kBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryUse::upload);
  if (!buffer.ok()) return buffer.status();
  const DriverMemory alive = live();
  vk::destroy_buffer(*context_, buffer.value());
  const DriverMemory after = live();
  return ProbeResult{.objects_while_alive = alive.objects - before.objects,
                     .objects_after = after.objects - before.objects};
}

}  // namespace ocean::soak
