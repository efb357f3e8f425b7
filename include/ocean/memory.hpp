// ocean/memory.hpp — storage for the large arrays a frame streams over: 64-byte aligned (whole
// cache lines for vector stores), and from 1 MiB up in whole 2 MiB pages with transparent huge
// pages requested where the system offers them (Linux, THP "madvise" or "always"), so that a
// pass over tens of MiB walks the page tables 512× less often.
#pragma once

#include <cstddef>
#include <vector>

namespace ocean {

/// Allocates `bytes` as described above; throws std::bad_alloc like operator new.
[[nodiscard]] void* allocate_large(std::size_t bytes);
/// Frees what allocate_large(bytes) returned, with the same `bytes`.
void free_large(void* p, std::size_t bytes) noexcept;

/// Where allocate_large takes its storage instead of operator new (the C ABI's
/// ocean_set_allocator): allocate(user_data, bytes, alignment) returns `bytes` aligned to
/// `alignment` (a power of two: 64, or 2 MiB for arrays of 1 MiB and up, whose size is then a
/// whole number of 2 MiB pages), or nullptr when it has none (allocate_large then throws
/// std::bad_alloc); deallocate(user_data, p, bytes, alignment) takes back what allocate gave.
struct LargeAllocatorHooks {
  void* user_data = nullptr;
  void* (*allocate)(void* user_data, std::size_t bytes, std::size_t alignment) = nullptr;
  void (*deallocate)(void* user_data, void* p, std::size_t bytes, std::size_t alignment) = nullptr;
};
/// Installs `hooks` (both functions set) or, with nullptr, operator new again; the table is
/// copied. Returns false and changes nothing while any array of allocate_large is live: each
/// must go back to the allocator that made it.
[[nodiscard]] bool set_large_allocator(const LargeAllocatorHooks* hooks);
/// The arrays of allocate_large not yet freed.
std::size_t live_large_arrays();

template <class T>
struct LargeAllocator {
  using value_type = T;
  LargeAllocator() = default;
  template <class U>
  constexpr LargeAllocator(const LargeAllocator<U>& /*other*/) noexcept {}
  [[nodiscard]] T* allocate(std::size_t count) {
    return static_cast<T*>(allocate_large(count * sizeof(T)));
  }
  void deallocate(T* p, std::size_t count) noexcept { free_large(p, count * sizeof(T)); }
  template <class U>
  friend bool operator==(const LargeAllocator& /*a*/, const LargeAllocator<U>& /*b*/) {
    return true;
  }
};

/// A std::vector on LargeAllocator: data() starts on a cache line (on a huge page when large).
template <class T>
using LargeVector = std::vector<T, LargeAllocator<T>>;

}  // namespace ocean
