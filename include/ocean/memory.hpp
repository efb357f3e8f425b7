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
