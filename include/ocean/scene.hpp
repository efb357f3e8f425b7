// ocean/scene.hpp — a simulation and a renderer on one Vulkan context: the glue an engine or a
// tool would otherwise write between ocean/sim.hpp and ocean/render.hpp. With the CPU backend
// each simulated Frame is uploaded into the renderer's images; with the Vulkan backend the
// simulation's GPU images (ocean/vk/images.hpp) are sampled where they are, with no copy; with
// the CUDA backend on the renderer's GPU each frame is written into the renderer's shared buffer
// (ocean/interop.hpp; make() creates the context with ContextParams::external_interop), else
// uploaded like the CPU backend's, and interop() says which. The pictures agree within the
// backends' conformance bounds (tests/render/scene_test.cpp).
//
// Contract: make() creates the context (or takes the caller's), the simulator and the renderer,
// and configures both; step() and warm_up() simulate and hand the result over without allocating
// (the CPU upload copies into a staging buffer made by configure). Every failure is a Status:
// invalid_argument for a backend name other than cpu/vulkan/cuda or a bad configuration,
// unsupported where the context has no graphics queue or no Vulkan device exists, device failures
// from the Vulkan backend's status(); with the cuda backend, `unsupported` "no CUDA device: ..."
// where there is none, before any Vulkan object is made. Threading: one thread drives a scene (it
// drives the renderer and the simulator, which share the context's queue).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ocean/render.hpp"
#include "ocean/sim.hpp"
#include "ocean/vk.hpp"

namespace ocean {
class DeviceCapabilities;
}
namespace ocean::vk {
class VulkanBackend;
}

namespace ocean::render {

struct SceneParams {
  SimulationConfig config;  ///< what is simulated (and what the renderer is sized for)
  /// cpu (frames uploaded), vulkan (images sampled, no copy) or cuda (frames written into the
  /// renderer's memory on the same GPU, no host copy, where the devices match; else uploaded)
  std::string backend = "cpu";
  int width = 1280;  ///< render target, pixels, [1, 16384]
  int height = 720;  ///< render target, pixels, [1, 16384]
  /// The sky from an HDR environment map (Renderer::set_environment); null: the analytic sky.
  std::shared_ptr<const render::Environment> environment;
  // The context the scene creates in make(params); ignored by make(context, params).
  bool validation = false;  ///< Khronos validation layer on the context
  /// Instance extensions and the swapchain extension, for a window (ocean view).
  std::vector<const char*> instance_extensions;
  bool swapchain = false;
};

class Scene {
 public:
  /// Whether `backend` can run here, before anything is made: for cuda the backend's
  /// "no CUDA device: ..." (or "built without CUDA") where it cannot; ok otherwise.
  static Status available(const std::string& backend);
  /// Creates a graphics context from `params` (ContextParams::graphics, validation, extensions),
  /// then the simulator and the renderer on it.
  static Result<std::unique_ptr<Scene>> make(const SceneParams& params);
  /// Uses the caller's context (which must have a graphics queue, as for Renderer::make).
  static Result<std::unique_ptr<Scene>> make(std::shared_ptr<vk::Context> context,
                                             const SceneParams& params);
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  /// Simulates time_s and hands the result to the renderer; the next draw shows it. While the
  /// simulator has a local layer (Simulator::set_local_layer), the frame's composited local
  /// surface goes to Renderer::set_local_surface too (docs/rendering.md R.19).
  Status step(double time_s);
  /// Keeps the far field's noise map (SimulationConfig::far_noise, when on) around this view's
  /// camera from the next step on: its window's origin snapped as far_noise_origin
  /// (ocean/far_field.hpp, docs/rendering.md R.13b) so the map does not swim as the camera moves.
  /// Allocates nothing; a no-op while the map is off.
  void follow(const View& view);
  /// Steps from time_s − warmup_s to time_s at `rate_hz` (ceil(warmup_s·rate_hz) frames), then
  /// step(time_s), so foam has accumulated as it would have in a running simulation.
  Status warm_up(double time_s, double warmup_s, double rate_hz = 10.0);
  /// New configuration for the simulation and the renderer (allocates).
  Status reconfigure(const SimulationConfig& config);

  [[nodiscard]] Renderer& renderer() { return *renderer_; }
  [[nodiscard]] Simulator& simulator() { return *simulator_; }
  [[nodiscard]] const std::shared_ptr<vk::Context>& context() const { return context_; }
  /// With the cuda backend, one line: whether its frames reach the renderer with no host copy
  /// (CUDA–Vulkan shared memory and semaphores) or read back and uploaded, and why; else empty.
  [[nodiscard]] const std::string& interop() const { return interop_; }
  /// The cuda backend's frames are written into the renderer's shared buffer.
  [[nodiscard]] bool zero_copy() const { return shared_; }

 private:
  Scene() = default;
  std::shared_ptr<vk::Context> context_;
  std::unique_ptr<Simulator> simulator_;
  vk::VulkanBackend* gpu_ = nullptr;    // owned by simulator_ when the backend is vulkan
  DeviceCapabilities* cuda_ = nullptr;  // of simulator_'s backend when it is cuda
  bool shared_ = false;                 // cuda_ writes the renderer's shared inputs
  std::string interop_;
  Status share();      // cuda_ ↔ renderer_ shared inputs, or the upload notice
  Status hand_over();  // the simulator's frame to the renderer
  std::unique_ptr<Renderer> renderer_;
  bool local_surface_ = false;  // the renderer draws the simulator's local surface
};

}  // namespace ocean::render
