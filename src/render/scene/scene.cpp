// A simulation and a renderer on one Vulkan context (ocean/scene.hpp): the CPU backend's frames
// uploaded, the Vulkan backend's images sampled with no copy.
#include "ocean/scene.hpp"

#include <cmath>

#include "ocean/backends.hpp"
#include "ocean/far_field.hpp"
#include "ocean/vk/simulation.hpp"

namespace ocean::render {

namespace {

Status check_backend(const std::string& name) {
  if (name == "cpu" || name == "vulkan") return {};
  return invalid_argument("scene: backend = " + name + " cannot render: must be cpu or vulkan");
}

}  // namespace

Result<std::unique_ptr<Scene>> Scene::make(const SceneParams& p) {
  if (Status s = check_backend(p.backend); !s.ok()) return s;
  const vk::ContextParams cp{.validation = p.validation,
                             .graphics = true,
                             .instance_extensions = p.instance_extensions,
                             .swapchain = p.swapchain};
  Result<std::unique_ptr<vk::Context>> ctx = vk::create_context(cp);
  if (!ctx.ok()) return ctx.status();
  return make(std::shared_ptr<vk::Context>(std::move(ctx).value()), p);
}

Result<std::unique_ptr<Scene>> Scene::make(std::shared_ptr<vk::Context> context,
                                           const SceneParams& p) {
  if (Status s = check_backend(p.backend); !s.ok()) return s;
  if (context == nullptr) return invalid_argument("scene: no Vulkan context");
  auto scene = std::unique_ptr<Scene>(new Scene());
  scene->context_ = std::move(context);
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
  Result<std::unique_ptr<Renderer>> renderer =
      Renderer::make(scene->context_, {.width = p.width, .height = p.height});
  if (!renderer.ok()) return renderer.status();
  scene->renderer_ = std::move(renderer).value();
  if (Status s = scene->renderer_->configure(p.config); !s.ok()) return s;
  if (Status s = scene->renderer_->set_environment(p.environment.get()); !s.ok()) return s;
  return scene;
}

Scene::~Scene() = default;

Status Scene::step(double time_s) {
  simulator_->step(time_s);
  if (gpu_ != nullptr) {
    if (!gpu_->status().ok()) return gpu_->status();
    if (Status s = renderer_->use_simulation_images(gpu_->images(), simulator_->frame()); !s.ok())
      return s;
  } else if (Status s = renderer_->upload(simulator_->frame()); !s.ok()) {
    return s;
  }
  // The composited local surface (R.19), while the simulator has a layer; once removed, the
  // renderer's layer goes with it (a layer the caller set on the renderer itself stays).
  const bool local = simulator_->local_layer() != nullptr;
  if (!local && !local_surface_) return {};
  local_surface_ = local;
  return renderer_->set_local_surface(simulator_->frame().local);
}

void Scene::follow(const View& view) {
  const FarNoiseConfig& window = simulator_->config().far_noise;
  if (window.resolution == 0) return;
  simulator_->set_far_noise_origin(
      far_noise_origin(window, view.camera.position_m.x, view.camera.position_m.z));
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

}  // namespace ocean::render
