// ocean/backends.hpp — the table of simulation backends, chosen at run time by name, and what
// the device backends offer beyond a step (ocean/backends/capabilities.hpp).
//
// Contract: every function here exists in every build; a backend that was not compiled in
// answers `unsupported` "built without Vulkan" or "built without CUDA" (make_backend: see there)
// instead of vanishing, so callers need no build switch and no concrete backend class.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/backends/capabilities.hpp"
#include "ocean/sim.hpp"

namespace ocean {

struct BackendInfo {
  std::string name;    ///< "cpu", "vulkan", ...
  bool available;      ///< compiled in and usable on this machine
  std::string detail;  ///< what it runs on, or why it is unavailable
};

/// Every backend the library knows, available or not.
std::vector<BackendInfo> list_backends();
/// What make_backend passes to the backends that take options (the others ignore them).
struct BackendOptions {
  /// CUDA: an index of list_cuda_devices(), which must be usable; −1 takes the first usable.
  int device = -1;
  cuda::FftEngine fft = cuda::FftEngine::automatic;  ///< CUDA: the inverse FFT
};

/// Creates a backend; unknown names are invalid_argument, known but unavailable ones answer
/// unsupported ("unsupported: built without ...").
Result<std::unique_ptr<Backend>> make_backend(std::string_view name,
                                              const BackendOptions& options = {});
/// `count` backends of one kind on one device: the Vulkan ones share one context (and its
/// queue), the CUDA ones one device; errors as make_backend.
Result<std::vector<std::unique_ptr<Backend>>> make_backends(std::string_view name, int count,
                                                            const BackendOptions& options = {});
/// The device abilities of `backend` (Vulkan, CUDA), or null for a backend without a device
/// (the CPU backend). Valid as long as the backend.
DeviceCapabilities* capabilities(Backend& backend);
const DeviceCapabilities* capabilities(const Backend& backend);
/// Ok when backend `name` ("vulkan", "cuda", ...) is part of this build; otherwise `unsupported`
/// "built without Vulkan" or "built without CUDA"; unknown names are invalid_argument.
Status compiled_in(std::string_view name);

/// A Vulkan physical device as `ocean info` lists it (vk::DeviceInfo, in every build).
struct VulkanDeviceInfo {
  std::string name;         ///< VkPhysicalDeviceProperties::deviceName
  std::string type;         ///< "discrete", "integrated", "virtual", "cpu" or "other"
  std::string api_version;  ///< "1.3.230"
  std::string driver;       ///< driver name and version where known
  bool usable = false;      ///< usable by the Vulkan backend (see reason otherwise)
  std::string reason;       ///< why not usable (empty when usable)
};
/// The Vulkan devices of this machine, or why there are none ("built without Vulkan", the
/// loader's message).
Result<std::vector<VulkanDeviceInfo>> list_vulkan_devices();
/// The CUDA devices of this machine, or why there are none ("built without CUDA", or a message
/// starting "no CUDA device: ").
Result<std::vector<cuda::DeviceInfo>> list_cuda_devices();
/// The CUDA driver and runtime versions ("driver 13.0, runtime 13.0"); empty without CUDA.
std::string cuda_versions();
/// Whether `--backend cuda` renders with no host copy: "zero-copy with Vulkan device [i]: ..."
/// for the first usable Vulkan device that is the same GPU as a usable CUDA device, else why not
/// (interop::choose against the first usable Vulkan device). `cuda_devices` is
/// list_cuda_devices()'s answer; without CUDA or without Vulkan in the build, its message ("ok"
/// when it has devices).
std::string cuda_render_path(const Result<std::vector<cuda::DeviceInfo>>& cuda_devices);
/// The Vulkan backend's mean GPU time per stage over `frames` frames (after one warm-up frame)
/// of `config` on the best device; `unsupported` without a device, timestamps or Vulkan.
Result<vk::StageTimings> vulkan_stage_timings(const SimulationConfig& config, int frames);
/// make_backend + Simulator::make.
Result<std::unique_ptr<Simulator>> make_simulator(const SimulationConfig& config,
                                                  std::string_view backend = "cpu",
                                                  std::shared_ptr<TaskRunner> runner = nullptr);

}  // namespace ocean
