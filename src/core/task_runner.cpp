// The serial task runner and the inline async slot every runner gets by default.
#include "ocean/task_runner.hpp"

namespace ocean {

namespace {

class InlineSlot final : public AsyncSlot {
 public:
  void kick(FunctionRef<void()> job) override { job(); }
  void wait() override {}
};

class SerialRunner final : public TaskRunner {
 public:
  void parallel_for(std::size_t n, std::size_t /*grain*/,
                    FunctionRef<void(std::size_t, std::size_t)> body) override {
    if (n > 0) body(0, n);
  }
  [[nodiscard]] int concurrency() const override { return 1; }
};

}  // namespace

std::unique_ptr<AsyncSlot> TaskRunner::make_async_slot() { return std::make_unique<InlineSlot>(); }

std::unique_ptr<TaskRunner> make_serial_runner() { return std::make_unique<SerialRunner>(); }

}  // namespace ocean
