// The backend table: every backend by name, with a clear answer for those not built in, and the
// device backends' abilities and devices behind functions that exist in every build.
#include <string>
#include <utility>

#include "ocean/backends.hpp"
#include "ocean/backends/cpu.hpp"
#include "ocean/fft.hpp"
#ifdef OCEAN_HAS_VULKAN
#include "ocean/backends/vulkan.hpp"
#include "ocean/vk/external.hpp"
#endif
#ifdef OCEAN_HAS_CUDA
#include "ocean/backends/cuda.hpp"
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

Result<std::unique_ptr<Backend>> make_backend(std::string_view name,
                                              const BackendOptions& options) {
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
    Result<std::unique_ptr<cuda::CudaBackend>> b =
        options.device < 0 ? cuda::make_cuda_backend(options.fft)
                           : cuda::make_cuda_backend(options.device, options.fft);
    if (!b.ok()) return b.status();
    return std::unique_ptr<Backend>(std::move(b).value());
  }
#endif
  (void)options;
  for (const BackendInfo& info : backend_table(false)) {
    if (info.name == name)
      return unsupported("unsupported: backend '" + info.name + "' " + info.detail);
  }
  return invalid_argument("backend = '" + excerpt(name) +
                          "' is unknown: must be one of cpu, vulkan, cuda");
}

Result<std::vector<std::unique_ptr<Backend>>> make_backends(std::string_view name, int count,
                                                            const BackendOptions& options) {
  std::vector<std::unique_ptr<Backend>> made;
#ifdef OCEAN_HAS_VULKAN
  if (name == "vulkan") {
    Result<std::unique_ptr<vk::Context>> ctx = vk::create_context();
    if (!ctx.ok()) return ctx.status();
    const std::shared_ptr<vk::Context> context(std::move(ctx).value());
    for (int i = 0; i < count; ++i) made.push_back(std::make_unique<vk::VulkanBackend>(context));
    return made;
  }
#endif
  for (int i = 0; i < count; ++i) {
    Result<std::unique_ptr<Backend>> b = make_backend(name, options);
    if (!b.ok()) return b.status();
    made.push_back(std::move(b).value());
  }
  return made;
}

DeviceCapabilities* capabilities(Backend& backend) {
  return dynamic_cast<DeviceCapabilities*>(&backend);
}

const DeviceCapabilities* capabilities(const Backend& backend) {
  return dynamic_cast<const DeviceCapabilities*>(&backend);
}

Status compiled_in(std::string_view name) {
  if (name == "cpu") return {};
  if (name == "vulkan") {
#ifdef OCEAN_HAS_VULKAN
    return {};
#else
    return unsupported("built without Vulkan");
#endif
  }
  if (name == "cuda") {
#ifdef OCEAN_HAS_CUDA
    return {};
#else
    return unsupported("built without CUDA");
#endif
  }
  return invalid_argument("backend = '" + excerpt(name) +
                          "' is unknown: must be one of cpu, vulkan, cuda");
}

Result<std::vector<VulkanDeviceInfo>> list_vulkan_devices() {
#ifdef OCEAN_HAS_VULKAN
  Result<std::vector<vk::DeviceInfo>> found = vk::list_devices();
  if (!found.ok()) return found.status();
  std::vector<VulkanDeviceInfo> devices;
  for (const vk::DeviceInfo& d : found.value())
    devices.push_back({.name = d.name,
                       .type = d.type,
                       .api_version = d.api_version,
                       .driver = d.driver,
                       .usable = d.usable,
                       .reason = d.reason});
  return devices;
#else
  return compiled_in("vulkan");
#endif
}

Result<std::vector<cuda::DeviceInfo>> list_cuda_devices() {
#ifdef OCEAN_HAS_CUDA
  return cuda::list_devices();
#else
  return compiled_in("cuda");
#endif
}

std::string cuda_versions() {
#ifdef OCEAN_HAS_CUDA
  return cuda::runtime_versions();
#else
  return {};
#endif
}

std::string cuda_render_path(const Result<std::vector<cuda::DeviceInfo>>& cuda_devices) {
  const std::string cuda_status = cuda_devices.ok() ? "ok" : cuda_devices.status().message();
#if defined(OCEAN_HAS_VULKAN) && defined(OCEAN_HAS_CUDA)
  Result<std::vector<vk::DeviceInfo>> listed = vk::list_devices();
  Result<std::vector<interop::VulkanSide>> sides = vk::list_interop_sides();
  if (cuda_devices.ok() && sides.ok() && listed.ok()) {
    std::vector<interop::CudaSide> cuda_sides;
    for (const cuda::DeviceInfo& d : cuda_devices.value())
      cuda_sides.push_back({.index = d.index, .name = d.name, .uuid = d.uuid, .usable = d.usable});
    std::string first_reason;
    for (std::size_t i = 0; i < sides.value().size(); ++i) {
      if (!listed.value()[i].usable) continue;
      const interop::Choice c = interop::choose(sides.value()[i], cuda_sides);
      if (first_reason.empty()) first_reason = c.reason;
      if (c.zero_copy) {
        first_reason = "zero-copy with Vulkan device [" + std::to_string(i) + "]: " + c.reason;
        break;
      }
    }
    return first_reason.empty() ? "no usable Vulkan device: CUDA frames cannot be rendered"
                                : first_reason;
  }
  if (cuda_devices.ok()) return "no Vulkan device: CUDA frames cannot be rendered";
#endif
  return cuda_status;
}

Result<vk::StageTimings> vulkan_stage_timings(const SimulationConfig& config, int frames) {
#ifdef OCEAN_HAS_VULKAN
  return vk::benchmark(config, frames);
#else
  (void)config, (void)frames;
  return compiled_in("vulkan");
#endif
}

Result<std::unique_ptr<Simulator>> make_simulator(const SimulationConfig& config,
                                                  std::string_view backend,
                                                  std::shared_ptr<TaskRunner> runner) {
  Result<std::unique_ptr<Backend>> b = make_backend(backend);
  if (!b.ok()) return b.status();
  return Simulator::make(config, std::move(b).value(), std::move(runner));
}

}  // namespace ocean
