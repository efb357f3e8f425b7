// `ocean bench`'s results as JSON and as a table.
#include "bench/report.hpp"

#include <iomanip>
#include <iostream>
#include <sstream>

namespace ocean::cli::bench {

namespace {

nlohmann::ordered_json stage_json(const PipelineResult& r) {
  return {{"synthesis", r.synthesis.median_ms},
          {"finalize", r.finalize.median_ms},
          {"mips", r.mips.median_ms}};
}

}  // namespace

nlohmann::ordered_json to_json(const Row& r) {
  const auto or_null = [&](double v) {
    return r.has_fftw ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
  };
  nlohmann::ordered_json j;
  j["resolution"] = r.resolution;
  j["cascades"] = r.cascades;
  j["threads"] = r.threads;
  j["runner"] = r.runner;
  j["outputs"] = r.outputs;
  j["frame_interval_ms"] = r.frame_interval_ms;
  j["ours_ms"] = r.ours.frame.median_ms;
  j["ours_min_ms"] = r.ours.frame.min_ms;
  j["ours_max_ms"] = r.ours.frame.max_ms;
  j["ours_stages_ms"] = stage_json(r.ours);
  if (r.frame_interval_ms > 0.0) {
    j["back_to_back_ms"] = r.back_to_back.frame.median_ms;
    j["paced_ratio"] = r.ours.frame.median_ms / r.back_to_back.frame.median_ms;
  }
  j["ours_fft_only_ms"] = r.ours_fft.median_ms;
  j["fftw_pipeline_ms"] = or_null(r.fftw.frame.median_ms);
  j["fftw_pipeline_min_ms"] = or_null(r.fftw.frame.min_ms);
  j["fftw_pipeline_max_ms"] = or_null(r.fftw.frame.max_ms);
  j["fftw_pipeline_threads"] = r.has_fftw ? nlohmann::ordered_json(r.fftw_threads) : nullptr;
  j["fftw_stages_ms"] = r.has_fftw ? stage_json(r.fftw) : nlohmann::ordered_json(nullptr);
  j["fftw_fft_only_ms"] = or_null(r.fftw_fft.median_ms);
  j["ratio"] = or_null(r.ours.frame.median_ms / r.fftw.frame.median_ms);
  j["fft_ratio"] = or_null(r.ours_fft.median_ms / r.fftw_fft.median_ms);
  j["fft_gflops"] = r.fft_gflops;
  j["fft_peak_fraction"] = r.peak_fraction;
  j["memory_per_cascade_bytes"] = r.memory_per_cascade;
  // Every byte of state and output touched once per frame: a lower bound on the traffic.
  const double touched = double(r.memory_per_cascade) * r.cascades;
  j["touched_gbps"] = touched / (r.ours.frame.median_ms * 1e-3) * 1e-9;
  j["frames"] = r.ours.frames;
  return j;
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

void print_table(const std::vector<Row>& rows, const std::string& target, double peak,
                 double bandwidth, double cache_bandwidth) {
  std::cout << "SIMD target " << target << ", measured FMA peak " << fixed(peak, 1)
            << " GFLOP/s per thread, copy bandwidth " << fixed(bandwidth, 1) << " GB/s (256 MiB), "
            << fixed(cache_bandwidth, 1) << " GB/s (16 MiB); outputs "
            << (rows.empty() ? "all" : rows.front().outputs);
  if (!rows.empty() && rows.front().frame_interval_ms > 0.0)
    std::cout << "; frames " << fixed(rows.front().frame_interval_ms, 1) << " ms apart";
  std::cout << "; times are medians in ms\n";
  const bool paced = !rows.empty() && rows.front().frame_interval_ms > 0.0;
  std::cout << std::setw(6) << "N" << std::setw(4) << "C" << std::setw(5) << "thr" << std::setw(7)
            << "runner" << std::setw(10) << "ours";
  if (paced) std::cout << std::setw(10) << "b2b" << std::setw(7) << "paced";
  std::cout << std::setw(10) << "fftw-pipe" << std::setw(7) << "ratio" << std::setw(10)
            << "ours-fft" << std::setw(10) << "fftw-fft" << std::setw(9) << "GFLOP/s"
            << std::setw(7) << "%peak" << std::setw(10) << "MiB/casc"
            << "   stages synth/final/mips\n";
  for (const Row& r : rows) {
    const auto opt = [&](double v, int digits) { return r.has_fftw ? fixed(v, digits) : "-"; };
    std::cout << std::setw(6) << r.resolution << std::setw(4) << r.cascades << std::setw(5)
              << r.threads << std::setw(7) << r.runner << std::setw(10)
              << fixed(r.ours.frame.median_ms, 3);
    if (paced) {
      std::cout << std::setw(10) << fixed(r.back_to_back.frame.median_ms, 3) << std::setw(7)
                << fixed(r.ours.frame.median_ms / r.back_to_back.frame.median_ms, 2);
    }
    std::cout << std::setw(10) << opt(r.fftw.frame.median_ms, 3) << std::setw(7)
              << opt(r.ours.frame.median_ms / r.fftw.frame.median_ms, 2) << std::setw(10)
              << fixed(r.ours_fft.median_ms, 3) << std::setw(10) << opt(r.fftw_fft.median_ms, 3)
              << std::setw(9) << fixed(r.fft_gflops, 1) << std::setw(7)
              << fixed(100.0 * r.peak_fraction, 1) << std::setw(10)
              << fixed(double(r.memory_per_cascade) / (1 << 20), 2) << "   "
              << fixed(r.ours.synthesis.median_ms, 3) << "/" << fixed(r.ours.finalize.median_ms, 3)
              << "/" << fixed(r.ours.mips.median_ms, 3) << "\n";
  }
}

}  // namespace ocean::cli::bench
