// SIMD kernels of the lane-blocked inverse FFT: mixed radix-16/8/4 Stockham autosort stages on 16
// interleaved signals, and the 16-row transposes with the (−1)^(x+y) shift. Compiled once per
// instruction set by Highway and dispatched at run time.
//
// This work is based on:
//   - Stockham, T. G. (1966) High-speed convolution and correlation; Cochran, W. T. et al. (1967)
//     What is the fast Fourier transform? Proc. IEEE 55(10) (the autosort formulation).
//   - Govindaraju, N. K. et al. (2008) High performance discrete Fourier transforms on graphics
//     processors, SC'08 (the per-element indexing of a mixed-radix Stockham stage).
//   - Aebi, VR Ocean, §3.6: twiddles hoisted into tables, dual-spectrum processing, sign
//     correction.
// Convention: x[n] = Σ_k X[k]·e^{+2πi·k·n/N} (docs/conventions.md).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "fft/lane_kernels.cpp"
#include "fft/lane_kernels.hpp"

#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "fft/transpose-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ocean::fft::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The R inputs of a butterfly at lane offset l, twiddled: t_r = v_r·w^r (w^0 = 1). The first
// stage (ns = 1, kTwiddled false) has w = 1 for every butterfly: no multiplications.
template <int R, bool kTwiddled, class D, class V>
HWY_INLINE void LoadTwiddled(D d, const float* const* in_re, const float* const* in_im,
                             std::size_t l, const float* wr, const float* wi, V* tr, V* ti) {
  tr[0] = hn::LoadU(d, in_re[0] + l), ti[0] = hn::LoadU(d, in_im[0] + l);
  for (int r = 1; r < R; ++r) {
    const auto vr = hn::LoadU(d, in_re[r] + l), vi = hn::LoadU(d, in_im[r] + l);
    if constexpr (kTwiddled) {
      const auto wr_r = hn::Set(d, wr[r - 1]), wi_r = hn::Set(d, wi[r - 1]);
      tr[r] = hn::MulSub(vr, wr_r, hn::Mul(vi, wi_r));
      ti[r] = hn::MulAdd(vr, wi_r, hn::Mul(vi, wr_r));
    } else {
      (void)wr, (void)wi;
      tr[r] = vr, ti[r] = vi;
    }
  }
}

// 4-point inverse DFT in place, X_q = Σ_r c_r·i^{rq}, on elements c[0], c[stride], c[2·stride],
// c[3·stride] (natural order in and out).
template <class V>
HWY_INLINE void Dft4(V* cr, V* ci, int stride) {
  const V a0r = hn::Add(cr[0], cr[2 * stride]), a0i = hn::Add(ci[0], ci[2 * stride]);
  const V a1r = hn::Sub(cr[0], cr[2 * stride]), a1i = hn::Sub(ci[0], ci[2 * stride]);
  const V a2r = hn::Add(cr[stride], cr[3 * stride]), a2i = hn::Add(ci[stride], ci[3 * stride]);
  const V a3r = hn::Sub(ci[3 * stride], ci[stride]);  // i·(c1 − c3)
  const V a3i = hn::Sub(cr[stride], cr[3 * stride]);
  cr[0] = hn::Add(a0r, a2r), ci[0] = hn::Add(a0i, a2i);
  cr[stride] = hn::Add(a1r, a3r), ci[stride] = hn::Add(a1i, a3i);
  cr[2 * stride] = hn::Sub(a0r, a2r), ci[2 * stride] = hn::Sub(a0i, a2i);
  cr[3 * stride] = hn::Sub(a1r, a3r), ci[3 * stride] = hn::Sub(a1i, a3i);
}

