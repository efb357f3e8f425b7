// A simulation and a renderer on one Vulkan context (see scene.hpp).
#include "scene.hpp"

#include <cmath>

#include "io/png_image.hpp"
#include "ocean/backends.hpp"
#include "ocean/vk/simulation.hpp"

namespace ocean::cli {

Result<std::unique_ptr<Scene>> Scene::make(const SceneParams& p) {
  if (p.backend != "cpu" && p.backend != "vulkan")
    return invalid_argument("--backend = " + p.backend + " cannot render: must be cpu or vulkan");
  auto scene = std::unique_ptr<Scene>(new Scene());
  vk::ContextParams cp{.validation = p.validation,
                       .graphics = true,
                       .instance_extensions = p.instance_extensions,
                       .swapchain = p.swapchain};
  Result<std::unique_ptr<vk::Context>> ctx = vk::create_context(cp);
  if (!ctx.ok()) return ctx.status();
  scene->context_ = std::shared_ptr<vk::Context>(std::move(ctx).value());
  std::unique_ptr<Backend> backend;
  if (p.backend == "vulkan") {
    auto gpu = std::make_unique<vk::VulkanBackend>(scene->context_);
    scene->gpu_ = gpu.get();
    backend = std::move(gpu);
  } else {
    Result<std::unique_ptr<Backend>> cpu = make_backend("cpu");
    if (!cpu.ok()) return cpu.status();
    backend = std::move(cpu).value();
  }
  Result<std::unique_ptr<Simulator>> sim = Simulator::make(p.config, std::move(backend));
  if (!sim.ok()) return sim.status();
  scene->simulator_ = std::move(sim).value();
  Result<std::unique_ptr<render::Renderer>> renderer =
      render::Renderer::make(scene->context_, {.width = p.width, .height = p.height});
  if (!renderer.ok()) return renderer.status();
  scene->renderer_ = std::move(renderer).value();
  if (Status s = scene->renderer_->configure(p.config); !s.ok()) return s;
  return scene;
}

Status Scene::step(double time_s) {
  simulator_->step(time_s);
  if (gpu_ != nullptr) {
    if (!gpu_->status().ok()) return gpu_->status();
    renderer_->use_simulation_images(gpu_->images());
    return {};
  }
  return renderer_->upload(simulator_->frame());
}

Status Scene::warm_up(double time_s, double warmup_s, double rate_hz) {
  const int steps = static_cast<int>(std::ceil(warmup_s * rate_hz));
  for (int i = steps; i > 0; --i) simulator_->step(time_s - i / rate_hz);
  return step(time_s);
}

Status Scene::reconfigure(const SimulationConfig& config) {
  if (Status s = simulator_->reconfigure(config); !s.ok()) return s;
  return renderer_->configure(config);
}

Status write_srgb_png(const std::filesystem::path& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<std::uint8_t> rgb(n * 3);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 3; ++c) rgb[3 * i + c] = rgba[4 * i + c];
  return io::write_png8(path, width, height, 3, rgb.data());
}

Status validation_status(const vk::Context& context) {
  const std::uint32_t messages = context.validation_messages.load();
  if (!context.validation || messages == 0) return {};
  return {ErrorCode::internal, "Vulkan validation reported " + std::to_string(messages) +
                                   " messages; last: " + context.last_validation_message};
}

}  // namespace ocean::cli
