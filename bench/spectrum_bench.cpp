// Microbenchmarks of the spectrum module: S(ω) per model, k(ω) inversion and h0 generation.
// Run: build/release/bench/spectrum_bench
#include <benchmark/benchmark.h>

#include "ocean/spectrum.hpp"

namespace {

void BM_SpectrumEvaluate(benchmark::State& state) {
  const auto model = static_cast<ocean::SpectrumModel>(state.range(0));
  ocean::FrequencySpectrumParams p{.model = model, .wind_speed_mps = 12.0};
  if (model == ocean::SpectrumModel::jonswap || model == ocean::SpectrumModel::tma)
    p.fetch_m = 50e3;
  if (model == ocean::SpectrumModel::tma) p.depth_m = 15.0;
  const ocean::FrequencySpectrum s = ocean::FrequencySpectrum::make(p).value();
  double omega = 0.3;
  for (auto _ : state) {
    benchmark::DoNotOptimize(s(omega));
    omega = omega > 3.0 ? 0.3 : omega + 1e-3;
  }
  state.SetLabel(std::string(ocean::to_string(model)));
}
BENCHMARK(BM_SpectrumEvaluate)->DenseRange(0, 3);

void BM_Wavenumber(benchmark::State& state) {
  const ocean::Dispersion d = ocean::Dispersion::make({.depth_m = 20.0}).value();
  double omega = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(d.wavenumber(omega));
    omega = omega > 10.0 ? 0.1 : omega + 1e-3;
  }
}
BENCHMARK(BM_Wavenumber);

void BM_InitialSpectrum(benchmark::State& state) {
  ocean::SeaStateParams params;
  params.wind_sea.spectrum = {
      .model = ocean::SpectrumModel::jonswap, .wind_speed_mps = 12.0, .fetch_m = 50e3};
  const ocean::SeaState sea = ocean::SeaState::make(params).value();
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    auto h0 = ocean::make_initial_spectrum(sea, {.grid = {.resolution = n, .patch_size_m = 500.0}});
    benchmark::DoNotOptimize(h0.ok());
  }
  state.SetItemsProcessed(state.iterations() * n * n);
}
BENCHMARK(BM_InitialSpectrum)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
