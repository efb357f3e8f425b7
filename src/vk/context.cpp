// The library's own context: instance, validation messenger, physical-device selection, logical
// device with one queue; the device list; VkResult → Status mapping.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>

#include "device_query.hpp"
#include "ocean/vk.hpp"

namespace ocean::vk {
namespace {

using detail::describe;
using detail::kNoDevice;
using detail::physical_devices;

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::mutex g_message_mutex;  // guards Context::last_validation_message across callbacks

// Preference when choosing automatically: discrete > integrated > virtual > cpu > other.
int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
  }
}

bool has_layer(const char* name) {
  std::uint32_t count = 0;
  if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
    return std::strcmp(l.layerName, name) == 0;
  });
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                          void* user) {
  auto* ctx = static_cast<Context*>(user);
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT && ctx != nullptr) {
    ctx->validation_messages.fetch_add(1);
    const std::lock_guard lock(g_message_mutex);
    static const bool verbose = std::getenv("OCEAN_VK_VERBOSE") != nullptr;
    if (verbose && data->pMessage != nullptr) std::fprintf(stderr, "vulkan: %s\n", data->pMessage);
    ctx->last_validation_message = data->pMessage != nullptr ? data->pMessage : "";
  }
  return VK_FALSE;
}

Status create_instance(Context& ctx, bool validation,
                       const std::vector<const char*>& extra_extensions = {}) {
  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "ocean",
                              .applicationVersion = VK_MAKE_API_VERSION(0, 0, 1, 0),
                              .pEngineName = "ocean",
                              .engineVersion = VK_MAKE_API_VERSION(0, 0, 1, 0),
                              .apiVersion = VK_API_VERSION_1_3};
  const char* layers[] = {kValidationLayer};
  std::vector<const char*> extensions = extra_extensions;
  if (validation) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  const VkDebugUtilsMessengerCreateInfoEXT messenger_info{
      .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
      .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
      // Performance advice (e.g. "prefer TRANSFER_SRC_OPTIMAL over GENERAL") is not counted: the
      // simulation's images stay in GENERAL on purpose, shared by compute, copies and sampling.
      .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
      .pfnUserCallback = on_message,
      .pUserData = &ctx};
  const VkInstanceCreateInfo info{
      .sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
      .pNext = validation ? &messenger_info : nullptr,
      .pApplicationInfo = &app,
      .enabledLayerCount = validation ? 1u : 0u,
      .ppEnabledLayerNames = validation ? layers : nullptr,
      .enabledExtensionCount = static_cast<std::uint32_t>(extensions.size()),
      .ppEnabledExtensionNames = extensions.data()};
  const VkResult r = vkCreateInstance(&info, nullptr, &ctx.instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER || r == VK_ERROR_INITIALIZATION_FAILED)
    return unsupported(kNoDevice);
  if (r == VK_ERROR_EXTENSION_NOT_PRESENT)
    return unsupported("the Vulkan loader lacks a window-system extension (no display?)");
  if (Status s = check(r, "vkCreateInstance"); !s.ok()) return s;
  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(ctx.instance, "vkCreateDebugUtilsMessengerEXT"));
    if (create == nullptr) return unsupported("the Vulkan loader lacks VK_EXT_debug_utils");
    if (Status s = check(create(ctx.instance, &messenger_info, nullptr, &ctx.messenger),
                         "vkCreateDebugUtilsMessengerEXT");
        !s.ok())
      return s;
  }
  ctx.validation = validation;
  return {};
}

}  // namespace

Status check(VkResult result, const char* what) {
  if (result == VK_SUCCESS) return {};
  const std::string op(what);
  switch (result) {
    case VK_ERROR_OUT_OF_HOST_MEMORY:
      return {ErrorCode::internal,
              op + ": out of host memory: free memory or lower the resolution"};
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
      return {ErrorCode::internal,
              op + ": out of device memory: lower the resolution or the number of cascades"};
    case VK_ERROR_DEVICE_LOST:
      return {ErrorCode::internal,
              op + ": Vulkan device lost (driver reset or crash): restart, or use --backend cpu"};
    case VK_ERROR_LAYER_NOT_PRESENT:
      return unsupported(op + ": Vulkan validation layer missing: install vulkan-validationlayers");
    case VK_ERROR_INCOMPATIBLE_DRIVER:
    case VK_ERROR_INITIALIZATION_FAILED: return unsupported(op + ": " + kNoDevice);
    case VK_TIMEOUT:
      return {ErrorCode::internal, op + ": timed out waiting for the GPU (hung device?)"};
    default: return {ErrorCode::internal, op + " failed with VkResult " + std::to_string(result)};
  }
}

