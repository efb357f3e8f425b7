// `ocean bench`: the CPU pipeline against the same pipeline with FFTW as its FFT engine and
// against FFTW's transforms alone, in one process, for chosen resolutions, cascade counts and
// thread counts: per-stage medians, min/max, ratios, pseudo-GFLOP/s and the fraction of this
// machine's measured FMA peak. docs/performance.md explains the method.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_common.hpp"
#include "commands.hpp"
#include "fftw_engine.hpp"
#include "progress.hpp"
#ifdef OCEAN_HAS_VULKAN
#include "ocean/vk/simulation.hpp"
#endif

namespace ocean::cli {

namespace {

struct BenchOptions {
  std::string resolutions = "64,128,256,512,1024,2048";
  std::string cascades = "1,4";
  std::string threads = "1,all";
  std::string min_time = "0.2";
  std::string backend = "cpu";
  std::string outputs = "all";
  std::string frame_interval = "0";
  bool json = false;
};

struct Stats {
  double median_ms = 0.0, min_ms = 0.0, max_ms = 0.0;
};

Stats stats_of(std::vector<double> seconds) {
  std::sort(seconds.begin(), seconds.end());
  const std::size_t n = seconds.size();
  const double median = n % 2 ? seconds[n / 2] : 0.5 * (seconds[n / 2 - 1] + seconds[n / 2]);
  return {1e3 * median, 1e3 * seconds.front(), 1e3 * seconds.back()};
}

using Clock = std::chrono::steady_clock;

// Times body() repeatedly: 2 warm-up runs, then at least 5 runs and about min_time seconds
// (at most 500 runs). With an interval, the runs start that many seconds apart, as frames of a
// frame loop do (the thread sleeps in between); min_time then counts the intervals.
template <typename Body>
std::vector<double> time_runs(double min_time, Body body, double interval = 0.0) {
  const auto pace = [&](Clock::time_point start) {
    if (interval > 0.0)
      std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                                std::chrono::duration<double>(interval)));
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

// Bytes of one cascade's output arrays (those the configuration's FrameOutputs keeps).
std::size_t frame_bytes(const CascadeFrame& f) {
  const auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  return bytes(f.displacement) + bytes(f.displacement_half) + bytes(f.normal) + bytes(f.jacobian) +
         bytes(f.foam) + bytes(f.packed_mips);
}

Result<PipelineResult> run_pipeline(const SimulationConfig& config, cpu::CpuOptions options,
                                    TaskRunner& runner, double min_time, double interval) {
  const std::unique_ptr<cpu::CpuBackend> backend = cpu::make_cpu_backend(options);
  if (Status s = backend->configure(config, runner); !s.ok()) return s;
  Frame frame;
  backend->allocate(frame);
  double t = 0.0;
  std::vector<double> synthesis, finalize, mips;
  const std::vector<double> frames = time_runs(
      min_time,
      [&] {
        backend->step(t, frame);
        t += 1.0 / 90.0;
        synthesis.push_back(backend->last_stage_times().synthesis_s);
        finalize.push_back(backend->last_stage_times().finalize_s);
        mips.push_back(backend->last_stage_times().mips_s);
      },
      interval);
  const auto drop_warmup = [](std::vector<double>& v) { v.erase(v.begin(), v.begin() + 2); };
  drop_warmup(synthesis), drop_warmup(finalize), drop_warmup(mips);
  return PipelineResult{stats_of(frames),
                        stats_of(synthesis),
                        stats_of(finalize),
                        stats_of(mips),
                        frames.size(),
                        backend->state_bytes_per_cascade(),
                        frame_bytes(frame.cascades.front())};
}

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

struct Row {
  int resolution, cascades, threads;
  std::string outputs;
  double frame_interval_ms = 0.0;
  PipelineResult ours, fftw;
  int fftw_threads = 0;
  Stats ours_fft, fftw_fft;
  double fft_gflops = 0.0, peak_fraction = 0.0;
  std::size_t memory_per_cascade = 0;
  bool has_fftw = false;
};

nlohmann::ordered_json stage_json(const PipelineResult& r) {
  return {{"synthesis", r.synthesis.median_ms},
          {"finalize", r.finalize.median_ms},
          {"mips", r.mips.median_ms}};
}

nlohmann::ordered_json to_json(const Row& r) {
  const auto or_null = [&](double v) {
    return r.has_fftw ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
  };
  nlohmann::ordered_json j;
  j["resolution"] = r.resolution;
  j["cascades"] = r.cascades;
  j["threads"] = r.threads;
  j["outputs"] = r.outputs;
  j["frame_interval_ms"] = r.frame_interval_ms;
  j["ours_ms"] = r.ours.frame.median_ms;
  j["ours_min_ms"] = r.ours.frame.min_ms;
  j["ours_max_ms"] = r.ours.frame.max_ms;
  j["ours_stages_ms"] = stage_json(r.ours);
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
  std::cout << std::setw(6) << "N" << std::setw(4) << "C" << std::setw(5) << "thr" << std::setw(10)
            << "ours" << std::setw(10) << "fftw-pipe" << std::setw(7) << "ratio" << std::setw(10)
            << "ours-fft" << std::setw(10) << "fftw-fft" << std::setw(9) << "GFLOP/s"
            << std::setw(7) << "%peak" << std::setw(10) << "MiB/casc"
            << "   stages synth/final/mips\n";
  for (const Row& r : rows) {
    const auto opt = [&](double v, int digits) { return r.has_fftw ? fixed(v, digits) : "-"; };
    std::cout << std::setw(6) << r.resolution << std::setw(4) << r.cascades << std::setw(5)
              << r.threads << std::setw(10) << fixed(r.ours.frame.median_ms, 3) << std::setw(10)
              << opt(r.fftw.frame.median_ms, 3) << std::setw(7)
              << opt(r.ours.frame.median_ms / r.fftw.frame.median_ms, 2) << std::setw(10)
              << fixed(r.ours_fft.median_ms, 3) << std::setw(10) << opt(r.fftw_fft.median_ms, 3)
              << std::setw(9) << fixed(r.fft_gflops, 1) << std::setw(7)
              << fixed(100.0 * r.peak_fraction, 1) << std::setw(10)
              << fixed(double(r.memory_per_cascade) / (1 << 20), 2) << "   "
              << fixed(r.ours.synthesis.median_ms, 3) << "/" << fixed(r.ours.finalize.median_ms, 3)
              << "/" << fixed(r.ours.mips.median_ms, 3) << "\n";
  }
}

Result<std::vector<int>> parse_ints(std::string_view flag, const std::string& text, int lo, int hi,
                                    bool allow_all) {
  std::vector<int> out;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (allow_all && item == "all") {
      out.push_back(0);
      continue;
    }
    Result<double> v = parse_number(flag, item);
    if (!v.ok()) return v.status();
    if (v.value() != std::floor(v.value()) || v.value() < lo || v.value() > hi) {
      return invalid_argument(std::string(flag) + " = '" + item +
                              "' is out of range: must be an integer in [" + std::to_string(lo) +
                              ", " + std::to_string(hi) + "]" + (allow_all ? " or 'all'" : ""));
    }
    out.push_back(static_cast<int>(v.value()));
  }
  if (out.empty()) return invalid_argument(std::string(flag) + " is empty");
  return out;
}

// Best of `repeats` parallel copies of `bytes`: read + write bytes per second, GB/s. 256 MiB
// streams from memory; 16 MiB is the size of a frame's state and outputs at 4 × 256², which the
// last-level cache may hold.
double measure_copy_bandwidth_gbps(TaskRunner& runner, std::size_t bytes, int repeats) {
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  const std::size_t kBytes = bytes;
  std::vector<char> from(kBytes, 1), to(kBytes, 0);
  double best = 0.0;
  for (int i = 0; i < repeats; ++i) {
    const Clock::time_point start = Clock::now();
    runner.parallel_for(kBytes / kChunk, 1, [&](std::size_t begin, std::size_t end) {
      std::memcpy(to.data() + begin * kChunk, from.data() + begin * kChunk, (end - begin) * kChunk);
    });
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    best = std::max(best, 2.0 * double(kBytes) / seconds * 1e-9);
  }
  return best;
}

// `--backend vulkan`: GPU time per stage from timestamp queries, mean over the frames.
int run_vulkan_bench(const std::vector<int>& resolutions, const std::vector<int>& cascades,
                     const FrameOutputs& outputs, const std::string& outputs_name, bool json) {
#ifdef OCEAN_HAS_VULKAN
  const std::vector<double> sizes = {1000.0, 233.0, 57.0, 13.0};
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  Progress progress("bench", static_cast<long long>(resolutions.size() * cascades.size()));
  long long done = 0;
  for (int n : resolutions) {
    for (int c : cascades) {
      SimulationConfig config;
      config.resolution = n;
      config.cascade_patch_sizes_m.assign(sizes.begin(), sizes.begin() + c);
      config.outputs = outputs;
      Result<vk::StageTimings> t = vk::benchmark(config, 20);
      if (!t.ok()) return report(t.status());
      const vk::StageTimings& v = t.value();
      rows.push_back({{"resolution", n},
                      {"cascades", c},
                      {"backend", "vulkan"},
                      {"outputs", outputs_name},
                      {"gpu_total_ms", v.total_ms},
                      {"gpu_stages_ms",
                       {{"evolve_fft_rows", v.evolve_fft_rows_ms},
                        {"fft_columns", v.fft_columns_ms},
                        {"finalize", v.finalize_ms},
                        {"mips", v.mips_ms},
                        {"readback", v.readback_ms}}}});
      progress.update(++done);
    }
  }
  progress.finish();
  if (json) {
    print_json({{"rows", rows}});
  } else {
    std::cout << "GPU time per frame from timestamp queries, mean of 20 frames, ms\n"
              << std::setw(6) << "N" << std::setw(4) << "C" << std::setw(10) << "total"
              << std::setw(14) << "evolve+rows" << std::setw(10) << "columns" << std::setw(10)
              << "finalize" << std::setw(8) << "mips" << std::setw(10) << "readback\n";
    for (const auto& r : rows) {
      const auto& st = r["gpu_stages_ms"];
      std::cout << std::setw(6) << r["resolution"].get<int>() << std::setw(4)
                << r["cascades"].get<int>() << std::setw(10)
                << fixed(r["gpu_total_ms"].get<double>(), 3) << std::setw(14)
                << fixed(st["evolve_fft_rows"].get<double>(), 3) << std::setw(10)
                << fixed(st["fft_columns"].get<double>(), 3) << std::setw(10)
                << fixed(st["finalize"].get<double>(), 3) << std::setw(8)
                << fixed(st["mips"].get<double>(), 3) << std::setw(10)
                << fixed(st["readback"].get<double>(), 3) << "\n";
    }
  }
  return kExitOk;
#else
  (void)resolutions, (void)cascades, (void)outputs, (void)outputs_name, (void)json;
  return report(unsupported("ocean bench --backend vulkan: built without Vulkan"));
#endif
}

// A scalar flag value in [lo, hi] (bounds written as integers in the error, with their unit).
Result<double> parse_in_range(std::string_view flag, const std::string& text, double lo, double hi,
                              std::string_view unit) {
  Result<double> v = parse_number(flag, text);
  if (!v.ok()) return v;
  if (!(v.value() >= lo && v.value() <= hi)) {
    return invalid_argument(std::string(flag) + " = " + text + " is out of range: must be in [" +
                            std::to_string(static_cast<long long>(lo)) + ", " +
                            std::to_string(static_cast<long long>(hi)) + "] " + std::string(unit));
  }
  return v;
}

int run_bench(const BenchOptions& o) {
  if (o.backend != "cpu" && o.backend != "vulkan") {
    return report(
        invalid_argument("--backend = '" + o.backend + "' is unknown: must be one of cpu, vulkan"));
  }
  Result<std::vector<int>> resolutions = parse_ints("--resolution", o.resolutions, 16, 2048, false);
  if (!resolutions.ok()) return report(resolutions.status());
  for (int n : resolutions.value()) {
    if (!std::has_single_bit(static_cast<unsigned>(n)))
      return report(
          invalid_argument("--resolution = " + std::to_string(n) + " is not a power of two"));
  }
  Result<std::vector<int>> cascades = parse_ints("--cascades", o.cascades, 1, 4, false);
  if (!cascades.ok()) return report(cascades.status());
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  Result<std::vector<int>> threads = parse_ints("--threads", o.threads, 1, 256, true);
  if (!threads.ok()) return report(threads.status());
  FrameOutputs outputs;
  if (o.outputs == "seed000") {
    outputs = FrameOutputs::seed000();
  } else if (o.outputs != "all") {
    return report(invalid_argument("--outputs = '" + o.outputs +
                                   "' is unknown: must be one of all, seed000"));
  }
  Result<double> interval_ms =
      parse_in_range("--frame-interval", o.frame_interval, 0.0, 1000.0, "ms");
  if (!interval_ms.ok()) return report(interval_ms.status());
  const double interval = interval_ms.value() * 1e-3;
  if (o.backend == "vulkan") {
    if (interval > 0.0) {
      return report(invalid_argument("--frame-interval = " + o.frame_interval +
                                     ": only the CPU backend's frames can be paced"));
    }
    return run_vulkan_bench(resolutions.value(), cascades.value(), outputs, o.outputs, o.json);
  }
  Result<double> min_time = parse_in_range("--min-time", o.min_time, 0.0, 60.0, "s");
  if (!min_time.ok()) return report(min_time.status());

  const std::string target = fft::active_simd_target();
  const double peak = fft::measure_fma_peak_gflops(0.2);
  const double bandwidth =
      measure_copy_bandwidth_gbps(*make_tbb_runner(), std::size_t{256} << 20, 3);
  const double cache_bandwidth =
      measure_copy_bandwidth_gbps(*make_tbb_runner(), std::size_t{16} << 20, 30);
  const std::vector<double> sizes = {1000.0, 233.0, 57.0, 13.0};
  std::vector<Row> rows;
  std::string fftw_note;
  Progress progress("bench",
                    static_cast<long long>(resolutions.value().size() * cascades.value().size() *
                                           threads.value().size()));
  long long done = 0;
  for (int n : resolutions.value()) {
    for (int c : cascades.value()) {
      for (int t_request : threads.value()) {
        const int t = t_request == 0 ? hardware : t_request;
        SimulationConfig config;  // the default sea, central differences
        config.resolution = n;
        config.cascade_patch_sizes_m.assign(sizes.begin(), sizes.begin() + c);
        config.outputs = outputs;
        std::shared_ptr<TaskRunner> runner = make_tbb_runner(t);
        Row row{n,
                c,
                runner->concurrency(),
                o.outputs,
                interval_ms.value(),
                {},
                {},
                0,
                {},
                {},
                0.0,
                0.0,
                0,
                false};
        Result<PipelineResult> ours = run_pipeline(config, {}, *runner, min_time.value(), interval);
        if (!ours.ok()) return report(ours.status());
        row.ours = ours.value();
        // The same transforms alone: two planes per cascade, three per pair of cascades (the
        // pipelines pair cascades: one plane carries both cascades' Dz).
        const auto plane_count = static_cast<std::size_t>(3 * (c / 2) + 2 * (c % 2));
        Planes planes(n, plane_count);
        const fft::SimdPlan2D plan = fft::SimdPlan2D::make(n).value();
        row.ours_fft = stats_of(
            time_runs(min_time.value(), [&] { plan.inverse(planes.views, *runner, true); }));
        const double flops = 5.0 * n * n * std::log2(double(n) * n) * double(plane_count);
        row.fft_gflops = flops / (row.ours_fft.median_ms * 1e-3) * 1e-9;
        row.peak_fraction = row.fft_gflops / (peak * row.threads);
        // FFTW at its best: 1 thread, and all of the row's threads when more than one.
        for (int ft : t > 1 ? std::vector<int>{1, t} : std::vector<int>{1}) {
          Result<std::unique_ptr<FftwEngine>> engine = FftwEngine::make(n, ft);
          if (!engine.ok()) {
            fftw_note = engine.status().message();
            continue;
          }
          Result<PipelineResult> fftw = run_pipeline(
              config, {.pipeline = cpu::CpuPipeline::external_fft, .fft = engine.value().get()},
              *runner, min_time.value(), interval);
          if (!fftw.ok()) return report(fftw.status());
          const Stats fft_only =
              stats_of(time_runs(min_time.value(), [&] { engine.value()->inverse(planes.views); }));
          if (!row.has_fftw || fftw.value().frame.median_ms < row.fftw.frame.median_ms) {
            row.fftw = fftw.value();
            row.fftw_threads = ft;
          }
          if (!row.has_fftw || fft_only.median_ms < row.fftw_fft.median_ms) row.fftw_fft = fft_only;
          row.has_fftw = true;
        }
        // Memory: the backend's state per cascade plus one frame's arrays.
        row.memory_per_cascade =
            row.ours.state_bytes_per_cascade + row.ours.frame_bytes_per_cascade;
        rows.push_back(row);
        progress.update(++done);
      }
    }
  }
  progress.finish();
  if (!fftw_note.empty()) std::cerr << "ocean bench: " << fftw_note << "; FFTW columns omitted\n";
  if (o.json) {
    nlohmann::ordered_json out;
    out["machine"] = {{"simd_target", target},
                      {"simd_targets", fft::simd_targets()},
                      {"fma_peak_gflops_per_thread", peak},
                      {"copy_bandwidth_gbps", bandwidth},
                      {"copy_bandwidth_16mib_gbps", cache_bandwidth},
                      {"hardware_threads", hardware}};
    out["rows"] = nlohmann::ordered_json::array();
    for (const Row& r : rows) out["rows"].push_back(to_json(r));
    print_json(out);
  } else {
    print_table(rows, target, peak, bandwidth, cache_bandwidth);
  }
  return kExitOk;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Time the CPU pipeline against the same pipeline on FFTW and FFTW alone");
  cmd->add_option("--resolution", options->resolutions,
                  "Comma-separated grid sizes N (powers of two, 16…2048)")
      ->capture_default_str();
  cmd->add_option("--cascades", options->cascades, "Comma-separated cascade counts (1…4)")
      ->capture_default_str();
  cmd->add_option("--threads", options->threads, "Comma-separated thread counts, or 'all'")
      ->capture_default_str();
  cmd->add_option("--min-time", options->min_time, "Seconds of timed runs per measurement")
      ->capture_default_str();
  cmd->add_option("--backend", options->backend, "Backend to measure")->capture_default_str();
  cmd->add_option("--outputs", options->outputs,
                  "Frame outputs: all (every array), or seed000 (displacement float3 + half4 and "
                  "the RGBA8 chain, no float normal, Jacobian or foam arrays)")
      ->capture_default_str();
  cmd->add_option("--frame-interval", options->frame_interval,
                  "Milliseconds from one timed frame's start to the next, as in a frame loop "
                  "(0: back to back); the FFT-only runs stay back to back")
      ->capture_default_str();
  cmd->add_flag("--json", options->json, "Print JSON instead of a table");
  return {cmd, [options] { return run_bench(*options); }};
}

}  // namespace ocean::cli
