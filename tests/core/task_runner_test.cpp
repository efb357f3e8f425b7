// Task runners cover every index exactly once, whatever the grain and thread count, also when a
// body runs a parallel loop of its own (the CPU backend's chained frame does).
#include "ocean/task_runner.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace {

TEST(TaskRunner, CoversEveryIndexOnce) {
  std::vector<std::unique_ptr<ocean::TaskRunner>> runners;
  runners.push_back(ocean::make_serial_runner());
  runners.push_back(ocean::make_tbb_runner(1));
  runners.push_back(ocean::make_tbb_runner(2));
  runners.push_back(ocean::make_tbb_runner());
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
}

TEST(TaskRunner, NestedLoopsCoverEveryIndexOnce) {
  std::vector<std::unique_ptr<ocean::TaskRunner>> runners;
  runners.push_back(ocean::make_serial_runner());
  runners.push_back(ocean::make_tbb_runner(1));
  runners.push_back(ocean::make_tbb_runner(2));
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

}  // namespace
