// Queries of a physical device shared by create_context() and adopt_context(): description for
// `ocean info`, queue-family choice, the device's own properties on a Context. Private to src/vk.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "ocean/vk.hpp"

namespace ocean::vk::detail {

inline constexpr const char* kNoDevice =
    "no Vulkan device: install mesa-vulkan-drivers or a GPU driver";

/// Name, type, versions and whether the device is usable (Vulkan ≥ 1.2 with a compute queue).
DeviceInfo describe(VkPhysicalDevice physical);

/// The first queue family with compute (a graphics+compute family is fine); with `graphics`, the
/// first that has both. `timestamps`: the family's timestampValidBits > 0.
bool find_compute_family(VkPhysicalDevice physical, std::uint32_t& family, bool& timestamps,
                         bool graphics = false);

/// Every physical device of `instance`; `unsupported` (kNoDevice) when there is none.
Result<std::vector<VkPhysicalDevice>> physical_devices(VkInstance instance);

/// Fills ctx.info, properties, memory and timestamp_period_ns from ctx.physical, and
/// ctx.timestamps from the family's timestamp bits and timestampComputeAndGraphics.
void read_device(Context& ctx, bool family_timestamps);

/// The sampler anisotropy the renderer uses when samplerAnisotropy is enabled: the device's
/// limit up to 16, 1 on software rasterisers unless OCEAN_VK_ANISOTROPY asks for more.
float max_anisotropy(const VkPhysicalDeviceProperties& properties);

/// A timeline semaphore of `physical` can be exported and imported as an opaque fd.
bool timeline_exportable(VkPhysicalDevice physical);

}  // namespace ocean::vk::detail
