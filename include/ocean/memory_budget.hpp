// ocean/memory_budget.hpp — how much memory this process can hope to hold, so that a size that
// cannot fit (a 16384² picture under `ulimit -v`) is refused with a one-line message before it
// is allocated, instead of ending in std::bad_alloc.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "ocean/core.hpp"

namespace ocean {

/// How much memory this process can hope to hold. A bound for refusing sizes that cannot fit,
/// not a promise that this much is free: other processes use memory too.
struct MemoryBudget {
  /// The physical memory (sysconf(_SC_PHYS_PAGES) × sysconf(_SC_PAGE_SIZE)) or, when the
  /// RLIMIT_AS soft limit (`ulimit -v`) is set and leaves less, that limit less the address
  /// space already mapped (/proc/self/statm). UINT64_MAX when neither is known.
  std::uint64_t bytes = 0;
  bool address_space_limited = false;  ///< `bytes` comes from RLIMIT_AS
};
/// The budget now (it shrinks as the address space fills). Never throws; thread-safe.
MemoryBudget memory_budget();

/// "512 MiB", "3.8 GiB": a byte count for a message, in binary units (one decimal below 10).
std::string format_bytes(std::uint64_t bytes);

/// ok when `bytes` fit memory_budget(); otherwise invalid_argument "<what> needs 3.8 GiB of
/// memory, more than the 2.0 GiB the address-space limit (ulimit -v) leaves" (or "... the
/// 15 GiB of physical memory").
Status require_memory(std::string_view what, std::uint64_t bytes);

}  // namespace ocean
