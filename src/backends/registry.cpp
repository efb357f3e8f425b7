// The backend table: every backend by name, with a clear answer for those not built in.
#include <string>

#include "ocean/backends.hpp"
#include "ocean/cpu_backend.hpp"
#include "ocean/fft.hpp"
#ifdef OCEAN_HAS_VULKAN
#include "ocean/vk/simulation.hpp"
#endif
#ifdef OCEAN_HAS_CUDA
#include "ocean/cuda/simulation.hpp"
#endif

namespace ocean {
namespace {

// With probe = false no Vulkan instance is created (make_backend for other names stays cheap).
BackendInfo vulkan_info(bool probe) {
#ifdef OCEAN_HAS_VULKAN
  if (!probe) return {"vulkan", true, "Vulkan compute"};
  Result<std::vector<vk::DeviceInfo>> devices = vk::list_devices();
  if (!devices.ok()) return {"vulkan", false, devices.status().message()};
  for (const vk::DeviceInfo& d : devices.value()) {
    if (d.usable) return {"vulkan", true, "Vulkan compute on " + d.name + " (" + d.type + ")"};
  }
  return {"vulkan", false, "no usable Vulkan device (needs Vulkan 1.2 with compute)"};
#else
  (void)probe;
  return {"vulkan", false,
          "built without Vulkan: the Vulkan compute backend is not part of this build"};
#endif
}

// With probe = false the CUDA runtime is not asked (no driver call, no context).
BackendInfo cuda_info(bool probe) {
#ifdef OCEAN_HAS_CUDA
  if (!probe) return {"cuda", true, "CUDA"};
  Result<std::vector<cuda::DeviceInfo>> devices = cuda::list_devices();
  if (!devices.ok()) return {"cuda", false, devices.status().message()};
  for (const cuda::DeviceInfo& d : devices.value()) {
    if (d.usable)
      return {"cuda", true,
              "CUDA on " + d.name + " (compute " + std::to_string(d.compute_major) + "." +
                  std::to_string(d.compute_minor) +
                  "), one stream per cascade, cuFFT where it loads"};
  }
  return {"cuda", false, "no CUDA device: none runs this build's kernels"};
#else
  (void)probe;
  return {"cuda", false, "built without CUDA: the CUDA backend is not part of this build"};
#endif
}

std::vector<BackendInfo> backend_table(bool probe) {
  return {{"cpu", true,
           "SIMD pipeline (" + fft::active_simd_target() + "), radix-16 Stockham FFT, oneTBB"},
          vulkan_info(probe),
          cuda_info(probe)};
}

}  // namespace

std::vector<BackendInfo> list_backends() { return backend_table(true); }

Result<std::unique_ptr<Backend>> make_backend(std::string_view name) {
  if (name == "cpu") return std::unique_ptr<Backend>(cpu::make_cpu_backend());
#ifdef OCEAN_HAS_VULKAN
  if (name == "vulkan") {
    Result<std::unique_ptr<vk::VulkanBackend>> b = vk::make_vulkan_backend();
    if (!b.ok()) return b.status();
    return std::unique_ptr<Backend>(std::move(b).value());
  }
#endif
#ifdef OCEAN_HAS_CUDA
  if (name == "cuda") {
    Result<std::unique_ptr<cuda::CudaBackend>> b = cuda::make_cuda_backend();
    if (!b.ok()) return b.status();
    return std::unique_ptr<Backend>(std::move(b).value());
  }
#endif
  for (const BackendInfo& info : backend_table(false)) {
    if (info.name == name)
      return unsupported("unsupported: backend '" + info.name + "' " + info.detail);
  }
  return invalid_argument("backend = '" + excerpt(name) +
                          "' is unknown: must be one of cpu, vulkan, cuda");
}

Result<std::unique_ptr<Simulator>> make_simulator(const SimulationConfig& config,
                                                  std::string_view backend,
                                                  std::shared_ptr<TaskRunner> runner) {
  Result<std::unique_ptr<Backend>> b = make_backend(backend);
  if (!b.ok()) return b.status();
  return Simulator::make(config, std::move(b).value(), std::move(runner));
}

}  // namespace ocean
