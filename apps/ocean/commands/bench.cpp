// `ocean bench`: the CPU pipeline against the same pipeline with FFTW as its FFT engine and
// against FFTW's transforms alone, in one process, for chosen resolutions, cascade counts and
// thread counts: per-stage medians, min/max, ratios, pseudo-GFLOP/s and the fraction of this
// machine's measured FMA peak. docs/performance.md explains the method; the parts live in
// bench/ (harness, parsers, bandwidth probe, Vulkan rows, report, the FFTW engine).
#include <algorithm>
#include <bit>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench/bandwidth.hpp"
#include "bench/cuda_rows.hpp"
#include "bench/fftw_engine.hpp"
#include "bench/harness.hpp"
#include "bench/overlap.hpp"
#include "bench/pacing.hpp"
#include "bench/parse.hpp"
#include "bench/report.hpp"
#include "bench/table_one.hpp"
#include "bench/vulkan_rows.hpp"
#include "cli_common.hpp"
#include "commands.hpp"
#include "progress.hpp"

namespace ocean::cli {

namespace {

using bench::measure_copy_bandwidth_gbps;
using bench::PacedResult;
using bench::parse_ints;
using bench::parse_runners;
using bench::PipelineResult;
using bench::Planes;
using bench::print_table;
using bench::product;
using bench::Row;
using bench::run_paced_pipeline;
using bench::run_pipeline;
using bench::run_vulkan_bench;
using bench::Stats;
using bench::stats_of;
using bench::time_runs;
using bench::to_json;

constexpr NumberOption<int> kResolution{
    .flag = "--resolution", .accept = Accept::integer_in_range, .lo = 16, .hi = 2048};
constexpr NumberOption<int> kCascades{
    .flag = "--cascades", .accept = Accept::integer_in_range, .lo = 1, .hi = 4};
constexpr NumberOption<int> kThreads{
    .flag = "--threads", .accept = Accept::integer_in_range, .lo = 1, .hi = 256};
constexpr NumberOption<double> kFrameInterval{.flag = "--frame-interval",
                                              .accept = Accept::in_range,
                                              .lo = 0.0,
                                              .hi = 1000.0,
                                              .echo = Echo::text,
                                              .unit = "ms"};
constexpr NumberOption<int> kFarNoiseResolution{
    .flag = "--far-noise-resolution", .accept = Accept::integer_in_range, .lo = 16, .hi = 4096};
constexpr NumberOption<double> kMinTime{.flag = "--min-time",
                                        .accept = Accept::in_range,
                                        .lo = 0.0,
                                        .hi = 60.0,
                                        .echo = Echo::text,
                                        .unit = "s"};

struct BenchOptions {
  std::string resolutions = "64,128,256,512,1024,2048";
  std::string cascades = "1,4";
  std::string threads = "1,all";
  std::string min_time = "0.2";
  std::string backend = "cpu";
  std::string outputs = "all";
  std::string frame_interval = "0";
  std::string runners = "tbb";
  bool json = false;
  bool table_one = false;
  bool overlap = false;
  bool pacing = false;
  std::string far_noise_resolution = "256";
  bool resolution_given = false;
  bool cascades_given = false;
  bool threads_given = false;
  bool min_time_given = false;
  bool frame_interval_given = false;
  bool runners_given = false;
};

int run_bench(const BenchOptions& o) {
  if (o.backend != "cpu" && o.backend != "vulkan" && o.backend != "cuda") {
    return report(invalid_argument("--backend = '" + excerpt(o.backend) +
                                   "' is unknown: must be one of cpu, vulkan, cuda"));
  }
  Result<std::vector<int>> resolutions = parse_ints(kResolution, o.resolutions, false);
  if (!resolutions.ok()) return report(resolutions.status());
  for (int n : resolutions.value()) {
    if (!std::has_single_bit(static_cast<unsigned>(n)))
      return report(
          invalid_argument("--resolution = " + std::to_string(n) + " is not a power of two"));
  }
  Result<std::vector<int>> cascades = parse_ints(kCascades, o.cascades, false);
  if (!cascades.ok()) return report(cascades.status());
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  Result<std::vector<int>> threads = parse_ints(kThreads, o.threads, true);
  if (!threads.ok()) return report(threads.status());
  FrameOutputs outputs;
  if (o.outputs == "textures") {
    outputs = FrameOutputs::textures();
  } else if (o.outputs != "all") {
    return report(invalid_argument("--outputs = '" + excerpt(o.outputs) +
                                   "' is unknown: must be one of all, textures"));
  }
  Result<double> interval_ms = parse(kFrameInterval, o.frame_interval);
  if (!interval_ms.ok()) return report(interval_ms.status());
  const double interval = interval_ms.value() * 1e-3;
  if (o.pacing && (o.backend != "cpu" || o.overlap || o.table_one))
    return report(invalid_argument(
        "--pacing times the CPU backend's frames alone: leave out --backend, --overlap and "
        "--table-one"));
  if (o.pacing && o.frame_interval_given && !(interval > 0.0))
    return report(invalid_argument("--frame-interval = " + excerpt(o.frame_interval) +
                                   ": --pacing needs a period above 0 ms"));
  if (o.overlap && (o.backend != "cpu" || interval > 0.0))
    return report(
        invalid_argument("--overlap times the CPU, Vulkan and CUDA backends: leave out --backend "
                         "and --frame-interval"));
  if (o.table_one && (o.backend != "cpu" || interval > 0.0))
    return report(invalid_argument(
        "--table-one times the CPU and the Vulkan backend back to back: leave out --backend and "
        "--frame-interval"));
  if (o.backend != "cpu") {
    if (interval > 0.0) {
      return report(invalid_argument("--frame-interval = " + excerpt(o.frame_interval) +
                                     ": only the CPU backend's frames can be paced"));
    }
    if (o.backend == "cuda")
      return bench::run_cuda_bench(resolutions.value(), cascades.value(), outputs, o.outputs,
                                   o.json);
    return run_vulkan_bench(resolutions.value(), cascades.value(), outputs, o.outputs, o.json);
  }
  Result<double> min_time = parse(kMinTime, o.min_time);
  if (!min_time.ok()) return report(min_time.status());
  if (o.overlap) {
    if (o.table_one)
      return report(
          invalid_argument("--overlap and --table-one are separate benchmarks: give one"));
    Result<int> noise = parse(kFarNoiseResolution, o.far_noise_resolution);
    if (!noise.ok()) return report(noise.status());
    return bench::run_overlap(
        {.resolutions = o.resolution_given ? resolutions.value() : std::vector<int>{256},
         .cascades = o.cascades_given ? cascades.value() : std::vector<int>{4},
         .noise_resolution = noise.value(),
         .threads =
             !o.threads_given || threads.value().front() == 0 ? hardware : threads.value().front(),
         .min_time = min_time.value(),
         .json = o.json});
  }
  if (o.table_one) {
    const std::vector<int> seed_sizes = {128, 512, 1024, 2048};
    return bench::run_table_one(o.resolution_given ? resolutions.value() : seed_sizes,
                                cascades.value().front(), min_time.value(), o.json);
  }
  Result<std::vector<std::string>> runner_names = parse_runners(o.runners);
  if (!runner_names.ok()) return report(runner_names.status());
  if (o.pacing) {
    bench::PacingOptions p{
        .resolution = o.resolution_given ? resolutions.value().front() : 256,
        .cascades = o.cascades_given ? cascades.value().front() : 4,
        .threads = {},
        .runners = o.runners_given ? runner_names.value() : std::vector<std::string>{"ready"},
        .outputs = outputs,
        .outputs_name = o.outputs,
        .min_time = o.min_time_given ? min_time.value() : 2.0,
        .json = o.json};
    if (o.frame_interval_given) p.intervals_ms = {interval_ms.value()};
    for (int t : threads.value()) p.threads.push_back(t == 0 ? hardware : t);
    return bench::run_pacing(p);
  }

  const std::string target = fft::active_simd_target();
  const double peak = fft::measure_fma_peak_gflops(0.2);
  const double bandwidth =
      measure_copy_bandwidth_gbps(*make_tbb_runner(), std::size_t{256} << 20, 3);
  const double cache_bandwidth =
      measure_copy_bandwidth_gbps(*make_tbb_runner(), std::size_t{16} << 20, 30);
  std::vector<Row> rows;
  std::string fftw_note;
  Progress progress("bench",
                    static_cast<long long>(resolutions.value().size() * cascades.value().size() *
                                           threads.value().size() * runner_names.value().size()));
  long long done = 0;
  for (int n : resolutions.value()) {
    for (int c : cascades.value()) {
      for (const std::pair<int, std::string>& tr : product(threads.value(), runner_names.value())) {
        const int t = tr.first == 0 ? hardware : tr.first;
        const std::string& runner_name = tr.second;
        const SimulationConfig config = bench::bench_config(n, c, outputs);
        std::shared_ptr<TaskRunner> runner =
            runner_name == "ready" ? make_ready_runner({.threads = t}) : make_tbb_runner(t);
        Row row{.resolution = n,
                .cascades = c,
                .threads = runner->concurrency(),
                .runner = runner_name,
                .outputs = o.outputs,
                .frame_interval_ms = interval_ms.value()};
        if (interval > 0.0) {
          Result<PacedResult> ours =
              run_paced_pipeline(config, {}, *runner, min_time.value(), interval);
          if (!ours.ok()) return report(ours.status());
          row.ours = ours.value().paced;
          row.back_to_back = ours.value().back_to_back;
        } else {
          Result<PipelineResult> ours =
              run_pipeline(config, {}, *runner, min_time.value(), interval);
          if (!ours.ok()) return report(ours.status());
          row.ours = ours.value();
        }
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
  add_option(*cmd, kResolution, options->resolutions,
             "Comma-separated grid sizes N (powers of two, 16…2048)")
      ->capture_default_str();
  add_option(*cmd, kCascades, options->cascades, "Comma-separated cascade counts (1…4)")
      ->capture_default_str();
  add_option(*cmd, kThreads, options->threads, "Comma-separated thread counts, or 'all'")
      ->capture_default_str();
  add_option(*cmd, kMinTime, options->min_time, "Seconds of timed runs per measurement")
      ->capture_default_str();
  cmd->add_option("--backend", options->backend, "Backend to measure: cpu, vulkan or cuda")
      ->capture_default_str();
  cmd->add_option("--outputs", options->outputs,
                  "Frame outputs: all (every array), or textures (displacement float3 + half4 and "
                  "the RGBA8 chain, no float normal, Jacobian or foam arrays)")
      ->capture_default_str();
  add_option(*cmd, kFrameInterval, options->frame_interval,
             "Milliseconds from one timed frame's start to the next, as in a frame loop "
             "(0: back to back); the FFT-only runs stay back to back, and our pipeline is "
             "also timed back to back, alternated with the paced frames, for the ratio")
      ->capture_default_str();
  cmd->add_option("--runner", options->runners,
                  "Comma-separated task runners: tbb (oneTBB), ready (workers spin up to 2 ms "
                  "after their work and are woken 3 ms before a paced frame)")
      ->capture_default_str();
  cmd->add_flag("--json", options->json, "Print JSON instead of a table");
  cmd->add_flag("--table-one", options->table_one,
                "VR-GIS FFT+Perlin's Table I: CPU and Vulkan ms per frame and their ratio at "
                "128, 512, 1024 and 2048 (or --resolution), the first --cascades count");
  cmd->add_flag(
      "--overlap", options->overlap,
      "concurrent kernels (the FFT and Perlin noise of the VR-GIS paper, docs/references.md): the "
      "cascades alone, the far field's noise map "
      "alone and both in one frame, on the CPU, Vulkan and CUDA backends, and the overlap "
      "(t_cascades + t_noise - t_both) / min(t_cascades, t_noise); the first "
      "--resolution and --cascades default to 256 and 4");
  cmd->add_flag("--pacing", options->pacing,
                "the frame budget of a paced frame loop: the CPU pipeline (the first --resolution "
                "and --cascades, default 256 and 4) at 90 and 120 Hz (or --frame-interval), each "
                "--threads count and --runner (default ready), paced (the runner woken 3 ms "
                "ahead), paced with the cache warm-up (also Backend::warm_caches 1.5 ms ahead) "
                "and back to back in " +
                    std::to_string(bench::kPacedRounds) +
                    " alternated rounds (--min-time: seconds of each kind per row, default 2): "
                    "the medians, the paced/back-to-back ratios and their spread over the rounds, "
                    "the stages' medians and the warm-up's time");
  add_option(*cmd, kFarNoiseResolution, options->far_noise_resolution,
             "--overlap: texels per side of the noise map (16…4096); the CPU runs on the first "
             "--threads count (default all)")
      ->capture_default_str();
  return {cmd, [options, cmd] {
            BenchOptions o = *options;
            o.resolution_given = cmd->get_option("--resolution")->count() > 0;
            o.cascades_given = cmd->get_option("--cascades")->count() > 0;
            o.threads_given = cmd->get_option("--threads")->count() > 0;
            o.min_time_given = cmd->get_option("--min-time")->count() > 0;
            o.frame_interval_given = cmd->get_option("--frame-interval")->count() > 0;
            o.runners_given = cmd->get_option("--runner")->count() > 0;
            return run_bench(o);
          }};
}

}  // namespace ocean::cli
