// The SIMD plan on every instruction set this CPU runs: against FFTW (double) and the scalar
// radix-2 reference, with and without the sign correction, odd and even stage counts, and
// bit-identical results for any task runner.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "fft/fft_test_util.hpp"
#include "fft/lane_plan.hpp"
#include "ocean/fft.hpp"

namespace {

using ocean::fft::LanePlan2D;
using ocean::fft::SimdPlan2D;
using ocean::fft::SplitComplex;
using ocean::fft::test::relative_rms;
using ocean::fft::test::Signal;

// Runs body once per instruction set, with dispatch forced to it; restores the best after.
template <typename Body>
void for_each_target(Body body) {
  const std::vector<std::string> targets = ocean::fft::simd_targets();
  ASSERT_FALSE(targets.empty());
  for (const std::string& target : targets) {
    ASSERT_TRUE(ocean::fft::force_simd_target(target).ok());
    ASSERT_EQ(ocean::fft::active_simd_target(), target);  // the kernels really run on it
    SCOPED_TRACE("target " + target);
    body(target == targets.front());
  }
  ASSERT_TRUE(ocean::fft::force_simd_target("").ok());
}

// The refused name is echoed as ocean::excerpt writes it: the message stays one line.
TEST(SimdTargets, UnknownTargetIsEchoedOnOneLine) {
  const std::string message = ocean::fft::force_simd_target("AVX9\n").message();
  EXPECT_EQ(
      message.rfind("SIMD target = 'AVX9\\n' is not available on this CPU: must be one of ", 0), 0u)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(SimdFft2D, MatchesFftwOnEveryTarget) {
  auto runner = ocean::make_tbb_runner();
  for_each_target([&](bool best) {
    // 32 = 8·4, 64 = 16·4, 128 = 16·8, 256 = 16·16 (even stage counts: the result stays in
    // the input buffer); 16, 512 = 16·8·4, 1024 = 16·16·4, 2048 = 16·16·8 (odd: it ends in
    // the scratch). Every radix (16, 8, 4) appears.
    for (int n = 16; n <= (best ? 2048 : 512); n *= 2) {
      const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
      Signal a(count, 3), b(count, 4);
      const auto ref_a = ocean::fft::test::fftw_inverse_2d(a, n);
      const auto ref_b = ocean::fft::test::fftw_inverse_2d(b, n);
      const auto plan = SimdPlan2D::make(n).value();
      const SplitComplex planes[] = {a.view(), b.view()};
      plan.inverse(planes, *runner, false);
      const double bound = 2e-7 * std::log2(double(count));  // the scalar plan's bound
      EXPECT_LT(relative_rms(a, ref_a), bound) << "n = " << n;
      EXPECT_LT(relative_rms(b, ref_b), bound) << "n = " << n;
    }
  });
}

// With the (−1)^(x+y) shift the SIMD plan reproduces the scalar reference to float rounding.
TEST(SimdFft2D, MatchesScalarReferenceWithSignCorrection) {
  auto runner = ocean::make_tbb_runner();
  for_each_target([&](bool) {
    for (int n : {16, 64, 128, 512}) {
      const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
      Signal ours(count, 5), ref(count, 5);
      const SplitComplex p_ours = ours.view(), p_ref = ref.view();
      SimdPlan2D::make(n).value().inverse({&p_ours, 1}, *runner, true);
      ocean::fft::Plan2D::make(n).value().inverse({&p_ref, 1}, *runner, true);
      std::vector<std::complex<double>> expected(count);
      for (std::size_t i = 0; i < count; ++i) expected[i] = {ref.re[i], ref.im[i]};
      EXPECT_LT(relative_rms(ours, expected), 1e-6) << "n = " << n;
    }
  });
}

// A band-limited input (zero outside elements [N/4, 3N/4)) transforms to the same bits with the
// pruned first stage, which must not read the outer half at all (NaNs there here); the row
// pass's tile transposes skip the same columns.
TEST(SimdFft2D, PrunedOuterHalfGivesTheSameBits) {
  for_each_target([&](bool best) {
    for (int n = 32; n <= (best ? 2048 : 256); n *= 2) {
      const auto plan = LanePlan2D::make(n).value();
      ASSERT_EQ(plan.prunes_outer_half(), n >= 64) << n;
      if (!plan.prunes_outer_half()) continue;
      const auto un = static_cast<std::size_t>(n);
      const std::size_t floats = 16 * un;
      std::vector<float> in_re(floats), in_im(floats);
      Signal signal(floats, 7);
      for (std::size_t j = 0; j < un; ++j) {
        const bool inner = j >= un / 4 && j < 3 * un / 4;
        for (std::size_t l = 0; l < 16; ++l) {
          in_re[j * 16 + l] = inner ? signal.re[j * 16 + l] : 0.0f;
          in_im[j * 16 + l] = inner ? signal.im[j * 16 + l] : 0.0f;
        }
      }
      alignas(64) static float buffers[4][2][16 * 2048];
      const LanePlan2D::LaneBlock full{buffers[0][0], buffers[0][1]};
      const LanePlan2D::LaneBlock full_scratch{buffers[1][0], buffers[1][1]};
      const LanePlan2D::LaneBlock pruned{buffers[2][0], buffers[2][1]};
      const LanePlan2D::LaneBlock pruned_scratch{buffers[3][0], buffers[3][1]};
      const LanePlan2D::LaneBlock a = plan.input_for(full, full_scratch);
      const LanePlan2D::LaneBlock b = plan.input_for(pruned, pruned_scratch);
      std::memcpy(a.re, in_re.data(), floats * sizeof(float));
      std::memcpy(a.im, in_im.data(), floats * sizeof(float));
      std::memcpy(b.re, in_re.data(), floats * sizeof(float));
      std::memcpy(b.im, in_im.data(), floats * sizeof(float));
      for (std::size_t j = 0; j < un; ++j) {  // the pruned transform must not read these
        if (j >= un / 4 && j < 3 * un / 4) continue;
        std::fill_n(b.re + j * 16, 16, std::numeric_limits<float>::quiet_NaN());
        std::fill_n(b.im + j * 16, 16, std::numeric_limits<float>::quiet_NaN());
      }
      plan.transform(full, full_scratch);
      plan.transform(pruned, pruned_scratch, true);
      std::size_t differing = 0;
      for (std::size_t i = 0; i < floats; ++i)
        differing += !(full.re[i] == pruned.re[i]) + !(full.im[i] == pruned.im[i]);
      EXPECT_EQ(differing, 0u) << "n = " << n;

      // Tiles: the pruned walk writes the inner columns as the full one does.
      std::vector<float> tiles(un * un), lanes_full(floats, 1.0f), lanes_pruned(floats, 1.0f);
      for (std::size_t i = 0; i < tiles.size(); ++i) tiles[i] = float(i % 977);
      plan.tiles_to_lanes(tiles.data(), 1, lanes_full.data());
      plan.tiles_to_lanes(tiles.data(), 1, lanes_pruned.data(), true);
      for (std::size_t c = 0; c < un; ++c) {
        const bool inner = c >= un / 4 && c < 3 * un / 4;
        for (std::size_t l = 0; l < 16; ++l) {
          const std::size_t i = c * 16 + l;
          ASSERT_EQ(lanes_pruned[i], inner ? lanes_full[i] : 1.0f) << "n " << n << " c " << c;
        }
      }
    }
  });
}

TEST(SimdFft2D, BitIdenticalForAnyRunner) {
  for_each_target(
      [](bool) { ocean::fft::test::expect_bit_identical_across_runners<SimdPlan2D>(); });
}

TEST(SimdFft2D, RejectsBadSizesAndTargets) {
  for (int n : {0, 8, 100, 4096}) {
    const auto plan = SimdPlan2D::make(n);
    ASSERT_FALSE(plan.ok()) << n;
    EXPECT_NE(plan.status().message().find("power of two in [16, 2048]"), std::string::npos);
  }
  const ocean::Status s = ocean::fft::force_simd_target("NOT_AN_ISA");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("must be one of"), std::string::npos) << s.message();
}

}  // namespace
