// SIMD surface pass of the CPU backend: gradients by central differences, normal, Jacobian,
// foam and the base RGBA8 level, four rows at a time with mip levels 1 and 2 from them.
// Compiled once per instruction set by Highway.
//
// The normal of the displaced surface and the foam follow docs/math.md (M.7.4), (M.7.5); the
// formulas are those of the scalar reference (finalize.cpp), which cites their sources.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "cpu/surface_kernels.cpp"
#include <hwy/cache_control.h>
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>

#include "cpu/cpu_backend.hpp"
#include "cpu/kernels.hpp"
#include "cpu/mip_sums-inl.h"
#include "cpu/simd_math-inl.h"
#include "ocean/sim.hpp"

HWY_BEFORE_NAMESPACE();
namespace ocean::cpu {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
  const auto threshold = hn::Set(df, a.foam_source.threshold);
  const auto gain = hn::Set(df, a.foam_source.gain);
  const bool breaking = a.foam_source.breaking;
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
    const auto x = hn::Mul(hn::Sub(threshold, jac), gain);
    const auto now = breaking ? NormalCdf(df, x) : hn::Min(hn::Max(x, zero), one);
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

HWY_EXPORT(SurfaceRowQuads);

void surface_row_quads(const SurfaceArgs& args, int first, int count) {
  HWY_DYNAMIC_DISPATCH(SurfaceRowQuads)(args, first, count);
}

}  // namespace ocean::cpu
#endif
