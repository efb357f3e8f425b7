// A simulation and a renderer on one Vulkan context (ocean/scene.hpp): the CPU backend's frames
// uploaded, the Vulkan backend's images sampled with no copy, the CUDA backend's frames written
// into the renderer's shared buffer on the same GPU (ocean/interop.hpp) or, where it cannot share,
// uploaded like the CPU backend's.
#include "ocean/scene.hpp"

#include <cmath>

#include "ocean/backends.hpp"
#include "ocean/backends/vulkan.hpp"
#include "ocean/far_field.hpp"
#include "ocean/vk/external.hpp"

namespace ocean::render {

namespace {

Status check_backend(const std::string& name) {
  if (name == "cpu" || name == "vulkan" || name == "cuda") return {};
  return invalid_argument("scene: backend = " + name +
                          " cannot render: must be cpu, vulkan or cuda");
}

// The CUDA devices as interop::choose reads them, or the backend's "no CUDA device: ..." status
// (or make_backend's "unsupported: backend 'cuda' built without CUDA: ...").
Result<std::vector<interop::CudaSide>> cuda_devices() {
  if (!compiled_in("cuda").ok()) return make_backend("cuda").status();
  Result<std::vector<cuda::DeviceInfo>> devices = list_cuda_devices();
  if (!devices.ok()) return devices.status();
  std::vector<interop::CudaSide> sides;
  for (const cuda::DeviceInfo& d : devices.value())
    sides.push_back({.index = d.index, .name = d.name, .uuid = d.uuid, .usable = d.usable});
  return sides;
}

}  // namespace

Status Scene::available(const std::string& backend) {
  if (backend != "cuda") return {};
  return cuda_devices().status();
}

Result<std::unique_ptr<Scene>> Scene::make(const SceneParams& p) {
  if (Status s = check_backend(p.backend); !s.ok()) return s;
  const bool cuda = p.backend == "cuda";
  if (Status s = available(p.backend); !s.ok()) return s;  // before any Vulkan object
  const vk::ContextParams cp{.validation = p.validation,
                             .graphics = true,
                             .instance_extensions = p.instance_extensions,
                             .swapchain = p.swapchain,
                             .external_interop = cuda};
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
  bool zero_copy = false;
  if (p.backend == "vulkan") {
    auto gpu = std::make_unique<vk::VulkanBackend>(scene->context_);
    scene->gpu_ = gpu.get();
    backend = std::move(gpu);
  } else if (p.backend == "cuda") {
    Result<std::vector<interop::CudaSide>> devices = cuda_devices();
    if (!devices.ok()) return devices.status();
    const interop::Choice choice =
        interop::choose(vk::interop_side(*scene->context_), devices.value());
    if (choice.cuda_device < 0)
      return unsupported("no CUDA device: none runs this build's kernels");
    Result<std::unique_ptr<Backend>> made = make_backend("cuda", {.device = choice.cuda_device});
    if (!made.ok()) return made.status();
    scene->cuda_ = capabilities(*made.value());
    backend = std::move(made).value();
    zero_copy = choice.zero_copy;
    scene->interop_ = choice.reason;
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
  if (Status s = scene->renderer_->configure(scene->simulator_->plan().surface()); !s.ok())
    return s;
  if (Status s = scene->renderer_->set_environment(p.environment.get()); !s.ok()) return s;
  scene->shared_ = zero_copy;
  if (Status s = scene->share(); !s.ok()) return s;
  return scene;
}

Scene::~Scene() = default;

Status Scene::share() {
  if (!shared_) return {};
  Result<interop::SharedInputs> exported = renderer_->share_inputs();
  Status s = exported.status();
  if (s.ok()) {
    interop::SharedInputs shared = exported.value();
    s = cuda_->share_inputs(shared);
    interop::close_unimported(shared);
  }
  if (!s.ok()) {  // the devices matched but sharing failed: upload instead, and say so
    shared_ = false;
    interop_ = "sharing memory with the renderer failed (" + s.message() +
               "): CUDA frames are read back and uploaded";
  }
  return {};
}

Status Scene::hand_over() {
  if (gpu_ != nullptr) {
    if (!gpu_->status().ok()) return gpu_->status();
    return renderer_->use_simulation_images(gpu_->images(), simulator_->frame());
  }
  if (cuda_ != nullptr) {
    if (!cuda_->status().ok()) return cuda_->status();
    if (shared_) {
      if (Status s = renderer_->take_shared(cuda_->shared_frame()); !s.ok()) return s;
      return renderer_->set_far_noise(simulator_->frame());  // the map is read back (R.13b)
    }
  }
  return renderer_->upload(simulator_->frame());
}

Status Scene::step(double time_s) {
  simulator_->step(time_s);
  if (Status s = hand_over(); !s.ok()) return s;
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
  for (int i = steps; i > 0; --i) {
    simulator_->step(time_s - i / rate_hz);
    // A shared frame must be taken before the next is written (CudaBackend::share_inputs).
    if (shared_) {
      if (Status s = hand_over(); !s.ok()) return s;
    }
  }
  return step(time_s);
}

Status Scene::reconfigure(const SimulationConfig& config) {
  if (Status s = simulator_->reconfigure(config); !s.ok()) return s;
  if (Status s = renderer_->configure(simulator_->plan().surface()); !s.ok()) return s;
  return share();
}

}  // namespace ocean::render
