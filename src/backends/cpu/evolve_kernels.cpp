// SIMD evolution of the CPU backend's fused column pass: the packed spectrum evolved with a
// vectorised sin/cos of the exact looping phase, every plane's factor applied, written where the
// column FFT reads it. Compiled once per instruction set by Highway.
//
// This work is based on:
//   - Aebi, VR Ocean, eqs. 24–30 (single-FMA evolution of the packed spectrum); Tessendorf (2001)
//     eqs. 43–44.
//   - The sine and cosine are Taylor polynomials on [−π/4, π/4] after reduction to quarter
//     turns (Cody & Waite 1980, Software Manual for the Elementary Functions, ch. 8):
//     truncation error below 2.5e-8, under float rounding.
// Equations: docs/math.md (M.6.5), (M.7.2), (M.7.3).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "cpu/evolve_kernels.cpp"
#include <hwy/cache_control.h>
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>
#include <complex>

#include "cpu/kernels.hpp"
#include "cpu/simd_math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ocean::cpu {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// sin and cos of 2π·f: quarter turn q = round(4f), x = 2π(f − q/4) ∈ [−π/4, π/4].
template <class DF, class V>
HWY_INLINE void SinCosTurns(DF df, V f, V& s, V& c) {
  const hn::RebindToSigned<DF> di;
  const auto one_i = hn::Set(di, 1), two_i = hn::Set(di, 2);
  const auto q = hn::NearestInt(hn::Mul(f, hn::Set(df, 4.0f)));
  const auto x = hn::Mul(hn::NegMulAdd(hn::ConvertTo(df, q), hn::Set(df, 0.25f), f),
                         hn::Set(df, 6.283185307179586f));
  const auto x2 = hn::Mul(x, x);
  auto ps = hn::MulAdd(x2, hn::Set(df, 1.0f / 362880.0f), hn::Set(df, -1.0f / 5040.0f));
  ps = hn::MulAdd(x2, ps, hn::Set(df, 1.0f / 120.0f));
  ps = hn::MulAdd(x2, ps, hn::Set(df, -1.0f / 6.0f));
  const auto sx = hn::MulAdd(hn::Mul(x2, ps), x, x);
  auto pc = hn::MulAdd(x2, hn::Set(df, 1.0f / 40320.0f), hn::Set(df, -1.0f / 720.0f));
  pc = hn::MulAdd(x2, pc, hn::Set(df, 1.0f / 24.0f));
  pc = hn::MulAdd(x2, pc, hn::Set(df, -0.5f));
  const auto cx = hn::MulAdd(x2, pc, hn::Set(df, 1.0f));
  // Quadrant: odd q swaps sin and cos; sin flips for q & 2, cos for (q + 1) & 2.
  const auto swap = hn::RebindMask(df, hn::Eq(hn::And(q, one_i), one_i));
  const auto sin_flip = hn::BitCast(df, hn::ShiftLeft<30>(hn::And(q, two_i)));
  const auto cos_flip = hn::BitCast(df, hn::ShiftLeft<30>(hn::And(hn::Add(q, one_i), two_i)));
  s = hn::Xor(hn::IfThenElse(swap, cx, sx), sin_flip);
  c = hn::Xor(hn::IfThenElse(swap, sx, cx), cos_flip);
}

