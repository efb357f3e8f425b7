// FFT against a naive DFT (long double) and FFTW at every supported size 16…2048; the sign
// correction; determinism across task runners.
#include "ocean/fft.hpp"

#include <fftw3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <random>
#include <vector>

#include "fft/fft_test_util.hpp"

namespace {

using ocean::fft::SplitComplex;
using ocean::fft::test::relative_rms;
using ocean::fft::test::Signal;

TEST(Fft1D, MatchesNaiveDft) {
  for (int n : {2, 4, 8, 16, 32, 64, 128, 256, 512}) {
    Signal s(static_cast<std::size_t>(n), 11);
    std::vector<std::complex<double>> ref(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
      std::complex<long double> sum = 0;
      for (int k = 0; k < n; ++k) {
        const long double angle = 2.0L * 3.141592653589793238462643383279502884L * j * k / n;
        sum += std::complex<long double>(s.re[static_cast<std::size_t>(k)],
                                         s.im[static_cast<std::size_t>(k)]) *
               std::complex<long double>(std::cos(angle), std::sin(angle));
      }
      ref[static_cast<std::size_t>(j)] =
          std::complex<double>(static_cast<double>(sum.real()), static_cast<double>(sum.imag()));
    }
    const auto plan = ocean::fft::Plan1D::make(n).value();
    const SplitComplex v = s.view();
    plan.inverse({&v, 1});
    EXPECT_LT(relative_rms(s, ref), 1e-6) << "n = " << n;
  }
}

// 2D, every supported size 16…2048 against FFTW's double-precision backward transform
// (FFTW_BACKWARD is e^{+2πi jk/N}, unnormalised: our convention).
TEST(Fft2D, MatchesFftwAtEverySize) {
  auto runner = ocean::make_tbb_runner();
  for (int n = 16; n <= 2048; n *= 2) {
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    Signal a(count, 3), b(count, 4);
    const auto ref_a = ocean::fft::test::fftw_inverse_2d(a, n);
    const auto ref_b = ocean::fft::test::fftw_inverse_2d(b, n);
    const auto plan = ocean::fft::Plan2D::make(n).value();
    const SplitComplex planes[] = {a.view(), b.view()};
    plan.inverse(planes, *runner, false);
    const double bound = 2e-7 * std::log2(double(count));  // float rounding grows with log N
    EXPECT_LT(relative_rms(a, ref_a), bound) << "n = " << n;
    EXPECT_LT(relative_rms(b, ref_b), bound) << "n = " << n;
  }
}

// A single centred wave vector (m, n) transforms to e^{2πi((m−N/2)x + (n−N/2)y)/N}; with the
// sign correction that is exactly the field of wave vector k = (m − N/2, n − N/2).
TEST(Fft2D, SignCorrectionCentresTheSpectrum) {
  const int n = 32;
  const std::size_t count = 32 * 32;
  std::vector<float> re(count, 0.0f), im(count, 0.0f);
  const int m = 19, row = 13;  // k = (3, −3) cycles per patch
  re[static_cast<std::size_t>(row * n + m)] = 1.0f;
  const auto plan = ocean::fft::Plan2D::make(n).value();
  auto serial = ocean::make_serial_runner();
  const SplitComplex plane{re.data(), im.data()};
  plan.inverse({&plane, 1}, *serial, true);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double phase = 2.0 * 3.14159265358979323846 * ((m - n / 2) * x + (row - n / 2) * y) / n;
      EXPECT_NEAR(re[static_cast<std::size_t>(y * n + x)], std::cos(phase), 1e-5);
      EXPECT_NEAR(im[static_cast<std::size_t>(y * n + x)], std::sin(phase), 1e-5);
    }
  }
}

TEST(Fft2D, BitIdenticalForAnyRunner) {
  ocean::fft::test::expect_bit_identical_across_runners<ocean::fft::Plan2D>();
}

TEST(Fft, RejectsBadSizes) {
  for (int n : {0, 1, 3, 100, 8192, -4}) {
    const auto p = ocean::fft::Plan2D::make(n);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.status().message().find(std::to_string(n)), std::string::npos);
  }
}

}  // namespace
