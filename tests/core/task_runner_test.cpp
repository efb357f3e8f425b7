// Task runners cover every index exactly once, whatever the grain and thread count, also when a
// body runs a parallel loop of its own (the CPU backend's chained frame does); async slots run
// a job inline (serial), concurrently with the caller (oneTBB, the ready runner), or on an
// engine's own threads. Nothing here is timed: the ready runner's speed is bench's to show.
#include "ocean/task_runner.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace {

TEST(TaskRunner, CoversEveryIndexOnce) {
  std::vector<std::unique_ptr<ocean::TaskRunner>> runners;
  runners.push_back(ocean::make_serial_runner());
  runners.push_back(ocean::make_tbb_runner(1));
  runners.push_back(ocean::make_tbb_runner(2));
  runners.push_back(ocean::make_tbb_runner());
  runners.push_back(ocean::make_ready_runner({.threads = 1}));
  runners.push_back(ocean::make_ready_runner({.threads = 2, .spin_us = 0.0}));
  runners.push_back(ocean::make_ready_runner({.threads = 3}));
  for (auto& runner : runners) {
    for (std::size_t n : {0u, 1u, 7u, 1000u}) {
      for (std::size_t grain : {1u, 3u, 64u}) {
        std::vector<std::atomic<int>> hits(n);
        runner->parallel_for(n, grain, [&](std::size_t b, std::size_t e) {
          for (std::size_t i = b; i < e; ++i) hits[i].fetch_add(1);
        });
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i].load(), 1);
      }
    }
    EXPECT_GE(runner->concurrency(), 1);
  }
  EXPECT_EQ(ocean::make_serial_runner()->concurrency(), 1);
  EXPECT_EQ(ocean::make_tbb_runner(1)->concurrency(), 1);
  EXPECT_EQ(ocean::make_ready_runner({.threads = 3})->concurrency(), 3);
}

TEST(TaskRunner, NestedLoopsCoverEveryIndexOnce) {
  std::vector<std::unique_ptr<ocean::TaskRunner>> runners;
  runners.push_back(ocean::make_serial_runner());
  runners.push_back(ocean::make_tbb_runner(1));
  runners.push_back(ocean::make_tbb_runner(2));
  runners.push_back(ocean::make_ready_runner({.threads = 2, .spin_us = 0.0}));
  runners.push_back(ocean::make_ready_runner({.threads = 3}));
  for (auto& runner : runners) {
    constexpr std::size_t kOuter = 3, kInner = 500;
    std::vector<std::atomic<int>> hits(kOuter * kInner);
    runner->parallel_for(kOuter, 1, [&](std::size_t ob, std::size_t oe) {
      for (std::size_t o = ob; o < oe; ++o) {
        runner->parallel_for(kInner, 7, [&](std::size_t b, std::size_t e) {
          for (std::size_t i = b; i < e; ++i) hits[o * kInner + i].fetch_add(1);
        });
      }
    });
    for (std::size_t i = 0; i < hits.size(); ++i) ASSERT_EQ(hits[i].load(), 1) << i;
  }
}

TEST(TaskRunner, SerialSlotRunsTheJobInlineInKick) {
  auto runner = ocean::make_serial_runner();
  auto slot = runner->make_async_slot();
  const std::thread::id caller = std::this_thread::get_id();
  int runs = 0;
  std::thread::id ran_on;
  auto job = [&] {
    ++runs;
    ran_on = std::this_thread::get_id();
  };
  slot->kick(job);
  EXPECT_EQ(runs, 1);  // before wait()
  EXPECT_EQ(ran_on, caller);
  slot->wait();
  slot->wait();  // nothing in flight: returns at once
  EXPECT_EQ(runs, 1);
}

// The job waits for the caller to pass kick(): it can finish only if it runs concurrently.
void expect_job_runs_concurrently(ocean::TaskRunner* runner) {
  auto slot = runner->make_async_slot();
  std::atomic<bool> kicked{false}, saw_kick{false};
  std::vector<std::atomic<int>> hits(1000);
  auto job = [&] {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!kicked.load() && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
    saw_kick = kicked.load();
    runner->parallel_for(hits.size(), 16, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) hits[i].fetch_add(1);
    });
  };
  for (int round = 0; round < 3; ++round) {
    kicked = false;
    saw_kick = false;
    slot->kick(job);
    kicked = true;
    slot->wait();
    EXPECT_TRUE(saw_kick.load());
  }
  for (const auto& h : hits) ASSERT_EQ(h.load(), 3);
}

TEST(TaskRunner, TbbSlotRunsTheJobConcurrentlyWithTheCaller) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one hardware thread";
  expect_job_runs_concurrently(ocean::make_tbb_runner().get());
}

// The ready runner's threads are its own: two of them work concurrently on any machine, whether
// the worker parks, dozes or spins between jobs.
TEST(TaskRunner, ReadySlotRunsTheJobConcurrentlyWithTheCaller) {
  auto parking = ocean::make_ready_runner({.threads = 2, .spin_us = 0.0, .park_after_us = 0.0});
  expect_job_runs_concurrently(parking.get());
  auto dozing = ocean::make_ready_runner({.threads = 2, .spin_us = 0.0, .nap_us = 200.0});
  expect_job_runs_concurrently(dozing.get());
  auto spinning = ocean::make_ready_runner({.threads = 2, .spin_us = 1e6});
  expect_job_runs_concurrently(spinning.get());
}

