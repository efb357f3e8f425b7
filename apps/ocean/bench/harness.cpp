// `ocean bench`'s timing harness: statistics of the samples and the CPU pipeline runs.
#include "bench/harness.hpp"

namespace ocean::cli::bench {

SimulationConfig bench_config(int resolution, int cascades, const FrameOutputs& outputs) {
  static const std::vector<double> kSizes = {1000.0, 233.0, 57.0, 13.0};
  SimulationConfig config;
  config.resolution = resolution;
  config.cascade_patch_sizes_m.assign(kSizes.begin(), kSizes.begin() + cascades);
  config.outputs = outputs;
  return config;
}

Stats stats_of(std::vector<double> seconds) {
  std::sort(seconds.begin(), seconds.end());
  const std::size_t n = seconds.size();
  const double median = n % 2 ? seconds[n / 2] : 0.5 * (seconds[n / 2 - 1] + seconds[n / 2]);
  return {1e3 * median, 1e3 * seconds.front(), 1e3 * seconds.back()};
}

namespace {

// Bytes of one cascade's output arrays (those the configuration's FrameOutputs keeps).
std::size_t frame_bytes(const CascadeFrame& f) {
  const auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  return bytes(f.displacement) + bytes(f.displacement_half) + bytes(f.normal) + bytes(f.jacobian) +
         bytes(f.foam) + bytes(f.packed_mips);
}

// The frame times and stage times of repeated runs, appended over rounds.
struct Samples {
  std::vector<double> frames, synthesis, finalize, mips;
};

// Times one round on a configured backend, appending to `out`.
void time_round(cpu::CpuBackend& backend, Frame& frame, double& t, double min_time, double interval,
                TaskRunner& runner, Samples& out, std::vector<double>* warm_up = nullptr) {
  std::vector<double> synthesis, finalize, mips;
  const auto warm_body = [&] {
    const Clock::time_point start = Clock::now();
    backend.warm_caches(frame);
    warm_up->push_back(std::chrono::duration<double>(Clock::now() - start).count());
  };
  FunctionRef<void()> warm(warm_body);
  const std::vector<double> frames = time_runs(
      min_time,
      [&] {
        backend.step(t, frame);
        t += 1.0 / 90.0;
        synthesis.push_back(backend.last_stage_times().synthesis_s);
        finalize.push_back(backend.last_stage_times().finalize_s);
        mips.push_back(backend.last_stage_times().mips_s);
      },
      interval, &runner, warm_up != nullptr ? &warm : nullptr);
  const auto append_timed = [](std::vector<double>& to, const std::vector<double>& from) {
    to.insert(to.end(), from.begin() + 2, from.end());  // without the two warm-up frames
  };
  out.frames.insert(out.frames.end(), frames.begin(), frames.end());
  append_timed(out.synthesis, synthesis), append_timed(out.finalize, finalize);
  append_timed(out.mips, mips);
}

void append(Samples& to, const Samples& from) {
  const auto add = [](std::vector<double>& a, const std::vector<double>& b) {
    a.insert(a.end(), b.begin(), b.end());
  };
  add(to.frames, from.frames), add(to.synthesis, from.synthesis);
  add(to.finalize, from.finalize), add(to.mips, from.mips);
}

PipelineResult result_of(const Samples& s, const cpu::CpuBackend& backend, const Frame& frame) {
  return {stats_of(s.frames),
          stats_of(s.synthesis),
          stats_of(s.finalize),
          stats_of(s.mips),
          s.frames.size(),
          backend.state_bytes_per_cascade(),
          frame_bytes(frame.cascades.front())};
}

}  // namespace

namespace {

// A backend configured on `runner` and a frame for it.
struct Configured {
  std::unique_ptr<cpu::CpuBackend> backend;
  Frame frame;
};

Result<Configured> configure(const SimulationConfig& config, cpu::CpuOptions options,
                             TaskRunner& runner) {
  Configured c{cpu::make_cpu_backend(options), {}};
  if (Status s = c.backend->configure(config, runner); !s.ok()) return s;
  c.backend->allocate(c.frame);
  return c;
}

}  // namespace

Result<PipelineResult> run_pipeline(const SimulationConfig& config, cpu::CpuOptions options,
                                    TaskRunner& runner, double min_time, double interval) {
  Result<Configured> c = configure(config, options, runner);
  if (!c.ok()) return c.status();
  double t = 0.0;
  Samples samples;
  time_round(*c.value().backend, c.value().frame, t, min_time, interval, runner, samples);
  return result_of(samples, *c.value().backend, c.value().frame);
}

Result<PacedResult> run_paced_pipeline(const SimulationConfig& config, cpu::CpuOptions options,
                                       TaskRunner& runner, double min_time, double interval) {
  Result<Configured> c = configure(config, options, runner);
  if (!c.ok()) return c.status();
  cpu::CpuBackend& backend = *c.value().backend;
  Frame& frame = c.value().frame;
  double t = 0.0;
  Samples paced, warmed, back_to_back;
  std::vector<double> round_ratios, warmed_round_ratios, warm_up;
  const double kind_time = min_time / kPacedRounds;
  for (int round = 0; round < kPacedRounds; ++round) {
    Samples paced_round, warmed_round, back_to_back_round;
    time_round(backend, frame, t, kind_time, 0.0, runner, back_to_back_round);
    time_round(backend, frame, t, kind_time, interval, runner, paced_round);
    time_round(backend, frame, t, kind_time, interval, runner, warmed_round, &warm_up);
    const double b2b = stats_of(back_to_back_round.frames).median_ms;
    round_ratios.push_back(stats_of(paced_round.frames).median_ms / b2b);
    warmed_round_ratios.push_back(stats_of(warmed_round.frames).median_ms / b2b);
    append(paced, paced_round), append(warmed, warmed_round);
    append(back_to_back, back_to_back_round);
  }
  return PacedResult{.paced = result_of(paced, backend, frame),
                     .warmed = result_of(warmed, backend, frame),
                     .back_to_back = result_of(back_to_back, backend, frame),
                     .round_ratios = std::move(round_ratios),
                     .warmed_round_ratios = std::move(warmed_round_ratios),
                     .warm_up = stats_of(warm_up)};
}

}  // namespace ocean::cli::bench
