// The AArch64 cross-build has no oneTBB (no arm64 multiarch packages): make_tbb_runner gives the
// library's own ready runner, which keeps the TaskRunner contract (tests/core/task_runner_test).
#include "ocean/task_runner.hpp"

namespace ocean {

std::unique_ptr<TaskRunner> make_tbb_runner(int max_threads) {
  return make_ready_runner({.threads = max_threads, .spin_us = 0.0});
}

}  // namespace ocean
