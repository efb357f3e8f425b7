// The fused SIMD pipeline of the CPU backend against its scalar reference pipeline, on every
// instruction set this CPU runs: the evolution kernel texel by texel, then whole frames
// (displacement, half maps, normals, Jacobian, foam, packed mips) within stated bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "cpu/cpu_backend.hpp"
#include "cpu/kernels.hpp"
#include "ocean/half.hpp"
#include "ocean/plan.hpp"

namespace {

using ocean::cpu::CpuBackendImpl;
using ocean::cpu::CpuOptions;
using ocean::cpu::CpuPipeline;

// Bounds, relative to the significant wave height Hs of the cascade set (4·sqrt(m0) of the
// summed displacement variance). Both pipelines round in float: different FFT orders and the
// polynomial sin/cos (< 3e-8 absolute) give measured maxima of 2.6e-7·Hs (displacement),
// 2.1e-7 (normals), 3.6e-7 (J), 7.7e-7 (foam) on AVX3/AVX2/SSE4/SSSE3/SCALAR; the bounds
// leave about 4× headroom.
constexpr double kDisplacementBound = 1e-6;  // max |ΔD| / Hs
constexpr double kNormalBound = 1e-6;        // max |Δn| (unit vectors)
constexpr double kJacobianBound = 2e-6;      // max |ΔJ|
constexpr double kFoamBound = 4e-6;          // max |Δfoam| (a ramp of width 0.3 in J)
constexpr int kPackedBound = 1;              // RGBA8 channels differ by at most one step

template <typename Body>
void for_each_target(Body body) {
  for (const std::string& target : ocean::fft::simd_targets()) {
    ASSERT_TRUE(ocean::fft::force_simd_target(target).ok());
    SCOPED_TRACE("target " + target);
    body();
  }
  ASSERT_TRUE(ocean::fft::force_simd_target("").ok());
}

ocean::Frame run(const ocean::SimulationConfig& config, CpuPipeline pipeline, int steps) {
  CpuBackendImpl backend(CpuOptions{.pipeline = pipeline});
  auto runner = ocean::make_tbb_runner();
  EXPECT_TRUE(backend.configure(config, *runner).ok());
  ocean::Frame frame;
  backend.allocate(frame);
  for (int s = 0; s < steps; ++s) backend.step(1234.5 + 0.25 * s, frame);
  return frame;
}

double hs_of(const ocean::Frame& frame) {
  double m0 = 0.0;
  std::size_t count = 0;
  for (const auto& c : frame.cascades) {
    for (std::size_t i = 1; i < c.displacement.size(); i += 3)
      m0 += double(c.displacement[i]) * c.displacement[i];
    count += c.displacement.size() / 3;
  }
  return 4.0 * std::sqrt(m0 / double(count) * double(frame.cascades.size()));
}

int channel(std::uint32_t v, int c) { return static_cast<int>((v >> (8 * c)) & 0xffu); }

void expect_frames_agree(const ocean::Frame& fast, const ocean::Frame& ref) {
  const double hs = hs_of(ref);
  ASSERT_GT(hs, 0.0);
  double d_err = 0, n_err = 0, j_err = 0, f_err = 0;
  int p_err = 0, half_ulps = 0;
  for (std::size_t c = 0; c < ref.cascades.size(); ++c) {
    const auto& a = fast.cascades[c];
    const auto& b = ref.cascades[c];
    for (std::size_t i = 0; i < b.displacement.size(); ++i) {
      d_err = std::max(d_err, std::abs(double(a.displacement[i]) - b.displacement[i]));
      n_err = std::max(n_err, std::abs(double(a.normal[i]) - b.normal[i]));
    }
    for (std::size_t i = 0; i < b.jacobian.size(); ++i) {
      j_err = std::max(j_err, std::abs(double(a.jacobian[i]) - b.jacobian[i]));
      f_err = std::max(f_err, std::abs(double(a.foam[i]) - b.foam[i]));
    }
    for (std::size_t i = 0; i < b.packed_mips.size(); ++i) {
      for (int ch = 0; ch < 4; ++ch)
        p_err = std::max(p_err,
                         std::abs(channel(a.packed_mips[i], ch) - channel(b.packed_mips[i], ch)));
    }
    // The half map is the float map converted with round-to-nearest-even, on every target.
    for (std::size_t i = 0; i < b.displacement.size() / 3; ++i) {
      for (std::size_t k = 0; k < 3; ++k) {
        if (a.displacement_half[4 * i + k] != ocean::float_to_half(a.displacement[3 * i + k]))
          ++half_ulps;
      }
      if (a.displacement_half[4 * i + 3] != 0) ++half_ulps;
    }
  }
  EXPECT_LT(d_err / hs, kDisplacementBound) << "Hs = " << hs;
  EXPECT_LT(n_err, kNormalBound);
  EXPECT_LT(j_err, kJacobianBound);
  EXPECT_LT(f_err, kFoamBound);
  EXPECT_LE(p_err, kPackedBound);
  EXPECT_EQ(half_ulps, 0);
}

// One 250 m cascade of the default sea with the evolution kernel's inputs (λ = 1.3); banded:
// the first of two cascades, with no spectrum beyond half its Nyquist wavenumber (M.7.1).
ocean::cpu::CascadeState kernel_state(int n, int planes, double loop_period_s,
                                      bool banded = false) {
  ocean::SimulationConfig config;
  config.resolution = n;
  config.cascade_patch_sizes_m = {250.0};
  if (banded) config.cascade_patch_sizes_m.push_back(60.0);
  ocean::cpu::CascadeState state;
  state.resolution = n;
  state.patch_size_m = 250.0;
  state.planes = planes;
  state.choppiness = 1.3;
  const ocean::SimulationPlan plan = ocean::SimulationPlan::make(config).value();
  state.spectrum = ocean::make_initial_spectrum(plan.sea(), plan.cascades()[0].spectrum).value();
  ocean::cpu::build_kernel_inputs(state, loop_period_s);
  return state;
}

TEST(CpuFused, EvolutionKernelMatchesScalarPhaseRecipe) {
  for_each_target([] {
    for (int planes : {2, 4}) {
      for (double period : {200.0, 0.0}) {
        const ocean::cpu::CascadeState state = kernel_state(64, planes, period);
        double amplitude = 0.0;
        for (const auto& packed : state.spectrum.packed)
          for (float v : packed) amplitude = std::max(amplitude, double(std::abs(v)));
        // A time three days in: frac(t/T) when looping, t itself otherwise.
        const ocean::cpu::EvolveArgs args = ocean::cpu::evolve_args(state, 259200.7, period);
        alignas(64) static float lanes[8][16 * 64];
        float* re[4] = {lanes[0], lanes[1], lanes[2], lanes[3]};
        float* im[4] = {lanes[4], lanes[5], lanes[6], lanes[7]};
        // Relative to the largest |factor| (|k| for the gradient planes, ≤ π·N/L).
        const double k_max = 3.15 * 64 / 250.0;
        double err[4] = {};
        for (int block = 0; block < 4; ++block) {
          ocean::cpu::evolve_planes(args, block, re, im);
          for (std::size_t row = 0; row < 64; ++row) {
            for (std::size_t l = 0; l < 16; ++l) {
              float ref_re[4], ref_im[4];
              ocean::cpu::evolve_texel_reference(args, int(row), 16 * block + int(l), ref_re,
                                                 ref_im);
              for (std::size_t p = 0; p < std::size_t(planes); ++p) {
                const double scale = p == 0 ? 1.0 + state.choppiness : 1.0 + k_max;
                const std::size_t j = row * 16 + l;
                err[p] = std::max(err[p], std::abs(re[p][j] - ref_re[p]) / scale);
                err[p] = std::max(err[p], std::abs(im[p][j] - ref_im[p]) / scale);
              }
            }
          }
        }
        // sin/cos to < 3e-8 absolute plus float rounding of the products and of k̂: measured
        // ≤ 4e-7 of the largest packed amplitude times the largest factor.
        for (int p = 0; p < planes; ++p)
          EXPECT_LT(err[p], 2e-6 * amplitude) << "plane " << p << ", loop period " << period;
      }
    }
  });
}

// Evolving a column block with its mirror block (h̃(−k) = conj h̃(k)) gives the bits of
// evolving each block on its own, on every target, for both plane counts, looping and not, and
// when plane 1 accumulates a pair's second Dz.
TEST(CpuFused, MirroredEvolutionIsBitIdentical) {
  for_each_target([] {
    for (int n : {32, 128}) {
      for (int planes : {2, 4}) {
        for (double period : {200.0, 0.0}) {
          // Banded: the mirrored kernel evolves only the rows with spectrum and writes zeros
          // elsewhere; the ranges must be narrower than N for that to be tested.
          const bool banded = period > 0.0 && n == 128;
          ocean::cpu::CascadeState state = kernel_state(n, planes, period, banded);
          if (banded) {
            ocean::cpu::build_row_ranges(state);
            ASSERT_EQ(state.evolution_rows.size(), std::size_t(n / 16));
            int empty = 0, narrow = 0;
            for (std::size_t u = 0; u < state.evolution_rows.size(); u += 2) {
              const int lo = state.evolution_rows[u], hi = state.evolution_rows[u + 1];
              empty += lo == hi;
              narrow += lo > 0 && hi < n && lo < hi;
            }
            EXPECT_GT(empty, 0);  // the outer block pairs
            EXPECT_GT(narrow, 0);
            EXPECT_TRUE(state.outer_half_zero);  // its planes transform pruned
            ocean::cpu::CascadeState full = kernel_state(n, planes, period);
            ocean::cpu::build_row_ranges(full);
            EXPECT_FALSE(full.outer_half_zero);  // the last cascade keeps every wavenumber
          }
          ocean::cpu::EvolveArgs args = ocean::cpu::evolve_args(state, 259200.7, period);
          args.dz_into_imaginary = planes == 2 && period > 0.0;
          const std::size_t floats = 16 * std::size_t(n);
          // [side][plane][re, im]: one block alone vs the mirrored pair (64-byte aligned,
          // as the kernels require).
          ocean::cpu::AlignedFloats alone(2 * 4 * 2 * floats), paired(alone.size());
          const auto ptrs = [&](ocean::cpu::AlignedFloats& v, std::size_t side, bool imag) {
            std::vector<float*> out(4);
            for (std::size_t p = 0; p < 4; ++p)
              out[p] = v.data() + ((side * 4 + p) * 2 + (imag ? 1 : 0)) * floats;
            return out;
          };
          for (int block = 0; block < n / 32; ++block) {
            const int mirror = n / 16 - 1 - block;
            auto a0r = ptrs(alone, 0, false), a0i = ptrs(alone, 0, true);
            auto a1r = ptrs(alone, 1, false), a1i = ptrs(alone, 1, true);
            std::fill_n(alone.data(), alone.size(), 0.25f);  // plane 1 may be accumulated into
            std::fill_n(paired.data(), paired.size(), 0.25f);
            ocean::cpu::evolve_planes(args, block, a0r.data(), a0i.data());
            ocean::cpu::evolve_planes(args, mirror, a1r.data(), a1i.data());
            auto p0r = ptrs(paired, 0, false), p0i = ptrs(paired, 0, true);
            auto p1r = ptrs(paired, 1, false), p1i = ptrs(paired, 1, true);
            ocean::cpu::evolve_planes_mirrored(args, block, p0r.data(), p0i.data(), p1r.data(),
                                               p1i.data());
            std::size_t differing = 0;
            for (std::size_t i = 0; i < alone.size(); ++i)
              differing += alone.data()[i] != paired.data()[i];
            EXPECT_EQ(differing, 0u) << "n " << n << ", planes " << planes << ", period " << period
                                     << ", block " << block;
          }
        }
      }
    }
  });
}

// The displacement assembly writes (−1)^(x+y) times the row FFT's output, as floats and as
// round-to-nearest-even halves, whether its stores are ordinary or streaming, and with
// streaming asked for but maps that do not start on a cache line (ordinary stores then).
TEST(CpuFused, AssemblyWritesTheSameBitsWithStreamingStores) {
  for_each_target([] {
    for (const int n : {64, 256}) {
      SCOPED_TRACE("n = " + std::to_string(n));
      const auto texels = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
      ocean::cpu::AlignedFloats lanes(3 * 16 * static_cast<std::size_t>(n));
      for (std::size_t i = 0; i < lanes.size(); ++i)
        lanes[i] = std::sin(0.37f * static_cast<float>(i)) * 3.0f;
      const float* h = lanes.data();
      const float* dx = h + 16 * n;
      const float* dz = dx + 16 * n;
      const auto assemble = [&](ocean::cpu::AssemblyStores stores, std::size_t offset) {
        ocean::LargeVector<float> d(3 * texels + 16);
        ocean::LargeVector<std::uint16_t> half(4 * texels + 32);
        for (int block = 0; block < n / 16; ++block) {  // the same row block's planes each time
          ocean::cpu::assemble_displacement(h, dx, dz, n, block, d.data() + offset,
                                            half.data() + 2 * offset, stores);
        }
        return std::pair{
            std::vector<float>(d.begin() + long(offset), d.begin() + long(offset + 3 * texels)),
            std::vector<std::uint16_t>(half.begin() + long(2 * offset),
                                       half.begin() + long(2 * offset + 4 * texels))};
      };
      const auto plain = assemble({}, 0);
      for (std::size_t row = 0; row < std::size_t(n); ++row) {
        for (std::size_t col = 0; col < std::size_t(n); ++col) {
          const float sign = (row + col) % 2 == 0 ? 1.0f : -1.0f;
          const std::size_t lane = col * 16 + row % 16, i = row * std::size_t(n) + col;
          const float expected[3] = {sign * dx[lane], sign * h[lane], sign * dz[lane]};
          for (std::size_t k = 0; k < 3; ++k) {
            ASSERT_EQ(plain.first[3 * i + k], expected[k]) << row << ", " << col;
            ASSERT_EQ(plain.second[4 * i + k], ocean::float_to_half(expected[k]));
          }
          ASSERT_EQ(plain.second[4 * i + 3], 0);
        }
      }
      const ocean::cpu::AssemblyStores streaming{.stream_displacement = true, .stream_half = true};
      EXPECT_EQ(assemble(streaming, 0), plain);
      EXPECT_EQ(assemble(streaming, 4), plain);  // 16 and 32 bytes past a cache line
    }
  });
}

TEST(CpuFused, FramesMatchScalarReference) {
  for_each_target([] {
    for (auto normals : {ocean::NormalMethod::central_difference, ocean::NormalMethod::analytic}) {
      ocean::SimulationConfig config;
      config.resolution = 64;
      config.normals = normals;
      SCOPED_TRACE(std::string(ocean::to_string(normals)));
      expect_frames_agree(run(config, CpuPipeline::fused_simd, 3),
                          run(config, CpuPipeline::scalar_reference, 3));
    }
  });
}

TEST(CpuFused, LargerGridsAndOtherSpectraMatchScalarReference) {
  ocean::SimulationConfig config;
  config.resolution = 256;
  config.sea.wind_sea.spectrum = {.model = ocean::SpectrumModel::phillips, .wind_speed_mps = 12.0};
  config.loop_period_s = 0.0;  // the non-looping phase path
  expect_frames_agree(run(config, CpuPipeline::fused_simd, 2),
                      run(config, CpuPipeline::scalar_reference, 2));
  config.resolution = 512;
  config.cascade_patch_sizes_m = {700.0};
  config.sea.wind_sea.spectrum = {
      .model = ocean::SpectrumModel::tma, .wind_speed_mps = 10.0, .fetch_m = 50e3, .depth_m = 15.0};
  config.loop_period_s = 100.0;
  expect_frames_agree(run(config, CpuPipeline::fused_simd, 2),
                      run(config, CpuPipeline::scalar_reference, 2));
}

// Leaving out the optional arrays (FrameOutputs::textures()) skips their stores in every target's
// surface kernel and changes no other bit.
TEST(CpuFused, TextureOutputsGiveTheSameBitsOnEveryTarget) {
  for_each_target([] {
    ocean::SimulationConfig config;
    config.resolution = 64;
    config.cascade_patch_sizes_m = {400.0, 93.0, 21.0, 5.0};
    config.foam.source = ocean::FoamSource::ramp;
    config.foam.jacobian_start = 1.0;
    const ocean::Frame full = run(config, CpuPipeline::fused_simd, 3);
    config.outputs = ocean::FrameOutputs::textures();
    const ocean::Frame lean = run(config, CpuPipeline::fused_simd, 3);
    for (std::size_t c = 0; c < full.cascades.size(); ++c) {
      const ocean::CascadeFrame& a = full.cascades[c];
      const ocean::CascadeFrame& b = lean.cascades[c];
      EXPECT_TRUE(b.normal.empty() && b.jacobian.empty() && b.foam.empty());
      EXPECT_TRUE(std::equal(a.displacement.begin(), a.displacement.end(), b.displacement.begin(),
                             b.displacement.end()));
      EXPECT_TRUE(std::equal(a.displacement_half.begin(), a.displacement_half.end(),
                             b.displacement_half.begin(), b.displacement_half.end()));
      EXPECT_TRUE(std::equal(a.packed_mips.begin(), a.packed_mips.end(), b.packed_mips.begin(),
                             b.packed_mips.end()))
          << "cascade " << c;
    }
  });
}

// The cache warm-up a frame loop calls before a paced step (Backend::warm_caches) reads and
// prefetches only: frames stepped with it between every step, on one and two threads, are the
// frames stepped without it, bit for bit (foam carried over the steps included).
TEST(CpuFused, WarmingTheCachesChangesNoBit) {
  ocean::SimulationConfig config;
  config.resolution = 64;
  config.cascade_patch_sizes_m = {400.0, 93.0, 21.0, 5.0};
  for (const int threads : {1, 2}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    std::shared_ptr<ocean::TaskRunner> runner = ocean::make_ready_runner({.threads = threads});
    ocean::Frame frames[2];
    for (const bool warm : {false, true}) {
      CpuBackendImpl backend;
      ASSERT_TRUE(backend.configure(config, *runner).ok());
      ocean::Frame& frame = frames[warm ? 1 : 0];
      backend.allocate(frame);
      for (int s = 0; s < 3; ++s) {
        if (warm) backend.warm_caches(frame);
        backend.step(1234.5 + 0.25 * s, frame);
      }
    }
    for (std::size_t c = 0; c < config.cascade_patch_sizes_m.size(); ++c) {
      const ocean::CascadeFrame& a = frames[0].cascades[c];
      const ocean::CascadeFrame& b = frames[1].cascades[c];
      const auto same_bits = [](const auto& x, const auto& y) {
        return x.size() == y.size() && !x.empty() &&
               std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
      };
      EXPECT_TRUE(same_bits(a.displacement, b.displacement)) << "cascade " << c;
      EXPECT_TRUE(same_bits(a.displacement_half, b.displacement_half)) << "cascade " << c;
      EXPECT_TRUE(same_bits(a.normal, b.normal)) << "cascade " << c;
      EXPECT_TRUE(same_bits(a.jacobian, b.jacobian)) << "cascade " << c;
      EXPECT_TRUE(same_bits(a.foam, b.foam)) << "cascade " << c;
      EXPECT_TRUE(same_bits(a.packed_mips, b.packed_mips)) << "cascade " << c;
    }
  }
}

// An FFT engine for the external pipeline: the scalar radix-2 plan without the shift.
class ScalarEngine final : public ocean::cpu::ExternalFft {
 public:
  explicit ScalarEngine(int n) : plan_(ocean::fft::Plan2D::make(n).value()) {}
  void inverse(std::span<const ocean::fft::SplitComplex> planes) override {
    ++calls, transformed += planes.size();
    plan_.inverse(planes, *runner_, false);
  }
  int calls = 0;
  std::size_t transformed = 0;

