// Internal, per instruction set: the vector arithmetic the CPU backend's kernels share (lane
// count of the FFT's layout, reciprocals to about 1 ulp, quantisation to 8 bits). Include after
// <hwy/highway.h> inside a Highway per-target compilation unit (the usual -inl.h toggle).
#if defined(OCEAN_CPU_SIMD_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef OCEAN_CPU_SIMD_MATH_INL_H_
#undef OCEAN_CPU_SIMD_MATH_INL_H_
#else
#define OCEAN_CPU_SIMD_MATH_INL_H_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <cstddef>

#include "sim/packing.hpp"

HWY_BEFORE_NAMESPACE();
namespace ocean::cpu {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

constexpr std::size_t kLanes = 16;

// 1/√x and 1/x for x > 0 to about 1 ulp: the hardware estimate and Newton steps, instead of a
// square root and divisions. Each step doubles the estimate's bits: x86's estimates have 12
// (SSE, AVX2) or 14 (AVX-512) bits and need one step; Arm's (NEON FRSQRTE/FRECPE) have 8 and
// need two — with one, normals were 1.2e-5 off the reference on NEON. The scalar target's
// estimate is coarser still, so it computes them exactly.
#if HWY_ARCH_ARM
constexpr int kNewtonSteps = 2;
#else
constexpr int kNewtonSteps = 1;
#endif
template <class DF, class V>
HWY_INLINE V ReciprocalSqrt(DF df, V x) {
#if HWY_TARGET == HWY_SCALAR
  return hn::Div(hn::Set(df, 1.0f), hn::Sqrt(x));
#else
  auto y = hn::ApproximateReciprocalSqrt(x);
  const auto half_x = hn::Mul(hn::Set(df, 0.5f), x);
  for (int i = 0; i < kNewtonSteps; ++i)
    y = hn::Mul(y, hn::NegMulAdd(half_x, hn::Mul(y, y), hn::Set(df, 1.5f)));
  return y;
#endif
}
template <class DF, class V>
HWY_INLINE V Reciprocal(DF df, V x) {
#if HWY_TARGET == HWY_SCALAR
  return hn::Div(hn::Set(df, 1.0f), x);
#else
  auto y = hn::ApproximateReciprocal(x);
  for (int i = 0; i < kNewtonSteps; ++i) y = hn::Mul(y, hn::NegMulAdd(x, y, hn::Set(df, 2.0f)));
  return y;
#endif
}

// Φ(x), the standard normal distribution function, as packing::normal_cdf computes it
// (Abramowitz & Stegun eq. 7.1.26; |z| capped at packing::kErfcZMax, beyond which erfc is 0 in
// float).
template <class DF, class V>
HWY_INLINE V NormalCdf(DF df, V x) {
  const auto z =
      hn::Min(hn::Mul(hn::Abs(x), hn::Set(df, 0.70710678f)), hn::Set(df, packing::kErfcZMax));
  const auto t = Reciprocal(df, hn::MulAdd(z, hn::Set(df, packing::kErfcP), hn::Set(df, 1.0f)));
  const auto& a = packing::kErfcA;
  auto poly = hn::MulAdd(t, hn::Set(df, a[4]), hn::Set(df, a[3]));
  poly = hn::MulAdd(t, poly, hn::Set(df, a[2]));
  poly = hn::MulAdd(t, poly, hn::Set(df, a[1]));
  poly = hn::Mul(t, hn::MulAdd(t, poly, hn::Set(df, a[0])));
  const auto tail = hn::Mul(hn::Mul(hn::Set(df, 0.5f), poly), hn::Exp(df, hn::Neg(hn::Mul(z, z))));
  return hn::IfThenElse(hn::Lt(x, hn::Zero(df)), tail, hn::Sub(hn::Set(df, 1.0f), tail));
}

// Truncation to int32 of values known to be in [0, 2^31): the bare conversion instruction,
// without the fix-up for out-of-range inputs that hn::ConvertTo adds on x86 (four more
// operations per vector).
template <class DF, class V>
HWY_INLINE auto TruncateInRange(DF df, V v) {
  const hn::RebindToSigned<DF> di;
  (void)df;
#if HWY_TARGET <= HWY_AVX3 && HWY_ARCH_X86
  if constexpr (hn::MaxLanes(df) == 16) return decltype(hn::Zero(di)){_mm512_cvttps_epi32(v.raw)};
#endif
#if HWY_TARGET <= HWY_AVX2 && HWY_ARCH_X86
  if constexpr (hn::MaxLanes(df) == 8) return decltype(hn::Zero(di)){_mm256_cvttps_epi32(v.raw)};
#endif
#if HWY_TARGET <= HWY_SSSE3 && HWY_ARCH_X86
  if constexpr (hn::MaxLanes(df) == 4) return decltype(hn::Zero(di)){_mm_cvttps_epi32(v.raw)};
#endif
  return hn::ConvertTo(di, v);
}

// Quantises to 8 bits as ⌊saturate(v)·255 + 0.5⌋ (eq. 50) values in [0, 1] up to rounding (n/2 +
// 1/2 of a unit vector's component, foam, clamped J, a mean of such values, a smoothness):
// without the clamp, since truncation towards zero maps v·255 + 0.5 to the clamped value's byte
// for every v in (−1/510, 1 + 1/510).
template <class DF, class V>
HWY_INLINE auto QuantiseUnit(DF df, V v) {
  return TruncateInRange(df, hn::MulAdd(v, hn::Set(df, 255.0f), hn::Set(df, 0.5f)));
}

}  // namespace HWY_NAMESPACE
}  // namespace ocean::cpu
HWY_AFTER_NAMESPACE();

#endif
