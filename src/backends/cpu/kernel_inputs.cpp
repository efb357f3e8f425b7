// The CPU backend's data layout for the fused evolution: the spectrum as records in
// column-block order, the rows that carry spectrum, and each frame's EvolveArgs (M.7.3).
#include <algorithm>
#include <cmath>

#include "cpu_backend.hpp"

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

}  // namespace ocean::cpu
