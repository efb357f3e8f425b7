// The surface particles' velocity (docs/math.md M.7.11): the time derivative of the evolved
// spectrum h̃(k, t) = S'xy·cos ω't + S'zw·sin ω't (M.6.5), ∂h̃/∂t = ω'·(S'zw·cos ω't −
// S'xy·sin ω't), and the displacement's factors (M.7.2) applied to it: ∂D̃/∂t = λ·i·k̂·∂h̃/∂t
// (Dean & Dalrymple 1991, ch. 4: the linear (Airy) wave's particle velocity at the surface is
// the time derivative of its displacement). Two planes per cascade, (w + i·u) and v, through the
// radix-2 Plan2D, so every pipeline gets the same velocity.
#include <cmath>

#include "cpu_backend.hpp"

namespace ocean::cpu {

void velocity(CascadeState& state, double time_s, double loop_period_s, const fft::Plan2D& plan,
              CascadeFrame& out, TaskRunner& runner) {
  const int n = state.resolution;
  const auto un = static_cast<std::size_t>(n);
  const double dk = 2.0 * kPi / state.patch_size_m;
  const double lambda = state.choppiness;
  const EvolutionPhase phase_of(time_s, loop_period_s);  // exact after days (M.7.3)
  runner.parallel_for(un, 8, [&](std::size_t row_begin, std::size_t row_end) {
    for (std::size_t row = row_begin; row < row_end; ++row) {
      const double kz = dk * (static_cast<double>(row) - n / 2);
      for (std::size_t col = 0; col < un; ++col) {
        const std::size_t i = row * un + col;
        const double kx = dk * (static_cast<double>(col) - n / 2);
        const double k = std::hypot(kx, kz);
        const double ux = k > 0.0 ? kx / k : 0.0;  // k̂
        const double uz = k > 0.0 ? kz / k : 0.0;
        const double omega = state.spectrum.omega[i];
        const double phase = phase_of(omega);
        const double c = std::cos(phase), s = std::sin(phase);
        const auto& p = state.spectrum.packed[i];
        // ∂h̃/∂t = ω'·∂h̃/∂(ω't)   (M.7.11)
        const double re = omega * (p[2] * c - p[0] * s);
        const double im = omega * (p[3] * c - p[1] * s);
        // Plane 0: ḣ̃ + i·(λ·i·k̂x·ḣ̃) = (1 − λ·k̂x)·ḣ̃ → (w, u); plane 1: λ·i·k̂z·ḣ̃ → v.
        state.velocity_re[0][i] = static_cast<float>((1.0 - lambda * ux) * re);
        state.velocity_im[0][i] = static_cast<float>((1.0 - lambda * ux) * im);
        state.velocity_re[1][i] = static_cast<float>(-lambda * uz * im);
        state.velocity_im[1][i] = static_cast<float>(lambda * uz * re);
      }
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
