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

#include "cpu/cpu_backend.hpp"
#include "ocean/half.hpp"
#include "ocean/sim.hpp"

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
  const hn::ScalableTag<float> df;
  const std::size_t step = hn::Lanes(df);
  const auto n = static_cast<std::size_t>(n_int);
  const std::size_t row0 = static_cast<std::size_t>(block) * kLanes;
  // (−1)^(x+y) for an even first column: +1, −1, +1, ... (eq. 43); odd rows flip it.
  alignas(64) float alternate[kLanes];
  for (std::size_t c = 0; c < kLanes; ++c) alternate[c] = (c & 1u) ? -1.0f : 1.0f;
  alignas(64) float row_h[2048], row_dx[2048], row_dz[2048];
  for (std::size_t l = 0; l < kLanes; ++l) {
    const std::size_t row = row0 + l;
    for (std::size_t c = 0; c < n; ++c) {  // lane layout → this row's values
      row_h[c] = h[c * kLanes + l];
      row_dx[c] = dx[c * kLanes + l];
      row_dz[c] = dz[c * kLanes + l];
    }
    const float row_sign = (row & 1u) ? -1.0f : 1.0f;
    float* out = displacement + 3 * row * n;
    std::uint16_t* half = displacement_half + 4 * row * n;
    for (std::size_t c = 0; c < n; c += step) {
      // c is even unless a vector holds a single lane.
      const auto sign = hn::Mul(hn::LoadU(df, alternate + (c & 1u)), hn::Set(df, row_sign));
      const auto vx = hn::Mul(hn::Load(df, row_dx + c), sign);
      const auto vh = hn::Mul(hn::Load(df, row_h + c), sign);
      const auto vz = hn::Mul(hn::Load(df, row_dz + c), sign);
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
      hn::StoreInterleaved4(hn::BitCast(du, hn::DemoteTo(dh, vx)),
                            hn::BitCast(du, hn::DemoteTo(dh, vh)),
                            hn::BitCast(du, hn::DemoteTo(dh, vz)), hn::Zero(du), du, half + 4 * c);
#endif
    }
  }
}

// Quantises [0, 1] to 8 bits as ⌊saturate(v)·255 + 0.5⌋ (eq. 50).
template <class DF, class V>
HWY_INLINE auto Quantise(DF df, V v) {
  const auto clamped = hn::Min(hn::Max(v, hn::Zero(df)), hn::Set(df, 1.0f));
  return hn::ConvertTo(hn::RebindToSigned<DF>(),
                       hn::MulAdd(clamped, hn::Set(df, 255.0f), hn::Set(df, 0.5f)));
}