 private:
  ocean::fft::Plan2D plan_;
  std::unique_ptr<ocean::TaskRunner> runner_ = ocean::make_serial_runner();
};

// Cascades are transformed in pairs that share plane 1 (one cascade's Dz in its real part, the
// other's in its imaginary part); an odd count leaves the last one alone. Every count gives
// the unpaired reference's frames, in the fused and in the external-engine pipeline.
TEST(CpuFused, PairedCascadesMatchUnpairedReference) {
  const std::vector<double> sizes = {900.0, 211.0, 49.0, 11.0};
  // 16: one column block (no mirror pair) and an odd stage count; 64: mirror pairs.
  for (const int n : {16, 64}) {
    for (std::size_t count = 1; count <= 4; ++count) {
      SCOPED_TRACE(std::to_string(count) + " cascades, n = " + std::to_string(n));
      ocean::SimulationConfig config;
      config.resolution = n;
      config.cascade_patch_sizes_m.assign(sizes.begin(), sizes.begin() + long(count));
      const ocean::Frame reference = run(config, CpuPipeline::scalar_reference, 2);
      expect_frames_agree(run(config, CpuPipeline::fused_simd, 2), reference);

      ScalarEngine engine(n);
      CpuBackendImpl backend(CpuOptions{.pipeline = CpuPipeline::external_fft, .fft = &engine});
      auto runner = ocean::make_tbb_runner();
      ASSERT_TRUE(backend.configure(config, *runner).ok());
      ocean::Frame frame;
      backend.allocate(frame);
      for (int s = 0; s < 2; ++s) backend.step(1234.5 + 0.25 * s, frame);
      expect_frames_agree(frame, reference);
      // 3 planes per pair and 2 for a lone cascade, one engine call per group, per step.
      EXPECT_EQ(engine.calls, 2 * int((count + 1) / 2));
      EXPECT_EQ(engine.transformed, 2 * (3 * (count / 2) + 2 * (count % 2)));
    }
  }
}

TEST(CpuFused, ExternalPipelineNeedsAnEngine) {
  CpuBackendImpl backend(CpuOptions{.pipeline = CpuPipeline::external_fft});
  auto runner = ocean::make_serial_runner();
  const ocean::Status s = backend.configure(ocean::SimulationConfig{}, *runner);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("needs an FFT engine"), std::string::npos);
}

}  // namespace

