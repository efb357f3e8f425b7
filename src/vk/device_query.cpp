// Physical-device description, queue-family choice and the properties a Context caches.
#include "device_query.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace ocean::vk::detail {
namespace {

std::string version_string(std::uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
         "." + std::to_string(VK_API_VERSION_PATCH(v));
}

const char* type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
  }
}

}  // namespace

bool find_compute_family(VkPhysicalDevice physical, std::uint32_t& family, bool& timestamps,
                         bool graphics) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  const VkQueueFlags need = VK_QUEUE_COMPUTE_BIT | (graphics ? VK_QUEUE_GRAPHICS_BIT : 0);
  for (std::uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & need) == need) {
      family = i;
      timestamps = families[i].timestampValidBits > 0;
      return true;
    }
  }
  return false;
}

DeviceInfo describe(VkPhysicalDevice physical) {
  VkPhysicalDeviceDriverProperties driver{.sType =
                                              VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 props{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                    .pNext = &driver};
  vkGetPhysicalDeviceProperties2(physical, &props);
  DeviceInfo info;
  info.name = props.properties.deviceName;
  info.type = type_name(props.properties.deviceType);
  info.api_version = version_string(props.properties.apiVersion);
  info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
  std::uint32_t family = 0;
  bool timestamps = false;
  if (props.properties.apiVersion < VK_API_VERSION_1_2) {
    info.reason = "Vulkan " + info.api_version + " < 1.2: update the driver";
  } else if (!find_compute_family(physical, family, timestamps)) {
    info.reason = "no compute queue";
  } else {
    info.usable = true;
  }
  return info;
}

Result<std::vector<VkPhysicalDevice>> physical_devices(VkInstance instance) {
  std::uint32_t count = 0;
  if (Status s = check(vkEnumeratePhysicalDevices(instance, &count, nullptr),
                       "vkEnumeratePhysicalDevices");
      !s.ok())
    return s;
  std::vector<VkPhysicalDevice> devices(count);
  if (Status s = check(vkEnumeratePhysicalDevices(instance, &count, devices.data()),
                       "vkEnumeratePhysicalDevices");
      !s.ok())
    return s;
  devices.resize(count);
  if (devices.empty()) return unsupported(kNoDevice);
  return devices;
}

void read_device(Context& ctx, bool family_timestamps) {
  ctx.info = describe(ctx.physical);
  vkGetPhysicalDeviceProperties(ctx.physical, &ctx.properties);
  vkGetPhysicalDeviceMemoryProperties(ctx.physical, &ctx.memory);
  if (ctx.properties.apiVersion >= VK_API_VERSION_1_1) {
    VkPhysicalDeviceIDProperties id{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ID_PROPERTIES};
    VkPhysicalDeviceMaintenance3Properties maintenance3{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES, .pNext = &id};
    VkPhysicalDeviceProperties2 properties2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                            .pNext = &maintenance3};
    vkGetPhysicalDeviceProperties2(ctx.physical, &properties2);
    ctx.max_allocation_bytes = maintenance3.maxMemoryAllocationSize;
    std::copy(std::begin(id.deviceUUID), std::end(id.deviceUUID), ctx.device_uuid.begin());
  }
  ctx.timestamps = family_timestamps && ctx.properties.limits.timestampComputeAndGraphics;
  ctx.timestamp_period_ns = static_cast<double>(ctx.properties.limits.timestampPeriod);
}

float max_anisotropy(const VkPhysicalDeviceProperties& properties) {
  const float most = std::min(16.0f, properties.limits.maxSamplerAnisotropy);
  // Software rasterisers (lavapipe) filter anisotropically ~20× slower than trilinearly: off
  // there unless OCEAN_VK_ANISOTROPY asks for it.
  const bool cpu = properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  float chosen = cpu ? 1.0f : most;
  if (const char* a = std::getenv("OCEAN_VK_ANISOTROPY"); a != nullptr)
    chosen = std::clamp(static_cast<float>(std::atof(a)), 1.0f, most);
  return chosen;
}

bool timeline_exportable(VkPhysicalDevice physical) {
  const VkSemaphoreTypeCreateInfo type{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO,
                                       .semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE};
  const VkPhysicalDeviceExternalSemaphoreInfo info{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTERNAL_SEMAPHORE_INFO,
      .pNext = &type,
      .handleType = VK_EXTERNAL_SEMAPHORE_HANDLE_TYPE_OPAQUE_FD_BIT};
  VkExternalSemaphoreProperties props{.sType = VK_STRUCTURE_TYPE_EXTERNAL_SEMAPHORE_PROPERTIES};
  vkGetPhysicalDeviceExternalSemaphoreProperties(physical, &info, &props);
  const VkExternalSemaphoreFeatureFlags both =
      VK_EXTERNAL_SEMAPHORE_FEATURE_EXPORTABLE_BIT | VK_EXTERNAL_SEMAPHORE_FEATURE_IMPORTABLE_BIT;
  return (props.externalSemaphoreFeatures & both) == both;
}

}  // namespace ocean::vk::detail
