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

namespace detail {
/// One stage of the SIMD plan (radix 16, 8 or 4 on sub-transforms of length ns; its twiddles start
/// at `twiddle`). Internal; see src/fft/lane_kernels.hpp.
struct Stage {
  int radix;
  int ns;
  std::size_t twiddle;
};
}  // namespace detail

/// Largest size of the SIMD plan (its per-thread scratch lives on the stack: 4·16·N floats).
inline constexpr int kMaxSimdSize = 2048;

/// The fast 2D inverse transform: columns, then rows, 16 lines at a time as one SIMD vector
/// (AVX-512; two AVX2 or four SSE/NEON vectors), mixed radix-16/8/4 Stockham stages with hoisted
/// twiddles, natural order in and out (no bit reversal), dispatched at run time to the best
/// instruction set (Highway). docs/performance.md describes the layout.
///
/// Same convention as Plan2D. Results agree with Plan2D to float rounding (relative RMS error
/// below 1e-6, tested for every instruction set) and are bit-identical for any task runner and
/// thread count on a given instruction set. Sizes: powers of two in [16, kMaxSimdSize].
class SimdPlan2D {
 public:
  /// Lines per block: the column pass handles columns [16·b, 16·b + 16), the row pass rows.
  static constexpr int kBlock = 16;

  static Result<SimdPlan2D> make(int n);
  [[nodiscard]] int size() const { return n_; }
  [[nodiscard]] int blocks() const { return n_ / kBlock; }

  /// In place, with the optional (−1)^(x+y) shift, like Plan2D::inverse. planes.size() ≤
  /// kMaxPlanes.
  void inverse(std::span<const SplitComplex> planes, TaskRunner& runner, bool sign_correct) const;

  // Building blocks for fused passes (the CPU backend evolves the spectrum straight into a
  // column block and assembles its outputs from a row block).

  /// Inverse-transforms columns [16·block, 16·block + 16) of an N×N plane, in place.
  void columns(SplitComplex plane, int block) const;

  /// 16 lines in lane layout: element j of line l at re/im[j·16 + l] (N·16 floats each,
  /// 64-byte aligned).
  struct LaneBlock {
    float* re;
    float* im;
  };
  /// Where a block's input goes so that transform() leaves the result in `out`: `out` itself
  /// for an even number of stages, `scratch` for an odd one (no copy either way).
  [[nodiscard]] LaneBlock input_for(LaneBlock out, LaneBlock scratch) const {
    return stages_.size() % 2 == 0 ? out : scratch;
  }
  /// Inverse-transforms the 16 lines of a lane block whose input is at input_for(out, scratch);
  /// the result is in `out`, the other buffer is overwritten. outer_half_zero: the input is
  /// zero outside elements [N/4, 3N/4) (a band-limited spectrum); where prunes_outer_half(),
  /// those elements are then not read (and need not be written), otherwise they must hold the
  /// zeros. Same result either way.
  void transform(LaneBlock out, LaneBlock scratch, bool outer_half_zero = false) const;
  /// Whether transform() skips the zero outer half (the first stage is radix 16: N ≥ 64).
  [[nodiscard]] bool prunes_outer_half() const { return stages_.front().radix == 16; }
  /// The column pass's output as the row pass's input. `tiles` holds a whole plane as column
  /// blocks in lane layout (column block b's row j at tiles[b·16·N + j·16 + l], what
  /// transform() leaves for a column block); writes rows [16·block, 16·block + 16) in lane
  /// layout along the rows (column c of row 16·block + l at dst[c·16 + l]): 16×16 tile
  /// transposes. outer_half_zero: only columns [N/4, 3N/4), for a transform() that prunes the
  /// rest.
  void tiles_to_lanes(const float* tiles, int block, float* dst,
                      bool outer_half_zero = false) const;
  /// Inverse-transforms rows [16·block, 16·block + 16). The result is left in lane layout in
  /// out_re/out_im (N·16 floats each: column c of row 16·block + l at [c·16 + l]); the plane's
  /// rows are overwritten with scratch.
  void rows(SplitComplex plane, int block, float* out_re, float* out_im) const;
  /// Writes a rows() result back into the plane's rows in row-major order, with the shift when
  /// sign_correct.
  void store_rows(const float* lane_re, const float* lane_im, SplitComplex plane, int block,
                  bool sign_correct) const;

 private:
  int n_ = 0;
  std::vector<detail::Stage> stages_;
  std::vector<float> twiddle_re_, twiddle_im_;
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