void SurfaceRowCentral(const SurfaceArgs& a, int row_int) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const std::size_t step = hn::Lanes(df);
  const auto n = static_cast<std::size_t>(a.n);
  const auto mask = static_cast<int>(n) - 1;
  const auto row = static_cast<std::size_t>(row_int);
  const float* up = a.displacement + 3 * n * static_cast<std::size_t>((row_int - 1) & mask);
  const float* centre = a.displacement + 3 * n * row;
  const float* down = a.displacement + 3 * n * static_cast<std::size_t>((row_int + 1) & mask);
  // The centre row deinterleaved with one wrapped texel on each side (eq. 46).
  alignas(64) float padded[3][2048 + 2];
  for (std::size_t c = 0; c < n; ++c) {
    for (std::size_t k = 0; k < 3; ++k) padded[k][c + 1] = centre[3 * c + k];
  }
  for (std::size_t k = 0; k < 3; ++k) {
    padded[k][0] = padded[k][n];
    padded[k][n + 1] = padded[k][1];
  }
  const auto half_inv = hn::Set(df, 0.5f);
  const auto inv = hn::Set(df, a.inv_spacing);
  const auto one = hn::Set(df, 1.0f), zero = hn::Zero(df);
  const auto base_length = hn::Set(df, a.base_length);
  const auto j_start = hn::Set(df, a.jacobian_start), j_range = hn::Set(df, a.jacobian_range);
  const auto decay = hn::Set(df, a.decay);
  const auto alpha =
      hn::ShiftLeft<24>(Quantise(df, hn::Set(df, a.smoothness)));  // constant smoothness
  for (std::size_t c = 0; c < n; c += step) {
    // ∂/∂x from the padded centre row, ∂/∂z from the rows above and below (eq. 45).
    const auto gx = [&](std::size_t k) {
      return hn::Mul(
          hn::Mul(hn::Sub(hn::LoadU(df, padded[k] + c + 2), hn::LoadU(df, padded[k] + c)),
                  half_inv),
          inv);
    };
    decltype(hn::Zero(df)) u0, u1, u2, d0, d1, d2;
    hn::LoadInterleaved3(df, up + 3 * c, u0, u1, u2);
    hn::LoadInterleaved3(df, down + 3 * c, d0, d1, d2);
    const auto dx_dx = gx(0), h_dx = gx(1), dz_dx = gx(2);
    const auto dx_dz = hn::Mul(hn::Mul(hn::Sub(d0, u0), half_inv), inv);
    const auto h_dz = hn::Mul(hn::Mul(hn::Sub(d1, u1), half_inv), inv);
    const auto dz_dz = hn::Mul(hn::Mul(hn::Sub(d2, u2), half_inv), inv);
    // Jacobian (eq. 48) and the normal of the displaced surface (M.7.5).
    const auto jxx = hn::Add(one, dx_dx), jzz = hn::Add(one, dz_dz);
    const auto jac = hn::Sub(hn::Mul(jxx, jzz), hn::Mul(dx_dz, dz_dx));
    auto nx = hn::Sub(hn::Mul(h_dz, dz_dx), hn::Mul(jzz, h_dx));
    auto ny = jac;
    auto nz = hn::Sub(hn::Mul(dx_dz, h_dx), hn::Mul(h_dz, jxx));
    const auto length =
        hn::Sqrt(hn::Add(hn::Add(hn::Mul(nx, nx), hn::Mul(ny, ny)), hn::Mul(nz, nz)));
    const auto valid = hn::Gt(length, zero);
    const auto safe = hn::IfThenElse(valid, length, one);
    nx = hn::IfThenElseZero(valid, hn::Div(nx, safe));
    ny = hn::IfThenElse(valid, hn::Div(ny, safe), one);
    nz = hn::IfThenElseZero(valid, hn::Div(nz, safe));
    // Foam ramp and accumulation (M.7.4).
    const std::size_t i = row * n + c;
    const auto now = hn::Min(hn::Max(hn::Div(hn::Sub(j_start, jac), j_range), zero), one);
    auto foam = now;
    if (!a.reset_foam) {
      const auto accumulated =
          hn::Sub(hn::LoadU(df, a.foam_state + i), hn::Div(decay, hn::Max(now, hn::Set(df, 0.5f))));
      foam = hn::Min(hn::Max(hn::Max(accumulated, now), zero), one);
    }
    hn::StoreU(foam, df, a.foam_state + i);
    hn::StoreU(jac, df, a.jacobian + i);
    hn::StoreU(foam, df, a.foam + i);
    hn::StoreInterleaved3(nx, ny, nz, df, a.normal + 3 * i);
    const auto blue =
        a.blue_is_foam
            ? foam
            : hn::Min(hn::Max(hn::MulAdd(jac, hn::Set(df, 0.5f), hn::Set(df, 0.5f)), zero), one);
    hn::StoreInterleaved4(hn::Mul(nx, base_length), hn::Mul(ny, base_length),
                          hn::Mul(nz, base_length), blue, df, a.mip_work + 4 * i);
    const auto rgba = hn::Or(
        hn::Or(
            Quantise(df, hn::MulAdd(nx, hn::Set(df, 0.5f), hn::Set(df, 0.5f))),
            hn::ShiftLeft<8>(Quantise(df, hn::MulAdd(nz, hn::Set(df, 0.5f), hn::Set(df, 0.5f))))),
        hn::Or(hn::ShiftLeft<16>(Quantise(df, blue)), alpha));
    hn::StoreU(rgba, di, reinterpret_cast<std::int32_t*>(a.packed + i));
  }
}

void MipRow(int n, int level, int row_int, float* work, std::uint32_t* packed) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const auto size = static_cast<std::size_t>(n >> level);
  const auto row = static_cast<std::size_t>(row_int);
  const std::size_t src_size = 2 * size;
  const float* src0 = work + 4 * (mip_offset(n, level - 1) + 2 * row * src_size);
  const float* src1 = src0 + 4 * src_size;
  const std::size_t dst = mip_offset(n, level) + row * size;
  // 2×2 sums (eq. 52), deinterleaved into structure-of-arrays for the vector part.
  alignas(64) float sum[4][1024];
  for (std::size_t c = 0; c < size; ++c) {
    for (std::size_t k = 0; k < 4; ++k) {
      sum[k][c] = 0.25f * (((src0[8 * c + k] + src0[8 * c + 4 + k]) + src1[8 * c + k]) +
                           src1[8 * c + 4 + k]);
    }
  }
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
    const auto rgba = hn::Or(
        hn::Or(Quantise(df, hn::MulAdd(hn::Mul(x, inv), half, half)),
               hn::ShiftLeft<8>(Quantise(df, hn::MulAdd(hn::Mul(z, inv), half, half)))),
        hn::Or(hn::ShiftLeft<16>(Quantise(df, b)), hn::ShiftLeft<24>(Quantise(df, smoothness))));
    hn::StoreU(rgba, di, reinterpret_cast<std::int32_t*>(packed + dst + c));
    hn::StoreInterleaved4(x, y, z, b, df, work + 4 * (dst + c));
  }
  for (; c < size; ++c) {  // rows narrower than a vector
    float* v = work + 4 * (dst + c);
    for (std::size_t k = 0; k < 4; ++k) v[k] = sum[k][c];
    const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const float inv = length > 0.0f ? 1.0f / length : 0.0f;
    packed[dst + c] =
        pack_rgba8(v[0] * inv, v[2] * inv, v[3], smoothness_from_normal_length(length));
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
HWY_EXPORT(SurfaceRowCentral);
HWY_EXPORT(MipRow);

void mip_row(int n, int level, int row, float* work, std::uint32_t* packed) {
  HWY_DYNAMIC_DISPATCH(MipRow)(n, level, row, work, packed);
}

void surface_row_central(const SurfaceArgs& args, int row) {
  HWY_DYNAMIC_DISPATCH(SurfaceRowCentral)(args, row);
}

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
