// `ocean bench`'s copy-bandwidth probe.
#include "bench/bandwidth.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

namespace ocean::cli::bench {

double measure_copy_bandwidth_gbps(TaskRunner& runner, std::size_t bytes, int repeats) {
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  const std::size_t kBytes = bytes;
  std::vector<char> from(kBytes, 1), to(kBytes, 0);
  double best = 0.0;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    runner.parallel_for(kBytes / kChunk, 1, [&](std::size_t begin, std::size_t end) {
      std::memcpy(to.data() + begin * kChunk, from.data() + begin * kChunk, (end - begin) * kChunk);
    });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, 2.0 * double(kBytes) / seconds * 1e-9);
  }
  return best;
}

}  // namespace ocean::cli::bench
