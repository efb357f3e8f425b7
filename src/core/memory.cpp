// Large-array storage (ocean/memory.hpp).
#include "ocean/memory.hpp"

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
}  // namespace

void* allocate_large(std::size_t bytes) {
  if (bytes < kHugeFrom) return ::operator new (bytes, std::align_val_t{kLine});
  void* p = ::operator new (rounded(bytes), std::align_val_t{kHugePage});
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Before the first touch, so that the pages fault in as huge pages. Advice only: where THP is
  // off the array simply stays on small pages.
  (void)::madvise(p, rounded(bytes), MADV_HUGEPAGE);
#endif
  return p;
}

void free_large(void* p, std::size_t bytes) noexcept {
  if (bytes < kHugeFrom) {
    ::operator delete (p, std::align_val_t{kLine});
  } else {
    ::operator delete (p, std::align_val_t{kHugePage});
  }
}

}  // namespace ocean
