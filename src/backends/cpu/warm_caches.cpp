// The CPU backend's cache warm-up before a paced frame (Backend::warm_caches).
//
// Why: a frame loop at 90 or 120 Hz leaves its threads idle for 7–11 ms between frames, and in
// that time other work (other processes, other tenants of the machine's shared last-level cache)
// evicts the frame's working set: ≈ 70 bytes per texel, 18 MB for 4 × 256², which back-to-back
// frames find in the last-level cache. The paced frame then reads it from memory, mostly in the
// evolution and FFT (docs/performance.md, paced frames: +25–30 % on the reference machine, two
// thirds of it in the synthesis). A step that starts from cold caches cannot avoid that
// traffic, but the frame loop can move it before the frame: called about 1 ms before step(),
// this pass reads the state the step reads and requests for writing the lines it writes, one
// access per cache line, each cascade group's arrays on the runner's threads as the chained step
// distributes them (chunk g of a loop over the groups, so a thread warms the group whose chain it
// will run, in its own core's caches where it stays on the same core).
#include <atomic>
#include <cstddef>

#include "cpu_backend.hpp"

namespace ocean::cpu {

namespace {

constexpr std::size_t kLine = 64;

// One load per cache line of a read-only array (the spectrum records, the rates); the sum, stored
// where the compiler cannot drop it, keeps the loads.
template <class T>
unsigned read_lines(const T* data, std::size_t count) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data);
  const std::size_t size = count * sizeof(T);
  unsigned sum = 0;
  for (std::size_t i = 0; i < size; i += kLine) sum += bytes[i];
  return sum;
}

// A prefetch with intent to write per cache line of an array the step writes (planes, foam
// state, mip work, the frame's outputs): the lines arrive owned, so the step's stores do not
// wait for them.
template <class T>
void own_lines(const T* data, std::size_t count) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data);
  const std::size_t size = count * sizeof(T);
  for (std::size_t i = 0; i < size; i += kLine) __builtin_prefetch(bytes + i, 1, 3);
}

template <class V>
unsigned read_lines(const V& v) {
  return read_lines(v.data(), v.size());
}
template <class V>
void own_lines(const V& v) {
  own_lines(v.data(), v.size());
}

}  // namespace

void CpuBackendImpl::warm_caches(const Frame& out) {
  // The fused pipeline only (the others are oracles), and only where a frame's arrays fit the
  // caches: from 512² they stream from memory back to back too (≈ 75 MB per frame, see the
  // chain-per-thread rule in step()), and warming them would evict what it had just read.
  if (options_.pipeline != CpuPipeline::fused_simd || config_.resolution > 256) return;
  // In the reverse order of the step's use (the last group first; in a group the outputs, the
  // planes and state it writes, then the records it reads first), so that what the step reads
  // first is what was touched last, in the nearest cache.
  runner_->parallel_for(groups_.size(), 1, [&](std::size_t begin, std::size_t end) {
    unsigned sum = 0;
    for (std::size_t g = end; g-- > begin;) {
      const CascadeGroup& group = groups_[g];
      for (std::size_t c = group.first + group.count; c-- > group.first;) {
        const CascadeFrame& frame = out.cascades[c];
        own_lines(frame.packed_mips), own_lines(frame.foam), own_lines(frame.jacobian);
        own_lines(frame.normal), own_lines(frame.displacement_half);
        own_lines(frame.displacement);
        const CascadeState& state = cascades_[c];
        own_lines(state.mip_work), own_lines(state.foam);
        for (const auto& plane : state.plane_im) own_lines(plane);
        for (const auto& plane : state.plane_re) own_lines(plane);
        own_lines(state.tiles);
        sum += read_lines(state.evolution_lane0_rate) + read_lines(state.evolution_rate) +
               read_lines(state.evolution_lane0) + read_lines(state.evolution_spectrum);
      }
    }
    warm_sink_.fetch_add(sum, std::memory_order_relaxed);
  });
}

}  // namespace ocean::cpu
