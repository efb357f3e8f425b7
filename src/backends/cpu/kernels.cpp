// SIMD kernels of the CPU backend: evolution of the packed spectrum with a vectorised sin/cos
// of the exact looping phase, and the displacement assembly with the (−1)^(x+y) shift and the
// half-float conversion. Compiled once per instruction set by Highway.
//
// This work is based on:
//   - Seed 000 eqs. 24–30 (single-FMA evolution of the packed spectrum), eq. 43 (sign
//     correction), eq. 44 (displacement assembly); Tessendorf (2001) eqs. 43–44.
//   - The sine and cosine are Taylor polynomials on [−π/4, π/4] after reduction to quarter
//     turns (Cody & Waite 1980, Software Manual for the Elementary Functions, ch. 8):
//     truncation error below 2.5e-8, under float rounding.
// Equations: docs/math.md (M.6.5), (M.7.2), (M.7.3).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "cpu/kernels.cpp"
#include "cpu/kernels.hpp"

#include <hwy/cache_control.h>
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>

#include "cpu/cpu_backend.hpp"
#include "fft/transpose-inl.h"
#include "ocean/half.hpp"
#include "ocean/sim.hpp"

HWY_BEFORE_NAMESPACE();
namespace ocean::cpu {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

constexpr std::size_t kLanes = 16;

// 1/√x and 1/x for x > 0 to about 1 ulp: the hardware estimate (12–14 bits) and one Newton
// step, instead of a square root and divisions. The scalar target's estimate is coarser, so it
// computes them exactly.
template <class DF, class V>
HWY_INLINE V ReciprocalSqrt(DF df, V x) {
#if HWY_TARGET == HWY_SCALAR
  return hn::Div(hn::Set(df, 1.0f), hn::Sqrt(x));
#else
  const auto y = hn::ApproximateReciprocalSqrt(x);
  return hn::Mul(y, hn::NegMulAdd(hn::Mul(hn::Set(df, 0.5f), x), hn::Mul(y, y), hn::Set(df, 1.5f)));
#endif
}
template <class DF, class V>
HWY_INLINE V Reciprocal(DF df, V x) {
#if HWY_TARGET == HWY_SCALAR
  return hn::Div(hn::Set(df, 1.0f), x);
#else
  const auto y = hn::ApproximateReciprocal(x);
  return hn::Mul(y, hn::NegMulAdd(x, y, hn::Set(df, 2.0f)));
#endif
}

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

#if HWY_TARGET <= HWY_AVX3 && HWY_ARCH_X86
// AVX-512: the float3 rows come straight out of the transposes. Taking a tile's 48 column
// vectors in interleaved order (Dx, h, Dz of column 0, of column 1, ...), vectors 16t … 16t + 15
// transposed give floats 16t … 16t + 15 of every row's 48 interleaved floats, so neither an
// interleaving store nor a round trip through a row-major tile is needed; the half4 texels
// are the rows converted and spread by one 16-bit permutation per 8 texels (zeros in w).
void AssembleDisplacementAvx3(const float* h, const float* dx, const float* dz, std::size_t n,
                              std::size_t row0, float* displacement,
                              std::uint16_t* displacement_half, AssemblyStores stores) {
  const hn::ScalableTag<float> df;
  using V = decltype(hn::Zero(df));
  static_assert(hn::MaxLanes(decltype(df)()) == kLanes);
  // (−1)^(x+y) (eq. 43): tiles start at even rows and columns, so column j of a tile has the
  // lane pattern (−1)^(l + j).
  alignas(64) float sign[2][kLanes];
  for (std::size_t l = 0; l < kLanes; ++l) {
    sign[0][l] = (l & 1u) != 0 ? -1.0f : 1.0f;
    sign[1][l] = -sign[0][l];
  }
  const V even = hn::Load(df, sign[0]), odd = hn::Load(df, sign[1]);
  // Half lane 4t + k of the 8 texels t takes half 3t + k of the 16 + 16 converted floats they
  // start in; lanes 4t + 3 are zero.
  alignas(64) static constexpr std::int16_t kSpread[2][32] = {
      {0,  1,  2,  0, 3,  4,  5,  0, 6,  7,  8,  0, 9,  10, 11, 0,
       12, 13, 14, 0, 15, 16, 17, 0, 18, 19, 20, 0, 21, 22, 23, 0},
      {8,  9,  10, 0, 11, 12, 13, 0, 14, 15, 16, 0, 17, 18, 19, 0,
       20, 21, 22, 0, 23, 24, 25, 0, 26, 27, 28, 0, 29, 30, 31, 0}};
  const __m512i spread0 = _mm512_load_si512(kSpread[0]), spread1 = _mm512_load_si512(kSpread[1]);
  constexpr __mmask32 kXyz = 0x77777777u;
  const float* src[3] = {dx, h, dz};
  // Every row segment below starts on a cache line when the maps do (N is a multiple of 16).
  const auto aligned = [](const void* p) { return reinterpret_cast<std::uintptr_t>(p) % 64 == 0; };
  const bool stream_float = stores.stream_displacement && aligned(displacement);
  const bool stream_half = stores.stream_half && aligned(displacement_half);
  for (std::size_t c0 = 0; c0 < n; c0 += kLanes) {
    V rows[3][kLanes];  // [t][l]: floats 16t … 16t + 15 of row l's interleaved 48
    for (std::size_t t = 0; t < 3; ++t) {
      V v[kLanes];
      for (std::size_t i = 0; i < kLanes; ++i) {
        const std::size_t m = 16 * t + i, j = m / 3;
        v[i] = hn::Mul(hn::Load(df, src[m % 3] + (c0 + j) * kLanes), (j & 1u) != 0 ? odd : even);
      }
      fft::detail::HWY_NAMESPACE::TransposeVectors(df, v);
      for (std::size_t l = 0; l < kLanes; ++l) rows[t][l] = v[l];
    }
    for (std::size_t l = 0; l < kLanes; ++l) {
      const std::size_t i = (row0 + l) * n + c0;
      float* out = displacement + 3 * i;
      for (std::size_t t = 0; t < 3; ++t) {
        if (stream_float) {
          _mm512_stream_ps(out + 16 * t, rows[t][l].raw);
        } else {
          hn::StoreU(rows[t][l], df, out + 16 * t);
        }
      }
      const __m256i h0 = _mm512_cvtps_ph(rows[0][l].raw, _MM_FROUND_NO_EXC);
      const __m256i h1 = _mm512_cvtps_ph(rows[1][l].raw, _MM_FROUND_NO_EXC);
      const __m256i h2 = _mm512_cvtps_ph(rows[2][l].raw, _MM_FROUND_NO_EXC);
      const __m512i lo = _mm512_inserti64x4(_mm512_castsi256_si512(h0), h1, 1);
      const __m512i hi = _mm512_inserti64x4(_mm512_castsi256_si512(h1), h2, 1);
      const __m512i half_lo = _mm512_maskz_permutexvar_epi16(kXyz, spread0, lo);
      const __m512i half_hi = _mm512_maskz_permutexvar_epi16(kXyz, spread1, hi);
      std::uint16_t* half = displacement_half + 4 * i;
      if (stream_half) {
        _mm512_stream_si512(reinterpret_cast<__m512i*>(half), half_lo);
        _mm512_stream_si512(reinterpret_cast<__m512i*>(half + 32), half_hi);
      } else {
        _mm512_storeu_si512(half, half_lo);
        _mm512_storeu_si512(half + 32, half_hi);
      }
    }
  }
  // Streaming stores are weakly ordered: make them visible before the caller signals that the
  // rows are done (another thread's surface pass reads them).
  if (stream_float || stream_half) _mm_sfence();
}
#endif

void AssembleDisplacement(const float* h, const float* dx, const float* dz, int n_int, int block,
                          float* displacement, std::uint16_t* displacement_half,
                          AssemblyStores stores) {
  const hn::ScalableTag<float> df;
  const std::size_t step = hn::Lanes(df);
  const auto n = static_cast<std::size_t>(n_int);
  const std::size_t row0 = static_cast<std::size_t>(block) * kLanes;
#if HWY_TARGET <= HWY_AVX3 && HWY_ARCH_X86
  if constexpr (hn::MaxLanes(decltype(df)()) == kLanes) {
    (void)step;
    AssembleDisplacementAvx3(h, dx, dz, n, row0, displacement, displacement_half, stores);
    return;
  }
#endif
  (void)stores;  // ordinary stores on the other targets
  // Tile by tile: lane layout → row-major 16×16 with (−1)^(x+y) (eq. 43; tiles start at even
  // rows and columns), then the rows interleaved into float3 and half4.
  alignas(64) float tile[3][kLanes * kLanes];
  for (std::size_t c0 = 0; c0 < n; c0 += kLanes) {
    const float* src[3] = {dx, h, dz};
    for (std::size_t k = 0; k < 3; ++k)
      fft::detail::HWY_NAMESPACE::Transpose16Tile(src[k] + c0 * kLanes, kLanes, tile[k], kLanes, 0);
    for (std::size_t l = 0; l < kLanes; ++l) {
      const std::size_t row = row0 + l;
      float* out = displacement + 3 * (row * n + c0);
      std::uint16_t* half = displacement_half + 4 * (row * n + c0);
      for (std::size_t c = 0; c < kLanes; c += step) {
        const auto vx = hn::Load(df, tile[0] + l * kLanes + c);
        const auto vh = hn::Load(df, tile[1] + l * kLanes + c);
        const auto vz = hn::Load(df, tile[2] + l * kLanes + c);
        hn::StoreInterleaved3(vx, vh, vz, df, out + 3 * c);
#if HWY_TARGET >= HWY_SSE4 || defined(HWY_DISABLE_F16C)
        // No F16C: Highway's emulated conversion truncates; keep round-to-nearest-even.
        for (std::size_t i = c; i < c + step; ++i) {
          for (std::size_t k = 0; k < 3; ++k) half[4 * i + k] = float_to_half(out[3 * i + k]);
          half[4 * i + 3] = 0;
        }
#else
        const hn::Rebind<hwy::float16_t, decltype(df)> dh;
        const hn::Rebind<std::uint16_t, decltype(df)> du;
        hn::StoreInterleaved4(
            hn::BitCast(du, hn::DemoteTo(dh, vx)), hn::BitCast(du, hn::DemoteTo(dh, vh)),
            hn::BitCast(du, hn::DemoteTo(dh, vz)), hn::Zero(du), du, half + 4 * c);
#endif
      }
    }
  }
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

// A displacement row deinterleaved (eq. 46): component k of texel c at row[k][kPad + c], with
// the wrapped neighbours at kPad − 1 and kPad + N.
constexpr std::size_t kPad = 16;
using PlanarRow = float[3][2048 + 2 * kPad];

HWY_INLINE void Planarize(const SurfaceArgs& a, int row_int, PlanarRow& out) {
  const hn::ScalableTag<float> df;
  const std::size_t step = hn::Lanes(df);
  const auto n = static_cast<std::size_t>(a.n);
  const float* src = a.displacement + 3 * n * static_cast<std::size_t>(row_int & (a.n - 1));
  for (std::size_t c = 0; c < n; c += step) {
    decltype(hn::Zero(df)) v0, v1, v2;
    hn::LoadInterleaved3(df, src + 3 * c, v0, v1, v2);
    hn::Store(v0, df, out[0] + kPad + c);
    hn::Store(v1, df, out[1] + kPad + c);
    hn::Store(v2, df, out[2] + kPad + c);
  }
  for (std::size_t k = 0; k < 3; ++k) {
    out[k][kPad - 1] = out[k][kPad + n - 1];
    out[k][kPad + n] = out[k][kPad];
  }
}

// One row of the surface pass from the deinterleaved rows above, at and below it: every output
// but the mip work values, which go to `work` as structure of arrays (n·len x, y, z, blue) for
// the fused first mip level.
HWY_INLINE void SurfaceRowValues(const SurfaceArgs& a, int row_int, const PlanarRow& up,
                                 const PlanarRow& padded, const PlanarRow& down,
                                 float* const* work) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const std::size_t step = hn::Lanes(df);
  const auto n = static_cast<std::size_t>(a.n);
  const auto row = static_cast<std::size_t>(row_int);
  const auto half_inv = hn::Set(df, 0.5f * a.inv_spacing);
  const auto one = hn::Set(df, 1.0f), zero = hn::Zero(df);
  const auto base_length = hn::Set(df, a.base_length);
  const auto j_start = hn::Set(df, a.jacobian_start);
  const auto inv_range = hn::Set(df, 1.0f / a.jacobian_range);
  // Locals: the stores below could alias `a` as far as the compiler knows.
  const bool reset_foam = a.reset_foam, blue_is_foam = a.blue_is_foam;
  float* const foam_state = a.foam_state;
  float* const jacobian = a.jacobian;
  float* const foam_out = a.foam;
  float* const normal = a.normal;
  auto* const packed = reinterpret_cast<std::int32_t*>(a.packed);
  const auto decay = hn::Set(df, a.decay);
  const auto alpha =
      hn::ShiftLeft<24>(QuantiseUnit(df, hn::Set(df, a.smoothness)));  // constant smoothness
  // The displacement row deinterleaved after this one (row + 2) and the foam state of the next
  // row (row + 1) are fetched while this row computes: the row pass wrote that displacement
  // more than a megabyte ago, so it comes from beyond the core's L2 (4 × 512²: −8–10 % per
  // frame).
  const float* next_displacement = a.displacement + 3 * n * ((row + 2) & (n - 1));
  const float* next_foam = foam_state + ((row + 1) & (n - 1)) * n;
  for (std::size_t c = 0; c < n; c += step) {
    if (c % kLanes == 0) {  // one cache line of foam and three of displacement per 16 texels
      hwy::Prefetch(next_displacement + 3 * c);
      hwy::Prefetch(next_displacement + 3 * c + kLanes);
      hwy::Prefetch(next_displacement + 3 * c + 2 * kLanes);
      hwy::Prefetch(next_foam + c);
    }
    // ∂/∂x from the padded centre row, ∂/∂z from the rows above and below (eq. 45).
    // (a − b)·(½·N/L): the reference's (a − b)·½·N/L bit for bit (halving is exact).
    const auto gx = [&](std::size_t k) {
      return hn::Mul(
          hn::Sub(hn::LoadU(df, padded[k] + kPad + c + 1), hn::LoadU(df, padded[k] + kPad + c - 1)),
          half_inv);
    };
    const auto gz = [&](std::size_t k) {
      return hn::Mul(hn::Sub(hn::Load(df, down[k] + kPad + c), hn::Load(df, up[k] + kPad + c)),
                     half_inv);
    };
    const auto dx_dx = gx(0), h_dx = gx(1), dz_dx = gx(2);
    const auto dx_dz = gz(0), h_dz = gz(1), dz_dz = gz(2);
    // Jacobian (eq. 48) and the normal of the displaced surface (M.7.5).
    const auto jxx = hn::Add(one, dx_dx), jzz = hn::Add(one, dz_dz);
    const auto jac = hn::Sub(hn::Mul(jxx, jzz), hn::Mul(dx_dz, dz_dx));
    auto nx = hn::Sub(hn::Mul(h_dz, dz_dx), hn::Mul(jzz, h_dx));
    auto ny = jac;
    auto nz = hn::Sub(hn::Mul(dx_dz, h_dx), hn::Mul(h_dz, jxx));
    const auto length2 = hn::MulAdd(nx, nx, hn::MulAdd(ny, ny, hn::Mul(nz, nz)));
    const auto valid = hn::Gt(length2, zero);
    const auto inv_length =
        hn::IfThenElseZero(valid, ReciprocalSqrt(df, hn::IfThenElse(valid, length2, one)));
    nx = hn::Mul(nx, inv_length);
    ny = hn::IfThenElse(valid, hn::Mul(ny, inv_length), one);
    nz = hn::Mul(nz, inv_length);
    // Foam ramp and accumulation (M.7.4).
    const std::size_t i = row * n + c;
    const auto now = hn::Min(hn::Max(hn::Mul(hn::Sub(j_start, jac), inv_range), zero), one);
    auto foam = now;
    if (!reset_foam) {
      const auto accumulated =
          hn::Sub(hn::LoadU(df, foam_state + i),
                  hn::Mul(decay, Reciprocal(df, hn::Max(now, hn::Set(df, 0.5f)))));
      foam = hn::Min(hn::Max(hn::Max(accumulated, now), zero), one);
    }
    hn::StoreU(foam, df, foam_state + i);
    if (jacobian != nullptr) hn::StoreU(jac, df, jacobian + i);
    if (foam_out != nullptr) hn::StoreU(foam, df, foam_out + i);
    if (normal != nullptr) hn::StoreInterleaved3(nx, ny, nz, df, normal + 3 * i);
    const auto blue =
        blue_is_foam
            ? foam
            : hn::Min(hn::Max(hn::MulAdd(jac, hn::Set(df, 0.5f), hn::Set(df, 0.5f)), zero), one);
    hn::Store(hn::Mul(nx, base_length), df, work[0] + c);
    hn::Store(hn::Mul(ny, base_length), df, work[1] + c);
    hn::Store(hn::Mul(nz, base_length), df, work[2] + c);
    hn::Store(blue, df, work[3] + c);
    const auto rgba =
        hn::Or(hn::Or(QuantiseUnit(df, hn::MulAdd(nx, hn::Set(df, 0.5f), hn::Set(df, 0.5f))),
                      hn::ShiftLeft<8>(
                          QuantiseUnit(df, hn::MulAdd(nz, hn::Set(df, 0.5f), hn::Set(df, 0.5f))))),
               hn::Or(hn::ShiftLeft<16>(QuantiseUnit(df, blue)), alpha));
    hn::StoreU(rgba, di, packed + i);
  }
}

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

// 2×2 averages (eq. 52) of two rows of structure-of-arrays values (x, y, z, blue) into `size`
// texels of `sum`, in the order of the mip rows: ((a + b) + c) + d.
HWY_INLINE void Average2x2(const float* const* top, const float* const* bottom, std::size_t size,
                           float (*sum)[1024]) {
  std::size_t c = 0;
#if HWY_TARGET != HWY_SCALAR
  const hn::ScalableTag<float> df;
  const std::size_t step = hn::Lanes(df);
  for (; c + step <= size; c += step) {
    for (std::size_t k = 0; k < 4; ++k) {
      const auto t0 = hn::Load(df, top[k] + 2 * c), t1 = hn::Load(df, top[k] + 2 * c + step);
      const auto b0 = hn::Load(df, bottom[k] + 2 * c), b1 = hn::Load(df, bottom[k] + 2 * c + step);
      const auto upper = hn::Add(hn::ConcatEven(df, t1, t0), hn::ConcatOdd(df, t1, t0));
      const auto all =
          hn::Add(hn::Add(upper, hn::ConcatEven(df, b1, b0)), hn::ConcatOdd(df, b1, b0));
      hn::Store(hn::Mul(all, hn::Set(df, 0.25f)), df, sum[k] + c);
    }
  }
#endif
  for (; c < size; ++c) {
    for (std::size_t k = 0; k < 4; ++k) {
      sum[k][c] =
          0.25f * (((top[k][2 * c] + top[k][2 * c + 1]) + bottom[k][2 * c]) + bottom[k][2 * c + 1]);
    }
  }
}

// Rows 2·pair and 2·pair + 1 of the surface pass from the deinterleaved rows 2·pair − 1 …
// 2·pair + 1 (ring[(row + 1) % 3] holds row `row`; each row done makes way for the row after
// the next, the last one only if `more` rows follow), then row `pair` of mip level 1 from them
// into `level1` (its RGBA8 row is written, its work values stay here): the base level's work
// values never leave the stack.
HWY_INLINE void SurfaceRowPairFrom(const SurfaceArgs& a, int pair, PlanarRow* ring, bool more,
                                   float (*level1)[1024]) {
  const auto n = static_cast<std::size_t>(a.n);
  alignas(64) float rows[2][4][2048];
  for (int r = 0; r < 2; ++r) {
    const int row = 2 * pair + r;
    float* const work[4] = {rows[r][0], rows[r][1], rows[r][2], rows[r][3]};
    SurfaceRowValues(a, row, ring[row % 3], ring[(row + 1) % 3], ring[(row + 2) % 3], work);
    if (r == 0 || more) Planarize(a, row + 2, ring[row % 3]);  // over row − 1
  }
  const float* const top[4] = {rows[0][0], rows[0][1], rows[0][2], rows[0][3]};
  const float* const bottom[4] = {rows[1][0], rows[1][1], rows[1][2], rows[1][3]};
  Average2x2(top, bottom, n / 2, level1);
  MipFromSums(level1, n / 2, nullptr,
              a.packed + mip_offset(a.n, 1) + static_cast<std::size_t>(pair) * (n / 2));
}

// Row quads [first, first + count): rows 4·first … 4·(first + count) − 1, each displacement row
// deinterleaved once, and their rows of mip levels 1 and 2 (level 1's work values stay on the
// stack, so mip_work's levels 0 and 1 are not written).
void SurfaceRowQuads(const SurfaceArgs& a, int first, int count) {
  alignas(64) PlanarRow ring[3];
  const int row0 = 4 * first;
  Planarize(a, row0 - 1, ring[row0 % 3]);
  Planarize(a, row0, ring[(row0 + 1) % 3]);
  Planarize(a, row0 + 1, ring[(row0 + 2) % 3]);
  const auto size = static_cast<std::size_t>(a.n / 4);
  alignas(64) float level1[2][4][1024];
  alignas(64) float level2[4][1024];
  for (int quad = first; quad < first + count; ++quad) {
    SurfaceRowPairFrom(a, 2 * quad, ring, true, level1[0]);
    SurfaceRowPairFrom(a, 2 * quad + 1, ring, quad + 1 < first + count, level1[1]);
    const float* const top[4] = {level1[0][0], level1[0][1], level1[0][2], level1[0][3]};
    const float* const bottom[4] = {level1[1][0], level1[1][1], level1[1][2], level1[1][3]};
    Average2x2(top, bottom, size, level2);
    const std::size_t row = static_cast<std::size_t>(quad) * size;
    MipFromSums(level2, size, a.mip_work + 4 * row, a.packed + mip_offset(a.n, 2) + row);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ocean::cpu
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ocean::cpu {

HWY_EXPORT(EvolvePlanes);
HWY_EXPORT(EvolvePlanesMirrored);
HWY_EXPORT(AssembleDisplacement);
HWY_EXPORT(SurfaceRowQuads);
HWY_EXPORT(MipRow);

void mip_row(int n, int level, int row, float* work, int work_level, std::uint32_t* packed) {
  HWY_DYNAMIC_DISPATCH(MipRow)(n, level, row, work, work_level, packed);
}

void surface_row_quads(const SurfaceArgs& args, int first, int count) {
  HWY_DYNAMIC_DISPATCH(SurfaceRowQuads)(args, first, count);
}

void evolve_planes(const EvolveArgs& args, int block, float* const* re, float* const* im) {
  HWY_DYNAMIC_DISPATCH(EvolvePlanes)(args, block, re, im);
}

void evolve_planes_mirrored(const EvolveArgs& args, int block, float* const* re, float* const* im,
                            float* const* mirror_re, float* const* mirror_im) {
  HWY_DYNAMIC_DISPATCH(EvolvePlanesMirrored)(args, block, re, im, mirror_re, mirror_im);
}

void assemble_displacement(const float* h, const float* dx, const float* dz, int n, int block,
                           float* displacement, std::uint16_t* displacement_half,
                           AssemblyStores stores) {
  HWY_DYNAMIC_DISPATCH(AssembleDisplacement)
  (h, dx, dz, n, block, displacement, displacement_half, stores);
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
