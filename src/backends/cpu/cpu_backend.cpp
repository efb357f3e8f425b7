// CPU backend: configuration (spectra per cascade band, plans, buffers) and the per-frame stage
// chain (seed 000 §4.2). The default pipeline fuses the SIMD evolution into the column FFT and
// the displacement assembly into the row FFT, over all cascades' 16-line blocks at once; the
// scalar reference pipeline (evolve → radix-2 FFT → assemble) is kept as the oracle and for
// external FFT engines. Both then share finalize and the mips.
#include "cpu_backend.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>

namespace ocean::cpu {

// The evolution kernel's inputs in column-block order (EvolveArgs): per (block, row) record the
// S' components and, when looping, the harmonic index j = ω'/ω0 as an exact float (exact phase,
// M.7.3); not looping, the rate ω/2π in double beside them. Every block's column 0 again on its
// own for the mirrored kernel.
void build_kernel_inputs(CascadeState& state, double loop_period_s, bool mirror_pairs) {
  const bool looping = loop_period_s > 0.0;
  const std::size_t record = evolution_record(looping);
  const auto n = static_cast<std::size_t>(state.resolution);
  constexpr auto kLanes = static_cast<std::size_t>(fft::LanePlan2D::kBlock);
  const std::size_t blocks = n / kLanes;
  const std::size_t stored = mirror_pairs && blocks >= 2 ? blocks / 2 : blocks;
  state.evolution_spectrum = AlignedFloats(stored * n * record);
  state.evolution_rate.assign(looping ? 0 : stored * n * kLanes, 0.0);
  state.evolution_lane0 = AlignedFloats(blocks * n * kLane0Record);
  state.evolution_lane0_rate.assign(looping ? 0 : blocks * n, 0.0);
  float* out = state.evolution_spectrum.data();
  float* lane0 = state.evolution_lane0.data();
  for (std::size_t block = 0; block < blocks; ++block) {
    for (std::size_t row = 0; row < n; ++row) {
      const std::size_t r = block * n + row;
      for (std::size_t l = 0; l < kLanes; ++l) {
        const std::size_t i = row * n + block * kLanes + l;
        const double rate = EvolutionPhase::rate(state.spectrum.omega[i], loop_period_s);
        if (l == 0) {
          for (std::size_t c = 0; c < 4; ++c)
            lane0[r * kLane0Record + c] = state.spectrum.packed[i][c];
          if (looping) {
            lane0[r * kLane0Record + 4] = static_cast<float>(rate);  // exact: an integer
          } else {
            state.evolution_lane0_rate[r] = rate;
          }
        }
        if (block >= stored) continue;  // mirrored: the records of blocks < N/32 only
        for (std::size_t c = 0; c < 4; ++c)
          out[r * record + c * kLanes + l] = state.spectrum.packed[i][c];
        if (looping) {
          out[r * record + 4 * kLanes + l] = static_cast<float>(rate);
        } else {
          state.evolution_rate[r * kLanes + l] = rate;
        }
      }
    }
  }
}

// Rows of each block pair (b, N/16 − 1 − b) with spectrum in either block (band-limited
// cascades have none beyond half their Nyquist wavenumber, M.7.1), as an interval closed under
// row → (N − row) mod N (the mirror row), or [0, N) where no such interval is smaller.
void build_row_ranges(CascadeState& state) {
  const auto n = static_cast<std::size_t>(state.resolution);
  constexpr auto kLanes = static_cast<std::size_t>(fft::LanePlan2D::kBlock);
  const std::size_t blocks = n / kLanes;
  const auto has_spectrum = [&](std::size_t row, std::size_t col) {
    const auto& s = state.spectrum.packed[row * n + col];
    return s[0] != 0.0f || s[1] != 0.0f || s[2] != 0.0f || s[3] != 0.0f;
  };
  state.evolution_rows.clear();
  state.outer_half_zero = true;
  for (std::size_t row = 0; row < n && state.outer_half_zero; ++row) {
    for (std::size_t col = 0; col < n; ++col) {
      const bool inner = row >= n / 4 && row < 3 * n / 4 && col >= n / 4 && col < 3 * n / 4;
      if (!inner && has_spectrum(row, col)) {
        state.outer_half_zero = false;
        break;
      }
    }
  }
  if (blocks < 2) return;
  for (std::size_t b = 0; b < blocks / 2; ++b) {
    std::vector<bool> live(n, false);
    for (const std::size_t block : {b, blocks - 1 - b}) {
      for (std::size_t row = 0; row < n; ++row) {
        for (std::size_t l = 0; l < kLanes; ++l) {
          if (has_spectrum(row, block * kLanes + l)) live[row] = live[(n - row) & (n - 1)] = true;
        }
      }
    }
    std::size_t lo = n, hi = 0;
    for (std::size_t row = 0; row < n; ++row) {
      if (live[row]) lo = std::min(lo, row), hi = row + 1;
    }
    if (lo > hi) {
      lo = hi = 0;  // no spectrum at all
    } else if (lo == 0 || lo + hi != n + 1) {
      lo = 0, hi = n;  // [lo, hi) is closed under the mirror only when lo + hi = N + 1
    }
    state.evolution_rows.push_back(static_cast<int>(lo));
    state.evolution_rows.push_back(static_cast<int>(hi));
  }
}

EvolveArgs evolve_args(const CascadeState& state, double time_s, double loop_period_s) {
  EvolveArgs args;
  args.n = state.resolution;
  args.spectrum = state.evolution_spectrum.data();
  args.record = evolution_record(loop_period_s > 0.0);
  args.rate = state.evolution_rate.empty() ? nullptr : state.evolution_rate.data();
  args.lane0 = state.evolution_lane0.data();
  args.lane0_rate =
      state.evolution_lane0_rate.empty() ? nullptr : state.evolution_lane0_rate.data();
  args.rows = state.evolution_rows.empty() ? nullptr : state.evolution_rows.data();
  args.clock = EvolutionPhase(time_s, loop_period_s).clock();  // frac(t/T), or t
  args.planes = state.planes;
  args.dk = 2.0 * kPi / state.patch_size_m;
  args.lambda = state.choppiness;
  return args;
}

namespace {

// (−1)^(x+y) on every plane, for FFT engines that do not fold it in (eq. 43).
void apply_sign(CascadeState& state, TaskRunner& runner) {
  const auto n = static_cast<std::size_t>(state.resolution);
  runner.parallel_for(n, 8, [&](std::size_t row_begin, std::size_t row_end) {
    for (std::size_t p = 0; p < state.plane_re.size(); ++p) {
      for (std::size_t row = row_begin; row < row_end; ++row) {
        float* re = state.plane_re[p].data() + row * n;
        float* im = state.plane_im[p].data() + row * n;
        for (std::size_t col = (row + 1) & 1u; col < n; col += 2)
          re[col] = -re[col], im[col] = -im[col];
      }
    }
  });
}

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

fft::SplitComplex plane_of(CascadeState& state, std::size_t p) {
  return {state.plane_re[p].data(), state.plane_im[p].data()};
}

/// K lane blocks of the largest size on a worker's stack (no allocation in the frame path).
template <std::size_t K>
struct StackLanes {
  static constexpr std::size_t kFloats = fft::LanePlan2D::kBlock * fft::kMaxSimdSize;
  alignas(64) float re[K][kFloats];
  alignas(64) float im[K][kFloats];
  fft::LanePlan2D::LaneBlock operator[](std::size_t i) { return {re[i], im[i]}; }
};

}  // namespace

Status CpuBackend::configure(const SimulationConfig& config, TaskRunner& runner) {
  if (Status s = validate(config); !s.ok()) return s;
  if (options_.pipeline == CpuPipeline::external_fft && options_.fft == nullptr)
    return invalid_argument("CPU backend: the external FFT pipeline needs an FFT engine");
  Result<SeaState> sea = SeaState::make(config.sea);
  if (!sea.ok()) return sea.status();
  Result<fft::Plan2D> plan = fft::Plan2D::make(config.resolution);
  if (!plan.ok()) return plan.status();
  Result<fft::LanePlan2D> simd_plan = fft::LanePlan2D::make(config.resolution);
  if (!simd_plan.ok()) return simd_plan.status();
  std::vector<CascadeState> cascades(config.cascade_patch_sizes_m.size());
  const auto texels =
      static_cast<std::size_t>(config.resolution) * static_cast<std::size_t>(config.resolution);
  const bool pairs =
      options_.pipeline != CpuPipeline::scalar_reference && plane_count(config.normals) == 2;
  std::vector<CascadeGroup> groups;
  for (std::size_t c = 0; c < cascades.size(); c += pairs ? 2 : 1)
    groups.push_back({c, std::min<std::size_t>(pairs ? 2 : 1, cascades.size() - c)});
  for (std::size_t c = 0; c < cascades.size(); ++c) {
    CascadeState& state = cascades[c];
    state.resolution = config.resolution;
    state.patch_size_m = config.cascade_patch_sizes_m[c];
    Result<InitialSpectrum> spectrum =
        make_initial_spectrum(sea.value(), cascade_spectrum_params(config, c));
    if (!spectrum.ok()) {
      return Status(spectrum.status().code(),
                    "cascade " + std::to_string(c) + ": " + spectrum.status().message());
    }
    state.spectrum = std::move(spectrum).value();
    state.planes = plane_count(config.normals);
    state.choppiness = config.choppiness;
    const bool second_of_pair = pairs && c % 2 == 1;
    const auto planes = second_of_pair ? 1 : static_cast<std::size_t>(state.planes);
    const bool fused = options_.pipeline == CpuPipeline::fused_simd;
    if (fused) {
      build_kernel_inputs(state, config.loop_period_s, true);
      build_row_ranges(state);
      state.tiles = AlignedFloats(2 * planes * texels);  // one allocation: huge pages sooner
      for (std::size_t p = 0; p < planes; ++p) {
        state.tile_re.push_back(state.tiles.data() + 2 * p * texels);
        state.tile_im.push_back(state.tiles.data() + (2 * p + 1) * texels);
      }
    } else {
      build_plane_factors(state, config.normals, config.choppiness);
    }
    if (!fused || config.normals == NormalMethod::analytic) {  // row-major planes
      state.plane_re.assign(planes, std::vector<float>(texels));
      state.plane_im.assign(planes, std::vector<float>(texels));
    }
    state.foam.assign(texels, 0.0f);
    // The fused central-difference surface pass keeps levels 0 and 1 of the work values on the
    // stack: its chain starts at level 2.
    const bool fused_surface = fused && config.normals == NormalMethod::central_difference;
    state.mip_work_level = fused_surface ? 2 : 0;
    state.mip_work.assign(4 * (mip_chain_texels(config.resolution) -
                               mip_offset(config.resolution, state.mip_work_level)),
                          0.0f);
  }
  config_ = config;
  runner_ = &runner;
  plan_ = std::move(plan).value();
  simd_plan_ = std::move(simd_plan).value();
  cascades_ = std::move(cascades);
  groups_ = std::move(groups);
  surface_args_.assign(cascades_.size(), SurfaceArgs{});
  chain_times_.assign(groups_.size(), StageTimes{});
  // Streaming stores for the maps that would leave the caches before anything reads them: the
  // half map (never read in the frame) from 256², where a cascade pair's maps outgrow a core's
  // L2, and the float map from 512², where they outgrow the last-level cache before the surface
  // pass reads them back. Measured (4 cascades, 2 threads, A/B in one process): 512² −12 %,
  // 1024² −9 %, 2048² −6 %; streaming the float map at 256² is 10 % slower (docs/performance.md).
  assembly_stores_ = {.stream_displacement = config.resolution >= 512,
                      .stream_half = config.resolution >= 256};
  evolve_args_.assign(cascades_.size(), EvolveArgs{});
  has_stepped_ = false;
  return {};
}

void CpuBackend::allocate(Frame& frame) const { allocate_frame(config_, frame); }

std::size_t CpuBackend::state_bytes_per_cascade() const {
  if (cascades_.empty()) return 0;
  const CascadeState& s = cascades_.front();
  const auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  std::size_t total = bytes(s.spectrum.packed) + bytes(s.spectrum.omega) + bytes(s.spectrum.h0) +
                      bytes(s.evolution_rate) + bytes(s.evolution_lane0_rate) + bytes(s.foam) +
                      bytes(s.mip_work) +
                      (s.evolution_spectrum.size() + s.evolution_lane0.size()) * sizeof(float);
  for (const auto& v : s.factor) total += bytes(v);
  for (const auto& v : s.plane_re) total += 2 * bytes(v);  // with plane_im
  total += bytes(s.tiles);
  return total;
}

bool CpuBackend::group_outer_half_zero(const CascadeGroup& group) const {
  bool all = true;
  for (std::size_t c = group.first; c < group.first + group.count; ++c)
    all = all && cascades_[c].outer_half_zero;
  return all;
}

bool CpuBackend::plane_outer_half_zero(const CascadeGroup& group, std::size_t c,
                                       std::size_t p) const {
  // Plane 1 of a pair carries both cascades' Dz; every other plane one cascade's fields.
  return simd_plan_.prunes_outer_half() &&
         (p == 1 ? group_outer_half_zero(group) : cascades_[c].outer_half_zero);
}

void CpuBackend::prepare_evolution(double time_s) {
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

void CpuBackend::synthesise_fused(TaskRunner& runner, std::size_t first_group,
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

void CpuBackend::prepare_surface(double dt_s, bool reset_foam, Frame& out) {
  const int n = config_.resolution;
  const float base_length = normal_length_from_roughness(static_cast<float>(config_.roughness));
  std::vector<SurfaceArgs>& args = surface_args_;  // sized at configure: no allocation here
  for (std::size_t c = 0; c < cascades_.size(); ++c) {
    CascadeState& state = cascades_[c];
    CascadeFrame& frame = out.cascades[c];
    args[c] = {.n = n,
               .displacement = frame.displacement.data(),
               .inv_spacing = static_cast<float>(n / state.patch_size_m),  // eq. 45
               .base_length = base_length,
               .smoothness = smoothness_from_normal_length(base_length),
               .jacobian_start = static_cast<float>(config_.foam.jacobian_start),
               .jacobian_range =
                   static_cast<float>(config_.foam.jacobian_start - config_.foam.jacobian_full),
               .decay = static_cast<float>(config_.foam.decay_per_s * dt_s),
               .reset_foam = reset_foam,
               .blue_is_foam = config_.blue_channel == BlueChannel::foam,
               .foam_state = state.foam.data(),
               .jacobian = frame.jacobian.empty() ? nullptr : frame.jacobian.data(),
               .foam = frame.foam.empty() ? nullptr : frame.foam.data(),
               .normal = frame.normal.empty() ? nullptr : frame.normal.data(),
               .mip_work = state.mip_work.data(),
               .packed = frame.packed_mips.data()};
  }
}

void CpuBackend::surface_fused(TaskRunner& runner, std::size_t first, std::size_t count) {
  const auto quads = static_cast<std::size_t>(config_.resolution / 4);
  runner.parallel_for(count * quads, 4, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end;) {  // runs of consecutive quads in one cascade
      const std::size_t c = i / quads, stop = std::min(end, (c + 1) * quads);
      surface_row_quads(surface_args_[first + c], static_cast<int>(i % quads),
                        static_cast<int>(stop - i));
      i = stop;
    }
  });
}

void CpuBackend::mips_fused(TaskRunner& runner, int first_level, std::size_t first,
                            std::size_t count, Frame& out) {
  const int n = config_.resolution;
  const int levels = std::countr_zero(static_cast<unsigned>(n));
  const auto level_rows = [&](int level) { return static_cast<std::size_t>(n >> level); };
  // Levels of at least 64 rows: one parallel loop each (each reads the level above). The levels
  // under 64 rows (at most 1365 texels per cascade): each cascade's rest of the chain on one
  // worker, one loop for all, so the frame does not wait on a barrier per small level.
  int level = first_level;
  for (; level <= levels && level_rows(level) >= 64; ++level) {
    const std::size_t rows = level_rows(level);
    runner.parallel_for(count * rows, 8, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t c = first + i / rows;
        mip_row(n, level, static_cast<int>(i % rows), cascades_[c].mip_work.data(),
                cascades_[c].mip_work_level, out.cascades[c].packed_mips.data());
      }
    });
  }
  if (level > levels) return;
  runner.parallel_for(count, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = first + begin; c < first + end; ++c) {
      for (int l = level; l <= levels; ++l) {
        for (std::size_t row = 0; row < level_rows(l); ++row) {
          mip_row(n, l, static_cast<int>(row), cascades_[c].mip_work.data(),
                  cascades_[c].mip_work_level, out.cascades[c].packed_mips.data());
        }
      }
    }
  });
}

