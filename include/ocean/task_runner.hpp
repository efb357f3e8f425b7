// ocean/task_runner.hpp — the job-system seam. The simulation expresses its parallel work as
// parallel_for over index ranges; engines plug in their own scheduler by implementing
// TaskRunner, the library ships a serial runner and a oneTBB runner (the default).
//
// Contract: parallel_for(n, grain, body) calls body(begin, end) over disjoint ranges covering
// [0, n) exactly once, possibly concurrently, and returns when all calls have returned. Bodies
// never throw; they may call parallel_for on the same runner (nested loops: the CPU backend runs
// one chain of stage loops per cascade group inside an outer loop), which must then neither
// deadlock nor serialise the outer loop. Results of the simulation never depend on how ranges
// are split or scheduled.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>

namespace ocean {

/// A non-owning reference to a callable (no allocation, unlike std::function).
template <typename Signature>
class FunctionRef;

template <typename R, typename... Args>
class FunctionRef<R(Args...)> {
 public:
  template <typename F>
  FunctionRef(F&& f)  // NOLINT(google-explicit-constructor)
      : object_(const_cast<void*>(static_cast<const void*>(&f))),
        call_([](void* o, Args... args) -> R {
          return (*static_cast<std::remove_reference_t<F>*>(o))(std::forward<Args>(args)...);
        }) {}
  R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

 private:
  void* object_;
  R (*call_)(void*, Args...);
};

class TaskRunner {
 public:
  virtual ~TaskRunner() = default;
  /// Runs body over [0, n) in chunks of about `grain` indices.
  virtual void parallel_for(std::size_t n, std::size_t grain,
                            FunctionRef<void(std::size_t, std::size_t)> body) = 0;
  /// Number of threads work may run on (1 for the serial runner).
  [[nodiscard]] virtual int concurrency() const = 0;
};

/// Runs everything on the calling thread, in order.
std::unique_ptr<TaskRunner> make_serial_runner();
/// oneTBB work stealing with at most max_threads threads (0 = all hardware threads).
std::unique_ptr<TaskRunner> make_tbb_runner(int max_threads = 0);

}  // namespace ocean
