// Microbenchmarks of the CPU backend's SIMD kernels on every instruction set: evolution of the
// two plane spectra into a column block (alone, and with its mirror block), displacement assembly
// from a row block, the surface row pairs (with mip level 1) and the rest of the mip chain, for one
// 256² or 512² cascade. Run: build/release/bench/kernels_bench
#include <benchmark/benchmark.h>

#include <string>

#include "cpu/cpu_backend.hpp"
#include "cpu/kernels.hpp"
#include "ocean/plan.hpp"

namespace {

struct Fixture {
  ocean::cpu::CpuBackendImpl backend;
  ocean::Frame frame;
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  ocean::cpu::CascadeState state;
  explicit Fixture(int n) {
    ocean::SimulationConfig config;
    config.resolution = n;
    config.cascade_patch_sizes_m = {500.0};
    (void)backend.configure(config, *runner);
    backend.allocate(frame);
    backend.step(1.0, frame);
    state.resolution = n;
    state.patch_size_m = 500.0;
    const ocean::SimulationPlan plan = ocean::SimulationPlan::make(config).value();
    state.spectrum = ocean::make_initial_spectrum(plan.sea(), plan.cascades()[0].spectrum).value();
    state.planes = ocean::cpu::plane_count(config.normals);
    state.choppiness = config.choppiness;
    ocean::cpu::build_kernel_inputs(state, config.loop_period_s);
    state.foam.assign(static_cast<std::size_t>(n * n), 0.0f);
    state.mip_work.assign(4 * ocean::mip_chain_texels(n), 0.1f);
  }
};

bool select_target(benchmark::State& state, int index) {
  const auto targets = ocean::fft::simd_targets();
  if (static_cast<std::size_t>(index) >= targets.size()) {
    state.SkipWithError("no such target on this CPU");
    return false;
  }
  (void)ocean::fft::force_simd_target(targets[static_cast<std::size_t>(index)]);
  state.SetLabel(targets[static_cast<std::size_t>(index)]);
  return true;
}

void set_texels(benchmark::State& state, int n) {
  state.counters["texels/s"] =
      benchmark::Counter(double(n) * n, benchmark::Counter::kIsIterationInvariantRate);
}

// Arguments: N, target index, 1 for block pairs with their mirror (the pipeline's kernel).
void BM_EvolvePlanes(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  if (!select_target(state, static_cast<int>(state.range(1)))) return;
  const bool mirrored = state.range(2) != 0;
  Fixture f(n);
  const ocean::cpu::EvolveArgs args = ocean::cpu::evolve_args(f.state, 1234.5, 200.0);
  alignas(64) static float lanes[8][16 * 2048];
  float* re[2] = {lanes[0], lanes[1]};
  float* im[2] = {lanes[2], lanes[3]};
  float* mirror_re[2] = {lanes[4], lanes[5]};
  float* mirror_im[2] = {lanes[6], lanes[7]};
  for (auto _ : state) {
    for (int block = 0; block < n / (mirrored ? 32 : 16); ++block) {
      if (mirrored) {
        ocean::cpu::evolve_planes_mirrored(args, block, re, im, mirror_re, mirror_im);
      } else {
        ocean::cpu::evolve_planes(args, block, re, im);
      }
    }
    benchmark::ClobberMemory();
  }
  set_texels(state, n);
  if (mirrored) state.SetLabel(ocean::fft::active_simd_target() + " mirrored");
}

// Arguments: N, target index, 1 for streaming stores of both maps (AVX-512 only; the pipeline
// streams them from 512²).
void BM_AssembleDisplacement(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  if (!select_target(state, static_cast<int>(state.range(1)))) return;
  const bool stream = state.range(2) != 0;
  const ocean::cpu::AssemblyStores stores{.stream_displacement = stream, .stream_half = stream};
  Fixture f(n);
  alignas(64) static float lanes[3][16 * 2048];
  for (auto& l : lanes) std::fill(l, l + 16 * n, 0.5f);
  auto& c = f.frame.cascades[0];
  for (auto _ : state) {
    for (int block = 0; block < n / 16; ++block)
      ocean::cpu::assemble_displacement(lanes[0], lanes[1], lanes[2], n, block,
                                        c.displacement.data(), c.displacement_half.data(), stores);
    benchmark::ClobberMemory();
  }
  set_texels(state, n);
}

void BM_SurfaceRows(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  if (!select_target(state, static_cast<int>(state.range(1)))) return;
  Fixture f(n);
  auto& c = f.frame.cascades[0];
  const bool all = state.range(2) == 0;  // else the texture set: no float normal, J, foam
  ocean::cpu::SurfaceArgs args{.n = n,
                               .displacement = c.displacement.data(),
                               .inv_spacing = float(n) / 500.0f,
                               .foam_state = f.state.foam.data(),
                               .jacobian = all ? c.jacobian.data() : nullptr,
                               .foam = all ? c.foam.data() : nullptr,
                               .normal = all ? c.normal.data() : nullptr,
                               .mip_work = f.state.mip_work.data(),
                               .packed = c.packed_mips.data()};
  for (auto _ : state) {
    ocean::cpu::surface_row_quads(args, 0, n / 4);
    benchmark::ClobberMemory();
  }
  set_texels(state, n);
}

void BM_MipChain(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  if (!select_target(state, static_cast<int>(state.range(1)))) return;
  Fixture f(n);
  auto& c = f.frame.cascades[0];
  for (auto _ : state) {
    for (int level = 3; (n >> level) >= 1; ++level) {  // levels 1 and 2 are the surface pass's
      for (int row = 0; row < (n >> level); ++row)
        ocean::cpu::mip_row(n, level, row, f.state.mip_work.data(), 2, c.packed_mips.data());
    }
    benchmark::ClobberMemory();
  }
  set_texels(state, n);
}

// The scalar reference stages on the same data, for the ratios.
void BM_ReferenceSurfaceAndMips(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Fixture f(n);
  ocean::SimulationConfig config;
  config.resolution = n;
  f.state.plane_re.assign(2, std::vector<float>(static_cast<std::size_t>(n * n)));
  f.state.plane_im.assign(2, std::vector<float>(static_cast<std::size_t>(n * n)));
  auto& c = f.frame.cascades[0];
  for (auto _ : state) {
    ocean::cpu::finalize(f.state, config, 0.01, false, c, *f.runner);
    ocean::cpu::build_mips(f.state, c, *f.runner);
    benchmark::ClobberMemory();
  }
  set_texels(state, n);
}

BENCHMARK(BM_EvolvePlanes)
    ->ArgsProduct({{256, 512}, {0, 1, 2}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AssembleDisplacement)
    ->ArgsProduct({{256, 512}, {0, 1, 2}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SurfaceRows)
    ->ArgsProduct({{256, 512}, {0, 1, 2}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MipChain)->ArgsProduct({{256, 512}, {0, 1, 2}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReferenceSurfaceAndMips)->Arg(256)->Arg(512)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