Context::~Context() {
  if (adopted) return;  // the caller's handles: adopt_context()
  if (device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device);
    vkDestroyDevice(device, nullptr);
  }
  if (messenger != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy != nullptr) destroy(instance, messenger, nullptr);
  }
  if (instance != VK_NULL_HANDLE) vkDestroyInstance(instance, nullptr);
}

Result<std::vector<DeviceInfo>> list_devices() {
  Context ctx;
  if (Status s = create_instance(ctx, false); !s.ok()) return s;
  Result<std::vector<VkPhysicalDevice>> devices = physical_devices(ctx.instance);
  if (!devices.ok()) return devices.status();
  std::vector<DeviceInfo> out;
  for (VkPhysicalDevice d : devices.value()) out.push_back(describe(d));
  return out;
}

Result<std::unique_ptr<Context>> create_context(const ContextParams& params) {
  auto ctx = std::make_unique<Context>();
  const char* env = std::getenv("OCEAN_VK_VALIDATION");
  const bool validation = params.validation || (env != nullptr && std::strcmp(env, "1") == 0);
  if (validation && !has_layer(kValidationLayer))
    return unsupported("Vulkan validation requested but " + std::string(kValidationLayer) +
                       " is missing: install vulkan-validationlayers");
  if (Status s = create_instance(*ctx, validation, params.instance_extensions); !s.ok()) return s;
  Result<std::vector<VkPhysicalDevice>> devices = physical_devices(ctx->instance);
  if (!devices.ok()) return devices.status();

  int chosen = -1;
  if (params.device_index >= 0) {
    if (static_cast<std::size_t>(params.device_index) >= devices.value().size())
      return invalid_argument("device = " + std::to_string(params.device_index) +
                              " is out of range: must be < " +
                              std::to_string(devices.value().size()) + " (see ocean info)");
    const DeviceInfo info =
        describe(devices.value()[static_cast<std::size_t>(params.device_index)]);
    if (!info.usable)
      return unsupported("Vulkan device '" + info.name + "' is not usable: " + info.reason);
    chosen = params.device_index;
  } else {
    int best_rank = -1;
    for (std::size_t i = 0; i < devices.value().size(); ++i) {
      if (!describe(devices.value()[i]).usable) continue;
      VkPhysicalDeviceProperties p;
      vkGetPhysicalDeviceProperties(devices.value()[i], &p);
      if (type_rank(p.deviceType) > best_rank) {
        best_rank = type_rank(p.deviceType);
        chosen = static_cast<int>(i);
      }
    }
    if (chosen < 0)
      return unsupported("no usable Vulkan device (needs Vulkan 1.2 with compute): " +
                         std::string(kNoDevice));
  }
  ctx->physical = devices.value()[static_cast<std::size_t>(chosen)];
  bool family_timestamps = false;
  const bool found = detail::find_compute_family(ctx->physical, ctx->queue_family,
                                                 family_timestamps, params.graphics);
  detail::read_device(*ctx, family_timestamps);
  if (!found) return unsupported("Vulkan device '" + ctx->info.name + "' has no graphics queue");

  // The renderer's features: dynamic rendering (core 1.3), wireframe, anisotropic filtering and
  // multiview and tessellation shaders where present.
  VkPhysicalDeviceVulkan11Features features11{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
  VkPhysicalDeviceVulkan13Features features13{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, .pNext = &features11};
  VkPhysicalDeviceFeatures2 supported{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                      .pNext = &features13};
  VkPhysicalDeviceFeatures2 enabled{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan11Features enabled11{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
  VkPhysicalDeviceVulkan13Features enabled13{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, .pNext = &enabled11};
  std::vector<const char*> device_extensions;
  if (params.graphics) {
    if (ctx->properties.apiVersion < VK_API_VERSION_1_3)
      return unsupported("Vulkan device '" + ctx->info.name + "' has Vulkan " +
                         ctx->info.api_version + "; the renderer needs 1.3: update the driver");
    vkGetPhysicalDeviceFeatures2(ctx->physical, &supported);
    if (features13.dynamicRendering != VK_TRUE)
      return unsupported("Vulkan device '" + ctx->info.name + "' lacks dynamic rendering");
    enabled13.dynamicRendering = VK_TRUE;
    enabled.pNext = &enabled13;
    enabled.features.fillModeNonSolid = supported.features.fillModeNonSolid;
    enabled.features.samplerAnisotropy = supported.features.samplerAnisotropy;
    enabled.features.tessellationShader = supported.features.tessellationShader;
    ctx->tessellation = supported.features.tessellationShader == VK_TRUE;
    ctx->graphics = true;
    ctx->wireframe = supported.features.fillModeNonSolid == VK_TRUE;
    // Stereo in one pass (VK_KHR_multiview, core since 1.1).
    enabled11.multiview = params.multiview ? features11.multiview : VK_FALSE;
    ctx->multiview = enabled11.multiview == VK_TRUE;
    if (supported.features.samplerAnisotropy == VK_TRUE)
      ctx->max_anisotropy = detail::max_anisotropy(ctx->properties);
  }
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(ctx->physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(ctx->physical, nullptr, &count, extensions.data());
  const auto has = [&](const char* name) {
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
  };
  if (params.swapchain) {
    if (!has(VK_KHR_SWAPCHAIN_EXTENSION_NAME))
      return unsupported("Vulkan device '" + ctx->info.name +
                         "' cannot present to a window (no VK_KHR_swapchain)");
    device_extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  }
  for (const char* name : params.device_extensions) {
    if (!has(name))
      return unsupported("Vulkan device '" + ctx->info.name + "' lacks the extension " +
                         excerpt(name));
    device_extensions.push_back(name);
  }

  // Sharing memory and semaphores with CUDA (ocean/vk/external.hpp), where the device can.
  VkPhysicalDeviceVulkan12Features enabled12{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  if (params.external_interop) {
    ctx->external_memory_fd = has(VK_KHR_EXTERNAL_MEMORY_FD_EXTENSION_NAME);
    ctx->external_semaphore_fd = has(VK_KHR_EXTERNAL_SEMAPHORE_FD_EXTENSION_NAME);
    if (ctx->external_memory_fd)
      device_extensions.push_back(VK_KHR_EXTERNAL_MEMORY_FD_EXTENSION_NAME);
    if (ctx->external_semaphore_fd)
      device_extensions.push_back(VK_KHR_EXTERNAL_SEMAPHORE_FD_EXTENSION_NAME);
    // Timeline semaphores (core 1.2), also where they cannot be exported: a producer on the
    // host or on this device can still use the renderer's (Renderer::shared_semaphores).
    VkPhysicalDeviceVulkan12Features features12{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceFeatures2 query{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                    .pNext = &features12};
    vkGetPhysicalDeviceFeatures2(ctx->physical, &query);
    if (features12.timelineSemaphore == VK_TRUE) {
      enabled12.timelineSemaphore = VK_TRUE;
      enabled12.pNext = enabled.pNext;
      enabled.pNext = &enabled12;
      ctx->timeline_semaphore = true;
      ctx->timeline_exportable =
          ctx->external_semaphore_fd && detail::timeline_exportable(ctx->physical);
    }
  }

  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queue{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                      .queueFamilyIndex = ctx->queue_family,
                                      .queueCount = 1,
                                      .pQueuePriorities = &priority};
  const VkDeviceCreateInfo info{
      .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
      .pNext = params.graphics || ctx->timeline_semaphore ? &enabled : nullptr,
      .queueCreateInfoCount = 1,
      .pQueueCreateInfos = &queue,
      .enabledExtensionCount = static_cast<std::uint32_t>(device_extensions.size()),
      .ppEnabledExtensionNames = device_extensions.data()};
  if (Status s =
          check(vkCreateDevice(ctx->physical, &info, nullptr, &ctx->device), "vkCreateDevice");
      !s.ok())
    return s;
  vkGetDeviceQueue(ctx->device, ctx->queue_family, 0, &ctx->queue);
  return ctx;
}

}  // namespace ocean::vk
