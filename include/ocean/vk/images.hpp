// ocean/vk/images.hpp — the simulation's output images on the GPU, as Vulkan handles: what a
// simulation that runs on a vk::Context (the Vulkan backend, ocean/backends/vulkan.hpp) hands to
// a consumer on the same context (the renderer, ocean/render.hpp) so that it samples them where
// they are, with no copy. A plain description of the vk layer: neither side depends on the other.
//
// Texel formats are those of the CPU Frame's arrays (ocean/sim.hpp): displacement as half floats
// (Dx, h, Dz, 0), normal/foam as the packed RGBA8 mip chain (n_x, n_z, foam, smoothness), the far
// field's noise map as float3 in a buffer.
#pragma once

#include <cstdint>

#include "ocean/vk.hpp"

namespace ocean::vk {

/// The simulation's GPU images, valid until the producer's next configure() or its destruction.
/// Both stay in VK_IMAGE_LAYOUT_GENERAL; a frame's writes are complete when the producer says so
/// (VulkanBackend: when step() or read() returns).
struct SimulationImages {
  VkImage displacement = VK_NULL_HANDLE;  ///< RGBA16F (Dx, h, Dz, 0), one array layer per cascade
  VkImageView displacement_view = VK_NULL_HANDLE;
  VkImage normal_foam = VK_NULL_HANDLE;  ///< RGBA8 unorm (n_x, n_z, foam, smoothness), all mips
  VkImageView normal_foam_view = VK_NULL_HANDLE;
  std::uint32_t size = 0, layers = 0, mips = 0;  ///< side N, cascades, mip levels (log2 N + 1)
  /// The far field's noise map (SimulationConfig::far_noise): a storage buffer of float3
  /// (h, ∂h/∂x, ∂h/∂z) per texel, row-major, as Frame::far_noise's array; written by the frame's
  /// submission like the images. VK_NULL_HANDLE and 0 while the map is off.
  VkBuffer far_noise = VK_NULL_HANDLE;
  std::uint32_t far_noise_resolution = 0;  ///< N texels per side
};

}  // namespace ocean::vk
