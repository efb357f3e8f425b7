// Counting VkAllocationCallbacks (counting_allocator.hpp). Each block is
//   [padding][Header][the driver's bytes]
// with the driver's bytes at the alignment it asked for and the header right in front of them,
// so release() finds the size and scope to uncount without a table.
#include "counting_allocator.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace ocean::soak {

namespace {

struct Header {
  std::size_t size;    // the driver's bytes
  std::size_t offset;  // from the start of the block to the driver's bytes
  VkSystemAllocationScope scope;
};

std::size_t round_up(std::size_t n, std::size_t to) { return (n + to - 1) / to * to; }

Header* header_of(void* memory) { return static_cast<Header*>(memory) - 1; }

}  // namespace

CountingAllocator::CountingAllocator() {
  callbacks_ = {.pUserData = this,
                .pfnAllocation = &CountingAllocator::allocate,
                .pfnReallocation = &CountingAllocator::reallocate,
                .pfnFree = &CountingAllocator::release};
}

DriverMemory CountingAllocator::live() const {
  DriverMemory m;
  for (const auto& n : live_) m.all += n.load(std::memory_order_relaxed);
  m.objects = live_[VK_SYSTEM_ALLOCATION_SCOPE_OBJECT].load(std::memory_order_relaxed);
  m.bytes = bytes_.load(std::memory_order_relaxed);
  m.made = made_.load(std::memory_order_relaxed);
  return m;
}

void CountingAllocator::count(VkSystemAllocationScope scope, std::int64_t allocations,
                              std::int64_t bytes) {
  const auto s = std::min(static_cast<std::size_t>(scope), kScopes - 1);
  live_[s].fetch_add(allocations, std::memory_order_relaxed);
  bytes_.fetch_add(bytes, std::memory_order_relaxed);
  if (allocations > 0) made_.fetch_add(allocations, std::memory_order_relaxed);
}

void* VKAPI_PTR CountingAllocator::allocate(void* user, std::size_t size, std::size_t alignment,
                                            VkSystemAllocationScope scope) {
  // NULL would mean "out of host memory"; a zero-byte request gets a block of its own, as
  // malloc(0) would (lavapipe asks for one when it copies an empty barrier array).
  size = std::max<std::size_t>(size, 1);
  const std::size_t align = std::max(alignment, alignof(std::max_align_t));
  const std::size_t offset = round_up(sizeof(Header), align);
  void* block = std::aligned_alloc(align, round_up(offset + size, align));
  if (block == nullptr) return nullptr;
  void* memory = static_cast<std::byte*>(block) + offset;
  *header_of(memory) = {.size = size, .offset = offset, .scope = scope};
  static_cast<CountingAllocator*>(user)->count(scope, 1, static_cast<std::int64_t>(size));
  return memory;
}

void* VKAPI_PTR CountingAllocator::reallocate(void* user, void* original, std::size_t size,
                                              std::size_t alignment,
                                              VkSystemAllocationScope scope) {
  if (original == nullptr) return allocate(user, size, alignment, scope);
  if (size == 0) {
    release(user, original);
    return nullptr;
  }
  // A new block, so the counts and the alignment stay exact; the original is kept on failure,
  // as the specification requires.
  void* memory = allocate(user, size, alignment, header_of(original)->scope);
  if (memory == nullptr) return nullptr;
  std::memcpy(memory, original, std::min(size, header_of(original)->size));
  release(user, original);
  return memory;
}

void VKAPI_PTR CountingAllocator::release(void* user, void* memory) {
  if (memory == nullptr) return;
  const Header h = *header_of(memory);
  static_cast<CountingAllocator*>(user)->count(h.scope, -1, -static_cast<std::int64_t>(h.size));
  std::free(static_cast<std::byte*>(memory) - h.offset);
}

}  // namespace ocean::soak
