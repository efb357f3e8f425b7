// ocean/interop.hpp — handing a GPU simulation's outputs to the renderer on another API without a
// host round trip (CUDA → Vulkan): the byte layout both sides write and read, the exported handles
// that pass between them, and the decision whether the two sides are the same GPU and can share
// memory at all. Plain data and pure functions: no Vulkan or CUDA header.
//
// The exchange, per frame n = 1, 2, … (docs/architecture.md, "CUDA to the renderer"):
//   simulation: wait `read` ≥ n − 1, write frame n into the shared buffer, signal `written` = n;
//   renderer:   wait `written` ≥ n, copy the buffer into its sampled images, signal `read` = n.
// With binary semaphores (no timeline support) each signal is waited for exactly once, in the
// same order; the simulation skips the wait of frame 1.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace ocean::interop {

/// Where each cascade's renderer inputs sit in the shared buffer (and in the renderer's upload
/// staging buffer, the same layout): first every cascade's displacement as half4 (Dx, h, Dz, 0),
/// N² texels of 8 bytes, then every cascade's packed RGBA8 mip chain (ocean/sim.hpp
/// mip_chain_texels, mip_offset), 4 bytes a texel. Offsets are multiples of 4 bytes.
struct InputsLayout {
  int resolution = 0;  ///< N
  int cascades = 0;
  std::size_t displacement_bytes = 0;  ///< one cascade's half4 map: 8·N²
  std::size_t mips_bytes = 0;          ///< one cascade's mip chain: 4·mip_chain_texels(N)
  [[nodiscard]] std::size_t displacement_offset(int cascade) const {
    return static_cast<std::size_t>(cascade) * displacement_bytes;
  }
  [[nodiscard]] std::size_t mips_offset(int cascade) const {
    return static_cast<std::size_t>(cascades) * displacement_bytes +
           static_cast<std::size_t>(cascade) * mips_bytes;
  }
  [[nodiscard]] std::size_t bytes() const {
    return static_cast<std::size_t>(cascades) * (displacement_bytes + mips_bytes);
  }
};
/// The layout for N = `resolution` (a power of two) and `cascades` cascades.
InputsLayout inputs_layout(int resolution, int cascades);

/// A device UUID (VkPhysicalDeviceIDProperties::deviceUUID, cudaDeviceProp::uuid): 16 bytes.
using Uuid = std::array<std::uint8_t, 16>;
/// "GPU-xxxxxxxx-xxxx-xxxx-xxxx-xxxxxxxxxxxx", as nvidia-smi prints it.
std::string to_string(const Uuid& uuid);

/// The renderer's side: its Vulkan device and what the context enabled (vk::Context).
struct VulkanSide {
  std::string name;
  Uuid uuid{};
  bool memory_fd = false;     ///< VK_KHR_external_memory_fd enabled
  bool semaphore_fd = false;  ///< VK_KHR_external_semaphore_fd enabled
  bool timeline = false;      ///< timelineSemaphore enabled, exportable as an opaque fd
};
/// One CUDA device (cuda::list_devices).
struct CudaSide {
  int index = 0;
  std::string name;
  Uuid uuid{};
  bool usable = false;
};

/// What the two sides can do together.
struct Choice {
  int cuda_device = -1;    ///< the CUDA device to simulate on; −1 when none is usable
  bool zero_copy = false;  ///< share memory and semaphores (else: read back and upload)
  bool timeline = false;   ///< timeline semaphores (else binary)
  std::string reason;      ///< one line: why zero_copy, or why not and what happens instead
};
/// Zero-copy needs the Vulkan side's two fd extensions and a usable CUDA device with the same
/// UUID (the same GPU). Without a match the first usable CUDA device simulates and its frames
/// are uploaded (zero_copy false, `reason` says why); without a usable one, cuda_device is −1.
Choice choose(const VulkanSide& vulkan, std::span<const CudaSide> cuda);

/// Handles exported by the renderer for the simulation to import (POSIX file descriptors,
/// "opaque fd" handle types). The importer owns each descriptor once its import succeeds
/// (Vulkan spec, "External Memory Handle Types"; CUDA Runtime API, cudaImportExternalMemory);
/// before that the exporter's `close_unimported` closes what is left.
struct SharedInputs {
  int memory_fd = -1;              ///< the buffer's whole allocation
  std::uint64_t memory_bytes = 0;  ///< VkMemoryAllocateInfo::allocationSize
  InputsLayout layout;             ///< the buffer holds layout.bytes() from offset 0
  int written_fd = -1;             ///< signalled by the simulation when a frame is in the buffer
  int read_fd = -1;                ///< signalled by the renderer when it has copied a frame
  // written_fd and read_fd are −1 where the renderer's device cannot export semaphores (its
  // timeline semaphores then serve a producer on the host: Renderer::shared_semaphores).
  bool timeline = false;  ///< both semaphores are timeline semaphores
  /// The allocation is dedicated to the buffer (the driver asks for it: DEDICATED_ONLY); the
  /// importer must say so (cudaExternalMemoryDedicated, VkMemoryDedicatedAllocateInfo).
  bool dedicated = false;
};
/// Closes every descriptor still ≥ 0 and sets it to −1.
void close_unimported(SharedInputs& shared);

}  // namespace ocean::interop
