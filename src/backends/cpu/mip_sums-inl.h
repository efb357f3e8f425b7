// Internal, per instruction set: a mip row from its 2×2 averages, shared by the surface pass
// (levels 1 and 2 from the rows it just computed) and the mip pass (the levels below). Include
// after <hwy/highway.h> inside a Highway per-target compilation unit.
#if defined(OCEAN_CPU_MIP_SUMS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef OCEAN_CPU_MIP_SUMS_INL_H_
#undef OCEAN_CPU_MIP_SUMS_INL_H_
#else
#define OCEAN_CPU_MIP_SUMS_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>
#include <cstdint>

#include "cpu/cpu_backend.hpp"
#include "cpu/simd_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ocean::cpu {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A mip row from its 2×2 averages `sum` (structure of arrays, `size` texels): smoothness
// from the filtered normal's length (eq. 53) and RGBA8 packing into packed_row, and unless
// work_row is null the averages as float4 work values for the next level into work_row.
HWY_INLINE void MipFromSums(const float (*sum)[1024], std::size_t size, float* work_row,
                            std::uint32_t* packed_row) {
  const bool store_work = work_row != nullptr;
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const std::size_t step = hn::Lanes(df);
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f), half = hn::Set(df, 0.5f);
  std::size_t c = 0;
  for (; c + step <= size; c += step) {
    const auto x = hn::LoadU(df, sum[0] + c), y = hn::LoadU(df, sum[1] + c);
    const auto z = hn::LoadU(df, sum[2] + c), b = hn::LoadU(df, sum[3] + c);
    const auto length = hn::Sqrt(hn::MulAdd(x, x, hn::MulAdd(y, y, hn::Mul(z, z))));
    // Smoothness from the length (eq. 53), as smoothness_from_normal_length().
    const auto t =
        hn::Min(hn::Max(hn::MulSub(hn::Set(df, 3.0f), length, hn::Set(df, 2.0f)), zero), one);
    const auto r = hn::Mul(hn::Sub(one, t), hn::MulAdd(hn::Set(df, 0.15f), t, one));
    const auto smoothness = hn::Sub(one, hn::Sqrt(r));
    const auto valid = hn::Gt(length, zero);
    const auto inv = hn::IfThenElseZero(valid, hn::Div(one, hn::IfThenElse(valid, length, one)));
    const auto rgba =
        hn::Or(hn::Or(QuantiseUnit(df, hn::MulAdd(hn::Mul(x, inv), half, half)),
                      hn::ShiftLeft<8>(QuantiseUnit(df, hn::MulAdd(hn::Mul(z, inv), half, half)))),
               hn::Or(hn::ShiftLeft<16>(QuantiseUnit(df, b)),
                      hn::ShiftLeft<24>(QuantiseUnit(df, smoothness))));
    hn::StoreU(rgba, di, reinterpret_cast<std::int32_t*>(packed_row + c));
    if (store_work) hn::StoreInterleaved4(x, y, z, b, df, work_row + 4 * c);
  }
  for (; c < size; ++c) {  // rows narrower than a vector
    float v[4];
    for (std::size_t k = 0; k < 4; ++k) v[k] = sum[k][c];
    if (store_work) std::copy(v, v + 4, work_row + 4 * c);
    const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const float inv = length > 0.0f ? 1.0f / length : 0.0f;
    packed_row[c] = pack_rgba8(v[0] * inv, v[2] * inv, v[3], smoothness_from_normal_length(length));
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ocean::cpu
HWY_AFTER_NAMESPACE();

#endif
