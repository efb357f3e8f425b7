// engine_integration — the ocean library used the way a game engine or a simulator uses it:
//
//   1. load a built-in preset (ocean/preset.hpp);
//   2. run the simulation on the engine's own job system: a TaskRunner implemented here on
//      std::thread (ocean/task_runner.hpp), stepped with kick()/wait() once per frame;
//   3. ask for the water height under a few world points (Simulator::heights_at: buoyancy,
//      collision, a boat's hull samples);
//   4. measure the surface's statistics on the same job system (ocean/statistics.hpp);
//   5. create a Vulkan instance and device with plain Vulkan calls, hand them to the library
//      (vk::adopt_context), render one frame headless and write it to a PPM image.
//
// Usage: engine_integration [image.ppm]   (default ocean.ppm)
// Exit status: 0 everything ran; 1 a failure (one line on stderr); 77 steps 1–4 ran but there is
// no Vulkan device able to render (one line on stdout), so no image was written.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/preset.hpp"
#include "ocean/render.hpp"
#include "ocean/statistics.hpp"
#include "ocean/vk.hpp"

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitNoVulkanDevice = 77;  // the "skipped" status of automake and CTest scripts

int fail(const std::string& message) {
  std::fprintf(stderr, "engine_integration: %s\n", message.c_str());
  return kExitFailure;
}

// ---- The engine's job system -------------------------------------------------------------------

// One background job at a time on a thread of its own: the simulator kicks a frame here and the
// frame's parallel loops run on the pool below. wait() blocks until the job has returned.
class ThreadSlot final : public ocean::AsyncSlot {
 public:
  ThreadSlot() : thread_([this] { run(); }) {}
  ~ThreadSlot() override {
    std::unique_lock lock(mutex_);
    stop_ = true;
    changed_.notify_all();
    lock.unlock();
    thread_.join();
  }
  void kick(ocean::FunctionRef<void()> job) override {
    std::lock_guard lock(mutex_);
    job_.emplace(job);
    changed_.notify_all();
  }
  void wait() override {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !job_.has_value(); });
  }

 private:
  void run() {
    std::unique_lock lock(mutex_);
    for (;;) {
      changed_.wait(lock, [&] { return stop_ || job_.has_value(); });
      if (!job_.has_value()) return;  // stopped with nothing in flight
      const ocean::FunctionRef<void()> job = *job_;
      lock.unlock();
      job();
      lock.lock();
      job_.reset();
      changed_.notify_all();
    }
  }
  std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<ocean::FunctionRef<void()>> job_;
  bool stop_ = false;
  std::thread thread_;  // last: starts after the members it uses
};

// A pool of worker threads. parallel_for cuts [0, n) into chunks that threads claim from an atomic
// counter; the calling thread claims chunks too. Helpers are queued for the workers; when the
// caller runs out of chunks it withdraws the helpers no worker has started and waits only for the
// started ones, which are running chunks. So a loop inside a chunk (the contract allows nesting)
// always makes progress on its own thread, and an idle worker can still join the outer loop.
class JobSystem final : public ocean::TaskRunner {
 public:
  explicit JobSystem(int threads) {
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
  }
  ~JobSystem() override {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    queued_.notify_all();
    for (std::thread& t : workers_) t.join();
  }
  void parallel_for(std::size_t n, std::size_t grain,
                    ocean::FunctionRef<void(std::size_t, std::size_t)> body) override {
    grain = std::max<std::size_t>(grain, 1);
    Loop loop{.body = body, .n = n, .grain = grain, .chunks = (n + grain - 1) / grain};
    if (loop.chunks > 1 && !workers_.empty()) {
      std::lock_guard lock(mutex_);
      const std::size_t helpers = std::min(loop.chunks - 1, workers_.size());
      for (std::size_t i = 0; i < helpers; ++i) queue_.push_back(&loop);
      queued_.notify_all();
    }
    run_chunks(loop);
    std::unique_lock lock(mutex_);
    std::erase(queue_, &loop);
    finished_.wait(lock, [&] { return loop.started_helpers == 0; });
  }
  [[nodiscard]] int concurrency() const override { return static_cast<int>(workers_.size()) + 1; }
  [[nodiscard]] std::unique_ptr<ocean::AsyncSlot> make_async_slot() override {
    return std::make_unique<ThreadSlot>();
  }