// Two chunks that each wait for the other to start finish only if two threads run the loop at
// once: the caller and a worker, whether the worker parked (spin 0, park at once), dozed, was
// woken by wake(), or is still spinning.
TEST(TaskRunner, ReadyRunnerRunsALoopOnTwoThreads) {
  const ocean::ReadyRunnerParams params[] = {
      {.threads = 2, .spin_us = 0.0, .wake_spin_us = 0.0, .park_after_us = 0.0},
      {.threads = 2, .spin_us = 0.0, .park_after_us = 0.0},
      {.threads = 2, .spin_us = 0.0, .wake_spin_us = 0.0, .nap_us = 300.0},
      {.threads = 2, .spin_us = 1e6}};
  for (std::size_t i = 0; i < std::size(params); ++i) {
    auto runner = ocean::make_ready_runner(params[i]);
    for (int round = 0; round < 20; ++round) {
      if (round % 2) runner->wake();
      std::atomic<int> started{0};
      std::atomic<int> met{0};
      runner->parallel_for(2, 1, [&](std::size_t, std::size_t) {
        started.fetch_add(1);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (started.load() < 2 && std::chrono::steady_clock::now() < deadline)
          std::this_thread::yield();
        if (started.load() == 2) met.fetch_add(1);
      });
      ASSERT_EQ(met.load(), 2) << "parameters " << i << " round " << round;
    }
  }
}

// A kicked job that nobody has taken yet runs in wait(); a slot destroyed with a job in flight
// waits for it.
TEST(TaskRunner, ReadySlotFinishesItsJob) {
  auto runner = ocean::make_ready_runner({.threads = 2, .spin_us = 0.0});
  int runs = 0;
  auto job = [&] { ++runs; };
  {
    auto slot = runner->make_async_slot();
    for (int i = 0; i < 50; ++i) {
      slot->kick(job);
      slot->wait();
    }
    slot->kick(job);
  }
  EXPECT_EQ(runs, 51);
}

// An engine's job system: parallel_for on the caller's thread, async jobs on a thread the
// engine owns. The default slot of a runner that does not override make_async_slot runs inline.
class EngineRunner final : public ocean::TaskRunner {
 public:
  void parallel_for(std::size_t n, std::size_t /*grain*/,
                    ocean::FunctionRef<void(std::size_t, std::size_t)> body) override {
    if (n > 0) body(0, n);
  }
  [[nodiscard]] int concurrency() const override { return 2; }
  [[nodiscard]] std::unique_ptr<ocean::AsyncSlot> make_async_slot() override {
    return std::make_unique<ThreadSlot>();
  }

 private:
  class ThreadSlot final : public ocean::AsyncSlot {
   public:
    ~ThreadSlot() override { wait(); }
    void kick(ocean::FunctionRef<void()> job) override { worker_ = std::thread(job); }
    void wait() override {
      if (worker_.joinable()) worker_.join();
    }

   private:
    std::thread worker_;
  };
};

class LoopOnlyRunner final : public ocean::TaskRunner {
 public:
  void parallel_for(std::size_t n, std::size_t /*grain*/,
                    ocean::FunctionRef<void(std::size_t, std::size_t)> body) override {
    if (n > 0) body(0, n);
  }
  [[nodiscard]] int concurrency() const override { return 1; }
};

TEST(TaskRunner, EngineRunnersPlugInTheirOwnAsyncJobs) {
  EngineRunner engine;
  auto slot = engine.make_async_slot();
  const std::thread::id caller = std::this_thread::get_id();
  std::thread::id ran_on = caller;
  std::size_t covered = 0;
  auto job = [&] {
    ran_on = std::this_thread::get_id();
    engine.parallel_for(100, 10, [&](std::size_t b, std::size_t e) { covered += e - b; });
  };
  slot->kick(job);
  slot->wait();
  EXPECT_NE(ran_on, caller);
  EXPECT_EQ(covered, 100u);

  LoopOnlyRunner loops;
  auto inline_slot = loops.make_async_slot();
  int runs = 0;
  auto count = [&] { ++runs; };
  inline_slot->kick(count);
  EXPECT_EQ(runs, 1);
  inline_slot->wait();
  EXPECT_EQ(runs, 1);
}

// oneTBB fails on an arena of 10^9 threads: a request beyond kMaxRunnerThreads is clamped, a
// negative one means every hardware thread, and the runner still runs a loop.
TEST(TbbRunner, ThreadCountsOutsideTheRangeAreClamped) {
  const auto huge = ocean::make_tbb_runner(1'000'000'000);
  EXPECT_LE(huge->concurrency(), ocean::kMaxRunnerThreads);
  EXPECT_EQ(ocean::make_tbb_runner(-5)->concurrency(), ocean::make_tbb_runner(0)->concurrency());
  std::atomic<int> sum{0};
  huge->parallel_for(100, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) sum += static_cast<int>(i);
  });
  EXPECT_EQ(sum.load(), 4950);
}

}  // namespace
