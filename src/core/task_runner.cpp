// Task runners: serial and oneTBB implementations of the job-system seam.
#include "ocean/task_runner.hpp"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

namespace ocean {

namespace {

class SerialRunner final : public TaskRunner {
 public:
  void parallel_for(std::size_t n, std::size_t /*grain*/,
                    FunctionRef<void(std::size_t, std::size_t)> body) override {
    if (n > 0) body(0, n);
  }
  [[nodiscard]] int concurrency() const override { return 1; }
};

class TbbRunner final : public TaskRunner {
 public:
  explicit TbbRunner(int max_threads)
      : arena_(max_threads > 0 ? max_threads : tbb::task_arena::automatic) {}
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

 private:
  tbb::task_arena arena_;
};

}  // namespace

std::unique_ptr<TaskRunner> make_serial_runner() { return std::make_unique<SerialRunner>(); }
std::unique_ptr<TaskRunner> make_tbb_runner(int max_threads) {
  return std::make_unique<TbbRunner>(max_threads);
}

}  // namespace ocean
