// The ready runner: a small thread pool for paced frame loops whose idle workers spin for a
// bounded time before they sleep, and which a frame loop wakes ahead of a frame (wake()).
//
// Why: at 90 Hz a 0.5 ms frame on oneTBB took 2.2× its back-to-back time on a quiet reference
// machine (a virtual machine of 2 vCPUs): its worker, asleep since the previous frame, does not
// run at full speed until about 2.5 ms after it is woken (measured: woken 1, 1.5, 2, 2.5, 3 ms
// ahead of the frame, the paced frame took 2.2, 2.2, 1.4, 1.3, 1.3× its back-to-back time; its
// wake-up itself took 20 µs at the median), so the calling thread ran most of the frame alone
// (docs/performance.md, paced frames). What costs is the long sleep, not the waking: a worker
// that dozes between frames in naps of 1 ms is at full speed 3 ms after wake() (paced/back to
// back 1.2 at 90 and 120 Hz), one that slept 5 ms on a condition variable is not (2.2), one that
// slept 2.6 ms nearly is (1.3). So an idle worker spins for spin_us after its work, then dozes in
// naps of nap_us (a timed sleep, a few µs of CPU each) while work or wake() came within
// park_after_us, and only then parks on the condition variable; wake() makes it spin again for
// wake_spin_us. A frame loop thus keeps its workers dozing between frames and spinning from 3 ms
// before each; an idle application parks them after park_after_us.
//
// Scheduling: open loops form a list (newest first, so helpers take the innermost nested loop
// first, as a depth-first work-stealing scheduler would); a thread claims a loop's chunks one
// at a time under the pool's mutex and runs them outside it. A loop leaves the list when its
// last chunk is claimed, before that chunk runs, so after its owner has seen every chunk
// finished nobody touches it again: loops live on their owner's stack, no allocation.
#include <algorithm>
#include <atomic>
#include <cassert>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "ocean/task_runner.hpp"

namespace ocean {

namespace {

using Clock = std::chrono::steady_clock;

// Tells the core (and a hypervisor) that this thread is spinning.
inline void cpu_pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

struct Loop {
  explicit Loop(FunctionRef<void(std::size_t, std::size_t)> b) : body(b) {}
  void reset(std::size_t n_, std::size_t grain_) {
    n = n_;
    grain = std::max<std::size_t>(grain_, 1);
    chunks = (n + grain - 1) / grain;
    next = 0;
    finished.store(0, std::memory_order_relaxed);
  }
  FunctionRef<void(std::size_t, std::size_t)> body;
  std::size_t n = 0, grain = 1, chunks = 0;
  std::size_t next = 0;  // the next chunk to claim; guarded by the pool's mutex
  std::atomic<std::size_t> finished{0};
  Loop* link = nullptr;  // the next open loop; guarded by the pool's mutex
};

class ReadyRunner final : public TaskRunner {
 public:
  explicit ReadyRunner(const ReadyRunnerParams& params)
      : threads_(params.threads > 0
                     ? params.threads
                     : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))),
        spin_(microseconds(params.spin_us)),
        wake_spin_(microseconds(params.wake_spin_us)),
        nap_(microseconds(params.nap_us)),
        park_after_(microseconds(params.park_after_us)) {
    assert(params.threads >= 0 && params.threads <= kMaxRunnerThreads);
    assert(params.spin_us >= 0.0 && params.spin_us <= 1e6);
    assert(params.wake_spin_us >= 0.0 && params.wake_spin_us <= 1e6);
    assert(params.nap_us > 0.0 && params.nap_us <= 1e6);
    assert(params.park_after_us >= 0.0 && params.park_after_us <= 1e7);
    workers_.reserve(static_cast<std::size_t>(threads_ - 1));
    for (int i = 1; i < threads_; ++i) workers_.emplace_back([this] { work(); });
  }

