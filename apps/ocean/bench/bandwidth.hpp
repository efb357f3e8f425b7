// `ocean bench`'s copy-bandwidth probe: the memory and cache bandwidth the frame times are read
// against (docs/performance.md).
#pragma once

#include <cstddef>

#include "ocean/task_runner.hpp"

namespace ocean::cli::bench {

/// Best of `repeats` parallel copies of `bytes`: read + write bytes per second, GB/s. 256 MiB
/// streams from memory; 16 MiB is the size of a frame's state and outputs at 4 × 256², which
/// the last-level cache may hold. Allocates 2·bytes.
double measure_copy_bandwidth_gbps(TaskRunner& runner, std::size_t bytes, int repeats);

}  // namespace ocean::cli::bench