// Every plane's spectrum factor(k)·h̃ at lane-layout index j (M.7.2), for wave vectors (kx, kz).
template <class DF, class V>
HWY_INLINE void StorePlanes(DF df, const EvolveArgs& a, V hr, V hi, V kx, V kz, std::size_t j,
                            float* const* out_re, float* const* out_im) {
  const auto lambda = static_cast<float>(a.lambda);
  const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f), neg_lambda = hn::Set(df, -lambda);
  // k̂ = k/|k| (0 at k = 0).
  const auto k2 = hn::MulAdd(kx, kx, hn::Mul(kz, kz));
  const auto has_k = hn::Gt(k2, zero);
  const auto inv_k = hn::IfThenElseZero(has_k, ReciprocalSqrt(df, hn::IfThenElse(has_k, k2, one)));
  const auto ux = hn::Mul(kx, inv_k), uz = hn::Mul(kz, inv_k);
  // Plane 0: (1 − λ·k̂x)·h̃ = h + i·Dx. Plane 1: i·λ·k̂z·h̃ = Dz (+ i·∂h/∂x: −kx·h̃).
  const auto f0 = hn::MulAdd(neg_lambda, ux, one);
  hn::Store(hn::Mul(f0, hr), df, out_re[0] + j);
  hn::Store(hn::Mul(f0, hi), df, out_im[0] + j);
  const auto dz = hn::Mul(hn::Set(df, lambda), uz);
  if (a.planes == 2) {
    if (a.dz_into_imaginary) {  // += i·(i·λ·k̂z·h̃) = −λ·k̂z·h̃
      hn::Store(hn::NegMulAdd(dz, hr, hn::Load(df, out_re[1] + j)), df, out_re[1] + j);
      hn::Store(hn::NegMulAdd(dz, hi, hn::Load(df, out_im[1] + j)), df, out_im[1] + j);
    } else {
      hn::Store(hn::Neg(hn::Mul(dz, hi)), df, out_re[1] + j);
      hn::Store(hn::Mul(dz, hr), df, out_im[1] + j);
    }
    return;
  }
  const auto neg_kx = hn::Neg(kx);
  hn::Store(hn::MulSub(neg_kx, hr, hn::Mul(dz, hi)), df, out_re[1] + j);
  hn::Store(hn::MulAdd(neg_kx, hi, hn::Mul(dz, hr)), df, out_im[1] + j);
  // Plane 2: i·(kz − λ·kx·k̂x)·h̃ = ∂h/∂z + i·∂Dx/∂x.
  const auto g = hn::MulAdd(hn::Mul(neg_lambda, kx), ux, kz);
  hn::Store(hn::Neg(hn::Mul(g, hi)), df, out_re[2] + j);
  hn::Store(hn::Mul(g, hr), df, out_im[2] + j);
  // Plane 3: −λ·kz·(k̂z + i·k̂x)·h̃ = ∂Dz/∂z + i·∂Dx/∂z.
  const auto lz = hn::Mul(neg_lambda, kz);
  const auto ar = hn::Mul(lz, uz), ai = hn::Mul(lz, ux);
  hn::Store(hn::MulSub(ar, hr, hn::Mul(ai, hi)), df, out_re[3] + j);
  hn::Store(hn::MulAdd(ar, hi, hn::Mul(ai, hr)), df, out_im[3] + j);
}

// kx of a block's 16 columns (the same on every row).
HWY_INLINE void BlockKx(const EvolveArgs& a, int block, float* kx) {
  const auto dk = static_cast<float>(a.dk);
  for (std::size_t l = 0; l < kLanes; ++l)
    kx[l] =
        dk * static_cast<float>(block * static_cast<int>(kLanes) + static_cast<int>(l) - a.n / 2);
}

// h̃(k, t) for lanes [l, l + vector) of `row` in `block` (M.6.5, M.7.3).
template <class DF, class V>
HWY_INLINE void EvolveVector(DF df, const EvolveArgs& a, int block, std::size_t row, std::size_t l,
                             V& hr, V& hi) {
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> dfh;  // half as many floats as doubles fit
  const auto n = static_cast<std::size_t>(a.n);
  const std::size_t r = static_cast<std::size_t>(block) * n + row;
  const float* record = a.spectrum + r * a.record;
  // Phase in turns, frac(rate·clock), in double: exact for the looping harmonics (M.7.3).
  const auto turns = [&](std::size_t lane) {
    const auto rate = a.rate == nullptr
                          ? hn::PromoteTo(dd, hn::LoadU(dfh, record + 4 * kLanes + lane))
                          : hn::LoadU(dd, a.rate + r * kLanes + lane);
    const auto v = hn::Mul(rate, hn::Set(dd, a.clock));
    return hn::DemoteTo(dfh, hn::Sub(v, hn::Floor(v)));
  };
#if HWY_TARGET == HWY_SCALAR
  const auto f = turns(l);
#else
  const auto f = hn::Combine(df, turns(l + hn::Lanes(dd)), turns(l));  // in registers: no store
#endif
  V s, c;
  SinCosTurns(df, f, s, c);
  // One FMA per component from the packed spectrum (M.6.5).
  const auto p0 = hn::Load(df, record + l), p1 = hn::Load(df, record + kLanes + l);
  const auto p2 = hn::Load(df, record + 2 * kLanes + l);
  const auto p3 = hn::Load(df, record + 3 * kLanes + l);
  hr = hn::MulAdd(p0, c, hn::Mul(p2, s));
  hi = hn::MulAdd(p1, c, hn::Mul(p3, s));
}

void EvolvePlanes(const EvolveArgs& a, int block, float* const* out_re, float* const* out_im) {
  const hn::ScalableTag<float> df;
  const std::size_t nf = hn::Lanes(df);
  const auto n = static_cast<std::size_t>(a.n);
  const auto dk = static_cast<float>(a.dk);
  alignas(64) float kx_lanes[kLanes];
  BlockKx(a, block, kx_lanes);
  for (std::size_t row = 0; row < n; ++row) {
    const auto kz = hn::Set(df, dk * static_cast<float>(static_cast<int>(row) - a.n / 2));
    for (std::size_t l = 0; l < kLanes; l += nf) {
      decltype(hn::Zero(df)) hr, hi;
      EvolveVector(df, a, block, row, l, hr, hi);
      StorePlanes(df, a, hr, hi, hn::Load(df, kx_lanes + l), kz, row * kLanes + l, out_re, out_im);
    }
  }
}