  ~ReadyRunner() override {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_.store(true, std::memory_order_relaxed);
      ++epoch_;
    }
    sleep_cv_.notify_all();
    for (std::thread& t : workers_) t.join();
  }

  void parallel_for(std::size_t n, std::size_t grain,
                    FunctionRef<void(std::size_t, std::size_t)> body) override {
    if (n == 0) return;
    if (threads_ == 1 || n <= grain) {
      body(0, n);
      return;
    }
    Loop loop(body);
    loop.reset(n, grain);
    open(loop);
    finish(loop);
  }

  [[nodiscard]] int concurrency() const override { return threads_; }

  void wake() override {
    wake_at_.store(Clock::now().time_since_epoch().count(), std::memory_order_relaxed);
    const std::lock_guard<std::mutex> lock(mutex_);
    if (sleepers_ == 0) return;
    ++epoch_;
    sleep_cv_.notify_all();
  }

  [[nodiscard]] std::unique_ptr<AsyncSlot> make_async_slot() override;

  // Puts a loop on the open list and wakes sleeping workers.
  void open(Loop& loop) {
    const std::lock_guard<std::mutex> lock(mutex_);
    loop.link = open_;
    open_ = &loop;
    open_count_.fetch_add(1, std::memory_order_release);
    ++epoch_;
    if (sleepers_ > 0) sleep_cv_.notify_all();
  }

  // Runs the loop's unclaimed chunks, then helps with other loops until every chunk of this one
  // has finished.
  void finish(Loop& loop) {
    while (run_one(&loop)) {
    }
    unsigned spins = 0;
    while (loop.finished.load(std::memory_order_acquire) < loop.chunks) {
      if (run_one(nullptr)) continue;
      cpu_pause();
      if (++spins % 1024 == 0) std::this_thread::yield();
    }
  }

  [[nodiscard]] int threads() const { return threads_; }

 private:
  // Claims one chunk, of `prefer` while it has unclaimed chunks (it is open), else of the newest
  // open loop, and runs it. False when there was nothing to claim.
  bool run_one(Loop* prefer) {
    if (open_count_.load(std::memory_order_acquire) == 0) return false;
    Loop* loop = nullptr;
    std::size_t chunk = 0;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      loop = open_;
      if (prefer != nullptr) {
        for (Loop* l = open_; l != nullptr; l = l->link)
          if (l == prefer) loop = l;
        if (loop != prefer) return false;
      }
      if (loop == nullptr) return false;
      chunk = loop->next++;
      if (loop->next == loop->chunks) unlink(*loop);
    }
    const std::size_t begin = chunk * loop->grain;
    loop->body(begin, std::min(loop->n, begin + loop->grain));
    loop->finished.fetch_add(1, std::memory_order_acq_rel);
    return true;
  }

  // Removes a fully claimed loop from the open list; the mutex is held.
  void unlink(Loop& loop) {
    Loop** at = &open_;
    while (*at != &loop) at = &(*at)->link;
    *at = loop.link;
    open_count_.fetch_sub(1, std::memory_order_release);
  }

  void work() {
    Clock::time_point idle_since = Clock::now();
    unsigned spins = 0;
    for (;;) {
      if (run_one(nullptr)) {
        idle_since = Clock::now();
        continue;
      }
      if (stop_.load(std::memory_order_relaxed)) return;
      cpu_pause();
      if (++spins % 64 != 0) continue;
      const Clock::time_point now = Clock::now();
      const Clock::time_point woken{Clock::duration(wake_at_.load(std::memory_order_relaxed))};
      if (now - idle_since < spin_ || now - woken < wake_spin_) continue;
      if (now - std::max(idle_since, woken) < park_after_) {
        std::this_thread::sleep_for(nap_);  // doze: a timed nap, no notification needed
        continue;
      }
      std::unique_lock<std::mutex> lock(mutex_);
      if (open_ != nullptr || stop_.load(std::memory_order_relaxed)) continue;
      const std::uint64_t seen = epoch_;
      ++sleepers_;
      sleep_cv_.wait(lock, [&] { return epoch_ != seen; });
      --sleepers_;
      idle_since = Clock::now();
    }
  }

  static Clock::duration microseconds(double us) {
    return std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double, std::micro>(us));
  }

  const int threads_;
  const Clock::duration spin_, wake_spin_, nap_, park_after_;
  std::mutex mutex_;
  std::condition_variable sleep_cv_;
  Loop* open_ = nullptr;            // open loops, newest first (guarded)
  std::uint64_t epoch_ = 0;         // bumped when a loop opens, on wake() and on stop (guarded)
  int sleepers_ = 0;                // workers waiting on sleep_cv_ (guarded)
  std::atomic<int> open_count_{0};  // loops on the list: a hint read without the mutex
  std::atomic<bool> stop_{false};
  std::atomic<Clock::rep> wake_at_{0};  // the last wake(): spin until wake_spin_ after it
  std::vector<std::thread> workers_;
};

// The job is a loop of one chunk: a worker claims it, or wait() runs it on the caller's thread.
class ReadySlot final : public AsyncSlot {
 public:
  explicit ReadySlot(ReadyRunner& runner) : runner_(runner), loop_(call_) {}
  ~ReadySlot() override { wait(); }
  void kick(FunctionRef<void()> job) override {
    assert(!in_flight_);
    if (runner_.threads() == 1) {
      job();
      return;
    }
    job_.emplace(job);
    loop_.reset(1, 1);
    in_flight_ = true;
    runner_.open(loop_);
  }
  void wait() override {
    if (!in_flight_) return;
    runner_.finish(loop_);
    in_flight_ = false;
  }

 private:
  struct Call {
    ReadySlot* slot;
    void operator()(std::size_t, std::size_t) const { (*slot->job_)(); }
  };
  ReadyRunner& runner_;
  Call call_{this};
  Loop loop_;
  std::optional<FunctionRef<void()>> job_;
  bool in_flight_ = false;
};

std::unique_ptr<AsyncSlot> ReadyRunner::make_async_slot() {
  return std::make_unique<ReadySlot>(*this);
}

}  // namespace

std::unique_ptr<TaskRunner> make_ready_runner(const ReadyRunnerParams& params) {
  return std::make_unique<ReadyRunner>(params);
}

}  // namespace ocean
