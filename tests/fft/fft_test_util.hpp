// Shared helpers of the FFT tests: random split-complex signals and relative RMS error.
#pragma once

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "ocean/fft.hpp"

namespace ocean::fft::test {

struct Signal {
  std::vector<float> re, im;
  explicit Signal(std::size_t n, std::uint64_t seed) : re(n), im(n) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<float> g(0.0f, 1.0f);
    for (std::size_t i = 0; i < n; ++i) {
      re[i] = g(rng);
      im[i] = g(rng);
    }
  }
  SplitComplex view() { return {re.data(), im.data()}; }
};

// Root-mean-square error of ours against a reference, relative to the reference's RMS.
inline double relative_rms(const Signal& ours, const std::vector<std::complex<double>>& ref) {
  double err = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    err += std::norm(std::complex<double>(ours.re[i], ours.im[i]) - ref[i]);
    norm += std::norm(ref[i]);
  }
  return std::sqrt(err / norm);
}

// FFTW's double-precision 2D backward transform of an N×N signal (FFTW_BACKWARD is
// e^{+2πi jk/N}, unnormalised: our convention).
inline std::vector<std::complex<double>> fftw_inverse_2d(const Signal& s, int n) {
  std::vector<std::complex<double>> ref(s.re.size());
  for (std::size_t i = 0; i < ref.size(); ++i) ref[i] = {s.re[i], s.im[i]};
  auto* data = reinterpret_cast<fftw_complex*>(ref.data());
  fftw_plan p = fftw_plan_dft_2d(n, n, data, data, FFTW_BACKWARD, FFTW_ESTIMATE);
  fftw_execute(p);
  fftw_destroy_plan(p);
  return ref;
}

// Transforms the same 128×128 signal with a serial and a two-thread runner and expects the same
// bits (the plans' determinism contract).
template <typename Plan>
void expect_bit_identical_across_runners() {
  const int n = 128;
  const std::size_t count = 128 * 128;
  Signal a(count, 8), b(count, 8);
  const auto plan = Plan::make(n).value();
  auto serial = ocean::make_serial_runner();
  auto tbb = ocean::make_tbb_runner(2);
  const SplitComplex pa = a.view(), pb = b.view();
  plan.inverse({&pa, 1}, *serial, true);
  plan.inverse({&pb, 1}, *tbb, true);
  EXPECT_EQ(std::memcmp(a.re.data(), b.re.data(), count * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(a.im.data(), b.im.data(), count * sizeof(float)), 0);
}

}  // namespace ocean::fft::test
