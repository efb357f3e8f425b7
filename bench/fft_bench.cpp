// Microbenchmarks of the FFT kernels: the scalar radix-2 reference, the SIMD plan on every
// instruction set, and FFTW (single precision, FFTW_MEASURE, split complex) on the same planes.
// Run: build/release/bench/fft_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <string>
#include <vector>

#include "ocean/fft.hpp"

namespace {

struct Planes {
  std::vector<float> re, im;
  explicit Planes(int n, int count)
      : re(static_cast<std::size_t>(n * n * count), 0.25f),
        im(static_cast<std::size_t>(n * n * count), -0.5f) {}
  std::vector<ocean::fft::SplitComplex> views(int n, int count) {
    std::vector<ocean::fft::SplitComplex> v;
    for (int p = 0; p < count; ++p) v.push_back({re.data() + p * n * n, im.data() + p * n * n});
    return v;
  }
};

// 5·N²·log2(N²) pseudo-flops per complex 2D transform.
void set_flops(benchmark::State& state, int n, int planes) {
  const double flops = 5.0 * n * n * std::log2(double(n) * n) * planes;
  state.counters["GFLOP/s"] = benchmark::Counter(
      flops, benchmark::Counter::kIsIterationInvariantRate, benchmark::Counter::kIs1000);
}

void BM_ScalarPlan2D(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Planes data(n, 2);
  const auto views = data.views(n, 2);
  const auto plan = ocean::fft::Plan2D::make(n).value();
  auto runner = ocean::make_serial_runner();
  for (auto _ : state) plan.inverse(views, *runner, true);
  set_flops(state, n, 2);
}

void BM_SimdPlan2D(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::vector<std::string> targets = ocean::fft::simd_targets();
  const std::string target = targets[static_cast<std::size_t>(state.range(1))];
  if (!ocean::fft::force_simd_target(target).ok()) state.SkipWithError("target");
  Planes data(n, 2);
  const auto views = data.views(n, 2);
  const auto plan = ocean::fft::SimdPlan2D::make(n).value();
  auto runner = ocean::make_serial_runner();
  for (auto _ : state) plan.inverse(views, *runner, true);
  set_flops(state, n, 2);
  state.SetLabel(target);
  (void)ocean::fft::force_simd_target("");
}

void BM_FftwSplit2D(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Planes data(n, 2);
  fftwf_iodim dims[2] = {{n, n, n}, {n, 1, 1}};
  fftwf_iodim howmany = {2, n * n, n * n};
  // Split-complex inverse: FFTW's split transforms are forward; swapping re and im gives the
  // backward transform.
  fftwf_plan plan = fftwf_plan_guru_split_dft(2, dims, 1, &howmany, data.im.data(), data.re.data(),
                                              data.im.data(), data.re.data(), FFTW_MEASURE);
  if (plan == nullptr) {
    state.SkipWithError("FFTW could not plan the split transform");
    return;
  }
  for (auto _ : state) fftwf_execute(plan);
  fftwf_destroy_plan(plan);
  set_flops(state, n, 2);
}

BENCHMARK(BM_ScalarPlan2D)->RangeMultiplier(2)->Range(64, 1024)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SimdPlan2D)
    ->ArgsProduct({{64, 128, 256, 512, 1024}, {0, 1, 2}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FftwSplit2D)->RangeMultiplier(2)->Range(64, 1024)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
