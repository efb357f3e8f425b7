// A Context around an engine's own instance, physical device, device and queue: checks what the
// library relies on, caches the device's properties, and owns nothing (Context::adopted).
#include <algorithm>
#include <string>

#include "device_query.hpp"
#include "ocean/vk.hpp"

namespace ocean::vk {
namespace {

std::string version_name(std::uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v));
}

// The first requirement `a` misses, or ok.
Status check_request(const AdoptedDevice& a) {
  if (a.instance == VK_NULL_HANDLE || a.physical == VK_NULL_HANDLE || a.device == VK_NULL_HANDLE ||
      a.queue == VK_NULL_HANDLE)
    return invalid_argument(
        "adopt_context: instance, physical device, device and queue must all be set");
  const std::uint32_t need = a.graphics ? VK_API_VERSION_1_3 : VK_API_VERSION_1_2;
  if (a.api_version == 0)
    return invalid_argument(
        "adopt_context: api_version not stated: pass the VkApplicationInfo::apiVersion your "
        "instance was created with (" +
        version_name(need) + " or later)");
  if (a.api_version < need)
    return invalid_argument("adopt_context: the instance was created for Vulkan " +
                            version_name(a.api_version) + "; the library needs " +
                            version_name(need) + (a.graphics ? " to render" : ""));
  if (a.graphics && !a.dynamic_rendering)
    return invalid_argument(
        "adopt_context: rendering needs dynamic rendering: enable "
        "VkPhysicalDeviceVulkan13Features::dynamicRendering at vkCreateDevice and set "
        "dynamic_rendering");
  return {};
}

}  // namespace

Result<std::unique_ptr<Context>> adopt_context(const AdoptedDevice& a) {
  if (Status s = check_request(a); !s.ok()) return s;
  Result<std::vector<VkPhysicalDevice>> devices = detail::physical_devices(a.instance);
  if (!devices.ok()) return devices.status();
  if (std::find(devices.value().begin(), devices.value().end(), a.physical) ==
      devices.value().end())
    return invalid_argument("adopt_context: the physical device is not one of the instance's");

  auto ctx = std::make_unique<Context>();
  ctx->adopted = true;
  ctx->instance = a.instance;
  ctx->physical = a.physical;
  ctx->device = a.device;
  ctx->queue = a.queue;
  ctx->queue_family = a.queue_family;

  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(a.physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(a.physical, &count, families.data());
  const bool in_range = a.queue_family < count;
  detail::read_device(*ctx, in_range && families[a.queue_family].timestampValidBits > 0);
  const std::string device = "Vulkan device '" + ctx->info.name + "'";
  if (!ctx->info.usable) return unsupported(device + " is not usable: " + ctx->info.reason);
  if (a.graphics && ctx->properties.apiVersion < VK_API_VERSION_1_3)
    return unsupported(device + " has Vulkan " + ctx->info.api_version +
                       "; the renderer needs 1.3: update the driver");
  if (!in_range)
    return invalid_argument("adopt_context: queue family " + std::to_string(a.queue_family) +
                            " is out of range: " + device + " has " + std::to_string(count));
  const VkQueueFlags need = VK_QUEUE_COMPUTE_BIT | (a.graphics ? VK_QUEUE_GRAPHICS_BIT : 0);
  if ((families[a.queue_family].queueFlags & need) != need)
    return invalid_argument("adopt_context: queue family " + std::to_string(a.queue_family) +
                            " of " + device + " lacks " +
                            (a.graphics ? "graphics and compute" : "compute"));

  ctx->graphics = a.graphics;
  ctx->wireframe = a.graphics && a.fill_mode_non_solid;
  ctx->multiview = a.graphics && a.multiview;
  ctx->tessellation = a.graphics && a.tessellation_shader;
  if (a.graphics && a.sampler_anisotropy)
    ctx->max_anisotropy = detail::max_anisotropy(ctx->properties);
  return ctx;
}

}  // namespace ocean::vk