void CpuBackend::synthesise_unfused(double time_s, Frame& out) {
  for (const CascadeGroup& group : groups_) {
    CascadeState& first = cascades_[group.first];
    fft::SplitComplex planes[fft::kMaxPlanes];
    std::size_t count = 0;
    for (std::size_t c = group.first; c < group.first + group.count; ++c) {
      CascadeState& state = cascades_[c];
      evolve(state, time_s, config_.loop_period_s, *runner_, c == group.first ? nullptr : &first);
      for (std::size_t p = 0; p < state.plane_re.size(); ++p) planes[count++] = plane_of(state, p);
    }
    const std::span<const fft::SplitComplex> view{planes, count};
    if (options_.pipeline == CpuPipeline::external_fft) {
      options_.fft->inverse(view);
      for (std::size_t c = group.first; c < group.first + group.count; ++c)
        apply_sign(cascades_[c], *runner_);
    } else {
      plan_.inverse(view, *runner_, true);
    }
    for (std::size_t c = group.first; c < group.first + group.count; ++c) {
      const float* dz = c == group.first ? first.plane_re[1].data() : first.plane_im[1].data();
      assemble_displacement_reference(cascades_[c], dz, out.cascades[c], *runner_);
    }
  }
}

void CpuBackend::step_chained(TaskRunner& stages, double time_s, double dt_s, bool reset_foam,
                              Frame& out) {
  // One chain per cascade group: columns → rows → surface (with mip levels 1 and 2) → the other
  // mip levels, the chains side by side and each stage a loop of its own. With the frame's
  // runner for the stages, a worker that ends its chain helps with the other chains' loops
  // instead of waiting at a barrier per stage; with a serial one, each chain stays on one
  // thread.
  prepare_evolution(time_s);
  prepare_surface(dt_s, reset_foam, out);
  runner_->parallel_for(groups_.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t g = begin; g < end; ++g) {
      const CascadeGroup& group = groups_[g];
      const Clock::time_point start = Clock::now();
      synthesise_fused(stages, g, 1, out);
      const Clock::time_point synthesised = Clock::now();
      surface_fused(stages, group.first, group.count);
      const Clock::time_point finalized = Clock::now();
      mips_fused(stages, 3, group.first, group.count, out);
      chain_times_[g] = {seconds(synthesised - start), seconds(finalized - synthesised),
                         seconds(Clock::now() - finalized)};
    }
  });
  times_ = {};  // the chains overlap in time: the longest chain's stages
  for (const StageTimes& t : chain_times_) {
    times_.synthesis_s = std::max(times_.synthesis_s, t.synthesis_s);
    times_.finalize_s = std::max(times_.finalize_s, t.finalize_s);
    times_.mips_s = std::max(times_.mips_s, t.mips_s);
  }
}

