// Exportable and imported memory and semaphores (ocean/vk/external.hpp).
#include "ocean/vk/external.hpp"

#include <string>
#include <string_view>

#include "device_query.hpp"

namespace ocean::vk {
namespace {

constexpr VkExternalMemoryHandleTypeFlagBits kMemoryFd =
    VK_EXTERNAL_MEMORY_HANDLE_TYPE_OPAQUE_FD_BIT;
constexpr VkExternalSemaphoreHandleTypeFlagBits kSemaphoreFd =
    VK_EXTERNAL_SEMAPHORE_HANDLE_TYPE_OPAQUE_FD_BIT;

// The device-level entry point `name` (extension functions are not exported by the loader).
template <typename F>
F device_function(const Context& ctx, const char* name) {
  return reinterpret_cast<F>(vkGetDeviceProcAddr(ctx.device, name));
}

Status need_memory_fd(const Context& ctx) {
  if (ctx.external_memory_fd) return {};
  return unsupported(
      "Vulkan device '" + ctx.info.name +
      "': VK_KHR_external_memory_fd is not enabled (ContextParams::external_interop)");
}
Status need_semaphore_fd(const Context& ctx) {
  if (ctx.external_semaphore_fd) return {};
  return unsupported(
      "Vulkan device '" + ctx.info.name +
      "': VK_KHR_external_semaphore_fd is not enabled (ContextParams::external_interop)");
}

// The first device-local memory type of `bits`.
int device_local_type(const Context& ctx, std::uint32_t bits) {
  for (std::uint32_t i = 0; i < ctx.memory.memoryTypeCount; ++i)
    if ((bits & (1u << i)) != 0 &&
        (ctx.memory.memoryTypes[i].propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) != 0)
      return static_cast<int>(i);
  return -1;
}

// Whether opaque-fd memory for a buffer of `usage` must be a dedicated allocation.
bool dedicated_only(const Context& ctx, VkBufferUsageFlags usage) {
  const VkPhysicalDeviceExternalBufferInfo info{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTERNAL_BUFFER_INFO,
      .usage = usage,
      .handleType = kMemoryFd};
  VkExternalBufferProperties props{.sType = VK_STRUCTURE_TYPE_EXTERNAL_BUFFER_PROPERTIES};
  vkGetPhysicalDeviceExternalBufferProperties(ctx.physical, &info, &props);
  return (props.externalMemoryProperties.externalMemoryFeatures &
          VK_EXTERNAL_MEMORY_FEATURE_DEDICATED_ONLY_BIT) != 0;
}

// A buffer with external-memory create info and its memory allocated with `next` (export or
// import info, then a dedicated-allocation info where `allocation.dedicated`) and bound;
// `allocation.bytes` 0 takes the buffer's requirement, and receives the size allocated.
Result<Buffer> make_buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                           const void* next, ExportedAllocation& allocation) {
  Buffer b;
  b.size = size;
  const VkExternalMemoryBufferCreateInfo external{
      .sType = VK_STRUCTURE_TYPE_EXTERNAL_MEMORY_BUFFER_CREATE_INFO, .handleTypes = kMemoryFd};
  const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                .pNext = &external,
                                .size = size,
                                .usage = usage,
                                .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
  if (Status s = check(vkCreateBuffer(ctx.device, &info, nullptr, &b.buffer), "vkCreateBuffer");
      !s.ok())
    return s;
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(ctx.device, b.buffer, &req);
  const int type = device_local_type(ctx, req.memoryTypeBits);
  const VkDeviceSize bytes = allocation.bytes != 0 ? allocation.bytes : req.size;
  Status s;
  if (type < 0) s = unsupported("Vulkan device '" + ctx.info.name + "' has no shareable memory");
  if (s.ok() && bytes < req.size)
    s = invalid_argument("imported memory of " + std::to_string(bytes) + " bytes is smaller than " +
                         "the buffer's " + std::to_string(req.size));
  if (s.ok()) {
    const VkMemoryDedicatedAllocateInfo dedicated{
        .sType = VK_STRUCTURE_TYPE_MEMORY_DEDICATED_ALLOCATE_INFO, .buffer = b.buffer};
    // `next` is one const struct of ours whose pNext is null: chain the dedicated info after it
    // through a copy.
    VkImportMemoryFdInfoKHR import{};
    VkExportMemoryAllocateInfo exported{};
    const void* chain = next;
    if (allocation.dedicated) {
      const auto* base = static_cast<const VkBaseInStructure*>(next);
      if (base->sType == VK_STRUCTURE_TYPE_IMPORT_MEMORY_FD_INFO_KHR) {
        import = *static_cast<const VkImportMemoryFdInfoKHR*>(next);
        import.pNext = &dedicated;
        chain = &import;
      } else {
        exported = *static_cast<const VkExportMemoryAllocateInfo*>(next);
        exported.pNext = &dedicated;
        chain = &exported;
      }
    }
    const VkMemoryAllocateInfo allocate{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                        .pNext = chain,
                                        .allocationSize = bytes,
                                        .memoryTypeIndex = static_cast<std::uint32_t>(type)};
    s = check(vkAllocateMemory(ctx.device, &allocate, nullptr, &b.memory), "vkAllocateMemory");
  }
  if (s.ok())
    s = check(vkBindBufferMemory(ctx.device, b.buffer, b.memory, 0), "vkBindBufferMemory");
  if (!s.ok()) {
    destroy_buffer(ctx, b);
    return s;
  }
  allocation.bytes = bytes;
  return b;
}

}  // namespace

