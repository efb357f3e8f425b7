// Shared helpers of the FFT tests: random split-complex signals and relative RMS error.
#pragma once

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <cstdint>
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

}  // namespace ocean::fft::test
