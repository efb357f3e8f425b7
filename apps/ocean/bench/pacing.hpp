// `ocean bench --pacing`: the frame budget of a paced frame loop. The CPU pipeline is timed with
// its frames a display period apart (the harness wakes the runner kWakeLead_s ahead, as a frame
// loop does), the same with the backend's cache warm-up kWarmLead_s ahead (Backend::warm_caches,
// as ocean xr does through Simulator::prepare_step), and back to back, alternated in kPacedRounds
// rounds on the same backend so that all three see the same minutes of a noisy machine; each row
// gives the medians, the paced/back-to-back ratios and their spread over the rounds, the stages'
// medians and the warm-up's own time (docs/performance.md, paced frames).
#pragma once

#include <string>
#include <vector>

#include "ocean/sim.hpp"

namespace ocean::cli::bench {

struct PacingOptions {
  int resolution = 256;
  int cascades = 4;
  std::vector<double> intervals_ms = {1000.0 / 90.0, 1000.0 / 120.0};  ///< display periods
  std::vector<int> threads;          ///< thread counts (resolved: no 0)
  std::vector<std::string> runners;  ///< tbb, ready
  FrameOutputs outputs;
  std::string outputs_name;  ///< as given: all or textures
  double min_time = 2.0;     ///< seconds of frames per row and kind
  bool json = false;
};

/// The median of the rounds' ratios and their extremes.
struct RatioSpread {
  double median = 0.0, min = 0.0, max = 0.0;
};
/// Of `ratios` (not empty).
RatioSpread spread_of(std::vector<double> ratios);

/// Prints the table (or JSON) and returns the exit code.
int run_pacing(const PacingOptions& options);

}  // namespace ocean::cli::bench
