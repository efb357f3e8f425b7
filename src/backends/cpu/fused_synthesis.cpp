// The fused pipeline's synthesis (evolution, FFT and assembly, regrouped by block): the SIMD
// evolution written straight into the column FFT's lane blocks, then the row FFT feeding the
// displacement assembly, over all cascades' 16-line blocks (src/backends/README.md).
#include <cstring>

#include "cpu_backend.hpp"

namespace ocean::cpu {

namespace {

/// K lane blocks of the largest size on a worker's stack (no allocation in the frame path).
template <std::size_t K>
struct StackLanes {
  static constexpr std::size_t kFloats = fft::LanePlan2D::kBlock * fft::kMaxSimdSize;
  alignas(64) float re[K][kFloats];
  alignas(64) float im[K][kFloats];
  fft::LanePlan2D::LaneBlock operator[](std::size_t i) { return {re[i], im[i]}; }
};

}  // namespace

void CpuBackendImpl::prepare_evolution(double time_s) {
  for (const CascadeGroup& group : groups_) {
    for (std::size_t c = group.first; c < group.first + group.count; ++c) {
      evolve_args_[c] = evolve_args(cascades_[c], time_s, config_.loop_period_s);
      evolve_args_[c].dz_into_imaginary = c != group.first;  // the pair's second cascade
      // The planes that transform pruned: their outer rows are not read.
      for (std::size_t p = 0; p < static_cast<std::size_t>(cascades_[c].planes); ++p) {
        if (plane_outer_half_zero(group, c, p)) evolve_args_[c].pruned_planes |= 1u << p;
      }
    }
  }
}

void CpuBackendImpl::synthesise_fused(TaskRunner& runner, std::size_t first_group,
                                      std::size_t group_count, Frame& out) {
  using LaneBlock = fft::LanePlan2D::LaneBlock;
  const int n = config_.resolution;
  const auto blocks = static_cast<std::size_t>(simd_plan_.blocks());
  const std::size_t items = group_count * blocks;
  // Column blocks in mirror pairs (b, N/16 − 1 − b) from N = 32: h̃(−k) = conj h̃(k).
  const std::size_t sides = blocks >= 2 ? 2 : 1;
  const std::size_t units = blocks / sides;
  constexpr std::size_t kLane = fft::LanePlan2D::kBlock;
  const std::size_t block_floats = kLane * static_cast<std::size_t>(n);
  // Columns: every (group, column block pair) evolves h̃ once per cascade and writes each
  // plane's spectrum where transform() wants it, so the result lands in the plane's tile
  // storage without a copy: the tile itself for an even stage count, a scratch buffer for an
  // odd one (the mirror block's planes and the analytic method's fourth plane take one
  // contiguous copy then).
  runner.parallel_for(group_count * units, 1, [&](std::size_t begin, std::size_t end) {
    StackLanes<3> scratch;
    for (std::size_t item = begin; item < end; ++item) {
      const CascadeGroup& group = groups_[first_group + item / units];
      const std::size_t unit = item % units;
      // A block pair with no spectrum in any cascade of the group transforms to zeros: its
      // tiles keep the zeros they were allocated with.
      bool live = sides == 1;
      bool cascade_live[2] = {true, true};
      for (std::size_t c = group.first; c < group.first + group.count; ++c) {
        const std::vector<int>& rows = cascades_[c].evolution_rows;
        cascade_live[c - group.first] = rows.empty() || rows[2 * unit] != rows[2 * unit + 1];
        live = live || cascade_live[c - group.first];
      }
      if (!live) continue;
      const std::size_t block[2] = {unit, blocks - 1 - unit};
      // The group's planes: the first cascade's, then plane 0 of the second; per side.
      LaneBlock tile[2][fft::kMaxPlanes];
      LaneBlock input[2][fft::kMaxPlanes];
      bool pruned[fft::kMaxPlanes] = {};  // zero outside rows [N/4, 3N/4)
      // A plane of one cascade of a pair that has no spectrum in this block pair (a band-limited
      // cascade beside the full-band one) is zero: not transformed, its tiles keep their zeros.
      // Plane 1 carries both cascades' Dz. (A lone cascade without spectrum here has made the
      // whole block pair dead above.)
      bool zero[fft::kMaxPlanes] = {};
      std::size_t count = 0;
      for (std::size_t c = group.first; c < group.first + group.count; ++c) {
        CascadeState& state = cascades_[c];
        float* re[2][fft::kMaxPlanes];
        float* im[2][fft::kMaxPlanes];
        for (std::size_t p = 0; p < state.tile_re.size(); ++p, ++count) {
          pruned[count] = plane_outer_half_zero(group, c, p);
          zero[count] = !cascade_live[c - group.first] && p != 1;
          for (std::size_t side = 0; side < sides; ++side) {
            const std::size_t origin = block[side] * block_floats;
            LaneBlock& t = tile[side][count];
            t = {state.tile_re[p] + origin, state.tile_im[p] + origin};
            input[side][count] =
                side == 0 && count < 3 ? simd_plan_.input_for(t, scratch[count]) : t;
            re[side][p] = input[side][count].re, im[side][p] = input[side][count].im;
          }
        }
        for (std::size_t side = 0; c != group.first && side < sides; ++side)
          re[side][1] = input[side][1].re, im[side][1] = input[side][1].im;  // shared plane 1
        const int first_block = static_cast<int>(block[0]);
        if (sides == 2) {
          evolve_planes_mirrored(evolve_args_[c], first_block, re[0], im[0], re[1], im[1]);
        } else {
          evolve_planes(evolve_args_[c], first_block, re[0], im[0]);
        }
      }
      for (std::size_t side = 0; side < sides; ++side) {
        for (std::size_t p = 0; p < count; ++p) {
          if (zero[p]) continue;
          const LaneBlock t = tile[side][p];
          const LaneBlock other = scratch[side == 0 && p < 3 ? p : 0];
          if (input[side][p].re == t.re && simd_plan_.input_for(t, other).re != t.re) {
            std::memcpy(other.re, t.re, block_floats * sizeof(float));
            std::memcpy(other.im, t.im, block_floats * sizeof(float));
          }
          simd_plan_.transform(t, other, pruned[p]);
        }
      }
    }
  });
  // Rows: the row FFT of plane 1 (Dz, or a pair's two Dz) and of each cascade's plane 0
  // (h + i·Dx) feeds the displacement assembly with the sign folded in; gradient planes
  // (analytic normals) go to the row-major planes.
  runner.parallel_for(items, 1, [&](std::size_t begin, std::size_t end) {
    StackLanes<3> buffers;  // plane 0's rows, plane 1's rows, scratch
    const LaneBlock p0 = buffers[0], p1 = buffers[1], scratch = buffers[2];
    for (std::size_t item = begin; item < end; ++item) {
      const CascadeGroup& group = groups_[first_group + item / blocks];
      const int block = static_cast<int>(item % blocks);
      // Plane p of cascade c: zero outside columns [N/4, 3N/4) where pruned.
      const auto row_fft = [&](std::size_t c, std::size_t p, LaneBlock lanes) {
        const CascadeState& state = cascades_[c];
        const bool pruned = plane_outer_half_zero(group, c, p);
        const LaneBlock input = simd_plan_.input_for(lanes, scratch);
        simd_plan_.tiles_to_lanes(state.tile_re[p], block, input.re, pruned);
        simd_plan_.tiles_to_lanes(state.tile_im[p], block, input.im, pruned);
        simd_plan_.transform(lanes, scratch, pruned);
      };
      CascadeState& first = cascades_[group.first];
      row_fft(group.first, 1, p1);
      for (std::size_t c = group.first; c < group.first + group.count; ++c) {
        row_fft(c, 0, p0);
        CascadeFrame& frame = out.cascades[c];
        assemble_displacement(p0.re, p0.im, c == group.first ? p1.re : p1.im, n, block,
                              frame.displacement.data(), frame.displacement_half.data(),
                              assembly_stores_);
      }
      if (first.planes > 2) {
        simd_plan_.store_rows(p1.re, p1.im, plane_of(first, 1), block, true);
        for (std::size_t p = 2; p < static_cast<std::size_t>(first.planes); ++p) {
          row_fft(group.first, p, p0);
          simd_plan_.store_rows(p0.re, p0.im, plane_of(first, p), block, true);
        }
      }
    }
  });
}

}  // namespace ocean::cpu
