// src/capi/job_system.cpp — an engine's ocean_job_system (C function pointers) as the library's
// TaskRunner (ocean/task_runner.hpp): parallel_for forwarded with a trampoline, the async slot
// on start_job / wait_job when the engine gives them (else the frame runs inline in kick).
#include "job_system.hpp"

namespace ocean::capi {
namespace {

using Body = FunctionRef<void(std::size_t, std::size_t)>;

// ocean_job_range_fn over a Body: job_data points at the FunctionRef the loop was given.
void run_range(void* job_data, std::size_t begin, std::size_t end) {
  (*static_cast<const Body*>(job_data))(begin, end);
}

// ocean_job_fn over a kicked job: job_data points at the slot's FunctionRef.
void run_job(void* job_data) { (*static_cast<const FunctionRef<void()>*>(job_data))(); }

class JobSlot final : public AsyncSlot {
 public:
  explicit JobSlot(const ocean_job_system& jobs) : jobs_(jobs) {}
  ~JobSlot() override { wait(); }
  JobSlot(const JobSlot&) = delete;
  JobSlot& operator=(const JobSlot&) = delete;

  void kick(FunctionRef<void()> job) override {
    job_ = job;
    handle_ = jobs_.start_job(jobs_.user_data, &run_job, &job_);
    in_flight_ = true;
  }
  void wait() override {
    if (!in_flight_) return;
    jobs_.wait_job(jobs_.user_data, handle_);
    in_flight_ = false;
  }

 private:
  ocean_job_system jobs_;
  FunctionRef<void()> job_{[] {}};
  void* handle_ = nullptr;
  bool in_flight_ = false;
};

class JobSystemRunner final : public TaskRunner {
 public:
  explicit JobSystemRunner(const ocean_job_system& jobs) : jobs_(jobs) {}
  void parallel_for(std::size_t n, std::size_t grain, Body body) override {
    if (n == 0) return;
    jobs_.parallel_for(jobs_.user_data, n, grain == 0 ? 1 : grain, &run_range, &body);
  }
  [[nodiscard]] int concurrency() const override { return jobs_.concurrency; }
  [[nodiscard]] std::unique_ptr<AsyncSlot> make_async_slot() override {
    if (jobs_.start_job == nullptr) return TaskRunner::make_async_slot();
    return std::make_unique<JobSlot>(jobs_);
  }

 private:
  ocean_job_system jobs_;
};

}  // namespace

Status validate_job_system(const ocean_job_system& jobs, std::string_view function) {
  const std::string prefix = std::string(function) + ": job_system->";
  if (jobs.struct_size < sizeof(ocean_job_system)) {
    return invalid_argument(prefix + "struct_size = " + std::to_string(jobs.struct_size) +
                            " is too small: set it to sizeof(ocean_job_system)");
  }
  if (jobs.parallel_for == nullptr) return invalid_argument(prefix + "parallel_for is NULL");
  if ((jobs.start_job == nullptr) != (jobs.wait_job == nullptr)) {
    return invalid_argument(prefix + "start_job and wait_job must be given together or not at all");
  }
  if (jobs.concurrency < 1 || jobs.concurrency > kMaxRunnerThreads) {
    return invalid_argument(prefix + "concurrency = " + std::to_string(jobs.concurrency) +
                            " is out of range: must be 1 to " + std::to_string(kMaxRunnerThreads));
  }
  return {};
}

std::shared_ptr<TaskRunner> make_job_system_runner(const ocean_job_system& jobs) {
  return std::make_shared<JobSystemRunner>(jobs);
}

}  // namespace ocean::capi
