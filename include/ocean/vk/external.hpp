// ocean/vk/external.hpp — Vulkan memory and semaphores shared with another API on the same GPU
// (CUDA) through POSIX file descriptors: a buffer whose allocation is exportable, semaphores
// (timeline where the context has them, else binary) exportable the same way, and the imports a
// second device (or a test standing in for CUDA) makes of them.
//
// Vulkan spec 1.3: "Memory Allocation" (VkExportMemoryAllocateInfo, vkGetMemoryFdKHR,
// VkImportMemoryFdInfoKHR), "Synchronization and Cache Control" (timeline semaphores,
// VkExportSemaphoreCreateInfo, vkGetSemaphoreFdKHR, vkImportSemaphoreFdKHR),
// "Capabilities" (vkGetPhysicalDeviceExternalBufferProperties). Handle type: OPAQUE_FD, which
// only the same driver on the same GPU can import (deviceUUID and driverUUID equal).
//
// Contract: every function needs a context made with ContextParams::external_interop whose
// Context::external_memory_fd / external_semaphore_fd say the extension is on (else
// `unsupported`, naming it). A returned descriptor belongs to the caller until an import of it
// succeeds, which takes it over (a failed import leaves it to the caller).
#pragma once

#include <cstdint>
#include <vector>

#include "ocean/interop.hpp"
#include "ocean/vk.hpp"

namespace ocean::vk {

/// This context's side of interop::choose (name, deviceUUID, what it enabled).
interop::VulkanSide interop_side(const Context& ctx);
/// Every physical device's side as a context made with ContextParams::external_interop would
/// have it (what the device advertises), in list_devices() order; `unsupported` without a device.
Result<std::vector<interop::VulkanSide>> list_interop_sides();

/// What an importer of an exported buffer's memory must be told besides the descriptor.
struct ExportedAllocation {
  VkDeviceSize bytes = 0;  ///< VkMemoryAllocateInfo::allocationSize
  bool dedicated = false;  ///< allocated for this buffer alone (the driver's DEDICATED_ONLY)
};
/// A device-local buffer of `size` bytes whose memory can be exported as an opaque fd, in an
/// allocation of its own where the driver requires it.
Result<Buffer> create_exportable_buffer(const Context& ctx, VkDeviceSize size,
                                        VkBufferUsageFlags usage, ExportedAllocation& allocation);
/// A new descriptor for `memory` (made by create_exportable_buffer).
Result<int> export_memory_fd(const Context& ctx, VkDeviceMemory memory);
/// A buffer of `size` bytes bound at offset 0 to the memory behind `fd`, an allocation as
/// described by `allocation` exported by a device with the same UUID.
Result<Buffer> import_buffer(const Context& ctx, int fd, const ExportedAllocation& allocation,
                             VkDeviceSize size, VkBufferUsageFlags usage);

/// A semaphore exportable as an opaque fd: a timeline semaphore (initial value 0) when
/// `timeline`, which needs Context::timeline_semaphore; else a binary one.
Result<VkSemaphore> create_exportable_semaphore(const Context& ctx, bool timeline);
/// A new descriptor for `semaphore` (made by create_exportable_semaphore).
Result<int> export_semaphore_fd(const Context& ctx, VkSemaphore semaphore);
/// A semaphore of the given type whose payload is the one behind `fd` (permanently imported).
Result<VkSemaphore> import_semaphore(const Context& ctx, int fd, bool timeline);

}  // namespace ocean::vk
