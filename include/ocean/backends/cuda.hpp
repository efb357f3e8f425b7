// ocean/backends/cuda.hpp — the CUDA simulation backend: the CPU reference pipeline (evolution,
// inverse FFTs of height, displacement and slopes, finalize: normals, Jacobian, foam, RGBA8 with
// its mips, half4) as CUDA kernels and cuFFT (or its own FFT kernels) transforms, each cascade on
// a stream of its own, the far field's noise map (SimulationConfig::far_noise) on another, the
// whole frame one CUDA graph; results read back into the Frame arrays.
//
// Conformance (tests/backends/conformance_test.cpp, src/backends/cuda/README.md): every output
// within conformance::kDeviceBounds of the CPU backend's scalar reference pipeline, the bound the
// Vulkan backend is held to; the noise map within conformance::kFarNoiseDeviceBounds of the CPU
// backend's.
//
// Contract: make_cuda_backend() answers `unsupported` with a message starting "no CUDA device: "
// when the machine has no usable device (no driver, a driver older than the runtime, no GPU, a
// GPU this build has no code for). configure() allocates every device
// buffer, pinned host buffer, stream, event, cuFFT plan and the frame's graph; step(),
// submit() and read() allocate nothing. A device failure during a frame leaves the Frame arrays
// unchanged and is reported by status() with a one-line message.
// Threading: one thread drives a backend at a time (the Simulator guarantees this).
// This header includes no CUDA header; its functions exist in builds with the CUDA backend
// (CMake option OCEAN_CUDA). Code outside the backends reaches them through ocean/backends.hpp,
// which exists in every build.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/backends/capabilities.hpp"
#include "ocean/far_noise.hpp"
#include "ocean/interop.hpp"
#include "ocean/sim.hpp"

namespace ocean::cuda {

namespace detail {
struct DeviceState;  // every CUDA object of a configured simulation (src/backends/cuda)
}

/// "cufft" or "kernels" ("automatic" for automatic).
std::string_view to_string(FftEngine engine);

/// What the CUDA runtime sees: the devices, or an error whose message starts "no CUDA device: "
/// (unsupported) saying why there are none.
Result<std::vector<DeviceInfo>> list_devices();
/// Driver and runtime versions as "driver 13.0, runtime 13.0" (driver "none" without one).
std::string runtime_versions();

/// A per-cascade output of a frame on the device, in the order of CascadeFrame's arrays.
enum class DeviceOutput { displacement, displacement_half, normal, jacobian, foam, packed_mips };

/// Implements DeviceCapabilities: asynchronous frames, shared inputs, time_frames; no GPU images
/// and no noise map alone (`unsupported`).
class CudaBackend final : public Backend, public DeviceCapabilities {
 public:
  /// Runs on device `device` (an index of list_devices()) with `fft` (cufft or kernels, already
  /// resolved: cuFFT must have loaded); see make_cuda_backend.
  CudaBackend(int device, FftEngine fft);
  ~CudaBackend() override;
  CudaBackend(const CudaBackend&) = delete;
  CudaBackend& operator=(const CudaBackend&) = delete;

  [[nodiscard]] std::string_view name() const override { return "cuda"; }
  /// Out of device memory and unsupported configurations answer `unsupported` naming the limit.
  using Backend::configure;
  Status configure(const SimulationPlan& plan, TaskRunner& runner) override;
  void allocate(Frame& frame) const override;
  /// submit(time_s) then read(out).
  void step(double time_s, Frame& out) override;
  void set_far_noise_origin(const std::array<double, 2>& origin_m) override {
    config_.far_noise.origin_m = origin_m;
  }

  /// Asynchronous use: submit() launches the frame's graph at time_s and returns; read() waits
  /// for it and copies the outputs into `out`.
  Status submit(double time_s) override;
  Status read(Frame& out) override;

