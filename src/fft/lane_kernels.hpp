// Internal: the SIMD kernels of the lane-blocked FFT (Highway, dispatched at run time to the best
// instruction set of the CPU). A "lane buffer" holds 16 independent signals interleaved: element
// j of signal l is re[j·stride + l], im[j·stride + l], so one element of all 16 signals is one
// 64-byte line and every butterfly is a plain vector operation with a broadcast twiddle.
#pragma once

#include <cstddef>
#include <cstdint>

namespace ocean::fft::detail {

/// Signals transformed together by one kernel call (one AVX-512 vector, two AVX2 vectors).
inline constexpr int kLanes = 16;

struct LaneBuffer {
  float* re;
  float* im;
  std::size_t stride;  ///< floats between consecutive elements (≥ kLanes)
};

/// One stage of the SIMD plan: radix 16, 8 or 4 on sub-transforms of length ns (product of the
/// radices of the previous stages); twiddles w^r, r = 1..radix−1, for k ∈ [0, ns) start at
/// `twiddle`.
struct Stage {
  int radix;
  int ns;
  std::size_t twiddle;
};

struct StageTable {
  int n;
  const Stage* stages;
  int count;
  const float* twiddle_re;  ///< e^{+2πi·r·k/(ns·radix)}, [(k·(radix−1) + r − 1)] per stage
  const float* twiddle_im;
};

/// Runs every stage, reading `a` and writing `b`, then back (a → b → a → ...). Natural order in
/// and out. Returns true when the result ended in `b`. outer_half_zero: elements outside
/// [N/4, 3N/4) are zero and not read (a first radix-16 stage skips them; others read them).
bool stockham(const StageTable& table, LaneBuffer a, LaneBuffer b, bool outer_half_zero = false);

/// A run of 16×16 tile transposes: tile t reads src + t·src_step (rows src_stride apart) and
/// writes dst + t·dst_step (rows dst_stride apart), dst[c·dst_stride + r] = src[r·src_stride +
/// c]·(−1)^(sign_parity + r + c) for r, c < 16 (no sign when sign_parity < 0). In-register
/// de-interleaving rounds on the vector's lanes (src/fft/transpose-inl.h).
struct TileWalk {
  const float* src;
  std::size_t src_stride, src_step;
  float* dst;
  std::size_t dst_stride, dst_step;
  std::size_t count;
  int sign_parity = -1;
};
void transpose_tiles(const TileWalk& walk);
/// dst[c·kLanes + l] = src[l·row_stride + c] for c < n, l < kLanes (16 rows → lane layout).
void rows_to_lanes(const float* src, std::size_t row_stride, int n, float* dst);
/// dst[l·row_stride + c] = src[c·kLanes + l]·(−1)^(parity + l + c) when sign_correct, else
/// copies: the inverse of rows_to_lanes with the (−1)^(x+y) shift folded in.
void lanes_to_rows(const float* src, int n, float* dst, std::size_t row_stride, bool sign_correct,
                   int parity);

/// Name of the instruction set the kernels dispatch to ("AVX3", "AVX2", "SSE4", "EMU128", ...).
const char* dispatched_target();
/// Runs `iterations` of ten independent vector FMA chains; returns their sum (to keep the work
/// observable) and the vector's lane count.
double fma_loop(std::size_t iterations, std::size_t* lanes);

}  // namespace ocean::fft::detail
