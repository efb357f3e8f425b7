// The surface particles' velocity (docs/math.md M.7.11): the time derivative of the evolved
// spectrum h̃(k, t) = S'xy·cos ω't + S'zw·sin ω't (M.6.5), ∂h̃/∂t = ω'·(S'zw·cos ω't −
// S'xy·sin ω't), and the displacement's factors (M.7.2) applied to it: ∂D̃/∂t = λ·i·k̂·∂h̃/∂t
// (Dean & Dalrymple 1991, ch. 4: the linear (Airy) wave's particle velocity at the surface is
// the time derivative of its displacement). Two planes per cascade, (w + i·u) and v, through the
// SIMD plan (fft.hpp, SimdPlan2D), the same for every pipeline.
#include <cmath>

#include "cpu_backend.hpp"

namespace ocean::cpu {

namespace {

// Harmonics up to which a looping cascade's phases come from a table of phasors (one sincos per
// harmonic and frame instead of one per wave vector): 2^16 covers ω' up to 2000 rad/s at T = 200 s.
constexpr double kMaxTabulatedHarmonic = 65536.0;

}  // namespace

void build_velocity_inputs(CascadeState& state, double loop_period_s) {
  const int n = state.resolution;
  const auto texels = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  const double dk = 2.0 * kPi / state.patch_size_m;
  state.velocity_khat.assign(2 * texels, 0.0f);
  state.velocity_harmonic.assign(texels, -1);
  bool tabulate = loop_period_s > 0.0;
  std::int32_t largest = 0;
  for (std::size_t i = 0; i < texels; ++i) {
    const auto& p = state.spectrum.packed[i];
    if (p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f && p[3] == 0.0f) continue;  // off the band
    const double kx = dk * (static_cast<double>(i % static_cast<std::size_t>(n)) - n / 2);
    const double kz = dk * (static_cast<double>(i / static_cast<std::size_t>(n)) - n / 2);
    const double k = std::hypot(kx, kz);
    state.velocity_khat[2 * i] = static_cast<float>(k > 0.0 ? kx / k : 0.0);
    state.velocity_khat[2 * i + 1] = static_cast<float>(k > 0.0 ? kz / k : 0.0);
    // The harmonic j = ω'/ω0 as EvolutionPhase computes it, so the table's phase is its own.
    const double j = tabulate ? EvolutionPhase::rate(state.spectrum.omega[i], loop_period_s) : 0.0;
    if (j > kMaxTabulatedHarmonic) tabulate = false;
    state.velocity_harmonic[i] = static_cast<std::int32_t>(std::min(j, kMaxTabulatedHarmonic));
    largest = std::max(largest, state.velocity_harmonic[i]);
  }
  if (tabulate) {
    state.velocity_phasor.assign(static_cast<std::size_t>(largest) + 1, {1.0, 0.0});
  } else {
    state.velocity_phasor.clear();  // every phase by EvolutionPhase and its own sincos
  }
}

void velocity(CascadeState& state, double time_s, double loop_period_s, const fft::SimdPlan2D& plan,
              CascadeFrame& out, TaskRunner& runner) {
  const auto un = static_cast<std::size_t>(state.resolution);
  const double lambda = state.choppiness;
  const EvolutionPhase phase_of(time_s, loop_period_s);  // exact after days (M.7.3)
  const bool tabulated = !state.velocity_phasor.empty();
  if (tabulated) {
    // 2π·frac(j·τ), what EvolutionPhase gives harmonic j.
    const double tau = phase_of.clock();
    for (std::size_t j = 0; j < state.velocity_phasor.size(); ++j) {
      const double turns = static_cast<double>(j) * tau;
      const double phase = 2.0 * kPi * (turns - std::floor(turns));
      state.velocity_phasor[j] = {std::cos(phase), std::sin(phase)};
    }
  }
  runner.parallel_for(un, 8, [&](std::size_t row_begin, std::size_t row_end) {
    for (std::size_t i = row_begin * un; i < row_end * un; ++i) {
      const std::int32_t j = state.velocity_harmonic[i];
      if (j < 0) {  // outside the cascade's band (most of a band-limited cascade)
        state.velocity_re[0][i] = state.velocity_im[0][i] = 0.0f;
        state.velocity_re[1][i] = state.velocity_im[1][i] = 0.0f;
        continue;
      }
      const double omega = state.spectrum.omega[i];
      double c, s;
      if (tabulated) {
        c = state.velocity_phasor[static_cast<std::size_t>(j)][0];
        s = state.velocity_phasor[static_cast<std::size_t>(j)][1];
      } else {
        const double phase = phase_of(omega);
        c = std::cos(phase);
        s = std::sin(phase);
      }
      const auto& p = state.spectrum.packed[i];
      // ∂h̃/∂t = ω'·∂h̃/∂(ω't)   (M.7.11)
      const double re = omega * (p[2] * c - p[0] * s);
      const double im = omega * (p[3] * c - p[1] * s);
      const double ux = state.velocity_khat[2 * i], uz = state.velocity_khat[2 * i + 1];
      // Plane 0: ḣ̃ + i·(λ·i·k̂x·ḣ̃) = (1 − λ·k̂x)·ḣ̃ → (w, u); plane 1: λ·i·k̂z·ḣ̃ → v.
      state.velocity_re[0][i] = static_cast<float>((1.0 - lambda * ux) * re);
      state.velocity_im[0][i] = static_cast<float>((1.0 - lambda * ux) * im);
      state.velocity_re[1][i] = static_cast<float>(-lambda * uz * im);
      state.velocity_im[1][i] = static_cast<float>(lambda * uz * re);
    }
  });
  const fft::SplitComplex planes[2] = {{state.velocity_re[0].data(), state.velocity_im[0].data()},
                                       {state.velocity_re[1].data(), state.velocity_im[1].data()}};
  plan.inverse(planes, runner, true);
  runner.parallel_for(un, 8, [&](std::size_t row_begin, std::size_t row_end) {
    for (std::size_t i = row_begin * un; i < row_end * un; ++i) {
      out.velocity[3 * i] = state.velocity_im[0][i];      // u = ∂Dx/∂t
      out.velocity[3 * i + 1] = state.velocity_re[0][i];  // w = ∂h/∂t
      out.velocity[3 * i + 2] = state.velocity_re[1][i];  // v = ∂Dz/∂t
    }
  });
}

}  // namespace ocean::cpu
