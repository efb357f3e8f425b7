// ocean/task_runner.hpp — the job-system seam. The simulation expresses its parallel work as
// parallel_for over index ranges; engines plug in their own scheduler by implementing
// TaskRunner, the library ships a serial runner, a oneTBB runner (the default) and a ready
// runner for paced frame loops (workers that spin, within a bound, instead of sleeping).
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
  /// A hint from a frame loop: work follows soon (within the runner's spin bound), so sleeping
  /// workers should get ready now rather than when the first loop arrives. Never needed for
  /// correctness; cheap (no allocation, at most one notification). The default does nothing.
  virtual void wake() {}
};

/// Runs everything on the calling thread, in order; its async slot runs jobs inline in kick().
std::unique_ptr<TaskRunner> make_serial_runner();
/// The most threads a runner takes: what a caller asks beyond it is clamped to it (oneTBB fails
/// on an arena of 10^9 threads).
inline constexpr int kMaxRunnerThreads = 256;

/// oneTBB work stealing with at most max_threads threads (0 or negative = all hardware threads,
/// above kMaxRunnerThreads that many). Its async
/// slot runs a job as a oneTBB task (a tbb::task_group) on a worker thread, concurrently with the
/// caller; the job's parallel loops run in the runner's arena.
std::unique_ptr<TaskRunner> make_tbb_runner(int max_threads = 0);

struct ReadyRunnerParams {
  int threads = 0;  ///< threads that run loops, the caller's included (0 = all hardware threads)
  /// How long an idle worker keeps spinning, µs, after its last piece of work. [0, 1e6].
  double spin_us = 2000.0;
  /// How long workers spin after wake(), µs, until work arrives: at least the lead with which
  /// the frame loop calls wake() before its frame (the bench and ocean xr: 3 ms). With spin_us,
  /// the bound on the CPU time a frame loop's runner burns between frames. [0, 1e6].
  double wake_spin_us = 4000.0;
  /// After spinning, an idle worker dozes in timed naps of nap_us µs, (0, 1e6], while its last
  /// work or wake() is less than park_after_us µs, [0, 1e7], old; then it parks on a condition
  /// variable until the next loop or wake(). A worker that slept 5 ms at a stretch ran a 90 Hz
  /// frame's share slowly even when woken 3 ms ahead; one that dozed did not
  /// (docs/performance.md, paced frames). park_after_us = 0 parks as soon as the spin ends.
  double nap_us = 1000.0;
  double park_after_us = 100000.0;
};

/// A pool of threads-1 workers for frame loops. An idle worker spins (with a pause instruction)
/// for spin_us, dozes in naps of nap_us until park_after_us have passed without work or wake(),
/// then parks; wake() makes workers spin again for wake_spin_us, so a frame that starts within
/// the bound finds every worker running instead of waking them. Lead and doze both matter: on
/// the reference virtual machine a worker parked 5 ms and woken 1 ms (or 3 ms) before a 90 Hz
/// frame still ran at a fraction of its speed (the frame took 2.2× its back-to-back time, as with
/// oneTBB), one that dozed and was woken 3 ms before at full speed (1.2×; docs/performance.md,
/// paced frames). A caller that
/// waits for its loop, or for an async job, runs chunks of open loops meanwhile, so nested loops
/// neither deadlock nor serialise. Scheduling: chunks of `grain` indices claimed in order from a
/// shared list of open loops (no stealing deques); fine for a few threads, the loops' owner running
/// its own chunks first. Its async slot runs the job on a worker (or on the caller's thread in
/// wait() if none took it). Allocates the threads at creation; parallel_for, kick and wait do not
/// allocate. Precondition: params.threads in [0, 256] and the times in their ranges (asserted).
std::unique_ptr<TaskRunner> make_ready_runner(const ReadyRunnerParams& params = {});

}  // namespace ocean
