// FFTW as a baseline FFT engine for `ocean bench`, loaded at run time with dlopen so that
// neither the library nor the tool links it (FFTW is GPL): single precision, split complex,
// FFTW_MEASURE plans, optionally multithreaded.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "ocean/backends/cpu.hpp"
#include "ocean/core.hpp"

namespace ocean::cli {

struct FftwApi;

/// Inverse 2D transforms of N×N split-complex planes with FFTW (no shift, unnormalised, our
/// sign convention). Plans on first use of each plane (FFTW_MEASURE overwrites the plane: run a
/// frame before measuring).
class FftwEngine final : public cpu::ExternalFft {
 public:
  /// threads = 1 or more. Fails with a one-line message when libfftw3f is not installed.
  static Result<std::unique_ptr<FftwEngine>> make(int n, int threads);
  ~FftwEngine() override;
  void inverse(std::span<const fft::SplitComplex> planes) override;
  [[nodiscard]] int threads() const { return threads_; }

 private:
  FftwEngine() = default;
  struct Plan;
  const FftwApi* api_ = nullptr;
  int n_ = 0;
  int threads_ = 1;
  std::vector<Plan> plans_;
};

}  // namespace ocean::cli