namespace {

// The foam source's Φ (packing::normal_cdf, Abramowitz & Stegun eq. 7.1.26, which the SIMD,
// Vulkan and CUDA kernels share) against ½·erfc(−x/√2) in double: the formula's bound of
// 1.5e-7 on erf plus float rounding, and relative accuracy in the lower tail where whitecap
// fractions live (Φ down to 1e-6).
TEST(FoamSource, NormalCdfMatchesErfc) {
  double worst_abs = 0.0, worst_rel = 0.0;
  for (int i = -4000; i <= 4000; ++i) {
    const double x = i * 0.002;
    const double exact = 0.5 * std::erfc(-x / std::sqrt(2.0));
    const double got = ocean::packing::normal_cdf(static_cast<float>(x));
    worst_abs = std::max(worst_abs, std::abs(got - exact));
    if (exact > 1e-6 && x < 0.0) worst_rel = std::max(worst_rel, std::abs(got / exact - 1.0));
  }
  EXPECT_LT(worst_abs, 3e-7);
  EXPECT_LT(worst_rel, 2e-3);
  EXPECT_EQ(ocean::packing::normal_cdf(-1e10f), 0.0f);  // the capped argument: no NaN
  EXPECT_EQ(ocean::packing::normal_cdf(1e10f), 1.0f);
  EXPECT_NEAR(ocean::packing::normal_cdf(0.0f), 0.5f, 1e-7f);
}

}  // namespace