interop::VulkanSide interop_side(const Context& ctx) {
  return {.name = ctx.info.name,
          .uuid = ctx.device_uuid,
          .memory_fd = ctx.external_memory_fd,
          .semaphore_fd = ctx.external_semaphore_fd,
          .timeline = ctx.timeline_exportable};
}

Result<std::vector<interop::VulkanSide>> list_interop_sides() {
  Context ctx;  // an instance only (destroyed with ctx)
  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "ocean",
                              .apiVersion = VK_API_VERSION_1_3};
  const VkInstanceCreateInfo info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                  .pApplicationInfo = &app};
  if (Status s = check(vkCreateInstance(&info, nullptr, &ctx.instance), "vkCreateInstance");
      !s.ok())
    return s;
  Result<std::vector<VkPhysicalDevice>> devices = detail::physical_devices(ctx.instance);
  if (!devices.ok()) return devices.status();
  std::vector<interop::VulkanSide> sides;
  for (VkPhysicalDevice d : devices.value()) {
    ctx.physical = d;
    detail::read_device(ctx, false);
    std::uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(d, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(d, nullptr, &count, extensions.data());
    const auto has = [&](std::string_view name) {
      for (const VkExtensionProperties& e : extensions)
        if (name == e.extensionName) return true;
      return false;
    };
    interop::VulkanSide side{.name = ctx.info.name,
                             .uuid = ctx.device_uuid,
                             .memory_fd = has(VK_KHR_EXTERNAL_MEMORY_FD_EXTENSION_NAME),
                             .semaphore_fd = has(VK_KHR_EXTERNAL_SEMAPHORE_FD_EXTENSION_NAME)};
    side.timeline = side.semaphore_fd && detail::timeline_exportable(d);
    sides.push_back(side);
  }
  return sides;
}

Result<Buffer> create_exportable_buffer(const Context& ctx, VkDeviceSize size,
                                        VkBufferUsageFlags usage, ExportedAllocation& allocation) {
  if (Status s = need_memory_fd(ctx); !s.ok()) return s;
  const VkExportMemoryAllocateInfo exported{.sType = VK_STRUCTURE_TYPE_EXPORT_MEMORY_ALLOCATE_INFO,
                                            .handleTypes = kMemoryFd};
  allocation = {.bytes = 0, .dedicated = dedicated_only(ctx, usage)};
  return make_buffer(ctx, size, usage, &exported, allocation);
}

