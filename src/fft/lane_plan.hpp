// Private to the FFT and the CPU backend (reached through the PRIVATE include path src/): the
// lane-layout building blocks of the SIMD plan, which fused passes call directly (the CPU
// backend evolves the spectrum straight into a column block and assembles its outputs from a
// row block). The public face is ocean::fft::SimdPlan2D (ocean/fft.hpp), which runs inverse().
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "fft/lane_kernels.hpp"
#include "ocean/fft.hpp"

namespace ocean::fft {

/// The SIMD plan's stages and twiddles with the column and row passes it is made of. Same
/// conventions and guarantees as SimdPlan2D; every member is const and allocates nothing.
class LanePlan2D {
 public:
  /// Lines per block: the column pass handles columns [16·b, 16·b + 16), the row pass rows.
  static constexpr int kBlock = 16;

  /// Sizes: powers of two in [16, kMaxSimdSize]; allocates the twiddle tables.
  static Result<LanePlan2D> make(int n);
  [[nodiscard]] int size() const { return n_; }
  [[nodiscard]] int blocks() const { return n_ / kBlock; }

  /// What SimdPlan2D::inverse runs: in place, with the optional (−1)^(x+y) shift.
  void inverse(std::span<const SplitComplex> planes, TaskRunner& runner, bool sign_correct) const;

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

}  // namespace ocean::fft
