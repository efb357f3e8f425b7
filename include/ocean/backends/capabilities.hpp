// ocean/backends/capabilities.hpp — what a device backend can do beyond Backend's step
// (ocean/sim.hpp), and the plain data it reports. capabilities(backend) (ocean/backends.hpp)
// gives the interface of a Vulkan or CUDA backend and null for the CPU backend, so that callers
// ask a Backend& instead of naming the concrete class or the build's options.
//
// This header includes no GPU header and exists in every build; the backends that implement it
// are ocean/backends/vulkan.hpp and ocean/backends/cuda.hpp.
//
// Contract: an ability a backend lacks answers `unsupported` (0 for shared_frame); none of these
// allocates after configure(). Threading: as the backend's own methods (one thread at a time).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "ocean/interop.hpp"
#include "ocean/sim.hpp"

namespace ocean::vk {

struct SimulationImages;  // ocean/vk/images.hpp

/// GPU time of each stage of one frame, from timestamp queries, milliseconds.
struct StageTimings {
  double evolve_fft_rows_ms = 0.0;  ///< evolution fused into the first FFT axis
  double fft_columns_ms = 0.0;      ///< second FFT axis and the (−1)^(x+y) sign
  double finalize_ms = 0.0;         ///< displacement, normals, Jacobian, foam, base packing
  double mips_ms = 0.0;             ///< mip chain of the packed map, every level
  double readback_ms = 0.0;         ///< copies of every output into host-visible memory
  double total_ms = 0.0;            ///< first to last timestamp
  std::string device;               ///< the device's name (benchmark() fills it)
};

}  // namespace ocean::vk

namespace ocean::cuda {

/// The inverse FFT between evolution and finalize.
enum class FftEngine {
  automatic,  ///< cuFFT where libcufft loads, else the own kernels
  cufft,      ///< NVIDIA's cuFFT (loaded at run time); `unsupported` when it does not load
  kernels,    ///< the backend's own shared-memory Stockham kernels (the Vulkan backend's port),
              ///< with the evolution fused into the row transforms
};

/// One CUDA device as the runtime reports it.
struct DeviceInfo {
  int index = 0;
  std::string name;
  int compute_major = 0;  ///< compute capability, e.g. 9.0 for an H100/H200
  int compute_minor = 0;
  std::uint64_t memory_bytes = 0;
  int multiprocessors = 0;
  bool usable = false;  ///< this build carries code the device runs (see reason otherwise)
  std::string reason;
  interop::Uuid uuid{};  ///< cudaDeviceProp::uuid: equal to the Vulkan deviceUUID of the same GPU
};

/// GPU time of one frame from CUDA events around the frame's graph, milliseconds.
struct FrameTimings {
  /// Every stage, the cascades and the far field's noise map (when configured) on concurrent
  /// streams, no readback: the frame with both.
  double simulation_ms = 0.0;
  double serial_ms = 0.0;    ///< the same work with every cascade and the map on one stream
  double readback_ms = 0.0;  ///< device → pinned host copies of the frame's outputs
  /// The cascades alone on their streams (no map, no readback); simulation_ms without a map.
  double cascades_ms = 0.0;
  /// The noise map alone on its stream (no cascades, no readback); 0 without a map.
  double noise_ms = 0.0;
  /// serial_ms / simulation_ms: how much the concurrent streams gain (1 = none).
  [[nodiscard]] double overlap() const {
    return simulation_ms > 0.0 ? serial_ms / simulation_ms : 0.0;
  }
  /// How much of the shorter of the cascades and the map the frame hides, as `ocean bench
  /// --overlap` defines it: (cascades_ms + noise_ms − simulation_ms) / min(cascades_ms,
  /// noise_ms); 1 = hidden entirely, 0 = one after the other; 0 without a map.
  [[nodiscard]] double noise_overlap() const {
    const double shorter = cascades_ms < noise_ms ? cascades_ms : noise_ms;
    return shorter > 0.0 ? (cascades_ms + noise_ms - simulation_ms) / shorter : 0.0;
  }
};

}  // namespace ocean::cuda

namespace ocean {

/// The abilities of a backend that runs on a device. Vulkan and CUDA implement every method;
/// where one has no such ability the method answers `unsupported` (noted per method).
class DeviceCapabilities {
 public:
  virtual ~DeviceCapabilities() = default;

  /// The device's name, as the backend's device list gives it.
  [[nodiscard]] virtual const std::string& device_name() const = 0;
  /// The first failure of a frame since configure(); ok while everything works.
  [[nodiscard]] virtual const Status& status() const = 0;
  /// The inverse FFT: "cufft" or "kernels" (the backend's own; Vulkan always).
  [[nodiscard]] virtual std::string_view fft_engine() const = 0;

  /// Asynchronous kick and wait: submit() starts the frame at time_s and returns; read() waits
  /// for it and copies the outputs into `out` (Backend::step is submit then read).
  virtual Status submit(double time_s) = 0;
  virtual Status read(Frame& out) = 0;

  /// The far field's noise map alone on the device (SimulationConfig::far_noise): Frame::far_noise
  /// at time_s, the cascades untouched. No-op when the map is off. CUDA: `unsupported` (its map
  /// is timed inside the frame's graph, time_frames).
  virtual Status step_far_noise(double time_s, Frame& out) = 0;

  /// GPU-resident outputs: the images a renderer on the same vk::Context samples with no copy,
  /// valid until the next configure(). CUDA: `unsupported` (it shares inputs instead).
  virtual Status gpu_images(vk::SimulationImages& out) const = 0;

  /// Shared inputs: from now on each frame is written into the buffer a renderer on the same GPU
  /// exported (ocean/interop.hpp; the contract is CudaBackend::share_inputs'). Vulkan:
  /// `unsupported` (its renderer samples gpu_images).
  virtual Status share_inputs(interop::SharedInputs& shared) = 0;
  /// The last frame written into the shared buffer (1, 2, …); 0 before the first or unshared.
  [[nodiscard]] virtual std::uint64_t shared_frame() const = 0;

  /// GPU time of `frames` frames from device events (CUDA: CudaBackend::time_frames). Needs a
  /// configured backend. Vulkan: `unsupported` (vulkan_stage_timings measures its stages).
  virtual Result<cuda::FrameTimings> time_frames(int frames) = 0;

 protected:
  DeviceCapabilities() = default;
  DeviceCapabilities(const DeviceCapabilities&) = default;
  DeviceCapabilities& operator=(const DeviceCapabilities&) = default;
};

}  // namespace ocean
