// Large-array storage (ocean/memory.hpp).
#include "ocean/memory.hpp"

#include <mutex>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace ocean {
namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
// From half a huge page up (rounded up to whole ones): at most 2× the memory of an array of
// 1…2 MiB, for the TLB reach of a huge page.
constexpr std::size_t kHugeFrom = kHugePage / 2;
constexpr std::size_t kLine = 64;
std::size_t rounded(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

// The installed hooks and the live arrays, under one mutex: a change waits for no array to be
// live, so that each is freed by the allocator that made it. Arrays are made when a simulator is
// (not per frame), so the lock costs nothing that matters.
std::mutex g_mutex;
LargeAllocatorHooks g_hooks;  // allocate null: operator new
std::size_t g_live = 0;

void* from_hooks(std::size_t bytes, std::size_t alignment) {
  void* p = g_hooks.allocate(g_hooks.user_data, bytes, alignment);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}
}  // namespace

bool set_large_allocator(const LargeAllocatorHooks* hooks) {
  const std::lock_guard lock(g_mutex);
  if (g_live != 0) return false;
  g_hooks = hooks != nullptr ? *hooks : LargeAllocatorHooks{};
  return true;
}

std::size_t live_large_arrays() {
  const std::lock_guard lock(g_mutex);
  return g_live;
}

void* allocate_large(std::size_t bytes) {
  const std::lock_guard lock(g_mutex);
  void* p = nullptr;
  if (bytes < kHugeFrom) {
    p = g_hooks.allocate != nullptr ? from_hooks(bytes, kLine)
                                    : ::operator new (bytes, std::align_val_t{kLine});
    ++g_live;
    return p;
  }
  if (g_hooks.allocate != nullptr) {  // the host's memory, with the host's page policy
    p = from_hooks(rounded(bytes), kHugePage);
    ++g_live;
    return p;
  }
  p = ::operator new (rounded(bytes), std::align_val_t{kHugePage});
  ++g_live;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Before the first touch, so that the pages fault in as huge pages. Advice only: where THP is
  // off the array simply stays on small pages.
  (void)::madvise(p, rounded(bytes), MADV_HUGEPAGE);
#endif
  return p;
}

void free_large(void* p, std::size_t bytes) noexcept {
  if (p == nullptr) return;
  const std::lock_guard lock(g_mutex);
  --g_live;
  if (g_hooks.deallocate != nullptr) {
    if (bytes < kHugeFrom) {
      g_hooks.deallocate(g_hooks.user_data, p, bytes, kLine);
    } else {
      g_hooks.deallocate(g_hooks.user_data, p, rounded(bytes), kHugePage);
    }
  } else if (bytes < kHugeFrom) {
    ::operator delete (p, std::align_val_t{kLine});
  } else {
    ::operator delete (p, std::align_val_t{kHugePage});
  }
}

}  // namespace ocean
