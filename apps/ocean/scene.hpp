// A simulation and a renderer on one Vulkan context: what `ocean render` and `ocean view` drive.
// The CPU backend's frames are uploaded into the renderer; the Vulkan backend's images are
// sampled where they are, with no copy.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "ocean/render.hpp"
#include "ocean/sim.hpp"
#include "ocean/vk.hpp"

namespace ocean::cli {

struct SceneParams {
  SimulationConfig config;
  std::string backend = "cpu";  ///< cpu or vulkan
  int width = 1280, height = 720;
  bool validation = false;  ///< Khronos validation layer on the context
  /// Instance extensions and the swapchain, for a window (ocean view).
  std::vector<const char*> instance_extensions;
  bool swapchain = false;
};

class Scene {
 public:
  static Result<std::unique_ptr<Scene>> make(const SceneParams& params);
  /// Simulates time_s and hands the result to the renderer.
  Status step(double time_s);
  /// Steps from time_s − warmup_s to time_s at `rate_hz`, so foam has accumulated as it would
  /// have in a running simulation.
  Status warm_up(double time_s, double warmup_s, double rate_hz = 10.0);
  /// New configuration for the simulation and the renderer.
  Status reconfigure(const SimulationConfig& config);

  [[nodiscard]] render::Renderer& renderer() { return *renderer_; }
  [[nodiscard]] Simulator& simulator() { return *simulator_; }
  [[nodiscard]] const std::shared_ptr<vk::Context>& context() const { return context_; }

 private:
  std::shared_ptr<vk::Context> context_;
  std::unique_ptr<Simulator> simulator_;
  vk::VulkanBackend* gpu_ = nullptr;  // owned by simulator_ when the backend is vulkan
  std::unique_ptr<render::Renderer> renderer_;
};

/// The renderer's sRGB pixels (RGBA8, alpha opaque) as an RGB PNG, written atomically.
Status write_srgb_png(const std::filesystem::path& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba);

/// ok unless the context runs the validation layer and it reported something: then one line
/// with the count and the last message (`--validation` fails on any message).
Status validation_status(const vk::Context& context);

}  // namespace ocean::cli