 private:
  struct Loop {
    ocean::FunctionRef<void(std::size_t, std::size_t)> body;
    std::size_t n = 0, grain = 1, chunks = 0;
    std::atomic<std::size_t> next_chunk{0};
    int started_helpers = 0;  // guarded by mutex_
  };
  static void run_chunks(Loop& loop) {
    for (std::size_t c = loop.next_chunk++; c < loop.chunks; c = loop.next_chunk++)
      loop.body(c * loop.grain, std::min(loop.n, (c + 1) * loop.grain));
  }
  void work() {
    std::unique_lock lock(mutex_);
    for (;;) {
      queued_.wait(lock, [&] { return stop_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopped
      Loop* loop = queue_.front();
      queue_.pop_front();
      ++loop->started_helpers;
      lock.unlock();
      run_chunks(*loop);
      lock.lock();
      --loop->started_helpers;
      finished_.notify_all();
    }
  }
  std::mutex mutex_;
  std::condition_variable queued_, finished_;
  std::deque<Loop*> queue_;
  bool stop_ = false;
  std::vector<std::thread> workers_;
};

// ---- The engine's Vulkan device ----------------------------------------------------------------

// What an engine has before the ocean library is involved: a Vulkan 1.3 instance and a device with
// one graphics+compute queue and dynamic rendering on. The library adopts these and destroys none
// of them; the destructor destroys them, after the library's objects are gone.
struct EngineVulkan {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t queue_family = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkPhysicalDeviceFeatures enabled{};
  ~EngineVulkan() {
    if (device != VK_NULL_HANDLE) vkDestroyDevice(device, nullptr);
    if (instance != VK_NULL_HANDLE) vkDestroyInstance(instance, nullptr);
  }
};

// Picks the first device with Vulkan 1.3, dynamic rendering and a graphics+compute queue family.
// false: there is none (no loader, no driver, no such device).
bool find_device(EngineVulkan& e) {
  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "engine_integration",
                              .apiVersion = VK_API_VERSION_1_3};
  const VkInstanceCreateInfo instance_info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                           .pApplicationInfo = &app};
  if (vkCreateInstance(&instance_info, nullptr, &e.instance) != VK_SUCCESS) {
    e.instance = VK_NULL_HANDLE;
    return false;
  }
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(e.instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(e.instance, &count, devices.data());
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(d, &properties);
    VkPhysicalDeviceVulkan13Features features13{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                       .pNext = &features13};
    vkGetPhysicalDeviceFeatures2(d, &features);
    if (properties.apiVersion < VK_API_VERSION_1_3 || features13.dynamicRendering != VK_TRUE)
      continue;
    std::uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(d, &n, families.data());
    constexpr VkQueueFlags kNeed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (std::uint32_t f = 0; f < n; ++f) {
      if ((families[f].queueFlags & kNeed) != kNeed) continue;
      e.physical = d;
      e.queue_family = f;
      // The renderer's optional features (wireframe view, anisotropic filtering), where present.
      e.enabled.fillModeNonSolid = features.features.fillModeNonSolid;
      e.enabled.samplerAnisotropy = features.features.samplerAnisotropy;
      return true;
    }
  }
  return false;
}

ocean::Status create_device(EngineVulkan& e) {
  VkPhysicalDeviceVulkan13Features features13{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, .dynamicRendering = VK_TRUE};
  const VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                           .pNext = &features13,
                                           .features = e.enabled};
  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queue_info{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                           .queueFamilyIndex = e.queue_family,
                                           .queueCount = 1,
                                           .pQueuePriorities = &priority};
  const VkDeviceCreateInfo device_info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                       .pNext = &features,
                                       .queueCreateInfoCount = 1,
                                       .pQueueCreateInfos = &queue_info};
  if (VkResult r = vkCreateDevice(e.physical, &device_info, nullptr, &e.device); r != VK_SUCCESS) {
    e.device = VK_NULL_HANDLE;
    return ocean::vk::check(r, "vkCreateDevice");
  }
  vkGetDeviceQueue(e.device, e.queue_family, 0, &e.queue);
  return {};
}

// Binary PPM (P6): the header, then RGB bytes row by row, top row first.
ocean::Status write_ppm(const char* path, int width, int height,
                        const std::vector<std::uint8_t>& rgba) {
  std::FILE* file = std::fopen(path, "wb");
  if (file == nullptr) return ocean::io_error(std::string("cannot write ") + path);
  std::fprintf(file, "P6\n%d %d\n255\n", width, height);
  for (std::size_t i = 0; i < rgba.size(); i += 4) std::fwrite(&rgba[i], 1, 3, file);
  return std::fclose(file) == 0 ? ocean::Status{}
                                : ocean::io_error(std::string("cannot write ") + path);
}

}  // namespace

