// The oneTBB task runner: work-stealing loops in a task arena, async jobs on a task group. The
// only file of the library that includes oneTBB.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>

#include "ocean/task_runner.hpp"

namespace ocean {

namespace {

// The job runs as a oneTBB task on a worker thread (as the simulator's double buffering always
// did); the loops it starts enter the runner's arena through parallel_for.
class TbbSlot final : public AsyncSlot {
 public:
  ~TbbSlot() noexcept override { group_.wait(); }
  void kick(FunctionRef<void()> job) override {
    group_.run([job] { job(); });
  }
  void wait() override { group_.wait(); }

 private:
  tbb::task_group group_;
};

class TbbRunner final : public TaskRunner {
 public:
  explicit TbbRunner(int max_threads)
      : arena_(max_threads > 0 ? std::min(max_threads, kMaxRunnerThreads)
                               : tbb::task_arena::automatic) {}
  void parallel_for(std::size_t n, std::size_t grain,
                    FunctionRef<void(std::size_t, std::size_t)> body) override {
    if (n == 0) return;
    arena_.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, n, std::max<std::size_t>(grain, 1)),
          [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
    });
  }
  [[nodiscard]] int concurrency() const override { return arena_.max_concurrency(); }
  [[nodiscard]] std::unique_ptr<AsyncSlot> make_async_slot() override {
    return std::make_unique<TbbSlot>();
  }

 private:
  tbb::task_arena arena_;
};

}  // namespace

std::unique_ptr<TaskRunner> make_tbb_runner(int max_threads) {
  return std::make_unique<TbbRunner>(max_threads);
}

}  // namespace ocean