Result<int> export_memory_fd(const Context& ctx, VkDeviceMemory memory) {
  if (Status s = need_memory_fd(ctx); !s.ok()) return s;
  auto get = device_function<PFN_vkGetMemoryFdKHR>(ctx, "vkGetMemoryFdKHR");
  const VkMemoryGetFdInfoKHR info{
      .sType = VK_STRUCTURE_TYPE_MEMORY_GET_FD_INFO_KHR, .memory = memory, .handleType = kMemoryFd};
  int fd = -1;
  if (Status s = check(get(ctx.device, &info, &fd), "vkGetMemoryFdKHR"); !s.ok()) return s;
  return fd;
}

Result<Buffer> import_buffer(const Context& ctx, int fd, const ExportedAllocation& allocation,
                             VkDeviceSize size, VkBufferUsageFlags usage) {
  if (Status s = need_memory_fd(ctx); !s.ok()) return s;
  const VkImportMemoryFdInfoKHR imported{
      .sType = VK_STRUCTURE_TYPE_IMPORT_MEMORY_FD_INFO_KHR, .handleType = kMemoryFd, .fd = fd};
  ExportedAllocation a = allocation;
  return make_buffer(ctx, size, usage, &imported, a);
}

Result<VkSemaphore> create_exportable_semaphore(const Context& ctx, bool timeline) {
  if (Status s = need_semaphore_fd(ctx); !s.ok()) return s;
  if (timeline && !ctx.timeline_exportable)
    return unsupported("Vulkan device '" + ctx.info.name +
                       "' cannot export timeline semaphores: use binary ones");
  const VkSemaphoreTypeCreateInfo type{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO,
                                       .semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE,
                                       .initialValue = 0};
  const VkExportSemaphoreCreateInfo exported{
      .sType = VK_STRUCTURE_TYPE_EXPORT_SEMAPHORE_CREATE_INFO,
      .pNext = timeline ? &type : nullptr,
      .handleTypes = kSemaphoreFd};
  const VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO,
                                   .pNext = &exported};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  if (Status s =
          check(vkCreateSemaphore(ctx.device, &info, nullptr, &semaphore), "vkCreateSemaphore");
      !s.ok())
    return s;
  return semaphore;
}

Result<int> export_semaphore_fd(const Context& ctx, VkSemaphore semaphore) {
  if (Status s = need_semaphore_fd(ctx); !s.ok()) return s;
  auto get = device_function<PFN_vkGetSemaphoreFdKHR>(ctx, "vkGetSemaphoreFdKHR");
  const VkSemaphoreGetFdInfoKHR info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_GET_FD_INFO_KHR,
                                     .semaphore = semaphore,
                                     .handleType = kSemaphoreFd};
  int fd = -1;
  if (Status s = check(get(ctx.device, &info, &fd), "vkGetSemaphoreFdKHR"); !s.ok()) return s;
  return fd;
}

Result<VkSemaphore> import_semaphore(const Context& ctx, int fd, bool timeline) {
  if (Status s = need_semaphore_fd(ctx); !s.ok()) return s;
  if (timeline && !ctx.timeline_exportable)
    return unsupported("Vulkan device '" + ctx.info.name + "' has no timeline semaphores enabled");
  const VkSemaphoreTypeCreateInfo type{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO,
                                       .semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE};
  const VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO,
                                   .pNext = timeline ? &type : nullptr};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  if (Status s =
          check(vkCreateSemaphore(ctx.device, &info, nullptr, &semaphore), "vkCreateSemaphore");
      !s.ok())
    return s;
  auto import = device_function<PFN_vkImportSemaphoreFdKHR>(ctx, "vkImportSemaphoreFdKHR");
  const VkImportSemaphoreFdInfoKHR imported{.sType = VK_STRUCTURE_TYPE_IMPORT_SEMAPHORE_FD_INFO_KHR,
                                            .semaphore = semaphore,
                                            .handleType = kSemaphoreFd,
                                            .fd = fd};
  if (Status s = check(import(ctx.device, &imported), "vkImportSemaphoreFdKHR"); !s.ok()) {
    vkDestroySemaphore(ctx.device, semaphore, nullptr);
    return s;
  }
  return semaphore;
}

}  // namespace ocean::vk