int main(int argc, char** argv) {
  const char* image_path = argc > 1 ? argv[1] : "ocean.ppm";

  // 1. The sea: the built-in "moderate" preset (presets/moderate.json in the ocean sources).
  ocean::Result<ocean::SimulationConfig> preset = ocean::preset::builtin("moderate");
  if (!preset.ok()) return fail(preset.status().message());
  const ocean::SimulationConfig config = std::move(preset).value();
  std::printf("preset moderate: %zu cascades of %d x %d texels, largest patch %.0f m\n",
              config.cascade_patch_sizes_m.size(), config.resolution, config.resolution,
              config.cascade_patch_sizes_m.front());

  // 2. The simulation on the engine's job system. kick() starts the frame on the job system and
  //    returns; the engine runs its own frame meanwhile; wait() publishes the result.
  const int threads = static_cast<int>(std::max(2u, std::thread::hardware_concurrency()));
  auto jobs = std::make_shared<JobSystem>(threads);
  ocean::Result<std::unique_ptr<ocean::Simulator>> made =
      ocean::make_simulator(config, "cpu", jobs);
  if (!made.ok()) return fail(made.status().message());
  ocean::Simulator& simulator = *made.value();
  constexpr int kFrames = 10;
  constexpr double kFrameTime_s = 1.0 / 30.0;
  for (int f = 0; f < kFrames; ++f) {
    simulator.kick(f * kFrameTime_s);
    // ... the engine's game logic and render submission for frame f would run here ...
    simulator.wait();
  }
  const double time_s = simulator.frame().time_s;
  std::printf("simulated %d frames with kick/wait on %d threads, t = %.4f s\n", kFrames,
              jobs->concurrency(), time_s);

  // 3. Heights of the displaced surface under world points (x, z), metres, Y up.
  const std::array<std::array<double, 2>, 4> points{
      {{0.0, 0.0}, {25.0, 0.0}, {0.0, -40.0}, {130.5, 77.25}}};
  std::array<ocean::HeightSample, points.size()> samples{};
  simulator.heights_at(points, samples);
  for (std::size_t i = 0; i < points.size(); ++i)
    std::printf("height at (%.2f, %.2f) m: %.4f m\n", points[i][0], points[i][1],
                samples[i].height_m);

  // 4. Statistics over 8 realisations on the same job system: the measured Hs agrees with the
  //    spectrum's within a few times the sampling standard deviation the library reports.
  constexpr int kSeeds = 8;
  ocean::Result<ocean::SurfaceStats> stats =
      ocean::compute_surface_stats(config, kSeeds, time_s, *jobs);
  if (!stats.ok()) return fail(stats.status().message());
  const ocean::SurfaceStats& s = stats.value();
  std::printf("Hs measured %.6f m, spectrum %.6f m, sampling std %.6f (relative, %d seeds)\n",
              s.hs_measured_m, s.hs_spectrum_m, s.hs_sampling_rel_std, kSeeds);

  // 5. One frame rendered on the engine's own Vulkan device.
  EngineVulkan engine;  // declared first: destroyed after the library's objects below
  if (!find_device(engine)) {
    std::printf("render skipped: no Vulkan 1.3 device with graphics and dynamic rendering\n");
    return kExitNoVulkanDevice;
  }
  if (ocean::Status st = create_device(engine); !st.ok()) return fail(st.message());
  ocean::Result<std::unique_ptr<ocean::vk::Context>> adopted = ocean::vk::adopt_context({
      .instance = engine.instance,
      .physical = engine.physical,
      .device = engine.device,
      .queue_family = engine.queue_family,
      .queue = engine.queue,
      .api_version = VK_API_VERSION_1_3,
      .graphics = true,
      .dynamic_rendering = true,
      .fill_mode_non_solid = engine.enabled.fillModeNonSolid == VK_TRUE,
      .sampler_anisotropy = engine.enabled.samplerAnisotropy == VK_TRUE,
  });
  if (!adopted.ok()) return fail(adopted.status().message());
  std::shared_ptr<ocean::vk::Context> context = std::move(adopted).value();

  constexpr int kWidth = 320, kHeight = 180;
  ocean::Result<std::unique_ptr<ocean::render::Renderer>> renderer_made =
      ocean::render::Renderer::make(context, {.width = kWidth, .height = kHeight});
  if (!renderer_made.ok()) return fail(renderer_made.status().message());
  std::unique_ptr<ocean::render::Renderer> renderer = std::move(renderer_made).value();
  // The CPU simulation's frame is uploaded into the renderer's images (with the Vulkan backend,
  // ocean/scene.hpp samples the simulation's images instead, with no copy).
  if (ocean::Status st = renderer->configure(simulator.plan().surface()); !st.ok())
    return fail(st.message());
  if (ocean::Status st = renderer->upload(simulator.frame()); !st.ok()) return fail(st.message());
  const ocean::render::View view{.camera = {.position_m = {0.0, 6.0, 0.0},
                                            .target_m = {300.0, -2.0, 60.0},
                                            .fov_y_rad = 55.0 * std::numbers::pi / 180.0,
                                            .aspect = double{kWidth} / kHeight}};
  if (ocean::Status st = renderer->draw(view); !st.ok()) return fail(st.message());
  std::vector<std::uint8_t> rgba;
  if (ocean::Status st = renderer->read_srgb(rgba); !st.ok()) return fail(st.message());
  if (ocean::Status st = write_ppm(image_path, kWidth, kHeight, rgba); !st.ok())
    return fail(st.message());
  std::printf("rendered %d x %d on %s: %s\n", kWidth, kHeight, context->info.name.c_str(),
              image_path);

  // The library's objects go first, then the engine's device and instance (~EngineVulkan).
  renderer.reset();
  context.reset();
  return 0;
}
