// SIMD mip rows of the CPU backend: the levels the surface pass does not compute, 2×2 sums,
// then length → smoothness and RGBA8 packing. Compiled once per instruction set by Highway.
//
// The formulas are those of the scalar reference (mips.cpp), which cites their sources.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "cpu/mip_kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "cpu/kernels.hpp"
#include "cpu/mip_sums-inl.h"
#include "cpu/simd_math-inl.h"
#include "ocean/sim.hpp"

HWY_BEFORE_NAMESPACE();
namespace ocean::cpu {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void MipRow(int n, int level, int row_int, float* work, int work_level, std::uint32_t* packed) {
  const auto size = static_cast<std::size_t>(n >> level);
  const auto row = static_cast<std::size_t>(row_int);
  const std::size_t src_size = 2 * size;
  const std::size_t origin = mip_offset(n, work_level);  // the work chain starts there
  const float* src0 = work + 4 * (mip_offset(n, level - 1) - origin + 2 * row * src_size);
  const float* src1 = src0 + 4 * src_size;
  const std::size_t dst = mip_offset(n, level) + row * size;
  // 2×2 sums (eq. 52), deinterleaved into structure-of-arrays for the vector part.
  alignas(64) float sum[4][1024];
  std::size_t c = 0;
#if HWY_TARGET != HWY_SCALAR
  const hn::ScalableTag<float> df;
  const std::size_t step = hn::Lanes(df);
  for (; c + step <= size; c += step) {  // texels 2c … 2c + 2·step of both source rows
    using V = decltype(hn::Zero(df));
    V lo[2][4], hi[2][4];
    for (std::size_t r = 0; r < 2; ++r) {
      const float* src = (r == 0 ? src0 : src1) + 8 * c;
      hn::LoadInterleaved4(df, src, lo[r][0], lo[r][1], lo[r][2], lo[r][3]);
      hn::LoadInterleaved4(df, src + 4 * step, hi[r][0], hi[r][1], hi[r][2], hi[r][3]);
    }
    for (std::size_t k = 0; k < 4; ++k) {  // the scalar loop's order of additions
      const auto top =
          hn::Add(hn::ConcatEven(df, hi[0][k], lo[0][k]), hn::ConcatOdd(df, hi[0][k], lo[0][k]));
      const auto all = hn::Add(hn::Add(top, hn::ConcatEven(df, hi[1][k], lo[1][k])),
                               hn::ConcatOdd(df, hi[1][k], lo[1][k]));
      hn::Store(hn::Mul(all, hn::Set(df, 0.25f)), df, sum[k] + c);
    }
  }
#endif
  for (; c < size; ++c) {
    for (std::size_t k = 0; k < 4; ++k) {
      sum[k][c] = 0.25f * (((src0[8 * c + k] + src0[8 * c + 4 + k]) + src1[8 * c + k]) +
                           src1[8 * c + 4 + k]);
    }
  }
  MipFromSums(sum, size, work + 4 * (dst - origin), packed + dst);
}

}  // namespace HWY_NAMESPACE
}  // namespace ocean::cpu
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ocean::cpu {

HWY_EXPORT(MipRow);

void mip_row(int n, int level, int row, float* work, int work_level, std::uint32_t* packed) {
  HWY_DYNAMIC_DISPATCH(MipRow)(n, level, row, work, work_level, packed);
}

}  // namespace ocean::cpu
#endif