void EvolvePlanesMirrored(const EvolveArgs& a, int block, float* const* out_re,
                          float* const* out_im, float* const* mirror_re, float* const* mirror_im) {
  const hn::ScalableTag<float> df;
  using V = decltype(hn::Zero(df));
  const std::size_t nf = hn::Lanes(df);
  const auto n = static_cast<std::size_t>(a.n);
  const auto dk = static_cast<float>(a.dk);
  const int mirror = a.n / static_cast<int>(kLanes) - 1 - block;
  constexpr bool kOneVector = hn::MaxLanes(decltype(df)()) == kLanes;  // AVX-512
  alignas(64) float kx_lanes[kLanes], kx_mirror[kLanes];
  BlockKx(a, block, kx_lanes);
  BlockKx(a, mirror, kx_mirror);
  // Rows outside [row_lo, row_hi) carry no spectrum (band-limited cascades): zeros, not evolved,
  // and only where the transform reads them ([fill_lo, fill_hi): the inner half when pruned).
  const auto row_lo = static_cast<std::size_t>(a.rows == nullptr ? 0 : a.rows[2 * block]);
  const auto row_hi = static_cast<std::size_t>(a.rows == nullptr ? a.n : a.rows[2 * block + 1]);
  for (int p = 0; p < a.planes; ++p) {
    if (p == 1 && a.dz_into_imaginary) continue;  // the pair's first cascade wrote the zeros
    const bool pruned = ((a.pruned_planes >> p) & 1u) != 0;
    const std::size_t fill_lo = pruned ? n / 4 : 0, fill_hi = pruned ? 3 * n / 4 : n;
    const std::size_t zero_to = row_lo == row_hi ? fill_hi : std::max(fill_lo, row_lo);
    const std::size_t zero_from = row_lo == row_hi ? fill_hi : std::min(fill_hi, row_hi);
    for (float* plane : {out_re[p], out_im[p], mirror_re[p], mirror_im[p]}) {
      std::fill(plane + fill_lo * kLanes, plane + zero_to * kLanes, 0.0f);
      std::fill(plane + zero_from * kLanes, plane + fill_hi * kLanes, 0.0f);
    }
  }
  // The mirror block's lane 0 (column 16·mirror) mirrors another block pair's column: evolved
  // here directly, nf rows at a time (the phase recipe of EvolveVector, one lane per row).
  alignas(64) float lane0_re[2048], lane0_im[2048];
  for (std::size_t row0 = row_lo / nf * nf; row0 < row_hi; row0 += nf) {
    alignas(64) float f[kLanes] = {}, p[4][kLanes] = {};
    for (std::size_t i = 0; i < nf && row0 + i < n; ++i) {
      const std::size_t r = static_cast<std::size_t>(mirror) * n + row0 + i;
      const float* record = a.lane0 + r * kLane0Record;
      const double rate = a.rate == nullptr ? double(record[4]) : a.lane0_rate[r];
      const double v = rate * a.clock;
      f[i] = static_cast<float>(v - std::floor(v));
      for (std::size_t k = 0; k < 4; ++k) p[k][i] = record[k];
    }
    V s, c;
    SinCosTurns(df, hn::Load(df, f), s, c);
    hn::Store(hn::MulAdd(hn::Load(df, p[0]), c, hn::Mul(hn::Load(df, p[2]), s)), df,
              lane0_re + row0);
    hn::Store(hn::MulAdd(hn::Load(df, p[1]), c, hn::Mul(hn::Load(df, p[3]), s)), df,
              lane0_im + row0);
  }
  // The records of the row 8 ahead (and its rates when not looping) are fetched now: the
  // records stream from beyond the core's caches (4 × 512²: −5 % per frame).
  constexpr std::size_t kAhead = 8;
  const std::size_t first_record = static_cast<std::size_t>(block) * n;
  for (std::size_t row = row_lo; row < row_hi; ++row) {
    if (row + kAhead < row_hi) {
      const std::size_t r = first_record + row + kAhead;
      for (std::size_t k = 0; k < a.record; k += kLanes)
        hwy::Prefetch(a.spectrum + r * a.record + k);
      if (a.rate != nullptr) {
        hwy::Prefetch(a.rate + r * kLanes);
        hwy::Prefetch(a.rate + r * kLanes + kLanes / 2);
      }
    }
    const auto kz = hn::Set(df, dk * static_cast<float>(static_cast<int>(row) - a.n / 2));
    alignas(64) float h_re[kLanes], h_im[kLanes];
    V hr16, hi16;
    for (std::size_t l = 0; l < kLanes; l += nf) {
      V hr, hi;
      EvolveVector(df, a, block, row, l, hr, hi);
      StorePlanes(df, a, hr, hi, hn::Load(df, kx_lanes + l), kz, row * kLanes + l, out_re, out_im);
      if constexpr (kOneVector) {
        hr16 = hr, hi16 = hi;
      } else {
        hn::Store(hr, df, h_re + l);
        hn::Store(hi, df, h_im + l);
      }
    }
    // h̃(−k) = conj h̃(k) (the packed spectrum of −k is S'(k) with components 1 and 3
    // negated: exact). Column 16·block + l mirrors to lane (16 − l) mod 16 of the mirror
    // block, row r to (N − r) mod N.
    const std::size_t mrow = (n - row) & (n - 1);
    const auto kz_m = hn::Set(df, dk * static_cast<float>(static_cast<int>(mrow) - a.n / 2));
    if constexpr (kOneVector) {  // a lane permutation in registers
      (void)h_re, (void)h_im;
      alignas(64) static constexpr std::int32_t kMirror[16] = {0, 15, 14, 13, 12, 11, 10, 9,
                                                               8, 7,  6,  5,  4,  3,  2,  1};
      const auto idx = hn::SetTableIndices(df, kMirror);
      const auto first = hn::FirstN(df, 1);
      const V mr =
          hn::IfThenElse(first, hn::Set(df, lane0_re[mrow]), hn::TableLookupLanes(hr16, idx));
      const V mi = hn::IfThenElse(first, hn::Set(df, lane0_im[mrow]),
                                  hn::Neg(hn::TableLookupLanes(hi16, idx)));
      StorePlanes(df, a, mr, mi, hn::Load(df, kx_mirror), kz_m, mrow * kLanes, mirror_re,
                  mirror_im);
    } else {
      (void)hr16, (void)hi16;
      alignas(64) float m_re[kLanes], m_im[kLanes];
      m_re[0] = lane0_re[mrow], m_im[0] = lane0_im[mrow];
      for (std::size_t m = 1; m < kLanes; ++m)
        m_re[m] = h_re[kLanes - m], m_im[m] = -h_im[kLanes - m];
      for (std::size_t l = 0; l < kLanes; l += nf) {
        StorePlanes(df, a, hn::Load(df, m_re + l), hn::Load(df, m_im + l),
                    hn::Load(df, kx_mirror + l), kz_m, mrow * kLanes + l, mirror_re, mirror_im);
      }
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ocean::cpu
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ocean::cpu {

HWY_EXPORT(EvolvePlanes);
HWY_EXPORT(EvolvePlanesMirrored);

void evolve_planes(const EvolveArgs& args, int block, float* const* re, float* const* im) {
  HWY_DYNAMIC_DISPATCH(EvolvePlanes)(args, block, re, im);
}

void evolve_planes_mirrored(const EvolveArgs& args, int block, float* const* re, float* const* im,
                            float* const* mirror_re, float* const* mirror_im) {
  HWY_DYNAMIC_DISPATCH(EvolvePlanesMirrored)(args, block, re, im, mirror_re, mirror_im);
}

void evolve_texel_reference(const EvolveArgs& a, int row, int col, float* re, float* im) {
  constexpr std::size_t kLanes = 16;
  const auto n = static_cast<std::size_t>(a.n);
  const auto block = static_cast<std::size_t>(col) / kLanes,
             l = static_cast<std::size_t>(col) % kLanes;
  const std::size_t r = block * n + static_cast<std::size_t>(row);
  const float* record = a.spectrum + r * a.record;
  // Same recipe as EvolutionPhase (M.7.3) on the same rate/clock inputs.
  const double rate = a.rate == nullptr ? record[4 * kLanes + l] : a.rate[r * kLanes + l];
  const double turns = rate * a.clock;
  const double phase = 2.0 * 3.14159265358979323846 * (turns - std::floor(turns));
  const double c = std::cos(phase), s = std::sin(phase);
  const std::complex<double> h(record[l] * c + record[2 * kLanes + l] * s,
                               record[kLanes + l] * c + record[3 * kLanes + l] * s);
  const double kx = a.dk * (col - a.n / 2);
  const double kz = a.dk * (row - a.n / 2);
  std::complex<double> f[4];
  plane_factors(kx, kz, a.lambda, a.planes, f);
  for (int p = 0; p < a.planes; ++p) {
    const std::complex<double> v = f[p] * h;
    re[p] = static_cast<float>(v.real());
    im[p] = static_cast<float>(v.imag());
  }
}

}  // namespace ocean::cpu
#endif