// One stage a → b. Element j of the input (j < N/R) with its R−1 partners at distance N/R is
// twiddled by w^r, w = e^{+2πi·k/(ns·R)}, k = j mod ns, combined by an R-point inverse DFT and
// written to (j − k)·R + k + r·ns. kTwiddled is false for the first stage (ns = 1). kPruned
// (first radix-16 stage only): inputs outside [N/4, 3N/4), r = r1 + 4·r2 with r2 ∈ {0, 3}, are
// zero and not read; the same operations on the rest give the same bits.
template <int R, bool kTwiddled, bool kPruned = false>
void StockhamStage(const StageTable& t, const Stage& s, LaneBuffer a, LaneBuffer b) {
  static_assert(!kPruned || (R == 16 && !kTwiddled), "pruning: the first radix-16 stage");
  const hn::ScalableTag<float> d;
  const std::size_t step = hn::Lanes(d);
  const int quarter = t.n / R;
  const auto mask = static_cast<std::size_t>(s.ns - 1);
  for (int jj = 0; jj < quarter; ++jj) {
    const auto j = static_cast<std::size_t>(jj);
    const std::size_t k = j & mask;
    const std::size_t out0 = (j - k) * R + k;
    const float* wr = t.twiddle_re + s.twiddle + k * (R - 1);
    const float* wi = t.twiddle_im + s.twiddle + k * (R - 1);
    const float* in_re[R];
    const float* in_im[R];
    float* out_re[R];
    float* out_im[R];
    for (int r = 0; r < R; ++r) {
      const std::size_t src = (j + static_cast<std::size_t>(r * quarter)) * a.stride;
      const std::size_t dst = (out0 + static_cast<std::size_t>(r * s.ns)) * b.stride;
      in_re[r] = a.re + src, in_im[r] = a.im + src;
      out_re[r] = b.re + dst, out_im[r] = b.im + dst;
    }
    if constexpr (R == 16) {
      // 16 = 4 × 4 (r = r1 + 4·r2, q = 4·q1 + q2): 4-point DFTs over r2, the internal
      // twiddles w16^(r1·q2), 4-point DFTs over r1 (w16 = e^{+iπ/8}).
      using V = decltype(hn::Zero(d));
      const auto half_sqrt2 = hn::Set(d, 0.70710678118654752f);
      const auto c8 = hn::Set(d, 0.92387953251128674f), s8 = hn::Set(d, 0.38268343236508977f);
      for (std::size_t l = 0; l < static_cast<std::size_t>(kLanes); l += step) {
        V tr[16], ti[16];
        if constexpr (kPruned) {
          // Column r1 with c0 = c3 = 0: X_q = c1·i^q + c2·(−1)^q, as Dft4 computes it.
          (void)wr, (void)wi;
          for (int r1 = 0; r1 < 4; ++r1) {
            const V c1r = hn::LoadU(d, in_re[r1 + 4] + l), c1i = hn::LoadU(d, in_im[r1 + 4] + l);
            const V c2r = hn::LoadU(d, in_re[r1 + 8] + l), c2i = hn::LoadU(d, in_im[r1 + 8] + l);
            const V a1r = hn::Neg(c2r), a1i = hn::Neg(c2i);  // c0 − c2
            const V a3r = hn::Neg(c1i), a3i = c1r;           // i·(c1 − c3)
            tr[r1] = hn::Add(c2r, c1r), ti[r1] = hn::Add(c2i, c1i);
            tr[r1 + 4] = hn::Add(a1r, a3r), ti[r1 + 4] = hn::Add(a1i, a3i);
            tr[r1 + 8] = hn::Sub(c2r, c1r), ti[r1 + 8] = hn::Sub(c2i, c1i);
            tr[r1 + 12] = hn::Sub(a1r, a3r), ti[r1 + 12] = hn::Sub(a1i, a3i);
          }
        } else {
          LoadTwiddled<16, kTwiddled>(d, in_re, in_im, l, wr, wi, tr, ti);
          // Column r1 (elements r1, r1 + 4, r1 + 8, r1 + 12) becomes Y[r1][q2] at r1 + 4·q2.
          for (int r1 = 0; r1 < 4; ++r1) Dft4(tr + r1, ti + r1, 4);
        }
        const auto rotate = [&](int i, V cr, V ci) {  // t_i ·= (cr + i·ci)
          const V x = tr[i], y = ti[i];
          tr[i] = hn::MulSub(x, cr, hn::Mul(y, ci));
          ti[i] = hn::MulAdd(x, ci, hn::Mul(y, cr));
        };
        const auto eighth = [&](int i, bool back) {  // ·(±1 + i)/√2
          const V x = tr[i], y = ti[i];
          tr[i] = hn::Mul(back ? hn::Neg(hn::Add(x, y)) : hn::Sub(x, y), half_sqrt2);
          ti[i] = hn::Mul(back ? hn::Sub(x, y) : hn::Add(x, y), half_sqrt2);
        };
        rotate(1 + 4, c8, s8);   // w^1
        eighth(1 + 8, false);    // w^2
        rotate(1 + 12, s8, c8);  // w^3
        eighth(2 + 4, false);    // w^2
        {                        // w^4 = i
          const V x = tr[2 + 8];
          tr[2 + 8] = hn::Neg(ti[2 + 8]), ti[2 + 8] = x;
        }
        eighth(2 + 12, true);                      // w^6
        rotate(3 + 4, s8, c8);                     // w^3
        eighth(3 + 8, true);                       // w^6
        rotate(3 + 12, hn::Neg(c8), hn::Neg(s8));  // w^9
        // Row q2 (elements 4·q2 … 4·q2 + 3 over r1) gives X[4·q1 + q2] at 4·q2 + q1.
        for (int q2 = 0; q2 < 4; ++q2) Dft4(tr + 4 * q2, ti + 4 * q2, 1);
        for (int q1 = 0; q1 < 4; ++q1) {
          for (int q2 = 0; q2 < 4; ++q2) {
            hn::StoreU(tr[4 * q2 + q1], d, out_re[4 * q1 + q2] + l);
            hn::StoreU(ti[4 * q2 + q1], d, out_im[4 * q1 + q2] + l);
          }
        }
      }
    } else if constexpr (R == 8) {
      const auto half_sqrt2 = hn::Set(d, 0.70710678118654752f);
      for (std::size_t l = 0; l < static_cast<std::size_t>(kLanes); l += step) {
        decltype(hn::Zero(d)) tr[8], ti[8];
        LoadTwiddled<8, kTwiddled>(d, in_re, in_im, l, wr, wi, tr, ti);
        // 8 = 2 × 4: a_r = t_r + t_{r+4} feed the even outputs, b_r·w8^r = (t_r − t_{r+4})·w8^r
        // the odd ones, each through a 4-point inverse DFT (w8 = e^{+iπ/4}).
        decltype(hn::Zero(d)) ar[4], ai[4], br[4], bi[4];
        for (int r = 0; r < 4; ++r) {
          ar[r] = hn::Add(tr[r], tr[r + 4]), ai[r] = hn::Add(ti[r], ti[r + 4]);
          br[r] = hn::Sub(tr[r], tr[r + 4]), bi[r] = hn::Sub(ti[r], ti[r + 4]);
        }
        {
          const auto r1 = hn::Mul(hn::Sub(br[1], bi[1]), half_sqrt2);  // ·(1 + i)/√2
          const auto i1 = hn::Mul(hn::Add(br[1], bi[1]), half_sqrt2);
          const auto r2 = hn::Neg(bi[2]), i2 = br[2];                           // ·i
          const auto r3 = hn::Mul(hn::Neg(hn::Add(br[3], bi[3])), half_sqrt2);  // ·(−1 + i)/√2
          const auto i3 = hn::Mul(hn::Sub(br[3], bi[3]), half_sqrt2);
          br[1] = r1, bi[1] = i1, br[2] = r2, bi[2] = i2, br[3] = r3, bi[3] = i3;
        }
        Dft4(ar, ai, 1);  // X_{2m}
        Dft4(br, bi, 1);  // X_{2m+1}
        for (int m = 0; m < 4; ++m) {
          hn::StoreU(ar[m], d, out_re[2 * m] + l), hn::StoreU(ai[m], d, out_im[2 * m] + l);
          hn::StoreU(br[m], d, out_re[2 * m + 1] + l), hn::StoreU(bi[m], d, out_im[2 * m + 1] + l);
        }
      }
    } else if constexpr (R == 4) {
      for (std::size_t l = 0; l < static_cast<std::size_t>(kLanes); l += step) {
        decltype(hn::Zero(d)) tr[4], ti[4];
        LoadTwiddled<4, kTwiddled>(d, in_re, in_im, l, wr, wi, tr, ti);
        Dft4(tr, ti, 1);
        for (int q = 0; q < 4; ++q) {
          hn::StoreU(tr[q], d, out_re[q] + l);
          hn::StoreU(ti[q], d, out_im[q] + l);
        }
      }
    } else {
      static_assert(R == 16 || R == 8 || R == 4, "the plan's radices");
    }
  }
}

