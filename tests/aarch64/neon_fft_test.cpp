// The SIMD FFT on AArch64 (NEON), run under qemu-user: it agrees with the scalar reference plan
// to float rounding (the bound of tests/fft/simd_fft_test.cpp), and gives the same bits on any
// runner and thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "ocean/fft.hpp"
#include "ocean/task_runner.hpp"

namespace {

using ocean::fft::SplitComplex;

struct Planes {
  std::vector<float> re, im;
  Planes(std::size_t count, unsigned seed) : re(count), im(count) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> g;
    for (std::size_t i = 0; i < count; ++i) re[i] = g(rng), im[i] = g(rng);
  }
  SplitComplex view() { return {re.data(), im.data()}; }
};

TEST(NeonFft, TheSimdTargetIsNeon) { EXPECT_EQ(ocean::fft::active_simd_target(), "NEON"); }

TEST(NeonFft, MatchesTheScalarReference) {
  auto runner = ocean::make_ready_runner({.threads = 2, .spin_us = 0.0});
  for (int n : {16, 64, 128}) {
    const std::size_t count = std::size_t(n) * std::size_t(n);
    Planes ours(count, 5), ref(count, 5);
    const SplitComplex a = ours.view(), b = ref.view();
    ocean::fft::SimdPlan2D::make(n).value().inverse({&a, 1}, *runner, true);
    ocean::fft::Plan2D::make(n).value().inverse({&b, 1}, *runner, true);
    double error = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
      error +=
          std::pow(double(ours.re[i]) - ref.re[i], 2) + std::pow(double(ours.im[i]) - ref.im[i], 2);
      norm += double(ref.re[i]) * ref.re[i] + double(ref.im[i]) * ref.im[i];
    }
    EXPECT_LT(std::sqrt(error / norm), 1e-6) << "n = " << n;
  }
}

TEST(NeonFft, BitIdenticalForAnyRunner) {
  const int n = 64;
  const std::size_t count = std::size_t(n) * std::size_t(n);
  Planes serial(count, 9), two(count, 9);
  const SplitComplex a = serial.view(), b = two.view();
  const auto plan = ocean::fft::SimdPlan2D::make(n).value();
  plan.inverse({&a, 1}, *ocean::make_serial_runner(), true);
  plan.inverse({&b, 1}, *ocean::make_ready_runner({.threads = 2, .spin_us = 0.0}), true);
  EXPECT_EQ(std::memcmp(serial.re.data(), two.re.data(), count * 4), 0);
  EXPECT_EQ(std::memcmp(serial.im.data(), two.im.data(), count * 4), 0);
}

}  // namespace
