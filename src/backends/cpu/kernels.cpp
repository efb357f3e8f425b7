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

#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>

#include "ocean/half.hpp"

HWY_BEFORE_NAMESPACE();
namespace ocean::cpu {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

constexpr std::size_t kLanes = 16;

void EvolveLanes(const EvolveArgs& a, int block, float* h_re, float* h_im) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const hn::ScalableTag<double> dd;
  const hn::Rebind<float, decltype(dd)> dfh;  // half as many floats as doubles fit
  const std::size_t nf = hn::Lanes(df), nd = hn::Lanes(dd);
  const auto one_i = hn::Set(di, 1), two_i = hn::Set(di, 2);
  const auto clock = hn::Set(dd, a.clock);
  const auto n = static_cast<std::size_t>(a.n);
  for (std::size_t row = 0; row < n; ++row) {
    const std::size_t base = row * n + static_cast<std::size_t>(block) * kLanes;
    // Phase in turns, frac(rate·clock), in double: exact for the looping harmonics (M.7.3).
    alignas(64) float turns[kLanes];
    for (std::size_t l = 0; l < kLanes; l += nd) {
      auto v = hn::Mul(hn::LoadU(dd, a.rate + base + l), clock);
      v = hn::Sub(v, hn::Floor(v));
      hn::StoreU(hn::DemoteTo(dfh, v), dfh, turns + l);
    }
    for (std::size_t l = 0; l < kLanes; l += nf) {
      // sin/cos of 2π·f: quarter turn q = round(4f), x = 2π(f − q/4) ∈ [−π/4, π/4].
      const auto f = hn::Load(df, turns + l);
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
      const auto s = hn::Xor(hn::IfThenElse(swap, cx, sx), sin_flip);
      const auto c = hn::Xor(hn::IfThenElse(swap, sx, cx), cos_flip);
      // h̃(k, t) from the packed spectrum with one FMA per component (M.6.5).
      const std::size_t i = base + l;
      const auto hr =
          hn::MulAdd(hn::LoadU(df, a.packed[0] + i), c, hn::Mul(hn::LoadU(df, a.packed[2] + i), s));
      const auto hi =
          hn::MulAdd(hn::LoadU(df, a.packed[1] + i), c, hn::Mul(hn::LoadU(df, a.packed[3] + i), s));
      hn::StoreU(hr, df, h_re + row * kLanes + l);
      hn::StoreU(hi, df, h_im + row * kLanes + l);
    }
  }
}

void ApplyFactor(const EvolveArgs& a, int plane, int block, const float* h_re, const float* h_im,
                 float* lane_re, float* lane_im) {
  const hn::ScalableTag<float> df;
  const auto n = static_cast<std::size_t>(a.n);
  for (std::size_t row = 0; row < n; ++row) {
    const std::size_t base = row * n + static_cast<std::size_t>(block) * kLanes;
    for (std::size_t l = 0; l < kLanes; l += hn::Lanes(df)) {
      const std::size_t i = base + l, j = row * kLanes + l;
      const auto hr = hn::Load(df, h_re + j), hi = hn::Load(df, h_im + j);
      const auto fr = hn::LoadU(df, a.factor_re[plane] + i);
      const auto fi = hn::LoadU(df, a.factor_im[plane] + i);
      hn::Store(hn::MulSub(fr, hr, hn::Mul(fi, hi)), df, lane_re + j);
      hn::Store(hn::MulAdd(fr, hi, hn::Mul(fi, hr)), df, lane_im + j);
    }
  }
}

void AssembleDisplacement(const float* h, const float* dx, const float* dz, int n_int, int block,
                          float* displacement, std::uint16_t* displacement_half) {
  const auto n = static_cast<std::size_t>(n_int);
  const std::size_t row0 = static_cast<std::size_t>(block) * kLanes;
  alignas(64) float row_values[4 * 2048];
  for (std::size_t l = 0; l < kLanes; ++l) {
    const std::size_t row = row0 + l;
    float* out = displacement + 3 * row * n;
    // (−1)^(x+y): the row's sign on even columns, the opposite on odd ones (eq. 43).
    const float even = (row & 1u) ? -1.0f : 1.0f;
    for (std::size_t c = 0; c < n; ++c) {
      const float sign = (c & 1u) ? -even : even;
      const std::size_t s = c * kLanes + l;
      out[3 * c + 0] = dx[s] * sign;
      out[3 * c + 1] = h[s] * sign;
      out[3 * c + 2] = dz[s] * sign;
      row_values[4 * c + 0] = out[3 * c + 0];
      row_values[4 * c + 1] = out[3 * c + 1];
      row_values[4 * c + 2] = out[3 * c + 2];
      row_values[4 * c + 3] = 0.0f;
    }
    std::uint16_t* half = displacement_half + 4 * row * n;
#if HWY_TARGET >= HWY_SSE4 || defined(HWY_DISABLE_F16C)
    // No F16C: Highway's emulated conversion truncates; keep round-to-nearest-even.
    for (std::size_t i = 0; i < 4 * n; ++i) half[i] = float_to_half(row_values[i]);
#else
    const hn::ScalableTag<float> df;
    const hn::Rebind<hwy::float16_t, decltype(df)> dh;
    for (std::size_t i = 0; i < 4 * n; i += hn::Lanes(df)) {
      hn::StoreU(hn::DemoteTo(dh, hn::Load(df, row_values + i)), dh,
                 reinterpret_cast<hwy::float16_t*>(half + i));
    }
#endif
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace ocean::cpu
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ocean::cpu {

HWY_EXPORT(EvolveLanes);
HWY_EXPORT(ApplyFactor);
HWY_EXPORT(AssembleDisplacement);

void evolve_lanes(const EvolveArgs& args, int block, float* h_re, float* h_im) {
  HWY_DYNAMIC_DISPATCH(EvolveLanes)(args, block, h_re, h_im);
}

void apply_factor(const EvolveArgs& args, int plane, int block, const float* h_re,
                  const float* h_im, float* lane_re, float* lane_im) {
  HWY_DYNAMIC_DISPATCH(ApplyFactor)(args, plane, block, h_re, h_im, lane_re, lane_im);
}

void assemble_displacement(const float* h, const float* dx, const float* dz, int n, int block,
                           float* displacement, std::uint16_t* displacement_half) {
  HWY_DYNAMIC_DISPATCH(AssembleDisplacement)(h, dx, dz, n, block, displacement, displacement_half);
}

void evolve_texel_reference(const EvolveArgs& a, std::size_t i, float* re, float* im) {
  // Same recipe as EvolutionPhase (M.7.3) on the same rate/clock inputs.
  const double turns = a.rate[i] * a.clock;
  const double phase = 2.0 * 3.14159265358979323846 * (turns - std::floor(turns));
  const float c = static_cast<float>(std::cos(phase));
  const float s = static_cast<float>(std::sin(phase));
  const float hr = a.packed[0][i] * c + a.packed[2][i] * s;
  const float hi = a.packed[1][i] * c + a.packed[3][i] * s;
  for (int p = 0; p < a.planes; ++p) {
    re[p] = a.factor_re[p][i] * hr - a.factor_im[p][i] * hi;
    im[p] = a.factor_re[p][i] * hi + a.factor_im[p][i] * hr;
  }
}

}  // namespace ocean::cpu
#endif
