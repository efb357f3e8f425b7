// `ocean bench`'s results: one row per (resolution, cascades, threads), as JSON and as the
// table the tool prints.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/harness.hpp"

namespace ocean::cli::bench {

struct Row {
  int resolution = 0, cascades = 0, threads = 0;
  std::string runner;  ///< tbb or ready
  std::string outputs;
  double frame_interval_ms = 0.0;
  PipelineResult ours, fftw;
  PipelineResult back_to_back;  ///< ours back to back in the same rounds, when paced
  int fftw_threads = 0;
  Stats ours_fft, fftw_fft;
  double fft_gflops = 0.0, peak_fraction = 0.0;
  std::size_t memory_per_cascade = 0;
  bool has_fftw = false;
};

/// The row's fields as `ocean bench --json` prints them.
nlohmann::ordered_json to_json(const Row& r);
/// v with `digits` decimals.
std::string fixed(double v, int digits);
/// The table: a machine line (SIMD target, FMA peak, copy bandwidths), then one line per row.
void print_table(const std::vector<Row>& rows, const std::string& target, double peak,
                 double bandwidth, double cache_bandwidth);

}  // namespace ocean::cli::bench
