// The shared-input layout and the CUDA–Vulkan pairing decision (ocean/interop.hpp).
#include "ocean/interop.hpp"

#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cstdio>

#include "ocean/sim.hpp"

namespace ocean::interop {

InputsLayout inputs_layout(int resolution, int cascades) {
  assert(resolution > 0 && (resolution & (resolution - 1)) == 0 && cascades > 0);
  const auto n = static_cast<std::size_t>(resolution);
  return {.resolution = resolution,
          .cascades = cascades,
          .displacement_bytes = n * n * 8,
          .mips_bytes = mip_chain_texels(resolution) * 4};
}

std::string to_string(const Uuid& u) {
  char text[48];
  std::snprintf(text, sizeof text,
                "GPU-%02x%02x%02x%02x-%02x%02x-%02x%02x-%02x%02x-%02x%02x%02x%02x%02x%02x", u[0],
                u[1], u[2], u[3], u[4], u[5], u[6], u[7], u[8], u[9], u[10], u[11], u[12], u[13],
                u[14], u[15]);
  return text;
}

Choice choose(const VulkanSide& vulkan, std::span<const CudaSide> cuda) {
  Choice c;
  const auto first_usable =
      std::find_if(cuda.begin(), cuda.end(), [](const CudaSide& d) { return d.usable; });
  if (first_usable == cuda.end()) {
    c.reason = "no usable CUDA device";
    return c;
  }
  c.cuda_device = first_usable->index;
  const std::string upload = ": CUDA frames are read back and uploaded";
  if (!vulkan.memory_fd || !vulkan.semaphore_fd) {
    c.reason = "Vulkan device '" + vulkan.name + "' lacks " +
               (vulkan.memory_fd ? "VK_KHR_external_semaphore_fd" : "VK_KHR_external_memory_fd") +
               upload;
    return c;
  }
  const auto same = std::find_if(cuda.begin(), cuda.end(), [&](const CudaSide& d) {
    return d.usable && d.uuid == vulkan.uuid;
  });
  if (same == cuda.end()) {
    c.reason = "no CUDA device is the Vulkan device '" + vulkan.name + "' (" +
               to_string(vulkan.uuid) + ")" + upload;
    return c;
  }
  c.cuda_device = same->index;
  c.zero_copy = true;
  c.timeline = vulkan.timeline;
  c.reason = "CUDA device " + std::to_string(same->index) + " '" + same->name +
             "' shares memory with the renderer (" + (vulkan.timeline ? "timeline" : "binary") +
             " semaphores)";
  return c;
}

void close_unimported(SharedInputs& s) {
  for (int* fd : {&s.memory_fd, &s.written_fd, &s.read_fd}) {
    if (*fd >= 0) ::close(*fd);
    *fd = -1;
  }
}

}  // namespace ocean::interop
