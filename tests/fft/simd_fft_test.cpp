// The SIMD plan on every instruction set this CPU runs: against FFTW (double) and the scalar
// radix-2 reference, with and without the sign correction, odd and even stage counts, and
// bit-identical results for any task runner.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "fft/fft_test_util.hpp"
#include "ocean/fft.hpp"

namespace {

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
