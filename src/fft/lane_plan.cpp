// The lane-blocked 2D inverse FFT: the plan (stage list, hoisted twiddles) and the column and
// row passes over 16-line blocks.
//
// This work is based on:
//   - Stockham autosort / Govindaraju et al. (2008): see lane_kernels.cpp.
//   - Aebi, VR Ocean, §3.6.5: per-thread local buffers on the stack; eqs. 42–43 (sign correction).
// Convention: x[n] = Σ_k X[k]·e^{+2πi·k·n/N} (docs/conventions.md).
#include "fft/lane_plan.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <string>

namespace ocean::fft {

static_assert(LanePlan2D::kBlock == detail::kLanes);

Result<LanePlan2D> LanePlan2D::make(int n) {
  if (n < kBlock || n > kMaxSimdSize || !std::has_single_bit(static_cast<unsigned>(n))) {
    return invalid_argument("FFT size = " + std::to_string(n) +
                            " is out of range for the SIMD plan: must be a power of two in [" +
                            std::to_string(kBlock) + ", " + std::to_string(kMaxSimdSize) + "]");
  }
  LanePlan2D plan;
  plan.n_ = n;
  // Radix-16 stages (fewest passes over the lane buffers), then a radix-4 or radix-8 stage for
  // the rest of log2 N; a remainder of one bit turns a 16 into 8·4: 256 = 16·16,
  // 512 = 16·8·4, 1024 = 16·16·4, 2048 = 16·16·8.
  const int log2n = std::countr_zero(static_cast<unsigned>(n));
  std::vector<int> radices(static_cast<std::size_t>(log2n / 4), 16);
  if (log2n % 4 == 1) radices.back() = 8, radices.push_back(4);  // n ≥ 16: at least one 16
  if (log2n % 4 == 2) radices.push_back(4);
  if (log2n % 4 == 3) radices.push_back(8);
  int ns = 1;
  std::size_t offset = 0;
  for (const int radix : radices) {
    plan.stages_.push_back({radix, ns, offset});
    for (int k = 0; k < ns; ++k) {
      for (int r = 1; r < radix; ++r) {  // w^r, w = e^{+2πi·k/(ns·radix)}, in double
        const double angle =
            2.0 * 3.14159265358979323846 * r * k / (static_cast<double>(ns) * radix);
        plan.twiddle_re_.push_back(static_cast<float>(std::cos(angle)));
        plan.twiddle_im_.push_back(static_cast<float>(std::sin(angle)));
      }
    }
    offset += static_cast<std::size_t>(ns * (radix - 1));
    ns *= radix;
  }
  return plan;
}

namespace {
detail::StageTable table_of(int n, const std::vector<detail::Stage>& stages,
                            const std::vector<float>& re, const std::vector<float>& im) {
  return {n, stages.data(), static_cast<int>(stages.size()), re.data(), im.data()};
}
}  // namespace

void LanePlan2D::columns(SplitComplex plane, int block) const {
  constexpr auto kLanes = static_cast<std::size_t>(detail::kLanes);
  alignas(64) float lane_re[kLanes * kMaxSimdSize];
  alignas(64) float lane_im[kLanes * kMaxSimdSize];
  // Contiguous ping-pong buffers: a column block read in place would stride by N floats, and
  // power-of-two strides alias in the caches.
  alignas(64) float scratch_re[kLanes * kMaxSimdSize];
  alignas(64) float scratch_im[kLanes * kMaxSimdSize];
  const LaneBlock out{lane_re, lane_im};
  const LaneBlock input = input_for(out, {scratch_re, scratch_im});
  const std::size_t origin = static_cast<std::size_t>(block) * kLanes;
  const auto n = static_cast<std::size_t>(n_);
  for (std::size_t j = 0; j < n; ++j) {
    std::memcpy(input.re + j * kLanes, plane.re + origin + j * n, kLanes * sizeof(float));
    std::memcpy(input.im + j * kLanes, plane.im + origin + j * n, kLanes * sizeof(float));
  }
  transform(out, {scratch_re, scratch_im});
  for (std::size_t j = 0; j < n; ++j) {
    std::memcpy(plane.re + origin + j * n, out.re + j * kLanes, kLanes * sizeof(float));
    std::memcpy(plane.im + origin + j * n, out.im + j * kLanes, kLanes * sizeof(float));
  }
}

void LanePlan2D::transform(LaneBlock out, LaneBlock scratch, bool outer_half_zero) const {
  const detail::StageTable table = table_of(n_, stages_, twiddle_re_, twiddle_im_);
  const LaneBlock input = input_for(out, scratch);
  const LaneBlock other = input.re == out.re ? scratch : out;
  constexpr auto kLanes = static_cast<std::size_t>(detail::kLanes);
  detail::stockham(table, {input.re, input.im, kLanes}, {other.re, other.im, kLanes},
                   outer_half_zero && prunes_outer_half());
}

void LanePlan2D::tiles_to_lanes(const float* tiles, int block, float* dst,
                                bool outer_half_zero) const {
  constexpr auto kLanes = static_cast<std::size_t>(detail::kLanes);
  const auto n = static_cast<std::size_t>(n_);
  // Tile (block, b) is 256 contiguous floats in column block b; pruned, b ∈ [N/64, 3N/64).
  const std::size_t first = outer_half_zero && prunes_outer_half() ? n / kLanes / 4 : 0;
  const std::size_t count = n / kLanes - 2 * first;
  detail::transpose_tiles(
      {.src = tiles + static_cast<std::size_t>(block) * kLanes * kLanes + first * kLanes * n,
       .src_stride = kLanes,
       .src_step = kLanes * n,
       .dst = dst + first * kLanes * kLanes,
       .dst_stride = kLanes,
       .dst_step = kLanes * kLanes,
       .count = count});
}

void LanePlan2D::rows(SplitComplex plane, int block, float* out_re, float* out_im) const {
  const detail::StageTable table = table_of(n_, stages_, twiddle_re_, twiddle_im_);
  constexpr auto kLanes = static_cast<std::size_t>(detail::kLanes);
  const std::size_t origin =
      static_cast<std::size_t>(block) * kLanes * static_cast<std::size_t>(n_);
  const auto row_stride = static_cast<std::size_t>(n_);
  detail::rows_to_lanes(plane.re + origin, row_stride, n_, out_re);
  detail::rows_to_lanes(plane.im + origin, row_stride, n_, out_im);
  // The 16 rows (16·N contiguous floats) now serve as the second lane buffer.
  const detail::LaneBuffer y{out_re, out_im, kLanes};
  const detail::LaneBuffer x{plane.re + origin, plane.im + origin, kLanes};
  if (!detail::stockham(table, y, x)) return;  // even stage count: result in out
  std::memcpy(out_re, x.re, kLanes * row_stride * sizeof(float));
  std::memcpy(out_im, x.im, kLanes * row_stride * sizeof(float));
}

void LanePlan2D::store_rows(const float* lane_re, const float* lane_im, SplitComplex plane,
                            int block, bool sign_correct) const {
  const std::size_t origin =
      static_cast<std::size_t>(block) * detail::kLanes * static_cast<std::size_t>(n_);
  const auto row_stride = static_cast<std::size_t>(n_);
  const int parity = (block * kBlock) & 1;
  detail::lanes_to_rows(lane_re, n_, plane.re + origin, row_stride, sign_correct, parity);
  detail::lanes_to_rows(lane_im, n_, plane.im + origin, row_stride, sign_correct, parity);
}

void LanePlan2D::inverse(std::span<const SplitComplex> planes, TaskRunner& runner,
                         bool sign_correct) const {
  const std::size_t count = planes.size();
  const auto block_count = static_cast<std::size_t>(blocks());
  // Every (plane, block) pair is independent within a pass.
  runner.parallel_for(count * block_count, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      columns(planes[i / block_count], static_cast<int>(i % block_count));
  });
  runner.parallel_for(count * block_count, 1, [&](std::size_t begin, std::size_t end) {
    alignas(64) float lane_re[kBlock * kMaxSimdSize];
    alignas(64) float lane_im[kBlock * kMaxSimdSize];
    for (std::size_t i = begin; i < end; ++i) {
      const SplitComplex& plane = planes[i / block_count];
      const int block = static_cast<int>(i % block_count);
      rows(plane, block, lane_re, lane_im);
      store_rows(lane_re, lane_im, plane, block, sign_correct);
    }
  });
}

}  // namespace ocean::fft
