// Simulator: owns a backend and two frames (front, back); kick/wait overlaps the next frame's
// computation with reading the current one (seed 000 §4.3 double buffering).
#include <tbb/task_group.h>

#include "ocean/sim.hpp"

namespace ocean {

struct Simulator::Async {
  tbb::task_group group;
  bool pending = false;
};

Simulator::~Simulator() {
  if (async_) async_->group.wait();
}

Result<std::unique_ptr<Simulator>> Simulator::make(const SimulationConfig& config,
                                                   std::unique_ptr<Backend> backend,
                                                   std::shared_ptr<TaskRunner> runner) {
  if (!backend) return invalid_argument("no backend given");
  std::unique_ptr<Simulator> sim(new Simulator());
  sim->runner_ = runner ? std::move(runner) : std::shared_ptr<TaskRunner>(make_tbb_runner());
  sim->backend_ = std::move(backend);
  sim->async_ = std::make_unique<Async>();
  if (Status s = sim->reconfigure(config); !s.ok()) return s;
  return sim;
}

Status Simulator::reconfigure(const SimulationConfig& config) {
  wait();
  if (Status s = backend_->configure(config, *runner_); !s.ok()) return s;
  config_ = config;
  for (Frame& f : frames_) {
    f = Frame{};
    backend_->allocate(f);
  }
  front_ = 0;
  return {};
}

void Simulator::step(double time_s) {
  wait();
  backend_->step(time_s, frames_[1 - front_]);
  front_ = 1 - front_;
}

void Simulator::kick(double time_s) {
  wait();
  Frame& back = frames_[1 - front_];
  async_->pending = true;
  async_->group.run([this, &back, time_s] { backend_->step(time_s, back); });
}

void Simulator::wait() {
  if (!async_->pending) return;
  async_->group.wait();
  async_->pending = false;
  front_ = 1 - front_;
}

const Frame& Simulator::frame() const { return frames_[front_]; }

}  // namespace ocean
