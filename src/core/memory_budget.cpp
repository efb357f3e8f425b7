// The memory budget (ocean/memory_budget.hpp): physical memory and the address-space limit.
#include "ocean/memory_budget.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <cinttypes>
#include <cstdio>
#include <limits>

namespace ocean {
namespace {

// The address space this process has mapped, in bytes (the first field of /proc/self/statm, in
// pages); 0 where that file is absent.
std::uint64_t mapped_bytes(std::uint64_t page) {
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  if (statm == nullptr) return 0;
  std::uint64_t pages = 0;
  if (std::fscanf(statm, "%" SCNu64, &pages) != 1) pages = 0;
  std::fclose(statm);
  return pages * page;
}

}  // namespace

MemoryBudget memory_budget() {
  MemoryBudget budget{.bytes = std::numeric_limits<std::uint64_t>::max()};
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page > 0)
    budget.bytes = static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page);
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t mapped = mapped_bytes(page > 0 ? static_cast<std::uint64_t>(page) : 0);
    const std::uint64_t left = limit.rlim_cur > mapped ? limit.rlim_cur - mapped : 0;
    if (left < budget.bytes) budget = {.bytes = left, .address_space_limited = true};
  }
  return budget;
}

std::string format_bytes(std::uint64_t bytes) {
  constexpr const char* kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  auto value = static_cast<double>(bytes);
  std::size_t unit = 0;
  while (value >= 1024.0 && unit + 1 < std::size(kUnits)) value /= 1024.0, ++unit;
  char text[32];
  if (unit == 0)
    std::snprintf(text, sizeof text, "%" PRIu64 " bytes", bytes);
  else
    std::snprintf(text, sizeof text, value < 10.0 ? "%.1f %s" : "%.0f %s", value, kUnits[unit]);
  return text;
}

Status require_memory(std::string_view what, std::uint64_t bytes) {
  const MemoryBudget budget = memory_budget();
  if (bytes <= budget.bytes) return {};
  std::string message(what);
  message.append(" needs ").append(format_bytes(bytes)).append(" of memory, more than the ");
  message.append(format_bytes(budget.bytes));
  message.append(budget.address_space_limited ? " the address-space limit (ulimit -v) leaves"
                                              : " of physical memory");
  return invalid_argument(std::move(message));
}

}  // namespace ocean
