// Internal, per instruction set: the 16×16 tile transpose of the lane-blocked FFT's layout
// changes, shared by the FFT kernels and the CPU backend's fused kernels. Include after
// <hwy/highway.h> inside a Highway per-target compilation unit (the usual -inl.h toggle).
#if defined(OCEAN_FFT_TRANSPOSE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef OCEAN_FFT_TRANSPOSE_INL_H_
#undef OCEAN_FFT_TRANSPOSE_INL_H_
#else
#define OCEAN_FFT_TRANSPOSE_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>

HWY_BEFORE_NAMESPACE();
namespace ocean::fft::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

inline constexpr std::size_t kTile = 16;

#if !HWY_HAVE_SCALABLE && HWY_TARGET != HWY_SCALAR
// In registers: v[c] becomes column c of the L×L matrix (L = lanes of the vector) whose row r
// was v[r], by log2 L rounds of even/odd de-interleaving (each round rotates the row/column
// index bits by one; after log2 L rounds rows and columns have swapped).
template <class D>
HWY_INLINE void TransposeVectors(D d, hn::Vec<D>* v) {
  constexpr std::size_t L = hn::MaxLanes(D());
  for (std::size_t round = 1; round < L; round *= 2) {
    hn::Vec<D> t[L];
    for (std::size_t i = 0; i < L / 2; ++i) {
      t[i] = hn::ConcatEven(d, v[2 * i + 1], v[2 * i]);
      t[i + L / 2] = hn::ConcatOdd(d, v[2 * i + 1], v[2 * i]);
    }
    for (std::size_t i = 0; i < L; ++i) v[i] = t[i];
  }
}

// One L×L sub-block of a 16×16 tile: out[c][r] = in[r][c]·sign.
template <class D>
HWY_INLINE void TransposeSubBlock(D d, const float* src, std::size_t src_stride, float* dst,
                                  std::size_t dst_stride, const float* sign_even,
                                  const float* sign_odd) {
  constexpr std::size_t L = hn::MaxLanes(D());
  using V = hn::Vec<D>;
  V v[L];
  for (std::size_t r = 0; r < L; ++r) v[r] = hn::LoadU(d, src + r * src_stride);
  TransposeVectors(d, v);
  if (sign_even == nullptr) {
    for (std::size_t c = 0; c < L; ++c) hn::StoreU(v[c], d, dst + c * dst_stride);
    return;
  }
  const auto even = hn::LoadU(d, sign_even), odd = hn::LoadU(d, sign_odd);
  for (std::size_t c = 0; c < L; ++c)
    hn::StoreU(hn::Mul(v[c], (c & 1u) ? odd : even), d, dst + c * dst_stride);
}
#endif

/// dst[c·dst_stride + r] = src[r·src_stride + c]·(−1)^(sign_parity + r + c) for r, c < 16
/// (no sign when sign_parity < 0).
HWY_INLINE void Transpose16Tile(const float* src, std::size_t src_stride, float* dst,
                                std::size_t dst_stride, int sign_parity) {
  // sign(r, c) = (−1)^(parity + r + c): the pattern of a destination row starting at an even
  // column, and of the next row; a sub-block's origin (multiples of L) keeps the parity when
  // L is even.
  alignas(64) float sign[2][kTile];
  const float* even = nullptr;
  const float* odd = nullptr;
  if (sign_parity >= 0) {
    for (std::size_t l = 0; l < kTile; ++l) {
      const bool flip = ((static_cast<std::size_t>(sign_parity) + l) & 1u) != 0;
      sign[0][l] = flip ? -1.0f : 1.0f;
      sign[1][l] = flip ? 1.0f : -1.0f;
    }
    even = sign[0], odd = sign[1];
  }
#if HWY_HAVE_SCALABLE || HWY_TARGET == HWY_SCALAR
  for (std::size_t r = 0; r < kTile; ++r) {
    for (std::size_t c = 0; c < kTile; ++c) {
      const float s = even == nullptr ? 1.0f : (((r + c) & 1u) != 0 ? odd[0] : even[0]);
      dst[c * dst_stride + r] = src[r * src_stride + c] * s;
    }
  }
#else
  const hn::ScalableTag<float> d;
  constexpr std::size_t L = hn::MaxLanes(decltype(d)());
  static_assert(kTile % L == 0 && (L & (L - 1)) == 0);
  for (std::size_t r0 = 0; r0 < kTile; r0 += L) {
    for (std::size_t c0 = 0; c0 < kTile; c0 += L) {
      // Destination row c0 + c starts at column r0: its sign pattern is that of row (c0 + c)
      // from column r0, i.e. the even/odd patterns shifted by r0 + c0 (even: unchanged).
      TransposeSubBlock(d, src + r0 * src_stride + c0, src_stride, dst + c0 * dst_stride + r0,
                        dst_stride, even == nullptr ? nullptr : even + r0,
                        odd == nullptr ? nullptr : odd + r0);
    }
  }
#endif
}

}  // namespace HWY_NAMESPACE
}  // namespace ocean::fft::detail
HWY_AFTER_NAMESPACE();

#endif  // OCEAN_FFT_TRANSPOSE_INL_H_
