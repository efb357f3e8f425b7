// ocean/task_runner.hpp — the job-system seam. The simulation expresses its parallel work as
// parallel_for over index ranges; engines plug in their own scheduler by implementing
// TaskRunner, the library ships a serial runner and a oneTBB runner (the default).
//
// Two kinds of work: parallel_for (a loop split over threads) and an async slot (one job
// started with kick and joined with wait, the simulator's double buffering).
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
#include <type_traits>
#include <utility>

namespace ocean {

/// A non-owning reference to a callable (no allocation, unlike std::function). Copies refer to
/// the same callable, which must outlive every call.
template <typename Signature>
class FunctionRef;

template <typename R, typename... Args>
class FunctionRef<R(Args...)> {
 public:
  template <typename F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, FunctionRef>)
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

/// One background job at a time: kick() starts it, wait() joins it. A slot belongs to one
/// caller: kick and wait on the same slot are called from one thread at a time (not
/// concurrently with each other); different slots, and parallel_for on the runner, may be used
/// concurrently. The job may call parallel_for on the runner that made the slot.
class AsyncSlot {
 public:
  virtual ~AsyncSlot() = default;
  /// Starts job and returns; the job runs inline before kick returns (the serial runner) or
  /// concurrently with the caller. Precondition: no job in flight on this slot (wait() first).
  /// FunctionRef is non-owning: the caller keeps the callable alive until wait() returns. Does
  /// not allocate beyond what the scheduler needs to queue one task.
  virtual void kick(FunctionRef<void()> job) = 0;
  /// Returns once the kicked job has finished; returns at once if none is in flight. Must be
  /// called before the slot is destroyed while a job is in flight.
  virtual void wait() = 0;
};

class TaskRunner {
 public:
  virtual ~TaskRunner() = default;
  /// Runs body over [0, n) in chunks of about `grain` indices.
  virtual void parallel_for(std::size_t n, std::size_t grain,
                            FunctionRef<void(std::size_t, std::size_t)> body) = 0;
  /// Number of threads work may run on (1 for the serial runner).
  [[nodiscard]] virtual int concurrency() const = 0;
  /// A slot for background jobs on this runner. Allocates: call at set-up, not per frame. The
  /// slot must not outlive the runner. The default runs each job inline in kick(), so a runner
  /// that implements parallel_for only stays correct (without overlap).
  [[nodiscard]] virtual std::unique_ptr<AsyncSlot> make_async_slot();
};

/// Runs everything on the calling thread, in order; its async slot runs jobs inline in kick().
std::unique_ptr<TaskRunner> make_serial_runner();
/// oneTBB work stealing with at most max_threads threads (0 = all hardware threads). Its async
/// slot runs a job as a oneTBB task (a tbb::task_group) on a worker thread, concurrently with the
/// caller; the job's parallel loops run in the runner's arena.
std::unique_ptr<TaskRunner> make_tbb_runner(int max_threads = 0);

}  // namespace ocean
