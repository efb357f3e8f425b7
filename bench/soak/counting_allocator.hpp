// The soak program's view of the Vulkan driver's host memory: VkAllocationCallbacks that count
// the allocations the driver makes through them and still holds, per allocation scope.
//
// The callbacks are given to vkCreateInstance and vkCreateDevice (counted_device.hpp). The library
// creates every child object (buffers, memory, images, views, pipelines, descriptor sets, command
// pools, fences, ...) with pAllocator = NULL; a driver may then use the device's allocator for the
// child's host memory (Mesa's drivers, lavapipe among them, do), and where it does every live
// object holds at least one VK_SYSTEM_ALLOCATION_SCOPE_OBJECT allocation counted here. Whether it
// does is measured, not assumed: CountedDevice::probe() creates and destroys a buffer.
//
// Contract: thread-safe (relaxed atomics; the driver may allocate from its own threads). Each
// block carries a small header in front of the driver's bytes, so counting costs two atomic adds
// per driver allocation, on top of the malloc the driver would have made anyway.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <atomic>
#include <cstdint>

namespace ocean::soak {

/// The driver's allocations at one moment.
struct DriverMemory {
  std::int64_t objects = 0;  ///< live allocations of scope VK_SYSTEM_ALLOCATION_SCOPE_OBJECT
  std::int64_t all = 0;      ///< live allocations of every scope (command, object, cache, ...)
  std::int64_t bytes = 0;    ///< bytes the live allocations hold (requested sizes)
  std::int64_t made = 0;     ///< allocations made so far, live or not
};

class CountingAllocator {
 public:
  CountingAllocator();
  CountingAllocator(const CountingAllocator&) = delete;
  CountingAllocator& operator=(const CountingAllocator&) = delete;

  /// The callbacks, for pAllocator at creation and destruction of the instance and the device.
  /// Valid while this object lives (it must outlive the instance).
  [[nodiscard]] const VkAllocationCallbacks* callbacks() const { return &callbacks_; }
  /// What the driver holds now.
  [[nodiscard]] DriverMemory live() const;

 private:
  static constexpr std::size_t kScopes = VK_SYSTEM_ALLOCATION_SCOPE_INSTANCE + 1;
  static void* VKAPI_PTR allocate(void* user, std::size_t size, std::size_t alignment,
                                  VkSystemAllocationScope scope);
  static void* VKAPI_PTR reallocate(void* user, void* original, std::size_t size,
                                    std::size_t alignment, VkSystemAllocationScope scope);
  static void VKAPI_PTR release(void* user, void* memory);
  void count(VkSystemAllocationScope scope, std::int64_t allocations, std::int64_t bytes);

  VkAllocationCallbacks callbacks_{};
  std::array<std::atomic<std::int64_t>, kScopes> live_{};
  std::atomic<std::int64_t> bytes_{0};
  std::atomic<std::int64_t> made_{0};
};

}  // namespace ocean::soak