void CpuBackend::step(double time_s, Frame& out) {
  // Foam accumulates over the time since the previous step; a first step or a jump back in
  // time starts it afresh.
  const bool reset_foam = !has_stepped_ || time_s < last_time_s_;
  const double dt = reset_foam ? 0.0 : time_s - last_time_s_;
  const bool fused = options_.pipeline == CpuPipeline::fused_simd;
  if (fused && config_.normals == NormalMethod::central_difference) {
    // A chain per thread when there are no more threads than cascade groups and a group's
    // frame (about 3 MiB at 256²) still fits the caches of one core: on a machine whose cores
    // do not share a cache, stealing inside a chain moves its planes and outputs between the
    // cores, and 4 × 64²…256² ran 15–30 % faster with each chain on one thread. From 512² the
    // group's data streams from memory either way, and the groups' unequal costs (band-limited
    // cascades evolve and transform less) weigh more: their stages are shared, 8–30 % faster
    // there (docs/performance.md).
    const bool chain_per_thread =
        static_cast<std::size_t>(runner_->concurrency()) <= groups_.size() &&
        config_.resolution <= 256;
    step_chained(chain_per_thread ? *serial_ : *runner_, time_s, dt, reset_foam, out);
  } else {
    const Clock::time_point start = Clock::now();
    if (fused) {
      prepare_evolution(time_s);
      synthesise_fused(*runner_, 0, groups_.size(), out);
    } else {
      synthesise_unfused(time_s, out);
    }
    const Clock::time_point synthesised = Clock::now();
    for (std::size_t c = 0; c < cascades_.size(); ++c)
      finalize(cascades_[c], config_, dt, reset_foam, out.cascades[c], *runner_);
    const Clock::time_point finalized = Clock::now();
    if (fused) {
      mips_fused(*runner_, 1, 0, cascades_.size(), out);
    } else {
      for (std::size_t c = 0; c < cascades_.size(); ++c)
        build_mips(cascades_[c], out.cascades[c], *runner_);
    }
    times_ = {seconds(synthesised - start), seconds(finalized - synthesised),
              seconds(Clock::now() - finalized)};
  }
  out.time_s = time_s;
  ++out.index;
  last_time_s_ = time_s;
  has_stepped_ = true;
}

}  // namespace ocean::cpu
