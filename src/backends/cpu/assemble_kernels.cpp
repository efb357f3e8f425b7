// SIMD displacement assembly of the CPU backend's fused row pass: the row FFT's lane blocks
// transposed back tile by tile with the (−1)^(x+y) shift into the float3 and half4 maps.
// Compiled once per instruction set by Highway.
//
// This work is based on: Aebi, VR Ocean, eq. 43 (sign correction), eq. 44 (displacement
// assembly).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "cpu/assemble_kernels.cpp"
#include <hwy/cache_control.h>
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>

#include "cpu/kernels.hpp"
#include "cpu/simd_math-inl.h"
#include "fft/transpose-inl.h"
#include "ocean/half.hpp"

HWY_BEFORE_NAMESPACE();
namespace ocean::cpu {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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

}  // namespace HWY_NAMESPACE
}  // namespace ocean::cpu
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ocean::cpu {

HWY_EXPORT(AssembleDisplacement);

void assemble_displacement(const float* h, const float* dx, const float* dz, int n, int block,
                           float* displacement, std::uint16_t* displacement_half,
                           AssemblyStores stores) {
  HWY_DYNAMIC_DISPATCH(AssembleDisplacement)
  (h, dx, dz, n, block, displacement, displacement_half, stores);
}

}  // namespace ocean::cpu
#endif
