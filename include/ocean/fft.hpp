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
#include <memory>
#include <span>
#include <string>
#include <string_view>
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

/// Radix-2 decimation-in-time Cooley–Tukey (Cooley & Tukey 1965; Aebi, VR Ocean, §3.6) with a
/// bit-reversed load and a precomputed twiddle table (computed in double precision, stored as
/// float).
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
/// local buffers, Aebi, VR Ocean, eqs. 40–41), each butterfly applied to every plane (eq. 39).
class Plan2D {
 public:
  static Result<Plan2D> make(int n);
  [[nodiscard]] int size() const { return plan_.size(); }
  /// In place. With sign_correct, output (col, row) is multiplied by (−1)^(col+row)
  /// (Aebi, VR Ocean, eqs. 42–43), which turns a centred spectrum (DC at N/2, N/2) into the field.
  /// planes.size() ≤ kMaxPlanes.
  void inverse(std::span<const SplitComplex> planes, TaskRunner& runner, bool sign_correct) const;

 private:
  Plan1D plan_;
};

/// Largest size of the SIMD plan (its per-thread scratch lives on the stack: 4·16·N floats).
inline constexpr int kMaxSimdSize = 2048;

class LanePlan2D;  // the SIMD plan's lane-layout building blocks (private: src/fft/lane_plan.hpp)

/// The fast 2D inverse transform: columns, then rows, 16 lines at a time as one SIMD vector
/// (AVX-512; two AVX2 or four SSE/NEON vectors), mixed radix-16/8/4 Stockham stages with hoisted
/// twiddles, natural order in and out (no bit reversal), dispatched at run time to the best
/// instruction set (Highway). docs/performance.md describes the layout.
///
/// Same convention as Plan2D. Results agree with Plan2D to float rounding (relative RMS error
/// below 1e-6, tested for every instruction set) and are bit-identical for any task runner and
/// thread count on a given instruction set. Sizes: powers of two in [16, kMaxSimdSize]. Copies
/// share the immutable tables.
class SimdPlan2D {
 public:
  static Result<SimdPlan2D> make(int n);
  [[nodiscard]] int size() const;

  /// In place, with the optional (−1)^(x+y) shift, like Plan2D::inverse. planes.size() ≤
  /// kMaxPlanes; the plan comes from make() (a default-constructed one has size 0 and no tables).
  void inverse(std::span<const SplitComplex> planes, TaskRunner& runner, bool sign_correct) const;

 private:
  std::shared_ptr<const LanePlan2D> plan_;
};

/// Instruction sets the SIMD kernels were compiled for and this CPU runs, best first (e.g.
/// "AVX3", "AVX2", "SSE4", "SSSE3", "EMU128").
std::vector<std::string> simd_targets();
/// The instruction set the SIMD kernels dispatch to now.
std::string active_simd_target();
/// Restricts dispatch to one of simd_targets() — for tests and benchmarks of each instruction
/// set; "" restores the best. Not thread-safe: call while no simulation runs.
Status force_simd_target(std::string_view name);
/// Measured single-thread peak of fused multiply-adds at the active instruction set, in
/// GFLOP/s (2 flops per lane per FMA), over about `seconds` of work. Benchmarks only.
double measure_fma_peak_gflops(double seconds = 0.1);

}  // namespace ocean::fft
