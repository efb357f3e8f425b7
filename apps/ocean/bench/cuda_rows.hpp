// `ocean bench --backend cuda`: GPU time per frame from CUDA events around the frame's graph.
#pragma once

#include <string>
#include <vector>

#include "ocean/sim.hpp"

namespace ocean::cli::bench {

/// Times every (resolution, cascades) pair on the CUDA backend: the simulation with the cascades
/// on concurrent streams, the same on one stream (their ratio is the streams' overlap), and the
/// readback; prints the rows (JSON or a table). Returns the exit code; without CUDA, "built
/// without CUDA"; without a device, "no CUDA device: ...".
int run_cuda_bench(const std::vector<int>& resolutions, const std::vector<int>& cascades,
                   const FrameOutputs& outputs, const std::string& outputs_name, bool json);

}  // namespace ocean::cli::bench
