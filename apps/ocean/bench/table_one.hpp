// `ocean bench --table-one`: VR-GIS FFT+Perlin's Table I for this machine — the CPU pipeline's
// and the Vulkan backend's time per frame at the same grid sizes, and their ratio.
#pragma once

#include <vector>

namespace ocean::cli::bench {

/// Times one frame of `cascades` cascades at each resolution on the CPU backend (every hardware
/// thread, median over about min_time seconds) and on the Vulkan backend (GPU time from
/// timestamp queries, mean of 20 frames, read-back included as the CPU frame's arrays are), and
/// prints the table (or JSON) with the source's figures beside ours. Returns the exit code; a
/// build without Vulkan answers "built without Vulkan", a machine without a device the
/// context's error.
int run_table_one(const std::vector<int>& resolutions, int cascades, double min_time, bool json);

}  // namespace ocean::cli::bench