bool Stockham(const StageTable& table, LaneBuffer a, LaneBuffer b, bool outer_half_zero) {
  for (int i = 0; i < table.count; ++i) {
    const Stage& s = table.stages[i];
    const bool first = s.ns == 1;
    if (s.radix == 16 && first && outer_half_zero) {
      StockhamStage<16, false, true>(table, s, a, b);
    } else if (s.radix == 16) {
      first ? StockhamStage<16, false>(table, s, a, b) : StockhamStage<16, true>(table, s, a, b);
    } else if (s.radix == 8) {
      first ? StockhamStage<8, false>(table, s, a, b) : StockhamStage<8, true>(table, s, a, b);
    } else {
      first ? StockhamStage<4, false>(table, s, a, b) : StockhamStage<4, true>(table, s, a, b);
    }
    const LaneBuffer swap = a;
    a = b, b = swap;
  }
  return (table.count & 1) != 0;
}

void TransposeTiles(const TileWalk& w) {
  for (std::size_t t = 0; t < w.count; ++t)
    Transpose16Tile(w.src + t * w.src_step, w.src_stride, w.dst + t * w.dst_step, w.dst_stride,
                    w.sign_parity);
}

const char* DispatchedTarget() { return hwy::TargetName(HWY_TARGET); }

// Ten independent FMA chains (more than latency × issue ports on current cores) on full
// vectors: 20·lanes flops per iteration.
double FmaLoop(std::size_t iterations, std::size_t* lanes) {
  const hn::ScalableTag<float> d;
  const auto x = hn::Set(d, 0.9999999f), y = hn::Set(d, 1e-7f);
  // Distinct starting values: identical chains would be merged by the compiler.
  auto a0 = hn::Set(d, 1.0f), a1 = hn::Set(d, 1.1f), a2 = hn::Set(d, 1.2f), a3 = hn::Set(d, 1.3f),
       a4 = hn::Set(d, 1.4f), a5 = hn::Set(d, 1.5f), a6 = hn::Set(d, 1.6f), a7 = hn::Set(d, 1.7f),
       a8 = hn::Set(d, 1.8f), a9 = hn::Set(d, 1.9f);
  for (std::size_t i = 0; i < iterations; ++i) {
    a0 = hn::MulAdd(a0, x, y), a1 = hn::MulAdd(a1, x, y), a2 = hn::MulAdd(a2, x, y);
    a3 = hn::MulAdd(a3, x, y), a4 = hn::MulAdd(a4, x, y), a5 = hn::MulAdd(a5, x, y);
    a6 = hn::MulAdd(a6, x, y), a7 = hn::MulAdd(a7, x, y), a8 = hn::MulAdd(a8, x, y);
    a9 = hn::MulAdd(a9, x, y);
  }
  *lanes = hn::Lanes(d);
  const auto sum = hn::Add(hn::Add(hn::Add(a0, a1), hn::Add(a2, a3)),
                           hn::Add(hn::Add(hn::Add(a4, a5), hn::Add(a6, a7)), hn::Add(a8, a9)));
  return static_cast<double>(hn::GetLane(hn::SumOfLanes(d, sum)));
}

}  // namespace HWY_NAMESPACE
}  // namespace ocean::fft::detail
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ocean::fft::detail {

HWY_EXPORT(Stockham);
HWY_EXPORT(TransposeTiles);
HWY_EXPORT(DispatchedTarget);
HWY_EXPORT(FmaLoop);

bool stockham(const StageTable& table, LaneBuffer a, LaneBuffer b, bool outer_half_zero) {
  return HWY_DYNAMIC_DISPATCH(Stockham)(table, a, b, outer_half_zero);
}
void transpose_tiles(const TileWalk& walk) { HWY_DYNAMIC_DISPATCH(TransposeTiles)(walk); }

namespace {
constexpr auto kL = static_cast<std::size_t>(kLanes);
}  // namespace

void rows_to_lanes(const float* src, std::size_t row_stride, int n, float* dst) {
  transpose_tiles({.src = src,
                   .src_stride = row_stride,
                   .src_step = kL,
                   .dst = dst,
                   .dst_stride = kL,
                   .dst_step = kL * kL,
                   .count = static_cast<std::size_t>(n) / kL});
}

void lanes_to_rows(const float* src, int n, float* dst, std::size_t row_stride, bool sign_correct,
                   int parity) {
  // (−1)^(x+y): tiles start at even columns, so the parity is the first row's.
  transpose_tiles({.src = src,
                   .src_stride = kL,
                   .src_step = kL * kL,
                   .dst = dst,
                   .dst_stride = row_stride,
                   .dst_step = kL,
                   .count = static_cast<std::size_t>(n) / kL,
                   .sign_parity = sign_correct ? parity : -1});
}

const char* dispatched_target() { return HWY_DYNAMIC_DISPATCH(DispatchedTarget)(); }
double fma_loop(std::size_t iterations, std::size_t* lanes) {
  return HWY_DYNAMIC_DISPATCH(FmaLoop)(iterations, lanes);
}

}  // namespace ocean::fft::detail
#endif
