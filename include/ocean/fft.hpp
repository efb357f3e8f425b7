// ocean/fft.hpp — inverse FFT plans for the spectral synthesis: 1D and 2D, several planes per
// pass (dual-spectrum processing), the (−1)^(x+y) shift folded into the final write.
//
// Convention (docs/conventions.md): inverse DFT without normalisation,
//   x[n] = Σ_k X[k]·e^{+2πi·k·n/N},
// which makes h(x) = Σ_k h̃(k)·e^{ik·x} on the patch grid. Data is split complex: separate
// float arrays for real and imaginary parts, row-major N×N for 2D (index row·N + col).
//
// Contract: make() validates and allocates (twiddle and bit-reversal tables); execution never
// allocates, never fails, and is deterministic: the same input gives the same bits for any
// task runner and thread count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/task_runner.hpp"

namespace ocean::fft {

/// A split-complex signal or plane: re[i], im[i].
struct SplitComplex {
  float* re;
  float* im;
};

/// Most planes one 2D pass transforms together.
inline constexpr int kMaxPlanes = 8;
/// Supported sizes: powers of two in [2, kMaxSize].
inline constexpr int kMaxSize = 4096;

/// Radix-2 decimation-in-time Cooley–Tukey (seed 000 §3.6) with a bit-reversed load and a
/// precomputed twiddle table (computed in double precision, stored as float).
class Plan1D {
 public:
  static Result<Plan1D> make(int n);
  [[nodiscard]] int size() const { return n_; }
  /// In-place inverse DFT of each signal (length N, contiguous).
  void inverse(std::span<const SplitComplex> signals) const;

  // Building blocks shared with Plan2D: load with bit reversal from a strided source into
  // contiguous local buffers, run all butterfly stages, for up to kMaxPlanes signals at once.
  void load_bit_reversed(const float* src_re, const float* src_im, std::ptrdiff_t stride,
                         float* dst_re, float* dst_im) const;
  void butterflies(std::span<const SplitComplex> local) const;

 private:
  int n_ = 0;
  int log2n_ = 0;
  std::vector<std::uint32_t> bit_reverse_;
  std::vector<float> twiddle_re_, twiddle_im_;  // e^{+2πi·t/N}, t ∈ [0, N/2)
};

/// Separable 2D inverse transform on N×N planes: all rows, then all columns (gathered into
/// local buffers, seed 000 eqs. 40–41), each butterfly applied to every plane (eq. 39).
class Plan2D {
 public:
  static Result<Plan2D> make(int n);
  [[nodiscard]] int size() const { return plan_.size(); }
  /// In place. With sign_correct, output (col, row) is multiplied by (−1)^(col+row)
  /// (seed 000 eqs. 42–43), which turns a centred spectrum (DC at N/2, N/2) into the field.
  /// planes.size() ≤ kMaxPlanes.
  void inverse(std::span<const SplitComplex> planes, TaskRunner& runner, bool sign_correct) const;

 private:
  Plan1D plan_;
};

}  // namespace ocean::fft
