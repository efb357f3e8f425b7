// The memory budget (ocean/memory_budget.hpp): bounded by the physical memory, and by the
// address-space limit when one is set (tried in a child process, so that this one keeps its
// limits).
#include "ocean/memory_budget.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

namespace {

constexpr std::uint64_t kBudgetMiB = std::uint64_t{1} << 20;

TEST(MemoryBudget, FormatsBytesInBinaryUnits) {
  EXPECT_EQ(ocean::format_bytes(0), "0 bytes");
  EXPECT_EQ(ocean::format_bytes(1023), "1023 bytes");
  EXPECT_EQ(ocean::format_bytes(1024), "1.0 KiB");
  EXPECT_EQ(ocean::format_bytes(512 * kBudgetMiB), "512 MiB");
  EXPECT_EQ(ocean::format_bytes(3 * 1024 * kBudgetMiB + 800 * kBudgetMiB), "3.8 GiB");
}

TEST(MemoryBudget, AtMostThePhysicalMemory) {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  ASSERT_GT(pages, 0);
  const auto physical = static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page);
  const ocean::MemoryBudget budget = ocean::memory_budget();
  EXPECT_LE(budget.bytes, physical);
  EXPECT_GT(budget.bytes, 0u);
  EXPECT_TRUE(ocean::require_memory("a byte", 1).ok());
  const ocean::Status too_much = ocean::require_memory("the test array", physical + 1);
  EXPECT_EQ(too_much.code(), ocean::ErrorCode::invalid_argument);
  EXPECT_EQ(too_much.message().rfind("the test array needs " + ocean::format_bytes(physical + 1) +
                                         " of memory, more than the ",
                                     0),
            0u)
      << too_much.message();
}

// Exit status of the child: 0 when the budget under `ulimit -v` (mapped now + 256 MiB) is
// between 128 and 256 MiB and says it comes from the limit, and when 512 MiB are refused.
int budget_under_a_limit() {
  const ocean::MemoryBudget before = ocean::memory_budget();
  if (before.address_space_limited) return 10;  // the test runs under a limit of its own
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  unsigned long long pages = 0;
  if (statm == nullptr || std::fscanf(statm, "%llu", &pages) != 1) return 11;
  std::fclose(statm);
  const std::uint64_t mapped = pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGE_SIZE));
  const rlimit limit{.rlim_cur = mapped + 256 * kBudgetMiB, .rlim_max = RLIM_INFINITY};
  if (::setrlimit(RLIMIT_AS, &limit) != 0) return 12;
  const ocean::MemoryBudget budget = ocean::memory_budget();
  if (!budget.address_space_limited) return 13;
  if (budget.bytes > 256 * kBudgetMiB || budget.bytes < 128 * kBudgetMiB) return 14;
  const ocean::Status s = ocean::require_memory("x", 512 * kBudgetMiB);
  if (s.message().find("the address-space limit (ulimit -v) leaves") == std::string::npos)
    return 15;
  return 0;
}

TEST(MemoryBudget, FollowsTheAddressSpaceLimit) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) std::_Exit(budget_under_a_limit());
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
