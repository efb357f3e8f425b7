// `ocean bench --backend vulkan`: GPU time per stage from timestamp queries.
#pragma once

#include <string>
#include <vector>

#include "ocean/sim.hpp"

namespace ocean::cli::bench {

/// Times every (resolution, cascades) pair on the Vulkan backend and prints the rows (JSON or a
/// table). Returns the exit code; without Vulkan, "built without Vulkan".
int run_vulkan_bench(const std::vector<int>& resolutions, const std::vector<int>& cascades,
                     const FrameOutputs& outputs, const std::string& outputs_name, bool json);

}  // namespace ocean::cli::bench
