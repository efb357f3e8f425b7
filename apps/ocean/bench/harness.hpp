// `ocean bench`'s timing harness: repeated runs with warm-up and optional pacing, medians, and
// one CPU pipeline configuration timed frame by frame with its stage times.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

#include "ocean/backends/cpu.hpp"
#include "ocean/fft.hpp"

namespace ocean::cli::bench {

struct Stats {
  double median_ms = 0.0, min_ms = 0.0, max_ms = 0.0;
};

/// Median, minimum and maximum of `seconds` (not empty), in ms.
Stats stats_of(std::vector<double> seconds);

/// What every backend's row measures: the default sea, central differences, `cascades` of the
/// first of 1000, 233, 57 and 13 m (cascades ≤ 4), N = resolution, the given outputs.
SimulationConfig bench_config(int resolution, int cascades, const FrameOutputs& outputs);

using Clock = std::chrono::steady_clock;

// How long before a paced frame's start the harness calls TaskRunner::wake(), as a frame loop
// that knows when its next frame starts does (ocean xr: before xrWaitFrame). Within the ready
// runner's default wake spin (4 ms). A worker woken 1 ms ahead was still slow when the frame
// began (docs/performance.md, paced frames): 3 ms is the shortest lead measured at full speed.
constexpr double kWakeLead_s = 3e-3;
// How long before a paced frame's start the harness calls Backend::warm_caches where a row asks
// for it (after the wake, on the woken workers). Measured (4 × 256², 1 thread, 90 Hz, a loaded
// machine): leads of 0.7, 1.5 and 3 ms gave paced / back to back 1.00–1.05, 1.01–1.13 and
// 1.06–1.15; the warm-up itself takes 0.3–0.7 ms, so 1.5 ms leaves it time to finish.
constexpr double kWarmLead_s = 1.5e-3;

// Times body() repeatedly: 2 warm-up runs, then at least 5 runs and about min_time seconds
// (at most 500 runs). With an interval, the runs start that many seconds apart, as frames of a
// frame loop do (the thread sleeps in between, and wakes `runner` kWakeLead_s before each
// frame when one is given, then calls warm() kWarmLead_s before it when one is given);
// min_time then counts the intervals. The samples are body()'s times, warm()'s not included.
template <typename Body>
std::vector<double> time_runs(double min_time, Body body, double interval = 0.0,
                              TaskRunner* runner = nullptr, FunctionRef<void()>* warm = nullptr) {
  const auto at = [](Clock::time_point start, double seconds) {
    return start +
           std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  };
  const auto pace = [&](Clock::time_point start) {
    if (interval <= 0.0) return;
    if (runner != nullptr && interval > kWakeLead_s) {
      std::this_thread::sleep_until(at(start, interval - kWakeLead_s));
      runner->wake();
    }
    if (warm != nullptr && interval > kWarmLead_s) {
      std::this_thread::sleep_until(at(start, interval - kWarmLead_s));
      (*warm)();
    }
    std::this_thread::sleep_until(at(start, interval));
  };
  for (int i = 0; i < 2; ++i) {
    const Clock::time_point start = Clock::now();
    body();
    pace(start);
  }
  std::vector<double> samples;
  double total = 0.0;
  while ((samples.size() < 5 || total < min_time) && samples.size() < 500) {
    const Clock::time_point start = Clock::now();
    body();
    samples.push_back(std::chrono::duration<double>(Clock::now() - start).count());
    total += std::max(samples.back(), interval);
    pace(start);
  }
  return samples;
}

struct PipelineResult {
  Stats frame;
  Stats synthesis, finalize, mips;
  std::size_t frames = 0;
  std::size_t state_bytes_per_cascade = 0;
  std::size_t frame_bytes_per_cascade = 0;  ///< the arrays of one cascade's outputs
};

/// Times the CPU backend with `options` on `config`: frames back to back (or `interval` s apart)
/// for about min_time seconds after two warm-up frames.
Result<PipelineResult> run_pipeline(const SimulationConfig& config, cpu::CpuOptions options,
                                    TaskRunner& runner, double min_time, double interval);

struct PacedResult {
  /// Paced frames with the runner woken ahead only (`paced`) and woken ahead plus
  /// Backend::warm_caches kWarmLead_s before each frame (`warmed`), and back-to-back frames.
  PipelineResult paced, warmed, back_to_back;
  /// Each round's paced (and warmed) median over its back-to-back median: the ratios' spread.
  std::vector<double> round_ratios, warmed_round_ratios;
  Stats warm_up;  ///< the warm_caches calls' wall times
};

/// The same pipeline paced `interval` s apart without and with the cache warm-up, and back to
/// back, alternated in kPacedRounds rounds of min_time / kPacedRounds seconds per kind so that
/// all three see the same minutes of a noisy machine; the medians are over all rounds' frames.
constexpr int kPacedRounds = 6;
Result<PacedResult> run_paced_pipeline(const SimulationConfig& config, cpu::CpuOptions options,
                                       TaskRunner& runner, double min_time, double interval);

// Scratch planes for the FFT-only measurements: `count` N×N split-complex planes.
struct Planes {
  std::vector<std::vector<float>> re, im;
  std::vector<fft::SplitComplex> views;
  Planes(int n, std::size_t count) {
    const auto texels = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    re.assign(count, std::vector<float>(texels, 0.5f));
    im.assign(count, std::vector<float>(texels, -0.25f));
    for (std::size_t p = 0; p < count; ++p) views.push_back({re[p].data(), im[p].data()});
  }
};

}  // namespace ocean::cli::bench