  /// Zero-copy to a renderer on the same GPU (ocean/interop.hpp; Renderer::share_inputs): imports
  /// the shared buffer (cudaImportExternalMemory, cudaExternalMemoryGetMappedBuffer) and the two
  /// semaphores (cudaImportExternalSemaphore); from then on each frame n waits on the origin
  /// stream for `read` ≥ n − 1 (none for n = 1), runs the frame's graph with the share copies
  /// (device to device, after each cascade's mips) besides the readback, and signals `written`
  /// = n. Every frame must then be taken by the renderer (Renderer::take_shared(shared_frame()))
  /// before the next one is submitted, or the next one waits for ever. Imported descriptors are
  /// set to −1 (the runtime owns them); on failure the rest stay the caller's
  /// (interop::close_unimported). Needs configure() first; configure() ends the sharing.
  Status share_inputs(interop::SharedInputs& shared) override;
  /// The last frame written into the shared buffer (1, 2, …), 0 before the first or unshared.
  [[nodiscard]] std::uint64_t shared_frame() const override;

  /// GPU-resident outputs: the device address of `output` of cascade `cascade` in the backend's
  /// own allocation, the array read() copies into the Frame (same layout: CascadeFrame's), on
  /// device `device()`. It holds the last frame read() returned until the next submit(); stable
  /// until the next configure(). `unsupported` for an output the configuration does not compute
  /// (FrameOutputs), invalid_argument for a cascade out of range, internal before configure().
  [[nodiscard]] Result<const void*> device_output(int cascade, DeviceOutput output) const;
  /// The CUDA device ordinal the backend runs on.
  [[nodiscard]] int device() const { return device_; }

  /// The first failure of a frame since configure(); ok while everything works.
  [[nodiscard]] const Status& status() const override { return status_; }
  /// The device's name, as list_devices() gives it.
  [[nodiscard]] const std::string& device_name() const override { return device_name_; }
  /// The FFT engine in use: FftEngine::cufft or FftEngine::kernels.
  [[nodiscard]] std::string_view fft_engine() const override { return to_string(fft_); }
  /// Times `frames` launches of the simulation graph (concurrent and serial), of the readback
  /// and, with a noise map, of the cascades alone and the map alone, each after one warm-up
  /// frame; means. Needs a configured backend.
  Result<FrameTimings> time_frames(int frames) override;
  Status step_far_noise(double /*time_s*/, Frame& /*out*/) override {
    return unsupported("the CUDA backend runs its noise map in the frame's graph (time_frames)");
  }
  Status gpu_images(vk::SimulationImages& /*out*/) const override {
    return unsupported("the CUDA backend has no Vulkan images: it shares inputs (share_inputs)");
  }

 private:
  Status submit_shared();  // the shared frame: wait `read`, graph, signal `written`
  int device_;
  FftEngine fft_;
  std::string device_name_;
  std::unique_ptr<detail::DeviceState> gpu_;
  SimulationConfig config_;
  FarFieldNoise far_noise_;  ///< fitted at configure when config_.far_noise is on
  Status status_;
  double last_time_s_ = 0.0;
  bool has_stepped_ = false;
  bool pending_ = false;
  double pending_time_s_ = 0.0;
  std::array<double, 2> pending_far_origin_m_{};  ///< the window the submitted map covers
};

/// The first usable device's backend, or `unsupported` "no CUDA device: ..." (see the contract);
/// FftEngine::cufft where cuFFT does not load: `unsupported` naming the library.
Result<std::unique_ptr<CudaBackend>> make_cuda_backend(FftEngine fft = FftEngine::automatic);
/// Device `device` (an index of list_devices()), which must be usable; as above otherwise.
Result<std::unique_ptr<CudaBackend>> make_cuda_backend(int device,
                                                       FftEngine fft = FftEngine::automatic);

/// Configures a backend for `config` and returns CudaBackend::time_frames(frames).
Result<FrameTimings> benchmark(const SimulationConfig& config, int frames,
                               FftEngine fft = FftEngine::automatic);

}  // namespace ocean::cuda
