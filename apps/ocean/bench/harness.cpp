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

}  // namespace

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

}  // namespace ocean::cli::bench
