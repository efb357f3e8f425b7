// A Vulkan instance and device made by the soak program with counting allocation callbacks
// (counting_allocator.hpp) and handed to the library with vk::adopt_context, the way an engine
// hands over its own device. The library is used unchanged: it creates its objects on the adopted
// device exactly as on one of vk::create_context.
//
// Contract: make() picks the first device in the loader's order (discrete GPUs first) with Vulkan
// 1.3, dynamic rendering and a graphics+compute queue family; unsupported when there is none. The
// destructor destroys the device and the instance, so every library object made on context()
// (scene, renderer, backend) and every other holder of context() must be gone first.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>

#include "counting_allocator.hpp"
#include "ocean/vk.hpp"

namespace ocean::soak {

/// What probe() saw: the driver's allocations while a buffer and its memory existed, against
/// before, and after they were destroyed, against before.
struct ProbeResult {
  std::int64_t objects_while_alive = 0;  ///< ≥ 2 where the driver counts child objects
  std::int64_t objects_after = 0;        ///< 0 where destruction frees what creation took
};

class CountedDevice {
 public:
  static Result<std::unique_ptr<CountedDevice>> make();
  ~CountedDevice();
  CountedDevice(const CountedDevice&) = delete;
  CountedDevice& operator=(const CountedDevice&) = delete;

  [[nodiscard]] const std::shared_ptr<vk::Context>& context() const { return context_; }
  /// The driver's live allocations made through the callbacks (instance, device and children).
  [[nodiscard]] DriverMemory live() const { return allocator_.live(); }
  /// Creates a small host-visible buffer with vk::create_buffer and destroys it, counting: tells
  /// whether this driver's object counts see the library's objects at all.
  Result<ProbeResult> probe();

 private:
  CountedDevice() = default;
  CountingAllocator allocator_;  // first: outlives the instance and device made with it
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  std::shared_ptr<vk::Context> context_;
};

}  // namespace ocean::soak
