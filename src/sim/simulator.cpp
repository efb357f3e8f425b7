// Simulator: owns a backend and two frames (front, back); kick/wait overlaps the next frame's
// computation with reading the current one (Aebi, VR Ocean, §4.3: double buffering).
#include <cassert>
#include <cmath>
#include <utility>

#include "ocean/plan.hpp"
#include "ocean/sim.hpp"

namespace ocean {

// The background step runs on the runner's async slot. The slot keeps only a reference to the
// job, so the job (and the frame time it reads) lives here, as long as the slot.
struct Simulator::Async {
  struct Job {
    Simulator* sim = nullptr;
    double time_s = 0.0;
    void operator()() const { sim->compute(time_s); }
  };
  std::unique_ptr<AsyncSlot> slot;
  Job job;
  bool pending = false;
};

Simulator::~Simulator() {
  if (async_) async_->slot->wait();
}

Status Backend::configure(const SimulationConfig& config, TaskRunner& runner) {
  Result<SimulationPlan> plan = SimulationPlan::make(config);
  if (!plan.ok()) return plan.status();
  return configure(plan.value(), runner);
}

Result<std::unique_ptr<Simulator>> Simulator::make(const SimulationConfig& config,
                                                   std::unique_ptr<Backend> backend,
                                                   std::shared_ptr<TaskRunner> runner) {
  if (!backend) return invalid_argument("no backend given");
  Result<SimulationPlan> plan = SimulationPlan::make(config);
  if (!plan.ok()) return plan.status();
  return make(plan.value(), std::move(backend), std::move(runner));
}

Result<std::unique_ptr<Simulator>> Simulator::make(const SimulationPlan& plan,
                                                   std::unique_ptr<Backend> backend,
                                                   std::shared_ptr<TaskRunner> runner) {
  if (!backend) return invalid_argument("no backend given");
  std::unique_ptr<Simulator> sim(new Simulator());
  sim->runner_ = runner ? std::move(runner) : std::shared_ptr<TaskRunner>(make_tbb_runner());
  sim->backend_ = std::move(backend);
  sim->async_ = std::make_unique<Async>();
  sim->async_->slot = sim->runner_->make_async_slot();
  sim->async_->job.sim = sim.get();
  if (Status s = sim->reconfigure(plan); !s.ok()) return s;
  return sim;
}

Status Simulator::reconfigure(const SimulationConfig& config) {
  Result<SimulationPlan> plan = SimulationPlan::make(config);
  if (!plan.ok()) return plan.status();
  return reconfigure(plan.value());
}

Status Simulator::reconfigure(const SimulationPlan& plan) {
  wait();
  if (Status s = backend_->configure(plan, *runner_); !s.ok()) return s;
  plan_ = std::make_shared<const SimulationPlan>(plan);
  config_ = plan.config();
  for (Frame& f : frames_) {
    f = Frame{};
    backend_->allocate(f);
  }
  front_ = 0;
  set_local_layer(std::move(local_layer_));
  return {};
}

void Simulator::compute(double time_s) {
  Frame& back = frames_[1 - front_];
  backend_->step(time_s, back);
  // Each of the two buffers is written every second frame: the published count is the front
  // frame's plus one, not the buffer's own count of writes.
  back.index = frames_[front_].index + 1;
  apply_band_roles(config_, back);
  compute_local_surface(back);
}

void Simulator::step(double time_s) {
  wait();
  compute(time_s);
  front_ = 1 - front_;
}

void Simulator::kick(double time_s) {
  wait();
  async_->job.time_s = time_s;
  async_->pending = true;
  async_->slot->kick(async_->job);
}

void Simulator::wait() {
  if (!async_->pending) return;
  async_->slot->wait();
  async_->pending = false;
  front_ = 1 - front_;
}

void Simulator::prepare_step() {
  wait();
  runner_->wake();
  backend_->warm_caches(frames_[1 - front_]);
}

const Frame& Simulator::frame() const { return frames_[front_]; }

const Frame& Simulator::back_buffer() const { return frames_[1 - front_]; }

Frame Simulator::detach(const Frame& buffer) {
  wait();
  assert(&buffer == &frames_[0] || &buffer == &frames_[1]);
  Frame& slot = frames_[&buffer == &frames_[0] ? 0 : 1];
  Frame copy = slot;
  std::swap(copy, slot);
  return copy;
}

void Simulator::set_far_noise_origin(const std::array<double, 2>& origin_m) {
  assert(std::isfinite(origin_m[0]) && std::isfinite(origin_m[1]) && std::abs(origin_m[0]) <= 1e9 &&
         std::abs(origin_m[1]) <= 1e9);
  wait();
  if (config_.far_noise.resolution == 0) return;
  config_.far_noise.origin_m = origin_m;
  backend_->set_far_noise_origin(origin_m);
}

}  // namespace ocean
