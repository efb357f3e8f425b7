// `ocean bench --overlap`: the concurrent kernels of [VR-GIS FFT+Perlin] measured — the cascades'
// frame alone, the far field's noise map alone (docs/rendering.md R.13a) and both in one frame, on
// the CPU backend (two tasks of the frame graph), the Vulkan backend (one submission, no barrier
// between the noise dispatch and the FFT's first stage) and the CUDA backend (the map on a stream
// of its own beside the cascades', one graph; GPU time from CudaBackend::time_frames), and how much
// of the shorter one the frame hides.
#pragma once

#include <vector>

#include "ocean/sim.hpp"

namespace ocean::cli::bench {

struct OverlapOptions {
  std::vector<int> resolutions;  ///< cascade grid sizes N
  std::vector<int> cascades;     ///< cascade counts
  int noise_resolution = 256;    ///< the noise map's texels per side
  int threads = 0;               ///< the CPU backend's threads (0: all)
  double min_time = 0.2;         ///< seconds of timed frames per measurement
  bool json = false;
};

/// overlap = (t_cascades + t_noise − t_both) / min(t_cascades, t_noise), medians of the wall
/// time per frame (CUDA: means of the GPU time per frame): 1 when the shorter part is hidden
/// entirely, 0 when the parts run one after the other, negative when running them together costs
/// more than in turn.
double overlap_of(double cascades_ms, double noise_ms, double both_ms);

/// Prints the table (or JSON) and returns the exit code.
int run_overlap(const OverlapOptions& options);

}  // namespace ocean::cli::bench
