// ocean/backends/vulkan.hpp — the Vulkan compute simulation backend: the CPU reference pipeline
// (evolution, inverse FFT, displacement, normals, Jacobian, foam, packed mips) as compute
// shaders, all cascades in one dispatch per stage, results in GPU images for the renderer and
// read back into the Frame arrays for queries and tests.
//
// Conformance (tests/backends/conformance_test.cpp, src/backends/vulkan/README.md): every output
// matches the CPU backend for the same configuration; displacement within 1e-4·Hs.
//
// Contract: configure() allocates every buffer, image, pipeline and the pre-recorded command
// buffer; step()/submit()/read() allocate nothing and create nothing. A device lost or a timeout
// during a frame leaves the Frame arrays unchanged and is reported by status() with a one-line
// message; configure() reports out-of-memory and unsupported limits the same way.
// Threading: one thread drives a backend at a time (the Simulator guarantees this).
#pragma once

#include <memory>

#include "ocean/backends/capabilities.hpp"
#include "ocean/far_noise.hpp"
#include "ocean/sim.hpp"
#include "ocean/vk.hpp"
#include "ocean/vk/images.hpp"

namespace ocean::vk {

namespace detail {
struct GpuState;  // every Vulkan object of a configured simulation (src/backends/vulkan)
}

/// Implements DeviceCapabilities: asynchronous frames, GPU images, the noise map alone; no
/// shared inputs and no time_frames (`unsupported`).
class VulkanBackend final : public Backend, public DeviceCapabilities {
 public:
  /// Uses `context` (shared with a renderer, for instance); see make_vulkan_backend.
  explicit VulkanBackend(std::shared_ptr<Context> context);
  ~VulkanBackend() override;
  VulkanBackend(const VulkanBackend&) = delete;
  VulkanBackend& operator=(const VulkanBackend&) = delete;

  [[nodiscard]] std::string_view name() const override { return "vulkan"; }
  /// Unsupported configurations (a resolution beyond the device's shared memory or storage-buffer
  /// range) answer `unsupported` with a message naming the limit.
  using Backend::configure;
  Status configure(const SimulationPlan& plan, TaskRunner& runner) override;
  void allocate(Frame& frame) const override;
  /// submit(time_s) then read(out).
  void step(double time_s, Frame& out) override;
  void set_far_noise_origin(const std::array<double, 2>& origin_m) override {
    config_.far_noise.origin_m = origin_m;
  }

  /// Asynchronous use: submit() starts the frame at time_s and returns; read() waits for it and
  /// copies the outputs into `out`. The GPU images are complete once read() returns.
  Status submit(double time_s) override;
  Status read(Frame& out) override;

  /// The far field's noise map alone (SimulationConfig::far_noise, docs/rendering.md R.13a):
  /// Frame::far_noise at time_s from its own pre-recorded command buffer, the cascades untouched
  /// (what `ocean bench --overlap` times against the whole frame). No-op when the map is off;
  /// returns status() while a submitted frame is pending. Allocates nothing.
  Status step_far_noise(double time_s, Frame& out) override;

  /// The first failure of a frame since configure(); ok while everything works.
  [[nodiscard]] const Status& status() const override { return status_; }
  /// Stage times of the last completed frame (zeros when the device has no timestamps).
  [[nodiscard]] const StageTimings& timings() const { return timings_; }
  [[nodiscard]] SimulationImages images() const;
  Status gpu_images(SimulationImages& out) const override {
    out = images();
    return {};
  }
  /// The context's device name.
  [[nodiscard]] const std::string& device_name() const override { return context_->info.name; }
  [[nodiscard]] std::string_view fft_engine() const override { return "kernels"; }
  Status share_inputs(interop::SharedInputs& /*shared*/) override {
    return unsupported("the Vulkan backend shares its images (gpu_images), not inputs");
  }
  [[nodiscard]] std::uint64_t shared_frame() const override { return 0; }
  Result<cuda::FrameTimings> time_frames(int /*frames*/) override {
    return unsupported("the Vulkan backend times its stages (timings, benchmark)");
  }
  [[nodiscard]] const Context& context() const { return *context_; }

 private:
  void write_far_noise_params(double time_s);
  void read_far_noise(Frame& out) const;
  std::shared_ptr<Context> context_;
  std::unique_ptr<detail::GpuState> gpu_;
  SimulationConfig config_;
  FarFieldNoise far_noise_;  ///< fitted at configure when config_.far_noise is on
  Status status_;
  StageTimings timings_;
  double last_time_s_ = 0.0;
  bool has_stepped_ = false;
  bool pending_ = false;
  double pending_time_s_ = 0.0;
  std::array<double, 2> pending_far_origin_m_{};  ///< the window the submitted map covers
};

/// Creates a context (see ContextParams) and a backend on it.
Result<std::unique_ptr<VulkanBackend>> make_vulkan_backend(const ContextParams& params = {});

/// Runs `frames` frames (after one warm-up frame) of `config` and returns the mean GPU time of
/// each stage. `unsupported` when no device or no timestamps.
Result<StageTimings> benchmark(const SimulationConfig& config, int frames,
                               const ContextParams& params = {});

}  // namespace ocean::vk
