// Benchmarks of the CPU reference simulation: one full frame (evolve, FFT, finalize, mips) for
// the resolutions and cascade counts of the performance targets, 1 thread and all threads; and a
// frame with and without the particle velocity.
// Run: build/release/bench/simulator_bench
#include <benchmark/benchmark.h>

#include "ocean/backends.hpp"

namespace {

void BM_SimulatorStep(benchmark::State& state) {
  ocean::SimulationConfig config;
  config.resolution = static_cast<int>(state.range(0));
  const std::vector<double> sizes = {1000.0, 233.0, 57.0, 13.0};
  config.cascade_patch_sizes_m.assign(sizes.begin(), sizes.begin() + state.range(1));
  const int threads = static_cast<int>(state.range(2));
  std::shared_ptr<ocean::TaskRunner> runner = ocean::make_tbb_runner(threads);
  auto sim = ocean::make_simulator(config, "cpu", runner).value();
  double t = 0.0;
  for (auto _ : state) {
    sim->step(t);
    t += 1.0 / 60.0;
  }
  state.SetLabel(std::to_string(state.range(1)) + " cascades, " +
                 std::to_string(runner->concurrency()) + " threads");
}
BENCHMARK(BM_SimulatorStep)
    ->ArgsProduct({{256, 512}, {1, 4}, {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A frame with and without the particle velocity (FrameOutputs::velocity: two more inverse FFTs
// per cascade, M.7.11), 3 cascades, all threads: the cost of the velocity is the ratio of the two.
// Arguments: resolution, velocity (0 or 1).
void BM_SimulatorStepVelocity(benchmark::State& state) {
  ocean::SimulationConfig config;
  config.resolution = static_cast<int>(state.range(0));
  config.outputs.velocity = state.range(1) != 0;
  auto sim = ocean::make_simulator(config, "cpu").value();
  double t = 0.0;
  for (auto _ : state) {
    sim->step(t);
    t += 1.0 / 60.0;
  }
  state.SetLabel(config.outputs.velocity ? "with velocity" : "without velocity");
}
BENCHMARK(BM_SimulatorStepVelocity)
    ->ArgsProduct({{256}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
